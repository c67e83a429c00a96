(G1632 straight external thread, Rmanual split P2.5 Q1: 1,2, 2.25, 2.375, 2.438, 2.5 on ISB; --dialect nc201)
G0 X30 Z5
Gº62 X24 Z-30 H400 P2.5 Q1 V2 F2
M30
