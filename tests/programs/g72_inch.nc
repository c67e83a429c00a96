(G72 face roughing in inch units; run with --units inch)
(Depth 0.05 in along Z, retract 0.02 in; the ns block moves Z only; a quarter arc R0.2 by G03 at the end.)
G20
G00 X2.2 Z0.1
G72 W0.05 R0.02
G72 P10 Q40 U0.01 W0.005 F0.008
N10 G00 Z-0.6
N20 G01 X1.2 Z-0.4
N30 Z-0.1
N40 G03 X0.8 Z0.1 R0.2
G70 P10 Q40 F0.004
M30
