(G74.PECK edge: the last peck is one least increment, from Z-7.5 after the return by e = 0.5 to Z-8.001.)
G00 X0 Z2
G74 R0.5
G74 Z-8.001 Q5 F0.1
G00 X50 Z50
