(F76.EX1, FANUC-style G76: 1 finishing pass, chamfer 1.0 lead, 60 deg, minor diameter 33.8)
G00 X60 Z10;
G76 P011060 Q0.1 R0.1W;
G976 X33.8 Z-60 R0 P2.4 Q0.7 F4;
M-30;
