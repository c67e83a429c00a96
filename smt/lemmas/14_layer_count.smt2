; Lemma 14 layer_count — G71.LAYER, G72.LAYER, PRJ.MAXPASS (issue #33)
;
; Property: for x ≥ 0 and step ≥ 1, q = ⌊x/step⌋ (SMT-LIB `div`, the floor for step > 0; Rust's
;   `/` on x ≥ 0, step ≥ 1, impl/src/rough/mod.rs `layers_within`) is the largest m with
;   m·step ≤ x: for every integer m, m·step ≤ x ⇔ m ≤ q; 0 ≤ q ≤ x; and q is monotone in x. With
;   x = D − 1: the layers k ≥ 1 strictly before Q₀ (k·step < D) are exactly k = 1…⌊(D − 1)/step⌋,
;   the closed-form count ⌈D/step⌉ − 1 that `Roughing::count` computes. (k + 1)·step =
;   k·step + step (the layer offsets' step) is distributivity. Used by the Kani harness
;   `g71_layer_step` (proofs/), whose stubs of `layers_within` and `layer_offset` assume these
;   facts at the layers it asks for; its drivers check them on exact products.
; Assumptions: x ≥ 0, y ≥ x, step ≥ 1, m any integer.
; Domain: mathematical integers, no upper bound.
; Expected: unsat.

(declare-const x Int)
(declare-const y Int)
(declare-const step Int)
(declare-const m Int)

(assert (>= x 0))
(assert (>= y x))
(assert (>= step 1))

(define-fun layers () Int (div x step))

; negated property (everything above is the model and the assumptions)
(assert (not (and
  (= (<= (* m step) x) (<= m layers))
  (>= layers 0)
  (<= layers x)
  (<= layers (div y step))
  (= (* (+ m 1) step) (+ (* m step) step)))))
(check-sat)
