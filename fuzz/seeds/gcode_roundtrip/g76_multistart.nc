(G76 three-start thread: every pass cut at 0, 120 and 240 degrees; lead-in E)
G00 X40 Z5;
G76 P011060 Q0.1 R0.05 L3 E0.5;
G76 X27.4 Z-20 P1.3 Q0.45 F6 J1 K2;
M30;
