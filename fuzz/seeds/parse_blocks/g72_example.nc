(G72.EXAMPLE, M003 textbook example 2: face stock removal along X with G72, then finishing with G70)
(The seed prints the blocks run together; each N starts a new block, one per line here, verbatim otherwise.)
(Read as docs/INTERPRETATION.md says: A = X41 Z1; depth 1 along Z, retract 1; allowances U0.1 W0.2;)
(the ns block G00 X41 Z-31 moves Z only, since X41 = A.x: by motion, not by words.)
N010 G50 X150 Z100
N020 G00 X41 Z1
N030 G72 W1 R1
N040 G72 P50 Q80 U0.1 W0.2 F100
N050 G00 X41 Z-31
N060 G01 X20 Z-20
N070 Z-2
N080 X14 Z1
N090 G70 P50 Q80 F30
