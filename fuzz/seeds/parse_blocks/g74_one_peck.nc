(G74.PECK edge: Q larger than the depth is one peck straight to the end, then the rapid back to the start.)
G00 X0 Z2
G74 R1
G74 Z-3 Q10 F0.1
G00 X50 Z50
