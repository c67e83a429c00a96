(G74.COLUMN and G74.RELIEF: a face groove widened in columns X20, 26, 32, 38 and the last exactly at X40,)
(Δi = 3, a radius; pecks of 2 mm with e = 0.5; a relief of 0.2 at the bottom of every column but the first.)
G00 X20 Z1
G74 R0.5
G74 X40 Z-5 P3 Q2 R0.2 F0.05
G00 X80 Z50
