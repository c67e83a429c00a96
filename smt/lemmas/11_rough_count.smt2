; Lemma 11 rough_count (brief: e, second half) — G76.DEPTH.LAST, G76.DEPTH.MIN, G78.DEPTHMODE,
; PRJ.MAXPASS (the count checked before any motion)
;
; Property: the closed-form count L of impl/src/schedule.rs `rough_pass_count` is what iterating
;   the schedule gives: the first pass whose rounded unclamped depth u reaches T, i.e.
;   L ≥ 1, u(L) ≥ T, and u(n) < T for every 1 ≤ n < L (so passes 1 … L − 1 are not last and
;   pass L is the last). The closed form:
;     reach = ⌊T(T − 1)/Δd²⌋ + 1 (degressive), ⌈T/Δd⌉ (constant mode);
;     L = reach when there is no switch or reach < s, else (s − 1) + ⌈(T − b)/Δdmin⌉ with
;     b = round(√((s−1)·Δd²)).
; Assumptions: Δd ≥ 1, Δdmin ≥ 0, T ≥ 1, any s ≥ 1 (the lemma holds for every s, so also for the
;   switch pass of lemma 07); rn, rL, b the rounded roots of n·Δd², L·Δd², (s−1)·Δd²; n any
;   integer.
; Uses: lemma 05 (root_threshold) at n·Δd², L·Δd², (s−1)·Δd²; lemma 04 (radicand_monotone)
;   at (n, q), (s − 1, q), (q + 1, L) with q = ⌊T(T − 1)/Δd²⌋ — each an instantiated hypothesis.
; Domain: mathematical integers, no upper bound.
; Expected: unsat.

(define-fun is_root ((v Int) (r Int)) Bool
  (and (>= r 0)
       (< (* 4 v) (+ (* 4 r r) (* 4 r) 1))
       (or (= r 0) (<= (+ (* 4 r r) (* -4 r) 1) (* 4 v)))))
(define-fun ceil_div ((x Int) (m Int)) Int (div (+ x m -1) m))

(declare-const dd Int)
(declare-const dm Int)
(declare-const t Int)
(declare-const constant Bool)
(declare-const s Int)
(declare-const b Int)

(assert (>= dd 1))
(assert (>= dm 0))
(assert (>= t 1))
(assert (>= s 1))
(assert (is_root (* (- s 1) dd dd) b))

(define-fun has_switch () Bool (and (not constant) (>= dm 1)))
; u(k), k ≥ 0, given rk = round(√(k·Δd²)): the unclamped rounded depth of pass k.
(define-fun depth_u ((k Int) (rk Int)) Int
  (ite constant (* k dd)
    (ite (and has_switch (>= k s)) (+ b (* (+ (- k s) 1) dm)) rk)))

(define-fun q () Int (div (* t (- t 1)) (* dd dd)))
(define-fun reach () Int (ite constant (ceil_div t dd) (+ q 1)))
(define-fun count () Int
  (ite (or (not has_switch) (< reach s)) reach (+ (- s 1) (ceil_div (- t b) dm))))

(declare-const n Int)
(declare-const rn Int)
(declare-const rl Int)
(assert (is_root (* n dd dd) rn))
(assert (is_root (* count dd dd) rl))

(define-fun root_threshold ((v Int) (r Int)) Bool                      ; lemma 05
  (=> (and (>= v 0) (is_root v r)) (= (>= r t) (> v (* t (- t 1))))))
(assert (root_threshold (* n dd dd) rn))
(assert (root_threshold (* count dd dd) rl))
(assert (root_threshold (* (- s 1) dd dd) b))
(define-fun radicand_monotone ((k Int) (m Int)) Bool                   ; lemma 04
  (=> (<= k m) (<= (* k dd dd) (* m dd dd))))
(assert (radicand_monotone n q))
(assert (radicand_monotone (- s 1) q))
(assert (radicand_monotone (+ q 1) count))

; negated property (everything above is the model and the assumptions)
(assert (not (and
  (>= count 1)
  (>= (depth_u count rl) t)
  (=> (and (>= n 1) (< n count)) (< (depth_u n rn) t)))))
(check-sat)
