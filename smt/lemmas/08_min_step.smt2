; Lemma 08 min_step (brief: c) — G76.DEPTH.MIN
;
; Property: from the switch pass s on, each pass adds exactly Δdmin to the unclamped rounded
;   depth: u(n) = u(n − 1) + Δdmin for every n ≥ s, the step INTO the switch pass included
;   (u(s − 1) is round(√((s−1)·Δd²)), and u(0) = 0 when s = 1). This is the production's running
;   form (impl/src/schedule.rs `pass`: previous depth + Δdmin) of the closed form
;   u(n) = round(√((s−1)·Δd²)) + (n − s + 1)·Δdmin.
; Assumptions: Δd ≥ 1, Δdmin ≥ 1 (a switch exists), degressive mode, any s ≥ 1 (the lemma does
;   not need s to be the switch pass), n ≥ s; b, r1 the rounded roots of (s−1)·Δd², (n−1)·Δd².
; Uses: lemma 03 (root_monotone), instantiated both ways at (n−1)·Δd² and (s−1)·Δd²
;   (uniqueness of the root when n = s).
; Domain: mathematical integers, no upper bound.
; Expected: unsat.

(define-fun is_root ((v Int) (r Int)) Bool
  (and (>= r 0)
       (< (* 4 v) (+ (* 4 r r) (* 4 r) 1))
       (or (= r 0) (<= (+ (* 4 r r) (* -4 r) 1) (* 4 v)))))
(define-fun root_monotone ((v Int) (r Int) (w Int) (q Int)) Bool      ; lemma 03
  (=> (and (<= 0 v) (<= v w) (is_root v r) (is_root w q)) (<= r q)))

(declare-const dd Int)
(declare-const dm Int)
(define-fun constant () Bool false)
(declare-const s Int)
(declare-const b Int)
(declare-const n Int)
(declare-const rn Int)
(declare-const r1 Int)

(assert (>= dd 1))
(assert (>= dm 1))
(assert (>= s 1))
(assert (is_root (* (- s 1) dd dd) b))

(define-fun has_switch () Bool (and (not constant) (>= dm 1)))
; u(k), k ≥ 0, given rk = round(√(k·Δd²)): the unclamped rounded depth of pass k.
(define-fun depth_u ((k Int) (rk Int)) Int
  (ite constant (* k dd)
    (ite (and has_switch (>= k s)) (+ b (* (+ (- k s) 1) dm)) rk)))

(assert (>= n s))
(assert (is_root (* n dd dd) rn))
(assert (is_root (* (- n 1) dd dd) r1))
(assert (root_monotone (* (- n 1) dd dd) r1 (* (- s 1) dd dd) b))
(assert (root_monotone (* (- s 1) dd dd) b (* (- n 1) dd dd) r1))

; negated property (everything above is the model and the assumptions)
(assert (not (= (depth_u n rn) (+ (depth_u (- n 1) r1) dm))))
(check-sat)
