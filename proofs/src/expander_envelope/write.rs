//! The drawn G92/G76/G78 program of `expander_never_panics`, written into a [`Program`], and
//! what the envelope needs of it.

use super::{ceil_div, optional, Scope};
use crate::program::Program;
use crate::source::Source;
use cycle_impl::config::DEFAULTS;
use cycle_vocab::Grid;

/// A drawn cycle, written out.
pub(super) struct Written {
    pub prog: Program,
    /// U (diameter).
    pub u: i64,
    /// G76/G78: the thread height k, the lead-in E, the finishing allowance d and the tool angle
    /// a (0 for G92).
    pub k: i64,
    pub e_len: i64,
    pub d_allow: i64,
    pub angle: i64,
    /// L (1 when absent).
    pub starts: u32,
    /// J*: a bound on the resolved pull-out (the larger of |J|, |K| and the No.19 / chamfer amount).
    pub pull_bound: i64,
}

/// Writes cycle `code` (0: G92, 1: G76, 2: G78) on `grid` for the drawn side `s`, taper, W and
/// lead, drawing its other words in the body's order; `p5141` is d's default (parameter 5141).
#[allow(clippy::too_many_arguments)]
pub(super) fn write<S: Source>(src: &mut S, scope: &Scope, code: u32, grid: Grid, s: i64, taper: i64, w: i64, lead: i64, p5141: i64) -> Written {
    let (dec, lpi, len) = (grid.decimals(), grid.lead_counts_per_increment(), scope.max_len);
    let mut prog = Program::new();
    // Envelope inputs.
    let (mut k, mut e_len, mut d_allow, mut angle) = (0i64, 0i64, 0i64, 0i64);
    let opt = scope.optional_words;
    let mut starts = 1u32;
    let pull_bound;
    let u;
    if code == 0 {
        // G92: A.x = C.x + s·2·depth, C.x = D.x + 2R.
        let depth = src.bounded_i64(1, len);
        u = -2 * taper - 2 * s * depth;
        let j = optional(src, opt, -len, len);
        let kk = optional(src, opt, -len, len);
        let l = if opt && src.bool() { Some(src.bounded_u32(1, scope.max_starts)) } else { None };
        prog.text(b"G92");
        prog.len_word(b'U', u, dec);
        prog.len_word(b'W', w, dec);
        if taper != 0 || (opt && src.bool()) {
            prog.len_word(b'R', taper, dec);
        }
        prog.len_word(b'F', lead, grid.lead_decimals());
        if let Some(j) = j {
            prog.len_word(b'J', j, dec);
        }
        if let Some(kk) = kk {
            prog.len_word(b'K', kk, dec);
        }
        if let Some(l) = l {
            prog.int_word(b'L', i64::from(l));
            starts = l;
        }
        prog.end_block();
        let no19 = ceil_div(i64::from(DEFAULTS.no19_pullout) * lead, 10 * lpi) + 1;
        pull_bound = j.unwrap_or(0).abs().max(kk.unwrap_or(0).abs()).max(no19);
    } else {
        let g = if code == 1 { 76 } else { 78 };
        k = src.bounded_i64(1, len);
        let clearance = src.bounded_i64(0, len);
        u = -2 * taper - s * (2 * k + clearance);
        let dd = src.bounded_i64(1, len);
        // First block: its values, or the parameters' defaults.
        let defaults = DEFAULTS;
        let mut chamfer_tenths = i64::from(defaults.p5130_chamfer);
        angle = i64::from(defaults.p5143_tool_angle);
        d_allow = p5141;
        if scope.first_block && src.bool() {
            let m = src.bounded_u32(1, scope.max_finish);
            let middle = if code == 1 { src.bounded_u32(0, 99) } else { src.every_u32(0, 4) };
            let a = src.bounded_u32(0, 99);
            prog.int_word(b'G', g);
            prog.six_digits(b'P', m, middle, a);
            angle = i64::from(a);
            if code == 1 {
                chamfer_tenths = i64::from(middle);
            }
            if let Some(q) = optional(src, true, 0, len) {
                prog.len_word(b'Q', q, dec);
            }
            if let Some(r) = optional(src, true, 0, len) {
                prog.len_word(b'R', r, dec);
                d_allow = r;
            }
            if src.bool() {
                let mode = src.every_u32(0, if code == 1 { 2 } else { 1 });
                prog.int_word(b'D', i64::from(mode));
            }
            if src.bool() {
                starts = src.bounded_u32(1, scope.max_starts);
                prog.int_word(b'L', i64::from(starts));
            }
            if let Some(e) = optional(src, true, 0, len) {
                prog.len_word(b'E', e, dec);
                e_len = e;
            }
            prog.end_block();
        }
        let j = optional(src, opt, 0, len);
        let kk = optional(src, opt, 0, len);
        prog.int_word(b'G', g);
        prog.len_word(b'U', u, dec);
        prog.len_word(b'W', w, dec);
        if taper != 0 || (opt && src.bool()) {
            prog.len_word(b'R', taper, dec);
        }
        prog.len_word(b'P', k, dec);
        prog.len_word(b'Q', dd, dec);
        prog.len_word(b'F', lead, grid.lead_decimals());
        if let Some(j) = j {
            prog.len_word(b'J', j, dec);
        }
        if let Some(kk) = kk {
            prog.len_word(b'K', kk, dec);
        }
        prog.end_block();
        // 5131 = 45° (default): an omitted J is round(K·tan 45°) = K.
        let chamfer = ceil_div(chamfer_tenths.max(i64::from(defaults.p5130_chamfer)) * lead, 10 * lpi) + 1;
        pull_bound = j.unwrap_or(0).max(kk.unwrap_or(0)).max(chamfer);
    }
    Written { prog, u, k, e_len, d_allow, angle, starts, pull_bound }
}
