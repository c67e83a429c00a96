(G78 constant depth ode D0: every cut is Q, the last clamped to k 1- d)
G00 X40 Z5;
G78 P010260 Q0.08 R0.05 D0;
G78 X27.4 Z-20 P1.3 Q
.4 F2 J1 K1;
M40;
