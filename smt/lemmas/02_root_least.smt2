; Lemma 02 root_least — G76.DEPTH.1 (how the model finds the root)
;
; Property: r = round(√v) (the bracket `is_root`) exactly when r is the least r ≥ 0 with
;   v ≤ r² + r: the bracket's upper half holds at r and fails at every 0 ≤ j < r. The driver's
;   model (src/model.rs, `root`) computes round(√v) as that least r by binary search over this
;   monotone test, so no square root is taken anywhere in the model.
; Assumptions: v, r, j integers; v ≥ 0.
; Domain: mathematical integers, no upper bound.
; Expected: unsat.

(define-fun is_root ((v Int) (r Int)) Bool
  (and (>= r 0)
       (< (* 4 v) (+ (* 4 r r) (* 4 r) 1))
       (or (= r 0) (<= (+ (* 4 r r) (* -4 r) 1) (* 4 v)))))
(define-fun fits ((v Int) (r Int)) Bool      ; the search test: v ≤ r² + r
  (<= v (+ (* r r) r)))

(declare-const v Int)
(declare-const r Int)
(declare-const j Int)

(assert (>= v 0))

; negated property (everything above is the model and the assumptions)
(assert (not (and
  ; the bracket is "fits at r, not at r − 1"
  (= (is_root v r) (and (>= r 0) (fits v r) (or (= r 0) (not (fits v (- r 1))))))
  ; and then it fails at every smaller candidate
  (=> (and (is_root v r) (<= 0 j) (< j r)) (not (fits v j))))))
(check-sat)
