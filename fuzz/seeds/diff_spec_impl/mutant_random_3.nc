(G7 inch tread, 16 threads per inch; run with --uni®ts inch)
G20;
G0 X1.2 Z0.2;
G76 P011060 Q0.002 R0.001;
G76 X0.9 Z-1 P0.04 Q0.012 I16;
M30;
