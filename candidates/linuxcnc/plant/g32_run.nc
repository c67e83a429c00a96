(G32 constant lead, modal repeat, then a taper thread)
G0 X30 Z5
G32 X30 Z-20 F2
G0 X34
Z5
X29.4
G32 Z-20
G0 X34
Z5
X28
G32 X30 Z-15 F1.5
G0 X34
M30
