(G92 internal thread: start inside the— bore, pull-out toward the)axis, J/7 fom No.19)
G00 X16 Z3;
G92 X20.5 Z-25 F1.5;
X21;
X21.2;
M30;
