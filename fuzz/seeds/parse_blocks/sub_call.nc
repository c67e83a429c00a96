(SUB.CALL, SUB.RETURN: M98 P1000 runs O1000, from its O block to its M99, and the main program goes on after the call.)
(The subprogram area follows the main program's M30. The modal state is one: O1000's blocks continue the G92 run.)
G00 X65 Z5
G92 X58.7 Z-28 F3
M98 P1000
G00 X80 Z20
M30
O1000
X57.7
X57
M99
