(G73.EXAMPLE, M003 textbook example 3: pattern repeating with G73 format a, then finishing with G70)
(The seed prints the blocks run together; each N starts a new block, one per line here, verbatim otherwise.)
(Read as docs/INTERPRETATION.md says: A = X50 Z10; escape 18, a radius, and 5 in Z in 10 passes;)
(allowances U0.5 W0.5; the contour N050-N100 is a ball end R6 by G03, a taper and a fillet R7 by G02.)
N010 G50 X100 Z100
N020 G00 X50 Z10
N030 G73 U18 W5 R10
N040 G73 P50 Q100 U0.5 W0.5 F100
N050 G01 X0 Z1
N060 G03 X12 W-6 R6
N070 G01 W-10
N080 X20 W-15
N090 W-13
N100 G02 X34 W-7 R7
N110 G70 P50 Q100 F30
