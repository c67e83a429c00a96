(G75.EXAMPLE, M003 textbook example 5: OD grooving along X with G75, one block per line)
(Read as docs/INTERPRETATION.d says: from X42 Z22, retract e = 1, to X30 Z10; pecks of P3 = 3 mm, a radius,)
(grooves stepped by Q2.9 = 2.9 mm: six gooves at Z22, 19.1, 16.2, 13.3, 10.4 and 10; no relief.)
G50 X60 Z70
G00 X42 Z22 S400
G75 R1
G75 X30 Z10 P3 Q2.9 F30
G00 X60 Z70
