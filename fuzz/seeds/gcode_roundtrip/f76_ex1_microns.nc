(F76.EX1 in the micron form of F76.MICRONS: run with --dialect fanuc)
G00 X60 Z10;
G76 P011060 Q100 R0.1;
G76 X33.8 Z-60 R0 P2400 Q700 F4;
M30;
