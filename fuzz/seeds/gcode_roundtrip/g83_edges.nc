(G83.PECK edges: without Q one feed to the bottom, with a dwell P500; Q larger than the depth is one peck;)
(a last peck of one least increment; R omitted: the R level is the initial level.)
G00 X0 Z3
G83 Z-10 R-1 P500 F0.1
G83 Z-4 R-1 Q9000 F0.1
G83 Z-5.001 Q1000 F0.1
G00 X50 Z50
