(G96.RAPID, the letter: a G00 block while G96 is in force is UNSUPPORTED on G, before it moves; under the declared reading g96.rapid = allow it runs.)
G50 S2000
G00 X40 Z2
G96 S150
G90 X36 Z-20 F0.3
G00 X60 Z10
M30
