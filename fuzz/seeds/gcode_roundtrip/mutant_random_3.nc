(G162 two-start thread: ne cycle per start, B0 and B180; --dialect nc201)
G0 X36 Z4
G162 X32 Z-24 H500 P0.9 Q0.3 F3 B0
G162 X32 Z-24 H500 P0.9 Q0.3 F3 B180
M30
