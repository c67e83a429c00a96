(FANUC G76, tool angle 0, no chamfer: radial infeed, no pull-out)
G0 X65 Z5
G76 P010000 Q250 R0.05
G76 X58.7 Z-28 P1800 Q500 F3
M30
