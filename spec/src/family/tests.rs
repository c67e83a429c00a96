use super::*;
use cycle_vocab::Dialect::{self, Fanuc, Gsk, Nc201};

const DIALECTS: [Dialect; 3] = [Gsk, Fanuc, Nc201];

/// Each G code selects at most one row under each dialect; each row has a name of its own, a
/// code and a dialect; no row takes G00/G01, G90/G91 under `nc201`, or a no-motion code.
#[test]
fn each_code_has_one_family() {
    let mut seen = Vec::new();
    let mut names = Vec::new();
    for row in rows() {
        assert!(!row.codes.is_empty() && !row.dialects.is_empty(), "{}", row.name);
        assert!(!names.contains(&row.name), "{} twice", row.name);
        names.push(row.name);
        for &g in row.codes {
            assert!(![0, 1, 18, 20, 21, 40, 91, 97, 99].contains(&g), "G{g}");
            assert!(!(g == 90 && row.dialects.contains(&Nc201)));
            for &d in row.dialects {
                assert!(!seen.contains(&(g, d)), "G{g} twice under {d:?}");
                seen.push((g, d));
            }
        }
    }
}

/// The dispatch: a code selects its dialect's row; under another dialect it is PRJ.DIALECT's;
/// a code no row has is the interpreter's.
#[test]
fn select_follows_the_rows() {
    let name = |g, d| match select(g, d) {
        Selection::Row(i) => Some(rows().nth(i).unwrap().name),
        _ => None,
    };
    assert_eq!(DIALECTS.map(|d| name(76, d)), [Some("g76"), Some("f76"), None]);
    assert_eq!(select(76, Nc201), Selection::OtherDialect);
    assert_eq!((name(78, Gsk), select(78, Fanuc)), (Some("g78"), Selection::OtherDialect));
    assert_eq!((name(162, Nc201), select(162, Gsk)), (Some("g162"), Selection::OtherDialect));
    assert_eq!(DIALECTS.map(|d| name(33, d)), [Some("g32"), Some("g32"), None]);
    assert_eq!(name(50, Fanuc), Some("g50"));
    assert_eq!([select(0, Gsk), select(163, Nc201), select(1_000, Gsk)], [Selection::None; 3]);
}
