//! The configuration check before the first block (docs/INTERPRETATION.md, "The configuration
//! is checked before the first block"): each bad value is `OUT OF RANGE` on line 0.

use crate::modal::FANUC_ANGLES;
use cycle_vocab::params::MAX_LENGTH;
use cycle_vocab::{Alarm, AlarmCode, Config, Dialect, Rule};

fn out(word: Option<u8>, rule: Rule) -> Alarm {
    Alarm::new(AlarmCode::OutOfRange, word, rule, 0)
}

/// COM.RANGES, G92.JK.1, G92.JK.8, G92.HOLD, G76.PULLOUT, G76.DEFAULTS, G78.MODE,
/// G78.DEPTHMODE, PRJ.MAXPASS, F76.FORMAT, NC201.XMODE: the configuration, in the register's
/// order.
pub fn check(c: &Config) -> Result<(), Alarm> {
    let p = &c.params;
    let length = |v: i64| (0..=MAX_LENGTH).contains(&v);
    let checks: [(bool, Option<u8>, Rule); 16] = [
        (c.start_x.unsigned_abs() <= MAX_LENGTH.unsigned_abs(), Some(b'X'), Rule::ComRanges),
        (c.start_z.unsigned_abs() <= MAX_LENGTH.unsigned_abs(), Some(b'Z'), Rule::ComRanges),
        (p.no19_pullout <= 255, None, Rule::G92Jk1),
        (p.no107_pullout_speed <= 999_999, None, Rule::G92Jk8),
        (p.no18_bit6_hold <= 1, None, Rule::G92Hold),
        (p.p5130_chamfer <= 99, None, Rule::G76Pullout),
        ((1..=89).contains(&p.p5131_chamfer_angle), None, Rule::G76Pullout),
        (length(p.p5140_min_cut), None, Rule::G76Defaults),
        (length(p.p5141_finish_allowance), None, Rule::G76Defaults),
        ((1..=99).contains(&p.p5142_finish_passes), None, Rule::G76Defaults),
        (p.p5143_tool_angle <= 99, None, Rule::G76Defaults),
        (p.p5144_infeed_mode <= 4, None, Rule::G78Mode),
        (p.p5145_depth_mode <= 1, None, Rule::G78DepthMode),
        ((1..=1_000_000).contains(&p.max_passes), None, Rule::PrjMaxPass),
        (c.dialect != Dialect::Fanuc || FANUC_ANGLES.contains(&p.p5143_tool_angle), None, Rule::F76Format),
        // Checked under every dialect, read only under nc201.
        (p.x_radius <= 1, None, Rule::Nc201XMode),
    ];
    match checks.iter().find(|(ok, _, _)| !ok) {
        Some(&(_, word, rule)) => Err(out(word, rule)),
        None => Ok(()),
    }
}
