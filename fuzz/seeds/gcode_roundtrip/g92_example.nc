(G92.EXAMPLE, GSK980TDi manual 3.24.9: thread in four cycles, first infeed 1.3 mm on diameter)
O0012;
M3 S300 G0 X150 Z50 T0101; (thread tool)
G0 X65 Z5; (rapid to the start point)
G92 X58.7 Z-28 F3 J3 K1; (first cycle)
X57.7; (second cycle, infeed 1 mm)
X57; (third cycle, infeed 0.7 mm)
X56.9; (fourth cycle, infeed 0.1 mm)
M30;
