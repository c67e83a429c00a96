(G162 two-start thread: one cycle per start, B0 and B180; --dialect nc201)
G X36 Z4
G162 X32 Z-24 H500 P0.9 Q0.3 F3 B0
G162 X32 Z-24 H500 P0.9 Q0.3 F3 B180
M30
