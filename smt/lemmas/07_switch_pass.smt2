; Lemma 07 switch_pass (brief: e, first half) — G76.DEPTH.MIN
;
; Property: with Δdmin ≥ 1 the closed form s = 1 when a < 0, else s = ⌊a²/c²⌋ + 2
;   (a = Δd² − Δdmin², c² = 4·Δd²·Δdmin², as in impl/src/schedule.rs `switch_pass`) is the
;   switch pass: for every pass n ≥ 1, the rule switches at n ⇔ n ≥ s. That is: s ≥ 1, the rule
;   holds at s, fails at every 1 ≤ n < s (s is the FIRST such pass), and holds at every n ≥ s
;   (the switch is permanent: "from then on every cut is Δdmin"). With Δdmin = 0 the rule holds
;   at no pass (no minimum).
; Assumptions: Δd ≥ 1, Δdmin ≥ 0, n ≥ 1 integers.
; Domain: mathematical integers, no upper bound.
; Expected: unsat.

(declare-const dd Int)
(declare-const dm Int)
(declare-const n Int)

(assert (>= dd 1))
(assert (>= dm 0))
(assert (>= n 1))

(define-fun a () Int (- (* dd dd) (* dm dm)))
(define-fun switches ((k Int)) Bool
  (or (< a 0) (< (* a a) (* 4 dd dd dm dm (- k 1)))))
(define-fun switch_pass () Int
  (ite (< a 0) 1 (+ (div (* a a) (* 4 dd dd dm dm)) 2)))

; negated property (everything above is the model and the assumptions)
(assert (not (and
  (=> (= dm 0) (not (switches n)))
  (=> (>= dm 1) (and (>= switch_pass 1) (= (switches n) (>= n switch_pass)))))))
(check-sat)
