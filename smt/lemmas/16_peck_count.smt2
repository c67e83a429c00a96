; Lemma 16 peck_count — G74.PECK, G74.COLUMN, G75.PECK, G75.COLUMN, G83.PECK, PRJ.MAXPASS
;
; Property: for a total length t ≥ 1 (a peck depth D, a step travel T) and a step l ≥ 1 (the
;   peck, the column step, G83's Q), the count the code computes,
;     K = t div l + (1 when t mod l ≠ 0, else 0)   (impl/src/g74.rs `ceil_div`),
;   is ⌈t/l⌉ (lemma 11's ceil_div), K ≥ 1, (K − 1)·l < t ≤ K·l, and for every m ≥ 0:
;   m·l ≥ t ⇔ m ≥ K — peck (column) m reaches the end exactly from K on, so min(m·l, t) is
;   below t for m < K and t from K on; also (m + 1)·l = m·l + l. These are the assumptions the
;   Kani harnesses g74_peck_step and g83_peck_step make of `span` (m·l) and `ceil_div`
;   (proofs/src/peck_parts.rs `Line::spec`), which their drivers check on the code.
; Assumptions: t ≥ 1, l ≥ 1, m ≥ 0 integers.
; Domain: mathematical integers, no upper bound.
; Expected: unsat.

(define-fun ceil_div ((x Int) (m Int)) Int (div (+ x m -1) m))

(declare-const t Int)
(declare-const l Int)
(declare-const m Int)

(assert (>= t 1))
(assert (>= l 1))
(assert (>= m 0))

(define-fun peck_count () Int (+ (div t l) (ite (= (mod t l) 0) 0 1)))

; negated property (everything above is the model and the assumptions)
(assert (not (and
  (= peck_count (ceil_div t l))
  (>= peck_count 1)
  (< (* (- peck_count 1) l) t)
  (<= t (* peck_count l))
  (= (>= (* m l) t) (>= m peck_count))
  (= (* (+ m 1) l) (+ (* m l) l)))))
(check-sat)
