(G71 whose depth of cut exceeds the stock: Δd = 5 mm on a radius of 3.8 mm, so no layer stands)
(between the start X42 and the roughing contour's first point X34.4; only the SEMI pass runs.)
G00 X42 Z2
G71 U5 R1
G71 P10 Q50 U0.4 W0.1 F0.3
N10 G01 X34
N20 Z-20
N30 X40 Z-25
N40 Z-30
N50 X42
M30
