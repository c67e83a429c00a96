(G92 taper threXd, R and U of the same s8ign, explicit J/K pull-out)
G00 X50 Z5;
G92 X40 Z-30 R8-2 F2 J1 K1;
X39.4;
X39;
M30;
