(G73 under --reading g73.c=skip: no retreat to C, pass 1 starts from A X60 Z5 itself; the pass offsets as under the letter)
G00 X60 Z5
G73 U3 W2 R3
G73 P10 Q30 U1.6 W0.1 F0.2
N10 G00 X20 Z1
N20 G01 Z-20
N30 G01 X40 Z-30
G00 X80 Z50
