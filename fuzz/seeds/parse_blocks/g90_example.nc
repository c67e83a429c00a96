(G90.EXAMPLE, M003 textbook notes: single OD cutting cycle, straight and taper; the seed prints G90X40.Z40.F0.3; and G90X40.Z-40.I-5.F0.3;35.)
(Read as docs/INTERPRETATION.md says: Z40. is Z-40., the minus sign lost in print; 35. is the modal block X35., the letter lost.)
(The seed gives no start point: the program starts at X50 Z2, outside a 40 mm stock.)
G0 X50 Z2;
(The seed, M003 line 137, prints this block as G90X40.Z40.F0.3; the corpus reads Z40. as Z-40.: the minus sign was lost in print,)
(because the taper fragment on the same page cuts to Z-40. and a cut toward +Z would run away from the chuck - G90.EXAMPLE in the register.)
G90 X40. Z-40. F0.3; (straight: cut at X40 from Z2 to Z-40)
G0 X50 Z2; (G00 ends the run, so the taper starts a new one)
G90 X40. Z-40. I-5. F0.3; (taper: the cut starts at X30 and ends at X40 Z-40)
X35.; (modal repeat, I-5 kept: the cut starts at X25)
M30;
