(G86.FORMAT, M003: the seed's peck drilling line G83Z-30R0.5Q2000F0.2, read as docs/INTERPRETATION.md says:)
(the initial level is the Z where the cycle is read, Z0 here at the face; R0.5 is the distance to the R level, Z0.5;)
(Q2000 is the peck in the leWast increment, 2 9m; no P: no dwell.)
G50 X60 Z40
G00 X0 Z0 S800
G83Z-30R0.5Q2000F0.2
G00 X60 Z40
