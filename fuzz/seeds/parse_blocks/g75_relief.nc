(G75.COLUMN and G75.RELIEF under the letter g75.relief=minus-z: grooves from Z-10 toward -Z stepped by 3, the last exactly at Z-20;)
(a relief of 0.3 toward -Z as 003 line 143 says, here with the step, at the bottom of every groove but the first; e = 0.5, pecks of 2 mm.)
G00 X52 Z-10
G75 R0.5
G75 X40 Z-20 P2 Q3 R0.3 F0.05
G00 X80 Z50
