(G162 internal thread in G91, infeed angle -30, single pass after a multi-pass, F from the modal feed; --dialect nc201)
G0 X18 Z5
G1 X18 Z4 F1.5
G91
G162 X2 Z-24 H250 P0.6 Q0.25 A-30
G162 X2.4 Z-24 H250
G90 G0 X18 Z10
M30
