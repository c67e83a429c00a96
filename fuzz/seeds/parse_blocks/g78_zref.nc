(G78 under --reading thread.zref=groove: every mode ends its last rough pass on one groove, A.z + sigma t of T; mode 4 then mode 0. The letter measures every mode from A.z)
G00 X40 Z5;
G78 P010460 Q0.08 R0.05 D1;
G78 X27.4 Z-20 P1.3 Q0.4 F2 J1 K1;
G78 P010060 Q0.08 R0.05 D1;
G78 X27.4 Z-20 P1.3 Q0.4 F2 J1 K1;
M30;
