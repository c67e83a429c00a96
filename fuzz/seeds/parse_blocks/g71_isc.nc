(G71 on the ISC grid, 0.0001 mm: run with --increment isc; the words need four decimals)
(Depth 1.2345, retract 0.5, allowances U0.1234 W0.0567; an arc R5.4321 by G03 from the axis.)
G00 X41.25 Z0.5
G71 U1.2345 R0.5
G71 P10 Q60 U0.1234 W0.0567 F0.2
N10 G01 X0 Z0.5
N20 G03 X10.8642 W-5.4321 R5.4321
N30 G01 W-9.8765
N40 X24.6802 W-7.0001
N50 W-12.3456
N60 X41.25
G70 P10 Q60 F0.1
M30
