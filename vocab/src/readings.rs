//! Declared readings (docs/INTERPRETATION.md, "Declared readings"): the points where the
//! manuals' letter and the practice of deployed controls differ and both are defensible. A
//! vendor declares the reading its expander follows; each defaults to the manuals' letter.
//!
//! The names and values are the ones `--reading NAME=VALUE`, the candidate protocol's
//! configuration and the evidence bundle write.

macro_rules! readings {
    ($(
        $(#[doc = $doc:literal])*
        $field:ident: $ty:ident => $name:literal { $first:ident => $first_name:literal $(, $variant:ident => $vname:literal)* $(,)? }
    )*) => {
        $(
            $(#[doc = $doc])*
            #[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash, PartialOrd, Ord)]
            #[cfg_attr(feature = "std", derive(serde::Serialize, serde::Deserialize))]
            pub enum $ty {
                /// The manuals' letter (the default).
                #[default]
                #[cfg_attr(feature = "std", serde(rename = $first_name))]
                $first,
                $(
                    #[cfg_attr(feature = "std", serde(rename = $vname))]
                    $variant,
                )*
            }

            impl $ty {
                /// Every value, the letter first.
                pub const ALL: &'static [$ty] = &[$ty::$first $(, $ty::$variant)*];

                /// The value's name as `--reading` writes it.
                pub const fn name(self) -> &'static str {
                    match self { $ty::$first => $first_name $(, $ty::$variant => $vname)* }
                }
            }
        )*

        /// The readings an expansion runs under; `Readings::default()` is the manuals' letter
        /// throughout.
        #[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
        #[cfg_attr(feature = "std", derive(serde::Serialize, serde::Deserialize))]
        pub struct Readings {
            $(
                $(#[doc = $doc])*
                #[cfg_attr(feature = "std", serde(rename = $name, default))]
                pub $field: $ty,
            )*
        }

        impl Readings {
            /// The readings' names, in order.
            pub const NAMES: &'static [&'static str] = &[$($name),*];

            /// The legal values of the reading `name`, the letter (default) first.
            pub fn values(name: &str) -> Option<&'static [&'static str]> {
                match name {
                    $($name => Some(&[$first_name $(, $vname)*]),)*
                    _ => None,
                }
            }

            /// Sets the reading `name` to `value`.
            pub fn set(&mut self, name: &str, value: &str) -> Result<(), BadReading> {
                match name {
                    $($name => {
                        self.$field = *$ty::ALL.iter().find(|v| v.name() == value).ok_or(BadReading::Value)?;
                    })*
                    _ => return Err(BadReading::Name),
                }
                Ok(())
            }

            /// The value of the reading `name`.
            pub fn get(&self, name: &str) -> Option<&'static str> {
                match name {
                    $($name => Some(self.$field.name()),)*
                    _ => None,
                }
            }

            /// Every reading as (name, value), in order.
            pub fn pairs(&self) -> [(&'static str, &'static str); Readings::NAMES.len()] {
                [$(($name, self.$field.name())),*]
            }

            /// Whether every reading is the letter.
            pub fn is_letter(&self) -> bool {
                *self == Readings::default()
            }
        }
    };
}

readings! {
    /// G94.TAPER: the sign of K. The letter (M003: "端面切削始点至终点位移在Z方向的…增量值", the
    /// Z increment from the cut's start to its end) is K = end Z − start Z; FANUC and ADTECH
    /// write K = start Z − end Z.
    g94_k: G94K => "g94.k" { EndMinusStart => "end-minus-start", StartMinusEnd => "start-minus-end" }
    /// G73.PATH: the retreat from A to C = A + (Δi + Δu/2, Δk + Δw) before the first pass. The
    /// letter (M003: "粗加工时刀具从A点后退至C点") visits C; `skip` goes straight to pass 1.
    g73_c: G73C => "g73.c" { Visit => "visit", Skip => "skip" }
    /// G75.RELIEF: the relief at a groove's bottom. The letter (M003: "在槽底沿-Z方向的退刀量") is
    /// along −Z; `against-step` relieves against the direction the grooves step in.
    g75_relief: G75Relief => "g75.relief" { MinusZ => "minus-z", AgainstStep => "against-step" }
    /// G162.I/J: the pitch change. The letter (M004: "через целый оборот") changes the lead by I
    /// in steps, once per J degrees; `continuous` changes it at a constant rate.
    g162_lead: G162Lead => "g162.lead" { Steps => "steps", Continuous => "continuous" }
    /// G76/G78 infeed Z reference. The letter (M000/M001: every infeed point Bn is displaced from
    /// B, at Z start, by X depth × tan(a/2)) measures every mode from the thread's start Z;
    /// `groove` places the modes so that all end on the same groove.
    thread_zref: ThreadZRef => "thread.zref" { Start => "start", Groove => "groove" }
    /// G96.RAPID: a G00 block under constant surface speed. The letter (M003: "一般不能出现G00程序段")
    /// refuses it; `allow` runs it.
    g96_rapid: G96Rapid => "g96.rapid" { Refuse => "refuse", Allow => "allow" }
}

/// A `--reading` that names no reading, or a value the reading does not take.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum BadReading {
    Name,
    Value,
}

#[cfg(test)]
mod tests;
