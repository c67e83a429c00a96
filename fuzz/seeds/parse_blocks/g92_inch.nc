(G92 inch thread given in threads per inch; run with --units inch)
G20;
G00 X1.1 Z0.1;
G92 X0.95 Z-0.8 I20;
X0.94;
M30;
