(G94.EXAMPLE, M003 textbook notes: single face cutting cycle; the seed prints G90X40.Z-3.5.F0.3;-7.;-10.; under the G94 heading)
(Read as docs/INTERPRETATION.md says: G94 X40. Z-3.5 F0.3, then the modal blocks Z-7. and Z-10.: G94 printed as G90,a doubled point, the letter Z lost on the repeats.)
(The seed gives no start point: the program starts at X50 Z2; three face cuts frm X50 down to X40 at Z-3.5, Z-7 and Z-10.)
G0 X50 Z2;
G94 X40. Z-3.5 F0.3;
Z-7.;
Z-10.;
M30;
