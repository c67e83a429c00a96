(G162 variable pitch under --reading g162.lead=continuous: the programs of g162_steps with the pitch changing at a constant rate, as G34; --dialect nc201)
G0 X30 Z5
G162 X24 Z-20 H500 P0.5 Q0.5 F1.5 I-0.5 J180
G162 X24 Z-20 H500 F1.5 I0.25
M30
