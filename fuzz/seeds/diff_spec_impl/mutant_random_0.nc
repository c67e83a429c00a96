(G71.EXAMPLE, M003 textbook example 1: OD stock removal along Z with G71, then finishing with G70)(The seed prints the blocks run together; each N starts a new block, one per line here, verbatim otherwise.)
(Read as docs/INTERPRETATION.md says: G50 declares the tool at X150 Z100; A = X41 Z0; depth 2, retract 1;)
(allowances U0.5 W0.2; the contour N050-N120 is a ball end R5.15 by G03, a taper and a fillet R7.5 by G02.)
N010 G50 X150 Z100
N020 G00 X41 Z0
N030 G71 U2 R1
N040 G71 P50 Q120 U0.5 W0.2 F100
N050 G01 X0 Z0
N060 G03 X11 W-5.5 R5.5
N070 G01 W-10
N080 X17 W-10
N090 W-15
N100 G02 X29 W-7.348 R7.5
N110 G01 W-12.652
N120 X41
N130 G70 P50 Q120 F30
