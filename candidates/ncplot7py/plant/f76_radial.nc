(FANUC G76, tool angle 0, no chamfer: radial infeed, no pull-out; depths 0.3 0.6 0.9 1.2 1.5 by the minimum cut, then 1.6)
G0 X65 Z5
G76 P010000 Q300 R0.1
G76 X58.7 Z-28 P1600 Q300 F3
M30
