use super::*;

#[test]
fn spec_engine_is_the_spec() {
    let p = b"G0 X65 Z5\nG92 X58.7 Z-28 F3 J3 K1\n";
    let c = Config::default();
    assert_eq!(SpecEngine.expand(p, &c), cycle_spec::expand(p, &c));
    assert!(!SpecEngine.expand(p, &c).events.is_empty());
}

#[test]
fn impl_engine_collects_the_stream_on_the_config_grid() {
    let c = Config { grid: cycle_vocab::Grid { units: cycle_vocab::Units::Inch, ..c_grid() }, ..Config::default() };
    let t = ImplEngine.expand(b"G0 X1 Z1\n", &c);
    assert_eq!(t.grid, c.grid);
    let direct = Trace::collect(c.grid, cycle_impl::Expander::new(b"G0 X1 Z1\n", c));
    assert_eq!(t, direct);
}

fn c_grid() -> cycle_vocab::Grid {
    cycle_vocab::Grid::METRIC_ISB
}

#[test]
fn names() {
    assert_eq!(by_name("spec").unwrap().name(), "spec");
    assert_eq!(by_name("impl").unwrap().name(), "impl");
    assert!(by_name("other").is_none());
}
