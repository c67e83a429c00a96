(G84.PATH under G99: the lead is F, 1.25 mm per revolution; a dwell P200 at the bottom; M29 in the same block;)
(then an R level below the initial level.)
G00 X0 Z5
G99 M29 S500 G84 Z-15 R-3 P200 F1.25
G80
G00 X50 Z50
