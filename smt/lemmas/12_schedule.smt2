; Lemma 12 schedule (brief: f, the done-when list) — G76.DEPTH.1, G76.DEPTH.MIN, G76.DEPTH.LAST,
; G78.DEPTHMODE
;
; Property: for every pass n ≥ 1 of the schedule (pass n exists when pass n − 1 was not last,
;   i.e. u(n − 1) < T; "pass 0" is depth 0), with D(k) the clamped depth:
;   - D(n) ≥ D(n − 1): the depth never decreases;
;   - D(n) > D(n − 1) when Δdmin ≥ 1, and always in constant mode;
;   - D(n) ≤ T = k − d, and the last pass (u(n) ≥ T) has D(n) = T exactly;
;   - a pass that is not last cuts at least Δdmin (degressive), exactly Δdmin from the switch
;     pass on, exactly Δd in constant mode (G78: Δdmin is not used);
;   - D(1) ≥ 1.
;   Since pass n + 1 exists exactly when pass n is not last (and lemma 11 says the passes are
;   1 … L with L the closed-form count), this step covers every pair of consecutive passes of
;   the whole schedule: the properties hold for the whole schedule by induction on n.
; Assumptions: Δd ≥ 1, Δdmin ≥ 0, T ≥ 1, s ≥ 1, n ≥ 1 integers; rn, r1, b the rounded roots
;   of n·Δd², (n−1)·Δd², (s−1)·Δd²; s the switch pass (lemma 07) when Δdmin ≥ 1.
; Uses (instantiated hypotheses): lemma 07 (switch_pass: switches n ⇔ n ≥ s, none without a
;   minimum), lemma 08 (min_step), lemma 09 (cut_before_switch); lemma 10 (clamp) is the
;   definition of D used here.
; Domain: mathematical integers, no upper bound.
; Expected: unsat.

(define-fun is_root ((v Int) (r Int)) Bool
  (and (>= r 0)
       (< (* 4 v) (+ (* 4 r r) (* 4 r) 1))
       (or (= r 0) (<= (+ (* 4 r r) (* -4 r) 1) (* 4 v)))))

(declare-const dd Int)
(declare-const dm Int)
(declare-const t Int)
(declare-const constant Bool)
(declare-const s Int)
(declare-const b Int)
(declare-const n Int)
(declare-const rn Int)
(declare-const r1 Int)

(assert (>= dd 1))
(assert (>= dm 0))
(assert (>= t 1))
(assert (>= s 1))
(assert (>= n 1))
(assert (is_root (* (- s 1) dd dd) b))
(assert (is_root (* n dd dd) rn))
(assert (is_root (* (- n 1) dd dd) r1))

(define-fun a () Int (- (* dd dd) (* dm dm)))
(define-fun switches ((k Int)) Bool
  (or (< a 0) (< (* a a) (* 4 dd dd dm dm (- k 1)))))
(define-fun has_switch () Bool (and (not constant) (>= dm 1)))
; u(k), k ≥ 0, given rk = round(√(k·Δd²)): the unclamped rounded depth of pass k.
(define-fun depth_u ((k Int) (rk Int)) Int
  (ite constant (* k dd)
    (ite (and has_switch (>= k s)) (+ b (* (+ (- k s) 1) dm)) rk)))
(define-fun last ((u Int)) Bool (>= u t))                              ; lemma 10
(define-fun depth ((u Int)) Int (ite (last u) t u))

(define-fun u () Int (depth_u n rn))
(define-fun u_prev () Int (depth_u (- n 1) r1))
(define-fun cut () Int (- (depth u) u_prev))

; pass n exists: pass n − 1 (or the start, depth 0) was not last
(assert (not (last u_prev)))

(assert (=> (>= dm 1) (= (switches n) (>= n s))))                      ; lemma 07
(assert (=> (= dm 0) (not (switches n))))                              ; lemma 07
(assert (=> (and has_switch (>= n s)) (= u (+ u_prev dm))))            ; lemma 08
(assert (=> (not (switches n)) (>= (- rn r1) dm)))                     ; lemma 09

; negated property (everything above is the model and the assumptions)
(assert (not (and
  (>= (depth u) u_prev)
  (=> (or (>= dm 1) constant) (> (depth u) u_prev))
  (<= (depth u) t)
  (=> (last u) (= (depth u) t))
  (=> (and (not (last u)) (not constant)) (>= cut dm))
  (=> (and (not (last u)) has_switch (>= n s)) (= cut dm))
  (=> (and (not (last u)) constant) (= cut dd))
  (=> (= n 1) (>= (depth u) 1)))))
(check-sat)
