(G90 modal runs: end X, end Z and I kept within a run; G76 between its blocks does not end it; after G94 or G01 a new run starts with I = 0 and the pass index at 1)
G0 X50 Z2;
G90 X46 Z-30 I-1 F0.25; (run 1, pass1)
X44; (pass 2: Z-30 and I-1 kept)
G76 P010060 Q0.1 R0.05; (G76 is one-shot: the run goes on)
G76 X46 Z-20 P1 Q0.4 F1.5; (a thread from the same start; F1.5 becomes the modal feed)
X42 F0.25; (pass 3 of run 1)
G94 X40 Z-1; (a face cut: G94 ends the G90 run)
G90 X40 Z-30; (run 2,1 pass 1: I = 0)
G01 X52 Z2; (G01 ends run 2)
G90 X38 Z-30; (run 3, pass 1)
M30;
