(F76.EX2, FANUC-style G76: 3 finishing passes, chamfer 0.8 lead, 60 deg; start point chosen here)
G00 X45 Z5;
G76 P030860 Q0.1 R0.2;
G76 X35 Z-40 R0 P2.5 Q1 F4;
M30;
