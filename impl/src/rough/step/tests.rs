use super::LineStep;
use crate::fixed::div_round_signed;

/// xorshift64*: a fixed, reproducible stream of test inputs.
struct Rng(u64);

impl Rng {
    fn next(&mut self) -> u64 {
        self.0 ^= self.0 >> 12;
        self.0 ^= self.0 << 25;
        self.0 ^= self.0 >> 27;
        self.0.wrapping_mul(0x2545_F491_4F6C_DD1D)
    }

    /// A signed value of up to `bits` bits, small magnitudes as often as large ones.
    fn signed(&mut self, bits: u32) -> i128 {
        let width = (self.next() % u64::from(bits)) as u32 + 1;
        let mag = i128::from(self.next() >> (64 - width.min(63)));
        if self.next() & 1 == 0 {
            mag
        } else {
            -mag
        }
    }
}

#[test]
fn stepping_matches_the_division_for_random_lines() {
    let mut rng = Rng(0x9E37_79B9_7F4A_7C15);
    for _ in 0..20_000 {
        let den = rng.signed(40);
        let num = rng.signed(60) * (1 + rng.signed(20).abs());
        let inc = rng.signed(50);
        let Some(mut s) = LineStep::new(num, den, inc) else {
            assert_eq!(den, 0);
            continue;
        };
        for t in 0..40i128 {
            let n = num + t * inc;
            assert_eq!(s.value(), div_round_signed(n, den), "num {num} den {den} inc {inc} t {t}");
            s.advance();
        }
    }
}

#[test]
fn ties_and_sign_changes_round_as_the_division() {
    // den 2 and 4: every step lands on exact values and on ties, crossing zero both ways.
    for (num, den, inc) in [(-7, 2, 1), (7, -2, 1), (9, 4, -1), (-9, -4, 1), (-5, 4, 2), (0, 3, -1)] {
        let mut s = LineStep::new(num, den, inc).expect("den ≠ 0");
        for t in 0..20i128 {
            assert_eq!(s.value(), div_round_signed(num + t * inc, den), "num {num} den {den} inc {inc} t {t}");
            s.advance();
        }
    }
    assert!(LineStep::new(5, 0, 1).is_none());
}
