//! G76.DEPTH.MIN's switch pass from legal words is the closed form, one division: the binary
//! search (256-bit products) is only for Δd, Δdmin whose a = Δd² − Δdmin² or c = 2·Δd·Δdmin
//! exceed 64 bits. Both give the same pass (`closed_form_switch_pass_is_the_searched_one`), so
//! `crate::probe` counts the searches.
use super::*;
use crate::probe;

#[test]
fn legal_words_take_the_closed_form() {
    let searches = |dd: u64, dmin: u64| {
        let before = probe::searches();
        let s = switch_pass(dd, dmin);
        (s, probe::searches() - before)
    };
    // Δd, Δdmin up to N < 2^30 increments: no search.
    for (dd, dmin) in [(1, 1), (700, 100), (100, 700), ((1 << 30) - 1, 1), ((1 << 30) - 1, (1 << 30) - 2), (1, (1 << 30) - 1)] {
        assert_eq!(searches(dd, dmin).1, 0, "Δd {dd} Δdmin {dmin}");
    }
    // The first n with a² < c²·(n − 1): a²/c² = 480000²/140000² = 11.76…, so n − 1 = 12.
    assert_eq!(searches(700, 100), (13, 0));
    // The positive control: Δd = 2^40, Δdmin = 2^39 make a beyond 64 bits: one search.
    assert_eq!(searches(1 << 40, 1 << 39).1, 1);
}
