(G94 face taper under the letter g94.k=end-minus-start, the default: K = end Z - cut start Z, so the cut starts at C.z = D.z - K; kept within the run)
G0 X50 Z2;
G94 X20 Z-5 K-2 F0.2; (the register's example: the cut starts at Z-3)
Z-8; (K-2 kept: the cut starts at Z-6)
G94 X20 Z-6 K-8; (k = C.z - D.z = 8 against W = -8, the edge: the cut starts at Z2, no approach move)
G94 X20 Z-4 K3; (k = -3 with W = -6: the cut starts at Z-7)
M30;
