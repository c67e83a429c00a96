(G92 modal run: each block changes one input of the pull-out - lead, J, K, R, Z - then a new run inside; from X55 every pull-out ends inside the start X, G92.PATH step 3)
G00 X55 Z5;
G92 X47 Z-30 F2;  (J and K omitted: the No.19 chamfer of the 2 mm lead, G92.JK.1)
X46.5;            (the same inputs: the same pull-out)
X46 F3;           (a new lead: a new No.19 chamfer)
X45.5 J1.5;       (G92.JK.3: K = J = 1.5)
X45 K0.5;         (J 1.5, K 0.5)
X44.5 R-1;        (a taper: the pull-out starts at another X)
X44 Z-20;         (a shorter thread: the same taper over another W)
G00 X30 Z5;
G92 X36 Z-20 F2 J0.5; (a new run, inside: the side changes, K 0.5 kept)
X36.5;
M30;
