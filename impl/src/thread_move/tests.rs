use super::*;

const G: Grid = Grid::METRIC_ISB;

fn w(lead: i64, p: u32, k: i64) -> ThreadWords {
    ThreadWords { lead, p, k }
}

#[test]
fn moves() {
    let m = thread_move(ThreadCode::G32, (30_000, 5_000), (29_000, -35_000), &w(20_000, 0, 0), G, 1).unwrap();
    assert_eq!(m, Move::thread(29_000, -35_000, 20_000, 0, Rule::G32));
    // G33 P180000: the second start of a two-start thread.
    let m = thread_move(ThreadCode::G33, (34_000, 5_000), (34_000, -26_000), &w(60_000, 180_000, 0), G, 1).unwrap();
    assert_eq!(m.angle, 180_000);
    assert_eq!(m.rule, Rule::G33);
    // P is ignored outside G33; K = 0 is a constant lead.
    let m = thread_move(ThreadCode::G34, (0, 0), (0, -1_000), &w(20_000, 0, 0), G, 1).unwrap();
    assert_eq!(m, Move::thread(0, -1_000, 20_000, 0, Rule::G34));
}

/// G34: a 2 mm lead shrinking by 0.1 mm per revolution over Z travel s: L² = F² + K·2s.
/// F = 20 000, K = −1 000 counts: F² = 4·10^8, so 2s·1 000 < 4·10^8 needs s < 200 000
/// counts = 20 mm (ISB: 10 counts per increment), i.e. |ΔZ| < 20 000 increments.
#[test]
fn g34_bound() {
    let ok = thread_move(ThreadCode::G34, (0, 0), (0, -19_999), &w(20_000, 0, -1_000), G, 4).unwrap();
    assert_eq!(ok, Move::variable_thread(0, -19_999, 20_000, 0, -1_000, 360_000, 0, Rule::G34));
    let bad = thread_move(ThreadCode::G34, (0, 0), (0, -20_000), &w(20_000, 0, -1_000), G, 4);
    assert_eq!(bad, Err(Alarm::new(AlarmCode::Geometry, Some(b'K'), Rule::G34, 4)));
    // X long (a face thread): s2 = |ΔX| (diameter) counts.
    assert!(thread_move(ThreadCode::G34, (0, 0), (39_998, 0), &w(20_000, 0, -1_000), G, 4).is_ok());
    assert!(thread_move(ThreadCode::G34, (0, 0), (40_000, 0), &w(20_000, 0, -1_000), G, 4).is_err());
    // Growing past the F maximum 9999 mm.
    let fmax = max_lead(G.units);
    assert!(thread_move(ThreadCode::G34, (0, 0), (0, -1), &w(fmax, 0, 1), G, 4).is_err());
    assert!(thread_move(ThreadCode::G34, (0, 0), (0, -1), &w(fmax - 1, 0, 1), G, 4).is_ok());
    // The exact edge: F = Fmax − 200 counts, s2 = 2·1 000·10 = 20 000 counts and
    // K·s2 = Fmax² − F² = 39 995 960 000: the end lead is exactly Fmax — allowed; K + 1 is not.
    assert!(thread_move(ThreadCode::G34, (0, 0), (0, -1_000), &w(fmax - 200, 0, 1_999_798), G, 4).is_ok());
    assert!(thread_move(ThreadCode::G34, (0, 0), (0, -1_000), &w(fmax - 200, 0, 1_999_799), G, 4).is_err());
}

/// The bound's sides belong to K's sign (the register: K < 0 bounds L² below by 0, K > 0
/// above by Fmax²): a lead above Fmax — reachable from I, threads per inch — is no alarm with
/// K = 0 (the constant form) nor with K < 0 while L² > 0; with K > 0 it is.
#[test]
fn g34_bound_sides() {
    let fmax = max_lead(G.units);
    let big = fmax + 1;
    let k0 = thread_move(ThreadCode::G34, (0, 0), (0, -1), &w(big, 0, 0), G, 2).unwrap();
    assert_eq!(k0, Move::thread(0, -1, big, 0, Rule::G34));
    let down = thread_move(ThreadCode::G34, (0, 0), (0, -1), &w(big, 0, -1), G, 2).unwrap();
    assert_eq!(down, Move::variable_thread(0, -1, big, 0, -1, 360_000, 0, Rule::G34));
    let up = thread_move(ThreadCode::G34, (0, 0), (0, -1), &w(big, 0, 1), G, 2);
    assert_eq!(up, Err(Alarm::new(AlarmCode::Geometry, Some(b'K'), Rule::G34, 2)));
    // The smallest lead, 1 count, with no travel: L² = F² = 1 > 0 whatever K's sign.
    for k in [-1, 0, 1] {
        let m = thread_move(ThreadCode::G34, (5, 5), (5, 5), &w(1, 0, k), G, 2).unwrap();
        assert_eq!(m, Move::variable_thread(5, 5, 1, 0, k, 360_000, 0, Rule::G34));
    }
}
