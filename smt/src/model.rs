//! The lemmas' model (smt/lemmas/*.smt2), transcribed: the same definitions, one function each,
//! over `i128` for legal words (lengths ≤ [`N`], pass numbers ≤ 2^33; radicands then stay
//! below 2^120). Independent of
//! `cycle-impl`: the rounded root is the least r with v ≤ r² + r (lemma 02), found by binary
//! search — no square root is taken.
//!
//! [`Variant`] selects the exact model or a deliberately wrong one (the negative controls).

/// The largest legal length word, increments (COM.RANGES).
pub const N: i64 = 999_999_999;

/// Which model: the register's, or a deliberately wrong variant (negative controls).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Variant {
    /// The register's model, as in the lemmas.
    Exact,
    /// Rounding one increment too high at v = r² + r (the impl's `planted-depth-bug`):
    /// [`is_root_ties_up`], the SMT mutant `IS_ROOT_TIES_UP` of tests/lemmas.rs.
    TiesUp,
    /// The switch pass one pass late (⌊a²/c²⌋ + 3) when a ≥ 0.
    SwitchLate,
}

/// The schedule's parameters, all lengths radius increments.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Params {
    /// Δd ≥ 1.
    pub dd: i64,
    /// Δdmin ≥ 0.
    pub dm: i64,
    /// T = k − d ≥ 1.
    pub t: i64,
    /// G78.DEPTHMODE 0: the depth of pass n is n·Δd.
    pub constant: bool,
}

/// Which rule set pass n's depth, before the clamp (the clamp makes it G76.DEPTH.LAST).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Phase {
    /// Before the switch: round(√(n·Δd²)) (G76.DEPTH.1).
    Root,
    /// From the switch pass on (G76.DEPTH.MIN).
    Min,
    /// Constant mode, n·Δd (G78.DEPTHMODE).
    Constant,
}

/// One rough pass of the model: `depth(u)` and `last(u)` of lemma 10.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Pass {
    pub n: i128,
    pub depth: i128,
    pub last: bool,
    pub phase: Phase,
}

/// `is_root v r`: 4r² − 4r + 1 ≤ 4v < 4r² + 4r + 1, r ≥ 0, and r = 0 allowed (v ≤ 0).
#[allow(clippy::int_plus_one)] // written as in the lemmas
pub fn is_root(v: i128, r: i128) -> bool {
    r >= 0 && 4 * v < 4 * r * r + 4 * r + 1 && (r == 0 || 4 * r * r - 4 * r + 1 <= 4 * v)
}

/// The TiesUp variant's bracket (tests/lemmas.rs `IS_ROOT_TIES_UP`): r² − r ≤ v < r² + r
/// (v ≥ 1), r = 0 for v ≤ 0.
pub fn is_root_ties_up(v: i128, r: i128) -> bool {
    (r == 0 && v <= 0) || (r >= 1 && v >= 1 && r * r - r <= v && v < r * r + r)
}

/// round(√v) (0 ≤ v < 2^120): the least r ≥ 0 with v ≤ r² + r (lemma 02). TiesUp: the least
/// r with v < r² + r (v ≥ 1).
pub fn root(v: i128, variant: Variant) -> i128 {
    assert!((0..1 << 120).contains(&v), "radicand {v} outside the model's range");
    let fits = |r: i128| match variant {
        Variant::TiesUp => v == 0 || v < r * r + r,
        _ => v <= r * r + r,
    };
    // The least r in 0..=2^60 with fits(r). Invariant: lo = −1 or !fits(lo); fits(hi) (v < 2^120).
    let (mut lo, mut hi) = (-1i128, 1i128 << 60);
    while hi - lo > 1 {
        let mid = lo + (hi - lo) / 2;
        if fits(mid) {
            hi = mid;
        } else {
            lo = mid;
        }
    }
    hi
}

/// G76.DEPTH.MIN as the register decides it in integers (`switches k`): a < 0 or
/// a² < 4·Δd²·Δdmin²·(k − 1), a = Δd² − Δdmin². A right side beyond `i128` exceeds a².
pub fn switches(dd: i64, dm: i64, k: i128) -> bool {
    let (dd, dm) = (i128::from(dd), i128::from(dm));
    let a = dd * dd - dm * dm;
    match (4 * dd * dd * dm * dm).checked_mul(k - 1) {
        _ if a < 0 => true,
        Some(rhs) => a * a < rhs,
        None => true,
    }
}

/// The switch pass s (lemma 07: 1 when a < 0, else ⌊a²/c²⌋ + 2); `None` without a minimum
/// (Δdmin = 0) and in constant mode.
pub fn switch_pass(p: &Params, variant: Variant) -> Option<i128> {
    if p.constant || p.dm == 0 {
        return None;
    }
    let (dd, dm) = (i128::from(p.dd), i128::from(p.dm));
    let a = dd * dd - dm * dm;
    if a < 0 {
        return Some(1);
    }
    let late = i128::from(variant == Variant::SwitchLate);
    Some(a * a / (4 * dd * dd * dm * dm) + 2 + late)
}

/// The model with its switch pass and b = round(√((s−1)·Δd²)) prepared.
#[derive(Clone, Copy, Debug)]
pub struct Model {
    pub p: Params,
    pub variant: Variant,
    pub s: Option<i128>,
    pub b: i128,
}

impl Model {
    pub fn new(p: Params, variant: Variant) -> Model {
        assert!((1..=N).contains(&p.dd) && (0..=N).contains(&p.dm) && (1..=N).contains(&p.t), "{p:?}: not legal words");
        let s = switch_pass(&p, variant);
        let b = s.map_or(0, |s| root((s - 1) * sq(p.dd), variant));
        Model { p, variant, s, b }
    }

    /// `depth_u k`: the unclamped rounded depth of pass k ≥ 0 (pass 0: depth 0), and its phase.
    pub fn depth_u(&self, k: i128) -> (i128, Phase) {
        let dd = i128::from(self.p.dd);
        match self.s {
            _ if self.p.constant => (k * dd, Phase::Constant),
            Some(s) if k >= s => (self.b + (k - s + 1) * i128::from(self.p.dm), Phase::Min),
            _ => (root(k * dd * dd, self.variant), Phase::Root),
        }
    }

    /// Pass n ≥ 1 (lemma 10's clamp): a rounded depth ≥ T becomes T and is the last pass.
    pub fn pass(&self, n: i128) -> Pass {
        let (u, phase) = self.depth_u(n);
        let t = i128::from(self.p.t);
        Pass { n, depth: u.min(t), last: u >= t, phase }
    }

    /// The closed-form rough pass count of lemma 11.
    pub fn rough_count(&self) -> i128 {
        let (dd, t) = (i128::from(self.p.dd), i128::from(self.p.t));
        let reach = if self.p.constant { ceil_div(t, dd) } else { t * (t - 1) / (dd * dd) + 1 };
        match self.s {
            Some(s) if reach >= s => (s - 1) + ceil_div(t - self.b, i128::from(self.p.dm)),
            _ => reach,
        }
    }
}

fn sq(x: i64) -> i128 {
    i128::from(x) * i128::from(x)
}

/// ⌈x/m⌉ for m ≥ 1, as `ceil_div` of lemma 11: ⌊(x + m − 1)/m⌋ (floor division).
pub fn ceil_div(x: i128, m: i128) -> i128 {
    (x + m - 1).div_euclid(m)
}

/// A fixed-seed xorshift64 generator for the random drivers.
pub struct Rng(pub u64);

impl Rng {
    pub fn next_u64(&mut self) -> u64 {
        self.0 ^= self.0 << 13;
        self.0 ^= self.0 >> 7;
        self.0 ^= self.0 << 17;
        self.0
    }

    /// Uniform-ish in lo..=hi, spread over magnitudes (one draw in two log-uniform) so that
    /// small and large values both occur.
    pub fn range(&mut self, lo: i64, hi: i64) -> i64 {
        let span = (hi - lo) as u64 + 1;
        let x = self.next_u64();
        let span = if x & 1 == 0 { span } else { (span >> ((x >> 1) % 64)).max(1) };
        lo + (self.next_u64() % span) as i64
    }
}
