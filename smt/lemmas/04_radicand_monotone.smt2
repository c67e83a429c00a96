; Lemma 04 radicand_monotone (brief: b) — G76.DEPTH.1
;
; Property: the radicand n·Δd² of pass n grows with n: k ≤ m ⇒ k·Δd² ≤ m·Δd², strictly when
;   k < m. With lemma 03, the depth before the switch, round(√(n·Δd²)), never decreases.
; Assumptions: Δd ≥ 1; k ≤ m any integers (pass numbers, also 0 and s − 1).
; Domain: mathematical integers, no upper bound.
; Expected: unsat.

(declare-const dd Int)
(declare-const k Int)
(declare-const m Int)

(assert (>= dd 1))
(assert (<= k m))

; negated property (everything above is the model and the assumptions)
(assert (not (and
  (<= (* k dd dd) (* m dd dd))
  (=> (< k m) (< (* k dd dd) (* m dd dd))))))
(check-sat)
