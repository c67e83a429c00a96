; Lemma 01 root_is_rounding — G76.DEPTH.1, G76.DEPTH.MIN (the rounding "once, half up")
;
; Property: the integer bracket `is_root v r` (4r² − 4r + 1 ≤ 4v < 4r² + 4r + 1, r ≥ 0, and
;   r = 0 for v = 0) holds exactly when r is √v rounded half up, r − ½ ≤ √v < r + ½; and adding
;   an integer k to an exact depth adds k to its rounding (round(x + k) = round(x) + k), which is
;   why the depth after the switch is round(√((s−1)·Δd²)) + (n − s + 1)·Δdmin.
;   Also: for v < 0 the bracket holds only for r = 0, so `is_root` is total (one r for every v)
;   and asserting it never constrains anything else.
; Assumptions: v integer ≥ 0 with X = √v (real X ≥ 0, X² = v); r, k any integers.
; Domain: mathematical integers and reals, no upper bound.
; Note: the bracket as often written (4r² − 4r + 1 ≤ 4v) excludes v = 0 (it gives 1 ≤ 0);
;   round(√0) = 0 needs the disjunct r = 0. The radicand 0 occurs: (s − 1)·Δd² with s = 1.
; Expected: unsat.

(define-fun is_root ((v Int) (r Int)) Bool
  (and (>= r 0)
       (< (* 4 v) (+ (* 4 r r) (* 4 r) 1))
       (or (= r 0) (<= (+ (* 4 r r) (* -4 r) 1) (* 4 v)))))
(define-fun rounds_to ((x Real) (r Int)) Bool
  (and (<= (- r 0.5) x) (< x (+ r 0.5))))

(declare-const v Int)
(declare-const r Int)
(declare-const k Int)
(declare-const X Real)
(declare-const w Int)

(assert (>= v 0))
(assert (>= X 0.0))
(assert (= (* X X) (to_real v)))

; negated property (everything above is the model and the assumptions)
(assert (not (and
  (= (is_root v r) (rounds_to X r))
  (= (rounds_to X r) (rounds_to (+ X k) (+ r k)))
  (=> (< w 0) (= (is_root w r) (= r 0))))))
(check-sat)
