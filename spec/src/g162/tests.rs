//! Unit tests of the G162 rules (M004): depths, the pitch conversion, the infeed angle, the lead
//! law and its bound under both `g162.lead` readings.

use super::*;

/// G162.SPLIT, the example: P2.5 Q1. On the ISC grid (0.0001 mm) the manual's
/// sequence exactly; on ISB (0.001 mm) 2.4375 rounds half up to 2.438.
#[test]
fn p2_5_q1_depths() {
    let isc: Vec<i64> = {
        let (k, d) = full_passes(25_000, 10_000);
        (1..=k).map(|n| n * 10_000).chain(split_depths(k * 10_000, d)).collect()
    };
    assert_eq!(isc, vec![10_000, 20_000, 22_500, 23_750, 24_375, 25_000]);
    let (k, d) = full_passes(2_500, 1_000);
    assert_eq!((k, d), (2, 500));
    assert_eq!(split_depths(2_000, 500), vec![2_250, 2_375, 2_438, 2_500]);
    assert_eq!(pass_count(2_500, 1_000), 6);
}

/// G162.SPLIT OPEN points: a zero remainder adds nothing; allowances below one increment
/// merge into the next cut; Q > P splits P itself.
#[test]
fn split_edge_cases() {
    assert_eq!(split_depths(3_000, 0), Vec::<i64>::new());
    assert_eq!(pass_count(3_000, 1_000), 3);
    assert_eq!(split_depths(2, 1), vec![3]); // targets 2.5→3, 2.75→3, 2.875→3, 3
    assert_eq!(split_depths(0, 2), vec![1, 2]); // 1, 1.5→2, 1.75→2, 2
    assert_eq!(split_depths(0, 3), vec![2, 3]); // 1.5→2, 2.25→2, 2.625→3, 3
    assert_eq!(split_depths(0, 500), vec![250, 375, 438, 500]); // P0.5 Q1
    for kq in [0, 7, 1_000] {
        for d in 1..200 {
            let v = split_depths(kq, d);
            assert_eq!(*v.last().unwrap(), kq + d, "ends at P");
            assert!(v.windows(2).all(|w| w[0] < w[1]) && v[0] > kq, "strictly increasing");
            assert!(v.len() <= 4);
        }
    }
}

/// G162.F (M004): 2 mm along a cone 50 mm long with a 20 mm diameter difference:
/// 2·50/√(50² + 10²) = 1.961161…: 1.9612 on the lead grid, the manual's 1.96 to two decimals.
#[test]
fn manual_pitch_example() {
    let f = long_axis_pitch(20_000, 50_000, 10_000);
    assert_eq!(f, 19_612);
    assert_eq!(round_div(f as i128, 100), 196);
    // The same in any unit of length; a straight thread keeps its pitch.
    assert_eq!(long_axis_pitch(20_000, 50, 10), 19_612);
    assert_eq!(long_axis_pitch(15_000, 40_000, 0), 15_000);
    // 3-4-5: 5·4/5 = 4 exactly; 7·4/5 = 5.6 → 6; 6·4/5 = 4.8 → 5; 3·4/5 = 2.4 → 2.
    assert_eq!(long_axis_pitch(5, 4, 3), 4);
    assert_eq!(long_axis_pitch(7, 4, 3), 6);
    assert_eq!(long_axis_pitch(6, 4, 3), 5);
    assert_eq!(long_axis_pitch(3, 4, 3), 2);
}

/// G162.F at the top of the ranges: F = 99 990 000 lead counts (the F maximum, COM.LEAD) along
/// a 45° cone whose long and short lengths are both N = 99 999 999: F·l/√(2l²) = 99 990 000/√2
/// = 70 703 607.05…, rounded once, half up: 70 703 607 — exact on the largest inputs.
#[test]
fn manual_pitch_at_the_top_of_the_ranges() {
    assert_eq!(long_axis_pitch(99_990_000, 99_999_999, 99_999_999), 70_703_607);
}

/// G162.F below half a count: 1 count along a cone of long length 1 and short length 3 is
/// 1/√10 = 0.316… counts, rounded once, half up: 0; 2/√10 = 0.632…: 1.
#[test]
fn manual_pitch_below_half_a_count() {
    assert_eq!(long_axis_pitch(1, 1, 3), 0);
    assert_eq!(long_axis_pitch(2, 1, 3), 1);
}

/// G162.A (M004): the sign rule and the rounding, t(0.5 mm) at 30° = round(288.675) = 289.
#[test]
fn infeed_angle_sign_and_rounding() {
    assert_eq!(z_shift(500, 300, 1), 289);
    assert_eq!(z_shift(500, 300, -1), -289);
    assert_eq!(z_shift(500, -300, 1), -289);
    assert_eq!(z_shift(500, -300, -1), 289);
    assert_eq!(z_shift(1_000, 300, 1), 577);
    assert_eq!(z_shift(1_000, 0, 1), 0);
    assert_eq!(z_shift(1_000, 450, 1), 1_000); // 45°
    assert_eq!(z_shift(0, 300, 1), 0);
    // Any tenth: 27.3° → tan = 0.516138…
    assert_eq!(z_shift(1_000, 273, 1), 516);
    assert_eq!(z_shift(1_000, -273, 1), -516);
}

/// G162.I, G162.J: the lead law and where the shrinking stops, under each reading.
#[test]
fn variable_pitch_law() {
    for reading in [G162Lead::Steps, G162Lead::Continuous] {
        let stepped = reading == G162Lead::Steps;
        assert_eq!(lead_law(15_000, 0, 360_000, reading), LeadLaw::default());
        assert_eq!(
            lead_law(15_000, 5_000, 180_000, reading),
            LeadLaw { change: 5_000, change_angle: 180_000, floor: 0, stepped }
        );
        assert_eq!(
            lead_law(15_000, -5_000, 180_000, reading),
            LeadLaw { change: -5_000, change_angle: 180_000, floor: 5_000, stepped }
        );
        // Already at or below |I|: the change has stopped before it starts.
        assert_eq!(lead_law(5_000, -5_000, 360_000, reading), LeadLaw::default());
        assert_eq!(lead_law(4_000, -5_000, 360_000, reading), LeadLaw::default());
    }
    // The letter is the default reading.
    assert_eq!(G162Lead::default(), G162Lead::Steps);
    assert_eq!(start_angle(360_000), 0);
    assert_eq!(start_angle(90_000), 90_000);
}

/// G162.I, `continuous`: a growing lead may reach the F maximum at the end of ② and not
/// beyond (L² = F² + I·s2 per revolution: F = 9000 mm, I = 1 mm/rev).
#[test]
fn growing_lead_bound_continuous() {
    let g = Grid::METRIC_ISB;
    let c = G162Lead::Continuous;
    let fmax = lead_max(g) as i128;
    // s2 chosen so that F² + I·s2 = Fmax² exactly (J = 360 000, per revolution).
    let f = 90_000_000i128;
    let i = 10_000i128;
    let s2 = (fmax * fmax - f * f) / i;
    assert_eq!((fmax * fmax - f * f) % i, 0);
    assert!(growing_lead_ok(f as i64, i as i64, 360_000, s2, g, c, 1).is_ok());
    assert_eq!(
        growing_lead_ok(f as i64, i as i64, 360_000, s2 + 1, g, c, 1),
        Err(alarm(AlarmCode::Geometry, b'I', Rule::G162I, 1))
    );
    assert!(growing_lead_ok(f as i64, -i as i64, 360_000, s2 * 1_000, g, c, 1).is_ok());
}

/// G162.I, `steps` (the letter): F = 9000 mm, I = 1 mm per revolution: the first lead above
/// Fmax = 9999 mm is step k* = 1000, reached after 1000·F + I·1000·999/2 lead counts of
/// travel. A thread of exactly that long-axis travel never takes it; one count longer does.
#[test]
fn growing_lead_bound_steps() {
    let g = Grid::METRIC_ISB;
    let st = G162Lead::Steps;
    let (f, i) = (90_000_000i64, 10_000i64);
    let travel = 1_000 * f as i128 + i as i128 * 1_000 * 999 / 2;
    assert!(growing_lead_ok(f, i, 360_000, 2 * travel, g, st, 1).is_ok());
    assert_eq!(growing_lead_ok(f, i, 360_000, 2 * travel + 1, g, st, 1), Err(alarm(AlarmCode::Geometry, b'I', Rule::G162I, 1)));
    // Half a revolution per step: the same steps come after half the travel.
    assert!(growing_lead_ok(f, i, 180_000, travel, g, st, 1).is_ok());
    assert!(growing_lead_ok(f, i, 180_000, travel + 1, g, st, 1).is_err());
    // The stepped lead stays below the continuous one's end: the continuous bound is the
    // stricter on the same thread (F² + I·s2 > Fmax² there).
    assert!(growing_lead_ok(f, i, 360_000, 2 * travel, g, G162Lead::Continuous, 1).is_err());
    // A shrinking lead has no bound; an I as large as the range, one step over at once.
    assert!(growing_lead_ok(f, -i, 360_000, i128::MAX / 1_000_000, g, st, 1).is_ok());
    assert!(stepped_lead_exceeds(1, 99_990_000, 360_000, 3, 99_990_000));
    assert!(!stepped_lead_exceeds(1, 99_990_000, 360_000, 1, 99_990_000));
}

#[test]
fn long_axis() {
    let g = Grid::METRIC_ISB;
    assert_eq!(long_travel_twice(-20_000, 0, g), 400_000);
    assert_eq!(long_travel_twice(1_000, 3_000, g), 30_000); // X long: 1.5 radius > 1
    assert_eq!(long_travel_twice(1_000, 2_000, g), 20_000); // equal: X (COM.LONGAXIS)
}
