(G92 two-start thread: each cycle cut at spindle angles 0 and 180 degrees)
G00 X35 Z5;
G92 X29.2 Z-20 F3 J1 K1 L2;
X28.6;
X28.4;
M30;
