(G76 external taper thread, i = -3 radius, chamfer from r = 10 tenths of the lead)
G00 X70 Z5;
G76 P021060 Q0.1 R0.05;
G76 X50 Z-40 R-3 P1.3 Q0.5 F2;
M30;
