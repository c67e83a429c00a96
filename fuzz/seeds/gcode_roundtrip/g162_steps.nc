(G162 variable pitch in steps, the letter g162.lead=steps of 004 lines 75-77: F1.5 for 180 degrees, then 1.0, then 0.5, never below or at abs I; then a pitch growing by 0.25 per revolution; --dialect nc201)
G0 X30 Z5
G162 X24 Z-20 H500 P0.5 Q0.5 F1.5 I-0.5 J180
G162 X24 Z-20 H500 F1.5 I0.25
M30
