(G84.FORMAT, M003: the seed's rigid tapping line G98M29S60G84Z-21R2F60G80, its blocks run together as in the)
(seed's other examples, one block per line here. Read as docs/INTERPRETATION.md says: under G98 the lead is)
(F / S = 60 / 60 = 1 mm; from the initial level Z0 to the R level Z2, tapping to Z-21 and back, then Z0.)
G50 X60 Z40
G00 X0 Z0
G98M29S60
G84Z-21R2F60
G80
G00 X60 Z40
