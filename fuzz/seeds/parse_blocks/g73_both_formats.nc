(G73.FORMAT: both formats on the same part. Format a: G73 U W R, then G73 P Q U W F, four passes; format b:)
(one block G73 P Q I K U W D F, three passes, its contour right after it as CNT.FIND asks, whose I, K, D do not)
(change the values format a keeps.)
G00 X50 Z5
G73 U8 W2 R4
G73 P10 Q40 U0.5 W0.2 F0.25
N10 G00 X16 Z2
N20 G01 Z-12
N30 G03 X28 Z-18 I0 K-6
N40 G01 X40 Z-30
G73 P50 Q80 I4.5 K1.5 U0.3 W0.1 D3 F0.2
N50 G00 X16 Z2
N60 G01 Z-12
N70 G03 X28 Z-18 I0 K-6
N80 G01 X40 Z-30
G00 X80 Z50
