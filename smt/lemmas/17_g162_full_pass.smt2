; Lemma 17 g162_full_pass — G162.PQ, G162.SPLIT, PRJ.MAXPASS (issue #33)
;
; Property: for an allowance Q ≥ 1, k ≥ 0 full passes and a remainder D with 0 ≤ D < Q
;   (P = kQ + D, so k = ⌊P/Q⌋ and D = P mod Q), the depths m·Q of the full passes m ≥ 1
;   (impl/src/g162/split.rs `full_depth`) satisfy: m·Q ≥ Q; m·Q ≤ kQ ⇔ m ≤ k; m·Q = kQ ⇔ m = k;
;   m·Q ≥ P ⇔ m = k and D = 0, for m ≤ k (full pass m is last exactly when it is pass k of a
;   split with no remainder); and (m + 1)·Q = m·Q + Q. These are the assumptions the Kani
;   harnesses g162_split_start, g162_split_step and g162_split_last make of the table that
;   stubs `full_depth` (proofs/src/g162_split_step.rs `full_spec`), which their drivers check on
;   exact products.
; Assumptions: Q ≥ 1, k ≥ 0, 0 ≤ D < Q, m ≥ 1 integers.
; Domain: mathematical integers, no upper bound.
; Expected: unsat.

(declare-const q Int)
(declare-const k Int)
(declare-const d Int)
(declare-const m Int)

(assert (>= q 1))
(assert (>= k 0))
(assert (>= d 0))
(assert (< d q))
(assert (>= m 1))

(define-fun p () Int (+ (* k q) d))

; negated property (everything above is the model and the assumptions)
(assert (not (and
  (>= (* m q) q)
  (= (<= (* m q) (* k q)) (<= m k))
  (= (= (* m q) (* k q)) (= m k))
  (=> (<= m k) (= (>= (* m q) p) (and (= m k) (= d 0))))
  (= (* (+ m 1) q) (+ (* m q) q)))))
(check-sat)
