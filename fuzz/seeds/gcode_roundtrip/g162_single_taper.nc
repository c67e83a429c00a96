(G162 single pass with a taper: the X word is the thread's END point, 004 line 34, so W2 starts segment 2 at X21 and ends it at X23; --dialect nc201)
G0 X30 Z5
G162 X23 Z-20 W2 H500 F1.5
M30
