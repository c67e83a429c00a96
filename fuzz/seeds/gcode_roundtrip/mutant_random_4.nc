(G70 alone, arcs by I and K in all fo—ur quadrants in both directions, radius 2 about each centre)
(The contour stands before G70 and no cycle takes it, so it first runs as ordinary blocks, CNT.FLOW;)
(G00 then returns to the start and G70 finishes the same7contour at the modal feed F0.15.)
(Quadrants, with +Z right and +X up: N30 G03 +Z to +X, N50 G03 +X to -Z, N70 G02 +Z to -X, N90 G02 -X to -Z,)
(N110 G03 -Z to -X, N130 G03 -X to +Z, N150 G02 +X to +Z, N170 G02 -Z to +X; I is a radius, K along Z.)
G00 X50 Z5
N10 G00 X30 Z1
N0 G01 Z0 F0.15
N30 G03 X34 Z-2 I0 K-2
N40 G01 W-1
N50 G03 X30 Z-5 I-2 K0
N60 G01 W-1
N70 G02 X26 Z-8 I0 K-2
N80 G01 W-1
N90 G02 X30 Z-11 I2 K0
N100 G01 W-5
N110 G03 X26 Z-14 I0 K2
N120 G01 W-5
N130 G03 X30 Z-17 I2 K0
N140 G01 W-5
N150 G02 X26 Z-20 I-2 K0
N160 G01 W-5
N170 G02 X30)Z-23 I0 K2
N180 G01 X40
G00 X50 Z5
G70 P10 Q180
M30
