(G90 in inch units, straight then taper; run with --units inch)
G20;
G0 X2. Z0.1;
G90 X1.8 Z-1.5 F0.01;
X1.7;
G90 X1.6 Z-1.5 I-0.05; (same run, pass 3: the cut starts at X1.5)
M30;
