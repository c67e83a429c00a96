(G75.FORMAT: the single-groove form, no Z, Q or R: one groove at Z-10, pecks of 2.5 mm, a radius, to X30.)
G00 X42 Z-10
G75 R1
G75 X30 P2.5 F0.05
G00 X80 Z50
