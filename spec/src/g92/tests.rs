use super::*;

#[test]
fn jk_table() {
    let (c, cs) = (30, 17);
    assert_eq!(resolve_jk(None, None, c, cs), Some((Amounts { j: 17, k: 30 }, Rule::G92Jk1)));
    assert_eq!(resolve_jk(None, Some(-5), c, cs), Some((Amounts { j: 30, k: 5 }, Rule::G92Jk2)));
    assert_eq!(resolve_jk(None, Some(0), c, cs), Some((Amounts { j: 30, k: 30 }, Rule::G92Jk2)));
    assert_eq!(resolve_jk(Some(0), None, c, cs), None);
    assert_eq!(resolve_jk(Some(0), Some(7), c, cs), None);
    assert_eq!(resolve_jk(Some(-4), None, c, cs), Some((Amounts { j: 4, k: 4 }, Rule::G92Jk3)));
    assert_eq!(resolve_jk(Some(4), Some(0), c, cs), Some((Amounts { j: 4, k: 4 }, Rule::G92Jk5)));
    assert_eq!(resolve_jk(Some(4), Some(9), c, cs), Some((Amounts { j: 4, k: 9 }, Rule::G92Pullout)));
    assert_eq!(resolve_jk(None, None, 0, 0), None);
    assert_eq!(resolve_jk(None, None, 30, 0), None); // J rounds to 0: no pull-out
}

/// No.5131 for G92: J = round(c·tan 5131°); 45° (the default) keeps J = c.
#[test]
fn jk1_short_axis_follows_5131() {
    assert_eq!(jk1_short(3_000, 45), 3_000);
    assert_eq!(jk1_short(3_000, 30), 1_732); // 1732.05
    assert_eq!(jk1_short(3_000, 60), 5_196); // 5196.15
    assert_eq!(jk1_short(3_000, 1), 52); // 52.36
    assert_eq!(jk1_short(0, 30), 0);
    assert_eq!(crate::config::DEFAULTS.p5131_chamfer_angle, 45);
}

/// G92.PATH step ③: X₃ beyond A.x on the side s is refused, on J when the pull-out took X
/// there, else on X; X₃ = A.x is legal.
#[test]
fn step3_opposite_to_step1() {
    let geometry = |w| Err(alarm(AlarmCode::Geometry, w, Rule::G92Path, 1));
    // G0 X65; G92 X58.7 … J5: the pull-out ends at X68.7 > 65.
    assert_eq!(step3_ok(65_000, 58_700, 68_700, 1, 1), geometry(b'J'));
    assert_eq!(step3_ok(65_000, 58_700, 65_000, 1, 1), Ok(()));
    assert_eq!(step3_ok(65_000, 58_700, 64_700, 1, 1), Ok(()));
    // Internal (s = −1): beyond is below A.x.
    assert_eq!(step3_ok(20_000, 26_000, 18_000, -1, 1), geometry(b'J'));
    assert_eq!(step3_ok(20_000, 26_000, 22_000, -1, 1), Ok(()));
    // The thread end itself beyond A.x: on X.
    assert_eq!(step3_ok(65_000, 66_000, 66_000, 1, 1), geometry(b'X'));
}

#[test]
fn taper_rule() {
    assert!(taper_ok(0, 100));
    assert!(taper_ok(-50, 100));
    assert!(!taper_ok(-51, 100));
    assert!(taper_ok(100, 100));
    assert!(taper_ok(5, 0));
}

#[test]
fn no19_is_tenths_of_the_lead() {
    assert_eq!(no19_amount(10, 30_000, Grid::METRIC_ISB), 3_000);
    assert_eq!(no19_amount(5, 15_001, Grid::METRIC_ISB), 750); // 750.05 → 750
    assert_eq!(no19_amount(1, 15, Grid::METRIC_ISB), 0); // 0.15 → 0
    assert_eq!(no19_amount(1, 50, Grid::METRIC_ISB), 1); // 0.5 → 1
}

/// The trace of `src` as canonical G-code lines (header dropped); the run must end clean.
fn gcode(src: &str, config: &cycle_vocab::Config) -> Vec<String> {
    let t = crate::expand(src.as_bytes(), config);
    assert_eq!(t.alarm, None, "{}", t.to_gcode());
    t.to_gcode().lines().skip(1).map(String::from).collect()
}

/// No.19 = 255, the top of its range (docs/INTERPRETATION.md "No.19": 0…255; M002 note 2,
/// `002_…` line 68: J, K omitted pull out by No.19), is legal: `G92 X60 Z-40 F1` from X120 Z5,
/// c = round(255 × 1 mm / 10) = 25.5 mm for J (45°) and K: the thread to Z-40 + 25.5, the
/// pull-out to X60 + 2·25.5 = X111 at Z-40, ③ X120, ④ Z5.
#[test]
fn no19_at_the_top_of_its_range() {
    let config = cycle_vocab::Config {
        params: cycle_vocab::Params { no19_pullout: Some(255), ..cycle_vocab::Params::default() },
        ..cycle_vocab::Config::default()
    };
    let lines = gcode("G0 X120 Z5\nG92 X60 Z-40 F1\n", &config);
    assert_eq!(
        lines[2..],
        [
            "G00 X60.000 Z5.000",
            "G32 X60.000 Z-14.500 F1.0000",
            "G32 X111.000 Z-40.000 F1.0000",
            "G00 X120.000 Z-40.000",
            "G00 X120.000 Z5.000",
        ]
    );
}

/// COM.LONGAXIS at |W| = |R| (docs/INTERPRETATION.md: "else X (including |W| = |R|)"; M002
/// `002_…` line 49: Z is long only when its travel is the greater). `G92 X40 W-10 R10 F2 J1 K3`
/// from X80 Z5: C = X60 Z5, D = X40 Z-5, |W| = |R| = 10 mm, X long. The pull-out (G92.PULLOUT,
/// X long) starts K = 3 mm of X before D: X40 + 2·3 = X46, Z-5 + round(10·3/10) = Z-2; it ends at
/// X40, Z-5 + J = Z-4 (toward A on Z).
#[test]
fn equal_travels_make_x_the_long_axis() {
    let lines = gcode("G0 X80 Z5\nG92 X40 W-10 R10 F2 J1 K3\n", &cycle_vocab::Config::default());
    assert_eq!(
        lines[2..],
        [
            "G00 X60.000 Z5.000",
            "G32 X46.000 Z-2.000 F2.0000",
            "G32 X40.000 Z-4.000 F2.0000",
            "G00 X80.000 Z-4.000",
            "G00 X80.000 Z5.000",
        ]
    );
}
