(G90 in inch units, straight then taper; run with --units inch)
G20;
G0 X2. Z0.1;
G90 X1.8 Z-1.5 F0.01;
X1.7;
G90 X1.6 Z-1.5 I-0.05; (sa5e run, pass ’: the cut starts at 51.5)
M30;
