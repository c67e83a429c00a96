(G78 J and K are modal by 000 lines 59 and 61: the second cycle omits J and K and pulls out J1.5 K2 as the first; the third writes K3 only and keeps J1.5)
G00 X70 Z5;
G78 P010060 Q0.1 R0.1;
G78 X60 Z-60 P3 Q1.8 F3 J1.5 K2;
G78 X60 Z-60 P3 Q1.8;
G78 X60 Z-60 P3 Q1.8 K3;
M30;
