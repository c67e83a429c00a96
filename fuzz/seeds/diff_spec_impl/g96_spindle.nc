(G96.SMAX: G50 S2000 limits the spindle before G96; G96.SPEED: S180 is the surface speed; G96.RAPID: no G00 block between G96 and G97.)
(The rapids G71 makes and its contour's G00 are not program blocks. G97 S800 before the rapid home.)
G50 X150 Z100 S2000
G00 X41 Z1
G96 S180
G71 U2 R1
G71 P10 Q30 F0.2
N10 G00 X0
N20 G01 Z-10
N30 X40
G97 S800
G00 X150 Z100
M30
