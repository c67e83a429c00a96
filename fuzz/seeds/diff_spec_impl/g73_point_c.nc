(G73 point C, the letter g73.c=visit: before pass 1 the tool retreats from A X60 Z5 to C = A + 2 Di + Du on X, A + Dk + Dw on Z = X67.6 Z7.1, then pass 1 starts from C)
G00 X60 Z5
G73 U3 W2 R3
G73 P10 Q30 U1.6 W0.1 F0.2
N10 G00 X20 Z1
N20 G01 Z-20
N30 G01 X40 Z-30
G00 X80 Z50
