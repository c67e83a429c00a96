(G76 internal thread: positive infeed, Z shifts toward +Z)
G00 X20 Z5;
G76 P011060 Q0.1 R0.05;
G76 X30 Z-30 P1.2 Q0.4 F2 J0.5 K1;
M30;
