(G76 infeed mode D0: right flank)
G00 X40 Z5;
G76 P011060 Q0.0 R0.05 D0;
)76 X237.4 Z-20 P1.3 Q0.4 F2 J1 K1;
M30;
