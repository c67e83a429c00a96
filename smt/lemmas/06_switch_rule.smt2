; Lemma 06 switch_rule — G76.DEPTH.MIN (the rule in integers is the register's rule)
;
; Property: the register's condition (√n − √(n−1))·Δd < Δdmin holds exactly when
;   Δd² − Δdmin² < 0 or (Δd² − Δdmin²)² < 4·Δd²·Δdmin²·(n − 1) — the integer test `switches`
;   used by every other lemma and by the production code.
; Assumptions: real n ≥ 1, Δd ≥ 1, Δdmin ≥ 0 (so also every integer word); x = √n, y = √(n−1)
;   given as reals x, y ≥ 0 with x² = n, y² = n − 1.
; Domain: real numbers (nonlinear real arithmetic, which z3 decides completely).
; Expected: unsat.

(declare-const n Real)
(declare-const dd Real)
(declare-const dm Real)
(declare-const x Real)
(declare-const y Real)

(assert (>= n 1.0))
(assert (>= dd 1.0))
(assert (>= dm 0.0))
(assert (and (>= x 0.0) (= (* x x) n)))
(assert (and (>= y 0.0) (= (* y y) (- n 1.0))))

(define-fun a_real () Real (- (* dd dd) (* dm dm)))

; negated property (everything above is the model and the assumptions)
(assert (not (=
  (< (* (- x y) dd) dm)
  (or (< a_real 0.0) (< (* a_real a_real) (* 4.0 dd dd dm dm (- n 1.0)))))))
(check-sat)
