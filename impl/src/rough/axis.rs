//! The frame of G71 and G72: the axis the layers step along and the one they cut along, and
//! each cycle's rules.

use cycle_vocab::Rule;

/// Which cycle: the axis of the cut.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Axis {
    /// Layers in X, cuts along Z.
    G71,
    /// Layers in Z, cuts along X.
    G72,
}

/// The rules of one cycle.
#[derive(Clone, Copy, Debug)]
pub(super) struct Rules {
    pub(super) layer: Rule,
    pub(super) retract: Rule,
    pub(super) lastpass: Rule,
    pub(super) ret: Rule,
    pub(super) first: Rule,
    pub(super) type2: Rule,
    pub(super) monotone: Rule,
}

impl Axis {
    pub(super) const fn rules(self) -> Rules {
        match self {
            Axis::G71 => Rules {
                layer: Rule::G71Layer,
                retract: Rule::G71Retract,
                lastpass: Rule::G71Lastpass,
                ret: Rule::G71Return,
                first: Rule::G71First,
                type2: Rule::G71Type2,
                monotone: Rule::G71Monotone,
            },
            Axis::G72 => Rules {
                layer: Rule::G72Layer,
                retract: Rule::G72Retract,
                lastpass: Rule::G72Lastpass,
                ret: Rule::G72Return,
                first: Rule::G72First,
                type2: Rule::G72Type2,
                monotone: Rule::G72Monotone,
            },
        }
    }

    /// The layer coordinate of a point.
    #[inline]
    pub(super) const fn a(self, p: (i64, i64)) -> i64 {
        match self {
            Axis::G71 => p.0,
            Axis::G72 => p.1,
        }
    }

    /// The cut coordinate of a point.
    #[inline]
    pub(super) const fn b(self, p: (i64, i64)) -> i64 {
        match self {
            Axis::G71 => p.1,
            Axis::G72 => p.0,
        }
    }

    /// The point (X, Z) with layer coordinate `a` and cut coordinate `b`.
    #[inline]
    pub(super) const fn point(self, a: i64, b: i64) -> (i64, i64) {
        match self {
            Axis::G71 => (a, b),
            Axis::G72 => (b, a),
        }
    }

    /// The letters of the layer and the cut coordinate.
    pub(super) const fn letters(self) -> (u8, u8) {
        match self {
            Axis::G71 => (b'X', b'Z'),
            Axis::G72 => (b'Z', b'X'),
        }
    }

    /// Counts per radius increment along a and b (X counts are diameters).
    pub(super) const fn per_radius(self) -> (i64, i64) {
        match self {
            Axis::G71 => (2, 1),
            Axis::G72 => (1, 2),
        }
    }

    /// Half increments per count along a and b (u = X, v = 2·Z).
    pub(super) const fn half(self) -> (i128, i128) {
        match self {
            Axis::G71 => (1, 2),
            Axis::G72 => (2, 1),
        }
    }

    /// The word of the depth Δd (PRJ.MAXPASS names it): G71 U, G72 W.
    pub(super) const fn depth_word(self) -> u8 {
        match self {
            Axis::G71 => b'U',
            Axis::G72 => b'W',
        }
    }
}
