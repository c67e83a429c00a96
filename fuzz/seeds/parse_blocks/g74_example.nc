(G74.EXAMPLE, M003 textbook example 4: peck drilling along Z with G74, one block per line)
(Read as docs/INTERPRETATION.md says: from X0 Z2, retract e = 1, to Z-12 in pecks of Q5 = 5 mm: one column,)
(pecks to Z-3, Z-8, Z-12 with a 1 mm rapid back after each but the last, then back to Z2.)
G50 X60 Z40
G00 X0 Z2
G74 R1
G74 Z-12 Q5 F30 S250
G00 X60 Z40
