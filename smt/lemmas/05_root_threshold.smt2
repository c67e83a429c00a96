; Lemma 05 root_threshold — G76.DEPTH.LAST (where the rounded depth reaches T)
;
; Property: round(√v) ≥ T ⇔ v > T·(T − 1). So before the switch, pass n's rounded depth reaches
;   T exactly when n·Δd² > T·(T − 1), i.e. from n = ⌊T(T − 1)/Δd²⌋ + 1 on (the production's
;   `reach`); and it compares the rounded depth, as G76.DEPTH.LAST requires.
; Assumptions: T ≥ 1; v ≥ 0; is_root v r.
; Domain: mathematical integers, no upper bound.
; Expected: unsat.

(define-fun is_root ((v Int) (r Int)) Bool
  (and (>= r 0)
       (< (* 4 v) (+ (* 4 r r) (* 4 r) 1))
       (or (= r 0) (<= (+ (* 4 r r) (* -4 r) 1) (* 4 v)))))

(declare-const v Int)
(declare-const r Int)
(declare-const t Int)

(assert (>= t 1))
(assert (>= v 0))
(assert (is_root v r))

; negated property (everything above is the model and the assumptions)
(assert (not (= (>= r t) (> v (* t (- t 1))))))
(check-sat)
