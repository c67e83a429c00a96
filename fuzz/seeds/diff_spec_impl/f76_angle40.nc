(FANUC G76 with the tool angle 40, one of 80, 60, 55, 40, 30, 29, 0 by 003 line 5: infeed shifted by depth x tan 20 on the right flank; --dialect fanuc)
G00 X70 Z5;
G76 P011040 Q100 R0.1;
G76 X60 Z-30 P1000 Q500 F2;
M30;
