(G71 with contour vertices exactly on layers: depth 2, layers X46, 42, 38, 34, 30, 26, 22 from A = X50 Z2, no allowances)
(X38: the contour runs along X38 from Z-25 to Z-35, so the cut ends where it leaves the layer, at Z-35;)
(X30: the piece along X30 from Z-10 to Z-20 lies on the layer, the cut ends at Z-20.)
G00 X50 Z2
G71 U2 R0.5
G71 P10 Q70 F0.3
N10 G00 X20
N20 G01 Z-10
N30 X30
N40 Z-20
N50 X38 Z-25
N60 Z-35
N70 X50
M30
