(G71 on an inside diameter: the tool starts in a 16 mm bore, the ns block moves X outward, so s = +1)
(Layers X19, 22, ... 37 from Z2 toward -Z; the allowance U-0.4 leaves stock inside the bore, W0.1 in Z)
(The contour: chamfer, bore 36, fillet R3 by G02 down to bore 30, bottom face back to X16)
G00 X16 Z2
G71 U1.5 R0.5
G71 P10 Q70 U-0.4 W0.1 F0.25
N10 G00 X40
N20 G01 Z0
N30 X36 Z-2
N40 Z-15
N50 G02 X30 Z-18 R3
N60 G01 Z-30
N70 X16
G70 P10 Q70 F0.1
G00 X16 Z50
M30
