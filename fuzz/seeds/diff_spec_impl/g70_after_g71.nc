(G71 roughing, then G70 alone twice, each finding the contour before it: first with U0.2 W0.05,)
(a finishing step that leaves a smaller allowance, G70.UW, then the finish without U and W.)
(The contour's own F0.08 on N30 applies to G70 from that block on, G70.FEED; roughing ignores it.)
G00 X44 Z1
G71 U1.5 R0.5
G71 P10 Q50 U0.5 W0.1 F0.3
N10 G00 X20
N20 G01 Z-12
N30 X30 Z-20 F0.08
N40 G03 X38 Z-24 R4
N50 G01 X44
G70 P10 Q50 U0.2 W0.05 F0.15
G70 P10 Q50 F0.12
M30
