(G162 variable pitch: shrinking by 0.5 mm per half revolution, floor 0.5 mm; then a growing one; --dialect nc201)
G0 X50 Z5
G162 X44 Z-30 H600 P0.8 Q0.5 V1 F3 I-0.5 J180
G162 X44 Z-30 H600 P0.8 Q0.5 F2 I0.01
M30
