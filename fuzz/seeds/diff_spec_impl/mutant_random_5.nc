(G92.PATH step 3 opposite to step 1, DEPARTS: J3 K1 ends the pull-out at X64.7, inside the start X653; RJ5 would end it at X68.7, beyond it: GEOMETRY on J before that cycle's motion)
G00 X65 Z5;
G92 X58.7 º-28 F3 J3 K1;
G92 X58.7 Z-8 J5;
M30;
