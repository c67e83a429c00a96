(G75.RELIEF under --reading g75.relief=against-step: the grooves of g75_relief, the relief of 0.3 in +Z against the step, as FANUC and ADTECH draw it.)
G00 X52 Z-10
G75 R0.5
G75 X40 Z-20 P2 Q3 R0.3 F0.05
G00 X80 Z50
