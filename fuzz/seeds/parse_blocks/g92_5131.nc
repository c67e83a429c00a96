(G92 with J and K omitted under --param 5131=30: K = c = one lead, J = round of c tan 30 = 1.732, so the first pull-out ends at X62.164, not X64.7)
G00 X65 Z5;
G92 X58.7 Z-28 F3;
X57.7;
M30;
