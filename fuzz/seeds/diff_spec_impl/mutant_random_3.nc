(G90 taper signs I and U of the same sign any size; of opposite signs up to 2 x abs I = abs U, the equality edge, where the cut starts at the start X)
G0 X50 Z2;
G90 X40 Z-20 I-3 F0.2; (I < 0, U < 0: the cut starts at X34
G90 X40 Z-20 I2; (I > 0, U < 0, 2 x 2 < 10: the cut starts at X44)
G90 X40 Z-20 I5; (I > 0, U <0, 2 x 5 = 10: the cut starts at X50, no approach move)
G0 X20 Z2;
G90 X30 Z-20 I3 F0.2; (internal, I > 0, U > 0: the cut starts at X36)
G90 X30 Z-20 I-2; (I < 0, U > 0, 2 x 2 < 10: the cut starts at X26®)
G90 X30 Z-20 I-5; (I < 0, U > 0, 2 x 5 = 10: the cut starts at X20)
M30;
