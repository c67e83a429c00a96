use super::*;

/// round_frac against exact rational rounding over a grid of numerators.
#[test]
fn rounding_quarters_and_halves() {
    // φ = 0: half away from zero of w/q, against the rational w/q rounded by hand.
    for q in [1i128, 2, 4] {
        for w in -40i128..=40 {
            let r = (2 * w.abs() + q) / (2 * q);
            assert_eq!(round_frac(w, q, false), if w < 0 { -r } else { r }, "w {w} q {q}");
        }
    }
    assert_eq!(round_frac(1, 2, false), 1); // 0.5 → 1
    assert_eq!(round_frac(-1, 2, false), -1); // −0.5 → −1
    assert_eq!(round_frac(-1, 2, true), 0); // (−1 + φ)/2 ∈ (−0.5, 0) → 0
    assert_eq!(round_frac(1, 2, true), 1); // (1 + φ)/2 ∈ (0.5, 1) → 1
    assert_eq!(round_frac(2, 4, false), 1); // 0.5 → 1
    assert_eq!(round_frac(-2, 4, false), -1); // −0.5 → −1
    assert_eq!(round_frac(-2, 4, true), 0); // (−2 + φ)/4 ∈ (−0.5, −0.25) → −0 … above −0.5 → 0
    assert_eq!(round_frac(-3, 4, true), -1); // (−3 + φ)/4 ∈ (−0.75, −0.5) → −1
    assert_eq!(round_frac(5, 4, true), 1); // (5 + φ)/4 ∈ (1.25, 1.5) → 1
    assert_eq!(round_frac(6, 4, true), 2); // (6 + φ)/4 ∈ (1.5, 1.75) → 2
}

/// round_sqrt_sum against a high-precision computation over small ranges.
#[test]
fn rounding_roots() {
    for m in 0u128..400 {
        for w in -30i128..=30 {
            for q in [1i128, 2, 4] {
                for plus in [true, false] {
                    let root = (m as f64).sqrt();
                    let v = (w as f64 + if plus { root } else { -root }) / q as f64;
                    let got = round_sqrt_sum(w, plus, m, q);
                    // Away from half-integers f64 decides; at exact halves (perfect squares)
                    // half away from zero.
                    let frac = v.abs().fract();
                    if (frac - 0.5).abs() > 1e-9 {
                        let want = v.abs().round() as i128 * if v < 0.0 { -1 } else { 1 };
                        assert_eq!(got, want, "w {w} m {m} q {q} plus {plus}");
                    } else {
                        let k = isqrt(m);
                        assert_eq!(k * k, m, "a tie needs an exact root");
                        let want = (v.abs() + 0.5).floor() as i128 * if v < 0.0 { -1 } else { 1 };
                        assert_eq!(got, want, "tie w {w} m {m} q {q} plus {plus}");
                    }
                }
            }
        }
    }
}

mod programs;
