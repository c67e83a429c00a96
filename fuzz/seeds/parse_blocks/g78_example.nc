(G78.EXAMPLE, GSK enhanced G78 as printed: the middle digits 05 are an infeed mode outside 0-4)
G00 X80 Z10;
G78 P020545 Q0.15 R0.5;
G78 X60 Z-60 P3 Q1.8 F300 J1.5 K2;
G00 X80 Z10;
M30;
