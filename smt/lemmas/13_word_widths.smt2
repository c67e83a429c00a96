; Lemma 13 word_widths — COM.RANGES (the production's integer widths, for legal words)
;
; Property: for legal words (1 ≤ Δd ≤ N, 0 ≤ Δdmin ≤ N, 1 ≤ T ≤ N, N = 999 999 999) the
;   values impl/src/schedule.rs computes stay inside the widths its fast paths assume, so the
;   mathematical-integer lemmas 01–12 describe what the 64-bit code computes there:
;   - switch_pass: a = Δd² − Δdmin² (when ≥ 0) and c = 2·Δd·Δdmin are below 2^64 (the closed
;     form ⌊a²/c²⌋ + 2 is taken, not the 256-bit search), a², c² are below 2^128 (u128), and
;     s = ⌊a²/c²⌋ + 2 is below 2^64 − 1 (it is never read as NEVER = u64::MAX);
;   - reach = ⌊T(T − 1)/Δd²⌋ + 1 is below 2^60 (u64) and constant-mode reach ⌈T/Δd⌉ ≤ T;
;   - a pass n < reach before the switch has radicand n·Δd² ≤ T(T − 1) < 2^60 and its hint
;     (the previous depth, below T) below 2^31: the root's 64-bit walk applies;
;   - after the switch, previous depth + Δdmin < T + N < 2^63 (u128 there, and the clamped
;     depth ≤ T fits i64).
; Assumptions: the word bounds above; n ≥ 1 any pass number; prev any depth 0 ≤ prev < T.
; Domain: mathematical integers bounded by the legal words (this is the only lemma that uses N).
; Expected: unsat.

(declare-const dd Int)
(declare-const dm Int)
(declare-const t Int)
(declare-const n Int)
(declare-const prev Int)

(define-fun N () Int 999999999)
(assert (and (<= 1 dd) (<= dd N)))
(assert (and (<= 0 dm) (<= dm N)))
(assert (and (<= 1 t) (<= t N)))
(assert (>= n 1))
(assert (and (<= 0 prev) (< prev t)))

(define-fun two64 () Int 18446744073709551616)
(define-fun two128 () Int 340282366920938463463374607431768211456)
(define-fun a () Int (- (* dd dd) (* dm dm)))
(define-fun c () Int (* 2 dd dm))
(define-fun q () Int (div (* t (- t 1)) (* dd dd)))                  ; reach = q + 1

; negated property (everything above is the model and the assumptions)
(assert (not (and
  (=> (and (>= dm 1) (>= a 0))
      (and (< a two64) (< c two64) (< (* a a) two128) (< (* c c) two128)
           (< (+ (div (* a a) (* c c)) 2) (- two64 1))))
  (< (+ q 1) 1152921504606846976)                                        ; 2^60
  (<= (div (+ t dd -1) dd) t)
  (=> (< n (+ q 1)) (and (<= (* n dd dd) (* t (- t 1))) (< (* t (- t 1)) 1152921504606846976)))
  (< prev 2147483648)                                                  ; 2^31
  (< (+ prev dm) 9223372036854775808))))                               ; 2^63
(check-sat)
