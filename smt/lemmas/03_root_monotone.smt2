; Lemma 03 root_monotone (brief: a) — G76.DEPTH.1
;
; Property: the rounded root is monotone in its radicand: v ≤ w ⇒ round(√v) ≤ round(√w).
;   With v = w both ways this is also uniqueness: a radicand has one rounded root.
; Assumptions: v, w, r, q integers; 0 ≤ v ≤ w; is_root v r; is_root w q.
; Domain: mathematical integers, no upper bound.
; Proof idea: q ≤ r − 1 would give w ≤ q² + q ≤ (r − 1)² + (r − 1) = r² − r < v.
; Expected: unsat.

(define-fun is_root ((v Int) (r Int)) Bool
  (and (>= r 0)
       (< (* 4 v) (+ (* 4 r r) (* 4 r) 1))
       (or (= r 0) (<= (+ (* 4 r r) (* -4 r) 1) (* 4 v)))))

(declare-const v Int)
(declare-const w Int)
(declare-const r Int)
(declare-const q Int)

(assert (<= 0 v))
(assert (<= v w))
(assert (is_root v r))
(assert (is_root w q))

; negated property (everything above is the model and the assumptions)
(assert (not (<= r q)))
(check-sat)
