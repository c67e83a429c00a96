//! Tests of `plot.rs`.
use super::*;

/// A feed hold or reset pressed by the operator is a diamond at its point, titled with it.
#[test]
fn a_press_is_marked_where_it_happened() {
    use cycle_vocab::{Button, Press};
    let p = cycle_kernel::corpus::find("g92_example").unwrap();
    let mut t = cycle_spec::expand(p.text.as_bytes(), &p.config());
    t.events.insert(3, Event::Press(Press { button: Button::Hold, x: 58_700, z: -11_000, rule: Rule::G92Hold }));
    let svg = svg("hold", &p.config(), &t, None, None);
    assert_eq!(svg.matches("class=\"press\"").count(), 1);
    assert!(svg.contains("(PRESS HOLD AT X58.700 Z-11.000)"), "{svg}");
}

#[test]
fn plots_the_g92_example_with_its_parts() {
    let p = cycle_kernel::corpus::find("g92_example").unwrap();
    let t = cycle_spec::expand(p.text.as_bytes(), &p.config());
    let svg = svg("g92_example", &p.config(), &t, None, None);
    assert!(svg.starts_with("<svg xmlns=\"http://www.w3.org/2000/svg\""));
    assert!(svg.trim_end().ends_with("</svg>"));
    let moves = t.moves().count();
    assert_eq!(svg.matches("<line class=").count(), moves);
    assert_eq!(svg.matches("class=\"pullout\"").count(), 4, "one pull-out per cycle");
    assert_eq!(svg.matches("class=\"infeed\"").count(), 4, "one infeed point per pass");
    assert!(svg.contains("stroke-dasharray"));
    assert!(!svg.contains("class=\"divergent\"") && !svg.contains("class=\"alarm\""));
}

#[test]
fn a_trace_that_ends_in_an_alarm_says_so() {
    let p = cycle_kernel::corpus::find("g78_example").unwrap();
    let t = cycle_spec::expand(p.text.as_bytes(), &p.config());
    let svg = svg("g78_example", &p.config(), &t, None, None);
    assert!(svg.contains("the trace ends in (ALARM 2002 LINE 3 WORD P RULE G78.MODE)"), "{svg}");
}

#[test]
fn divergent_moves_are_red() {
    let p = cycle_kernel::corpus::find("g92_example").unwrap();
    let t = cycle_spec::expand(p.text.as_bytes(), &p.config());
    let mut c = t.clone();
    let i = c.events.iter().position(|e| matches!(e, Event::Move(m) if is_pullout(m.rule))).unwrap();
    if let Event::Move(m) = &mut c.events[i] {
        m.x += 1;
    }
    let svg = svg("g92_example", &p.config(), &t, Some(&c), Some((i, Some(Rule::G92Pullout))));
    // The changed move and the one after it (which now starts elsewhere) differ in end
    // point only for the changed one.
    assert_eq!(svg.matches("class=\"divergent\"").count(), 1, "{svg}");
    assert!(svg.contains(&format!("first divergence: event {i}, rule G92.PULLOUT")));
}

/// Example 1's two arcs are drawn as arcs: the ball end G03 counter-clockwise (sweep flag 0)
/// and the fillet G02 clockwise (1), each a quarter circle or less, in the semi-finish pass
/// and in G70; the view holds the ball end's whole sweep.
#[test]
fn arcs_are_drawn_as_arcs() {
    let program = include_str!("../../../../corpus/g71_example.nc");
    let config = Config::default();
    let t = cycle_spec::expand(program.as_bytes(), &config);
    let svg = svg("g71_example", &config, &t, None, None);
    let arcs: Vec<&str> = svg.lines().filter(|l| l.starts_with("<path class=\"arc\"")).collect();
    assert_eq!(arcs.len(), 4, "{svg}");
    assert_eq!(arcs.iter().filter(|l| l.contains(" 0 0 0 ")).count(), 2, "two G03, small arcs: {arcs:?}");
    assert_eq!(arcs.iter().filter(|l| l.contains(" 0 0 1 ")).count(), 2, "two G02, small arcs: {arcs:?}");
    assert_eq!(svg.matches("<line class=").count() + arcs.len(), t.moves().count());
}

/// A quadrant point inside an arc's sweep bounds the view; the ends alone would clip it.
#[test]
fn an_arc_extent_includes_its_quadrant_points() {
    // A quarter from X0 Z0 counter-clockwise about X0 Z−5 to X10 Z−5 (radius 5): its ends
    // bound it.
    let m = Move::arc(false, 10_000, -5_000, 0, -5_000, 1, Rule::ArcIk);
    let seg = Segment { index: 0, from: (0, 0), to: (10_000, -5_000), m, pass: None, first_thread_of_pass: false };
    let e = extent(&seg, 1000.0);
    assert!(e.iter().all(|&(z, r)| (-5.0..=0.0).contains(&z) && (0.0..=5.0 + 1e-9).contains(&r)), "{e:?}");
    // A half circle counter-clockwise from Z0 to Z−10 about Z−5 on the axis passes over the
    // top (radius 5), which neither end reaches.
    let half = Move::arc(false, 0, -10_000, 0, -5_000, 1, Rule::ArcIk);
    let seg = Segment { index: 0, from: (0, 0), to: (0, -10_000), m: half, pass: None, first_thread_of_pass: false };
    let top = extent(&seg, 1000.0).into_iter().map(|(_, r)| r).fold(f64::MIN, f64::max);
    assert!((top - 5.0).abs() < 1e-9, "the half circle's top bounds the view: {top}");
}

#[test]
fn ticks_are_round() {
    assert_eq!(ticks(0.0, 10.0), vec![0.0, 2.0, 4.0, 6.0, 8.0, 10.0]);
    assert_eq!(ticks(-28.3, 5.2), vec![-25.0, -20.0, -15.0, -10.0, -5.0, 0.0, 5.0]);
}
