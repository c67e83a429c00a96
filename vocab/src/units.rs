//! Lengths on the least-increment grid (COM.UNITS).

/// Input units (COM.UNITS).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[cfg_attr(feature = "std", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "std", serde(rename_all = "snake_case"))]
pub enum Units {
    Metric,
    Inch,
}

/// Increment system (COM.UNITS): ISB 0.001 mm / 0.0001 in, ISC 0.0001 mm / 0.00001 in.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[cfg_attr(feature = "std", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "std", serde(rename_all = "snake_case"))]
pub enum Increment {
    Isb,
    Isc,
}

/// The grid every length and lead lives on.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[cfg_attr(feature = "std", derive(serde::Serialize, serde::Deserialize))]
pub struct Grid {
    pub units: Units,
    pub increment: Increment,
}

impl Grid {
    pub const METRIC_ISB: Grid = Grid { units: Units::Metric, increment: Increment::Isb };

    /// Decimal places of one length increment: 3, 4 (metric ISB, ISC), 4, 5 (inch ISB, ISC).
    pub const fn decimals(self) -> u32 {
        match (self.units, self.increment) {
            (Units::Metric, Increment::Isb) => 3,
            (Units::Metric, Increment::Isc) | (Units::Inch, Increment::Isb) => 4,
            (Units::Inch, Increment::Isc) => 5,
        }
    }

    /// Decimal places of one lead count (COM.LEAD): 0.0001 mm, 0.00001 in, in ISB and ISC.
    pub const fn lead_decimals(self) -> u32 {
        match self.units {
            Units::Metric => 4,
            Units::Inch => 5,
        }
    }

    /// How many lead counts make one length increment (10 in ISB, 1 in ISC).
    pub const fn lead_counts_per_increment(self) -> i64 {
        match self.increment {
            Increment::Isb => 10,
            Increment::Isc => 1,
        }
    }

    /// The unit's name as printed in trace headers.
    pub const fn unit_name(self) -> &'static str {
        match self.units {
            Units::Metric => "MM",
            Units::Inch => "INCH",
        }
    }
}

#[cfg(test)]
mod tests;
