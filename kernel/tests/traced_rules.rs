//! Checks of rules that the traceability matrix (`cyclecheck certify`) found without a test
//! naming them: each runs both engines (spec and production) and checks the rule on the trace.

use cycle_kernel::engine::{Engine, ImplEngine, SpecEngine};
use cycle_vocab::text::Trace;
use cycle_vocab::{Config, Event, MoveKind, PassKind, Rule};

/// The spec's and the production expander's traces; under `CYCLECHECK_SPEC_ALONE=1` the spec's
/// in both slots, so every check (and "spec and impl agree") is on the spec alone.
fn both(program: &str, config: &Config) -> [Trace; 2] {
    let spec = SpecEngine.expand(program.as_bytes(), config);
    let other = if cycle_kernel::spec_alone::skip("the production expander's trace") { spec.clone() } else { ImplEngine.expand(program.as_bytes(), config) };
    let traces = [spec, other];
    for t in &traces {
        assert_eq!(t.alarm, None, "{program}\n{}", t.to_gcode());
    }
    traces
}

/// Per pass: its kind and the (X, Z) where its first thread move starts (the infeed point).
fn infeed_points(t: &Trace, start: (i64, i64)) -> Vec<(PassKind, (i64, i64))> {
    let mut at = start;
    let mut out = Vec::new();
    let mut pass = None;
    for e in &t.events {
        match e {
            Event::Pass(p) => pass = Some(p.kind),
            Event::Move(m) => {
                if m.kind == MoveKind::Thread {
                    if let Some(kind) = pass.take() {
                        out.push((kind, at));
                    }
                }
                at = (m.x, m.z);
            }
            Event::Dwell(_) | Event::Spindle(_) | Event::Press(_) | Event::Stop(_) | Event::Resume(_) => {}
        }
    }
    out
}

/// COM.AXES: X words are diameters, G92 R is a radius: the cutting start X is the end X plus
/// twice R, and the pass depth (radius) is half the X infeed.
#[test]
fn com_axes_x_is_a_diameter_and_r_a_radius() {
    let program = "G0 X65 Z5\nG92 X58.7 Z-28 R-1 F3 J0\n";
    for t in both(program, &Config::default()) {
        let first_thread = t.moves().position(|m| m.kind == MoveKind::Thread).unwrap();
        let infeed = t.moves().nth(first_thread - 1).unwrap();
        assert_eq!(infeed.x, 58_700 - 2 * 1_000, "{}", t.to_gcode());
        let Some(Event::Pass(p)) = t.events.iter().find(|e| matches!(e, Event::Pass(_))) else { panic!() };
        assert_eq!(p.diameter_depth, 65_000 - 56_700, "{}", t.to_gcode());
        assert!(t.to_gcode().contains("(PASS 1 ROUGH DEPTH 4.150)"), "radius depth printed: {}", t.to_gcode());
    }
}

/// G76.FINISH.Z: the finishing (and spring) passes start at the Z of the last rough pass, while
/// in mode 0 each rough pass starts further along Z as it goes deeper (G76.INFEED.Z).
#[test]
fn g76_finish_z_is_the_z_of_the_last_rough_pass() {
    let program = "G00 X80 Z10\nG76 P030060 Q0.15 R0.1\nG76 X60 Z-60 P3 Q1.2 F3\n";
    for t in both(program, &Config::default()) {
        let points = infeed_points(&t, (0, 0));
        let rough: Vec<i64> = points.iter().filter(|p| p.0 == PassKind::Rough).map(|p| p.1 .1).collect();
        let finishing: Vec<i64> = points.iter().filter(|p| p.0 != PassKind::Rough).map(|p| p.1 .1).collect();
        assert!(rough.len() >= 3 && finishing.len() == 3, "{}", t.to_gcode());
        assert!(rough.windows(2).all(|w| w[0] != w[1]), "mode 0 moves Z with depth: {rough:?}");
        let last = *rough.last().unwrap();
        assert!(finishing.iter().all(|&z| z == last), "finishing Z {finishing:?} vs last rough {last}");
    }
}

/// G78.PULLOUT: with J and K omitted the pull-out comes from parameters 5130 (width, tenths of
/// the lead) and 5131 (angle) — the first block has no chamfer digit — so doubling 5130 doubles
/// the pull-out's length along Z.
#[test]
fn g78_pullout_from_parameters_5130_5131() {
    let program = "G00 X80 Z10\nG78 P010060 Q0.15 R0.1\nG78 X60 Z-60 P1 Q0.5 F2\n";
    let pullout_length = |p5130: i64| {
        let mut config = Config::default();
        config.params.set("5130", p5130).unwrap();
        let lengths = both(program, &config).map(|t| {
            let moves: Vec<_> = t.moves().collect();
            let i = moves.iter().position(|m| m.rule == Rule::G78Pullout || (m.kind == MoveKind::Thread && m.z == -60_000 && m.x != 60_000));
            let i = i.unwrap_or_else(|| panic!("no pull-out: {}", t.to_gcode()));
            (moves[i].z - moves[i - 1].z).abs()
        });
        assert_eq!(lengths[0], lengths[1], "spec and impl agree");
        lengths[0]
    };
    assert_eq!(pullout_length(10), 2_000, "5130 = 10 tenths of the 2 mm lead");
    assert_eq!(pullout_length(20), 4_000);
}

/// The thread moves of a G92 trace's single pass: the cut, and the pull-out when there is one.
fn g92_thread_moves(program: &str) -> [Vec<(i64, i64)>; 2] {
    both(program, &Config::default()).map(|t| t.moves().filter(|m| m.kind == MoveKind::Thread).map(|m| (m.x, m.z)).collect())
}

/// G92.JK.4: J = 0 (K omitted, or K = 0 too) — no pull-out: the cut runs straight to Z, one
/// thread move, in both engines.
#[test]
fn g92_jk4_j_zero_means_no_pullout() {
    for jk in ["J0", "J0 K0"] {
        let program = format!("G0 X65 Z5\nG92 X58.7 Z-28 F3 {jk}\n");
        for moves in g92_thread_moves(&program) {
            assert_eq!(moves, [(58_700, -28_000)], "{jk}: a straight cut to the end, no pull-out");
        }
    }
}

/// G92.JK.6: J = 0 with K ≠ 0 — still no pull-out.
#[test]
fn g92_jk6_j_zero_k_nonzero_means_no_pullout() {
    for moves in g92_thread_moves("G0 X65 Z5\nG92 X58.7 Z-28 F3 J0 K1\n") {
        assert_eq!(moves, [(58_700, -28_000)]);
    }
}

/// G92.JK.7: negative J and K are taken as positive — the same trace as J3 K1 — and the
/// pull-out ends K before Z, J outward.
#[test]
fn g92_jk7_negative_j_and_k_are_taken_as_positive() {
    let positive = g92_thread_moves("G0 X65 Z5\nG92 X58.7 Z-28 F3 J3 K1\n");
    assert_eq!(positive[0], [(58_700, -27_000), (64_700, -28_000)]);
    for jk in ["J-3 K-1", "J-3 K1", "J3 K-1"] {
        let negative = g92_thread_moves(&format!("G0 X65 Z5\nG92 X58.7 Z-28 F3 {jk}\n"));
        assert_eq!(negative, positive, "{jk}");
    }
}
