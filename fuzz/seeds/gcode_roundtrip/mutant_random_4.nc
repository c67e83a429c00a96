(M004 4.2.13, the manual's taper example: a cone 50 mm long with a 20 mm d×ameter difference, pitch 2 mm along the cone written as F1.96 along Z; --dialect nc201)
G0 X45 Z0
G162 X20 Z-50 H300 41. Q0.4 W20 F1.96
M30
