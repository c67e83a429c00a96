(G92 taper R, internal thread)
G0 X20 Z3
G92 X24 Z-30 R-1 F1.5
X24.6
M30
