//! G70, G71, G72 and the contour (docs/INTERPRETATION.md, "Contours, arcs and the stock-removal
//! cycles") on the whole expander.
extern crate std;

use crate::tests::{expand, gcode, moves, passes};
use cycle_vocab::Config;

pub const EXAMPLE_1: &str = "N010 G50 X150 Z100\nN020 G00 X41 Z0\nN030 G71 U2 R1\nN040 G71 P50 Q120 U0.5 W0.2 F100\nN050 G01 X0 Z0\nN060 G03 X11 W-5.5 R5.5\nN070 G01 W-10\nN080 X17 W-10\nN090 W-15\nN100 G02 X29 W-7.348 R7.5\nN110 G01 W-12.652\nN120 X41\nN130 G70 P50 Q120 F30\n";
pub const EXAMPLE_2: &str = "N010 G50 X150 Z100\nN020 G00 X41 Z1\nN030 G72 W1 R1\nN040 G72 P50 Q80 U0.1 W0.2 F100\nN050 G00 X41 Z-31\nN060 G01 X20 Z-20\nN070 Z-2\nN080 X14 Z1\nN090 G70 P50 Q80 F30\n";

#[test]
fn smoke() {
    std::println!("{}", gcode(EXAMPLE_1, Config::default()));
    std::println!("{}", gcode(EXAMPLE_2, Config::default()));
    let _ = (moves, passes, expand);
}
