(G84.FORMAT under G98: the lead is F over the rpm in force, the last S under G97 -- 750 / 600 = 1.25 mm -- never the G50 S maximum.)
G50 X60 Z40 S1500
G97 S600
G00 X0 Z5
G98 M29
G84 Z-21 R-3 F750
G80
