; Lemma 09 cut_before_switch — G76.DEPTH.1, G76.DEPTH.MIN
;
; Property: at a pass n ≥ 1 where the rule does not switch, the rounded cut is at least Δdmin:
;   round(√(n·Δd²)) − round(√((n−1)·Δd²)) ≥ Δdmin. (Before the switch the exact cut
;   (√n − √(n−1))·Δd is ≥ Δdmin; rounding each depth once loses less than one increment on
;   each side, and the cut is an integer.) With Δdmin = 0 this says the depth never decreases.
; Assumptions: Δd ≥ 1, Δdmin ≥ 0, n ≥ 1 integers; `switches n` false (n before the switch
;   pass s, lemma 07, or no minimum); rn, r1 the rounded roots of n·Δd², (n−1)·Δd²;
;   x = √n, y = √(n−1) as reals.
; Uses: lemma 06 (switch_rule) at n, and lemma 01 (root_is_rounding, the direction
;   bracket ⇒ r − ½ ≤ √v < r + ½) at X = x·Δd and Y = y·Δd — each as an instantiated hypothesis.
; Domain: mathematical integers and reals, no upper bound.
;   (Measured: the same query without the two lemma 01 instances did not finish in 60 s under
;   z3 4.8.12; with them what is left is linear.)
; Expected: unsat.

(define-fun is_root ((v Int) (r Int)) Bool
  (and (>= r 0)
       (< (* 4 v) (+ (* 4 r r) (* 4 r) 1))
       (or (= r 0) (<= (+ (* 4 r r) (* -4 r) 1) (* 4 v)))))
(define-fun rounds_to ((x Real) (r Int)) Bool
  (and (<= (- r 0.5) x) (< x (+ r 0.5))))
(define-fun root_is_rounding ((v Int) (r Int) (X Real)) Bool           ; lemma 01
  (=> (and (>= v 0) (>= X 0.0) (= (* X X) (to_real v)) (is_root v r)) (rounds_to X r)))

(declare-const dd Int)
(declare-const dm Int)
(declare-const n Int)
(declare-const rn Int)
(declare-const r1 Int)
(declare-const x Real)
(declare-const y Real)

(assert (>= dd 1))
(assert (>= dm 0))
(assert (>= n 1))
(assert (and (>= x 0.0) (= (* x x) (to_real n))))
(assert (and (>= y 0.0) (= (* y y) (to_real (- n 1)))))

(define-fun a () Int (- (* dd dd) (* dm dm)))
(define-fun switches ((k Int)) Bool
  (or (< a 0) (< (* a a) (* 4 dd dd dm dm (- k 1)))))

(assert (not (switches n)))
(assert (= (switches n) (< (* (- x y) dd) dm)))                          ; lemma 06 at n
(assert (is_root (* n dd dd) rn))
(assert (is_root (* (- n 1) dd dd) r1))
(assert (root_is_rounding (* n dd dd) rn (* x dd)))                     ; lemma 01
(assert (root_is_rounding (* (- n 1) dd dd) r1 (* y dd)))               ; lemma 01

; negated property (everything above is the model and the assumptions)
(assert (not (>= (- rn r1) dm)))
(check-sat)
