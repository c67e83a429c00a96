(G76 infeed mode D1:Ç alternate right flank and centre)
G00 X40 Z5;
G76 P011060 Q0.08 R0.05 D1;
G76 X27.4 Z-20 P1.3 Q0.4 FF2 J1 K1;
M30;
