use super::*;

#[test]
fn grid_decimals() {
    assert_eq!(Grid::METRIC_ISB.decimals(), 3);
    let inch_isc = Grid { units: Units::Inch, increment: Increment::Isc };
    assert_eq!(inch_isc.decimals(), 5);
    assert_eq!(inch_isc.lead_decimals(), 5);
    assert_eq!(inch_isc.lead_counts_per_increment(), 1);
}
