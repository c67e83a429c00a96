(G84.FORMAT: G50 S1500 is the maximum, no spindle speed: under G98 with no rpm in force G84 is MISSING WORD S.)
G50 X60 Z40 S1500
G00 X20 Z10
G00 X0 Z0
G98 M29
G84 Z-21 R2 F60
