(G92 taper thread, R and U of the same sign, explicit J/K pull-out)
G00 X50 Z5;
G92 X40 Z-30 R-2 F2 J1 K1;
X39.4;
X39;
M30;
