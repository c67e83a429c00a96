(G94 face taper, --reading g94.k=start-minus-end, as FANUC and ADTECH write it: K = cut start Z - end Z, kept within the run; K and W of the same sign any size, of opposite signs up to abs K = abs W)
G0 X50 Z2;
G94 X20 Z-2 K-1 F0.2; (K < 0, W < 0: the cut starts at Z-3)
Z-4; (K-1 kept: the cut starts at Z-5)
K2; (only K: the kept taper changes, nothing is cut)
Z-6; (K > 0, W < 0, 2 < 8: the cut starts at Z-4)
G94 X20 Z-6 K8; (K = abs W: the cut starts at Z2, no approach move)
U-50 Z-6 K0; (X0 written as a distance, K0: a straight face cut to the centre)
M30;
