use super::*;

/// The frame's ccw sweep is G02 exactly where the seed's example 1 says: its ball end
/// (quadrant III of the frame, swept clockwise there) is G03.
#[test]
fn frame_orientation_matches_the_seed() {
    let f = Frame { axis: Axis::G71, a: (41_000, 0), s: -1, c: -1 };
    // N060 G03 X11 W-5.5 R5.5 from X0 Z0: centre X0 Z−5.5.
    assert_eq!(f.half((0, 0)), (41_000, 0));
    assert_eq!(f.half((0, -5_500)), (41_000, 11_000));
    assert_eq!(f.half((11_000, -5_500)), (30_000, 11_000));
    let arc = quadrant(f, (41_000, 0), 11_000, false);
    assert_eq!((arc[0].kind, f.xz(arc[0].end), arc[0].centre.map(|c| f.xz(c))), (Kind::Arc { cw: false }, (11_000, -5_500), Some((0, -5_500))));
    // N100 G02 X29 W-7.348 R7.5 from X17 Z−40.5 about X32 Z−40.5: quadrant I of the frame.
    assert!(f.cw(true));
    // G72 of example 2: s = −1, c = −1.
    let g = Frame { axis: Axis::G72, a: (41_000, 1_000), s: -1, c: -1 };
    assert_eq!(g.xz(g.half((14_000, -2_000))), (14_000, -2_000));
    assert!(!g.cw(true));
}

#[test]
fn lattice_points_are_on_their_circles() {
    for r in RADII {
        let pts = lattice(r);
        assert!(pts.len() >= 3, "{r}: {pts:?}");
        assert!(pts.iter().all(|&(t, w)| t * t + w * w == r * r));
        assert_eq!((pts[0], pts[pts.len() - 1]), ((r, 0), (0, r)));
    }
    assert_eq!(lattice(65).len(), 10);
}
