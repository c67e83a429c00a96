(G92 modal run of three cycles, no pull-out: the manual example M002 with No.19 = 0)
G0 X65 Z5
G92 X58.7 Z-28 F3
X58.1
X57.6
M30
