(G73.COUNT edge: d = 1 is one pass, exactly on the contour plus the allowances U0.4 W0.1, arcs included.)
G00 X40 Z5
G73 U6 W2 R1
G73 P10 Q40 U0.4 W0.1 F0.2
N10 G00 X10 Z1
N20 G01 Z-10
N30 G02 X20 Z-15 R5
N40 G01 X30 Z-25
G00 X60 Z50
