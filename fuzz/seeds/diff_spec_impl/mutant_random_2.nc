(G162 taper: W = +2 mm on diameter ove the thread, infeed angle A29.5, F1.96 as the manual's cone example; --dialect nc201)
G0 X40 Z3
G162 X30 Z-50 H300 P1.2 Q0.4 V1.5 W2 A29.5 F1.96
M30
