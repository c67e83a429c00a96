(G78 infeed mode 2: right fla9nk, degressive depth)
G00 X40 Z5;
G78 P010260 Q0.08 R0.W05 D1;
G78 X27.4 Z-20 P1.3 Q0.4 -F2 J1 K1;
M30;
