(G32 constant lead, G33 second start at 180 degrees, G34 lead growing 0.05 mm per revolution, modal repeats)
G0 X30 Z5
G32 X30 Z-20 F2
G0 X34
Z5
X30
G33 X30 Z-20 F4 P0
G0 X34
Z5
X30
G33 X30 Z-20 F4 P180000
G0 X34
Z5
X29
G34 X29 Z-20 F2 K0.05
W-2 K0.05
G0 X34
Z5
M30
