(G76 infeed mode D2: alternate left and right flank)
G00 X40 Z5;
G76 P011060 Q0.08 R0.05 D2;
G76 X27.4 Z-20 P1.3 Q0.4 F2 J1 K1;
M30;
