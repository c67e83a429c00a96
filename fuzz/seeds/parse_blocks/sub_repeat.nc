(SUB.CALL: M98 P42000 calls O2000 four times, 003_... line 144; the last four digits are the number, those before them the repeats.)
(The main program turns the diameter; O2000 cuts one groove 5 mm further along Z at each run.)
G00 X52 Z2
G90 X48 Z-30 F0.3
G00 X50 Z-5
M98 P42000
G00 X60 Z10
M30
O2000
G00 W-5
G01 U-4 F0.1
G00 U4
M99
