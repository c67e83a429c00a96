; Lemma 15 g73_escape — G73.DEPTH, G73.PATH (issue #33)
;
; Property: pass n's escape e(n) = round(v·(d − n)/d), rounded once half away from zero
;   (impl/src/g73.rs `escape`, through `fixed::div_round_signed`: for d ≥ 1 the magnitude is
;   ⌊(2|x| + d)/(2d)⌋, the sign that of x), v = Δi or Δk any integer, d ≥ 1, 1 ≤ n ≤ d:
;   e(n) lies between 0 and v (the sign of v, never beyond it); e(n + 1) is no farther from 0
;   than e(n) on the same side (the offsets never grow, n + 1 ≤ d); e(d) = 0 (the last pass at
;   the allowance). Used by the Kani harness `g73_passes` (proofs/), whose stub of `escape`
;   assumes these facts at the two passes it asks for; its drivers check them on the exact
;   quotients.
; Assumptions: d ≥ 1, 1 ≤ n ≤ d, v any integer.
; Domain: mathematical integers, no upper bound.
; Expected: unsat.

(declare-const v Int)
(declare-const d Int)
(declare-const n Int)

(assert (>= d 1))
(assert (and (>= n 1) (<= n d)))

(define-fun round_away ((x Int) (d Int)) Int
  (ite (>= x 0) (div (+ (* 2 x) d) (* 2 d)) (- (div (+ (* -2 x) d) (* 2 d)))))
(define-fun e ((k Int)) Int (round_away (* v (- d k)) d))

; negated property (everything above is the model and the assumptions)
(assert (not (and
  (=> (>= v 0) (and (<= 0 (e n)) (<= (e n) v)))
  (=> (<= v 0) (and (<= v (e n)) (<= (e n) 0)))
  (=> (< n d) (and (=> (>= v 0) (<= (e (+ n 1)) (e n))) (=> (<= v 0) (>= (e (+ n 1)) (e n)))))
  (=> (= n d) (= (e n) 0)))))
(check-sat)
