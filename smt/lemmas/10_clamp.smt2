; Lemma 10 clamp (brief: d) — G76.DEPTH.LAST
;
; Property: the clamp of a rounded depth u at T (u ≥ T becomes T and is the last rough pass):
;   the clamped depth never exceeds T; a last pass has depth exactly T; a pass that is not last
;   keeps its rounded depth u, which is below T; clamping never lowers a depth below a smaller
;   rounded depth (u' ≤ u ⇒ clamp u' ≤ clamp u), so it keeps the order lemmas 03, 08, 09 give.
; Assumptions: T ≥ 1; u, u' any integers (rounded depths).
; Domain: mathematical integers, no upper bound.
; Expected: unsat.

(declare-const t Int)
(declare-const u Int)
(declare-const u2 Int)

(assert (>= t 1))

(define-fun last ((u Int)) Bool (>= u t))
(define-fun depth ((u Int)) Int (ite (last u) t u))

; negated property (everything above is the model and the assumptions)
(assert (not (and
  (<= (depth u) t)
  (=> (last u) (= (depth u) t))
  (=> (not (last u)) (and (= (depth u) u) (< u t)))
  (=> (<= u2 u) (<= (depth u2) (depth u))))))
(check-sat)
