//! Rule IDs: the project's rule catalogue (`docs/RULES.md`) as code.
//!
//! Every move of a trace and every alarm names the rule it realises, so a diff or an evidence
//! report can point a reviewer at the catalogue entry.

macro_rules! rules {
    ($($variant:ident => $id:literal),* $(,)?) => {
        /// One rule of the catalogue.
        #[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
        pub enum Rule { $($variant),* }

        impl Rule {
            /// Every rule, in catalogue order.
            pub const ALL: &'static [Rule] = &[$(Rule::$variant),*];

            /// The catalogue ID, e.g. `"G76.DEPTH.MIN"`.
            pub const fn id(self) -> &'static str {
                match self { $(Rule::$variant => $id),* }
            }

            /// The rule with this catalogue ID.
            pub fn from_id(id: &str) -> Option<Rule> {
                match id { $($id => Some(Rule::$variant),)* _ => None }
            }
        }
    };
}

rules! {
    ComAxes => "COM.AXES",
    ComUnits => "COM.UNITS",
    ComRanges => "COM.RANGES",
    ComAbsInc => "COM.ABSINC",
    ComLead => "COM.LEAD",
    ComLongAxis => "COM.LONGAXIS",
    ComPoints => "COM.POINTS",
    ComSide => "COM.SIDE",
    ComMultiStart => "COM.MULTISTART",
    PrjLex => "PRJ.LEX",
    PrjWord => "PRJ.WORD",
    PrjDialect => "PRJ.DIALECT",
    PrjModal => "PRJ.MODAL",
    PrjSupported => "PRJ.SUPPORTED",
    PrjNoop => "PRJ.NOOP",
    PrjMaxPass => "PRJ.MAXPASS",
    PrjTrace => "PRJ.TRACE",
    OpScript => "OP.SCRIPT",
    OpHold => "OP.HOLD",
    OpResume => "OP.RESUME",
    OpReset => "OP.RESET",
    OpSingle => "OP.SINGLE",
    OpScope => "OP.SCOPE",
    OpAt => "OP.AT",
    OpReach => "OP.REACH",
    G92Format => "G92.FORMAT",
    G92Modal => "G92.MODAL",
    G92Path => "G92.PATH",
    G92Taper => "G92.TAPER",
    G92Pullout => "G92.PULLOUT",
    G92Jk1 => "G92.JK.1",
    G92Jk2 => "G92.JK.2",
    G92Jk3 => "G92.JK.3",
    G92Jk4 => "G92.JK.4",
    G92Jk5 => "G92.JK.5",
    G92Jk6 => "G92.JK.6",
    G92Jk7 => "G92.JK.7",
    G92Jk8 => "G92.JK.8",
    G92Hold => "G92.HOLD",
    G92Single => "G92.SINGLE",
    G92Reset => "G92.RESET",
    G92Example => "G92.EXAMPLE",
    G76Format => "G76.FORMAT",
    G76Defaults => "G76.DEFAULTS",
    G76Required => "G76.REQUIRED",
    G76Depth1 => "G76.DEPTH.1",
    G76DepthMin => "G76.DEPTH.MIN",
    G76DepthLast => "G76.DEPTH.LAST",
    G76Finish => "G76.FINISH",
    G76FinishZ => "G76.FINISH.Z",
    G76InfeedX => "G76.INFEED.X",
    G76InfeedZ => "G76.INFEED.Z",
    G76Mode => "G76.MODE",
    G76LeadIn => "G76.LEADIN",
    G76Pullout => "G76.PULLOUT",
    G76Path => "G76.PATH",
    G76MultiStart => "G76.MULTISTART",
    G76Hold => "G76.HOLD",
    G76Single => "G76.SINGLE",
    G76Example => "G76.EXAMPLE",
    G78Format => "G78.FORMAT",
    G78Mode => "G78.MODE",
    G78DepthMode => "G78.DEPTHMODE",
    G78Pullout => "G78.PULLOUT",
    G78Example => "G78.EXAMPLE",
    F76Format => "F76.FORMAT",
    F76Microns => "F76.MICRONS",
    F76Ex1 => "F76.EX1",
    F76Ex2 => "F76.EX2",
    Nc201AbsInc => "NC201.ABSINC",
    Nc201XMode => "NC201.XMODE",
    G162Format => "G162.FORMAT",
    G162X => "G162.X",
    G162H => "G162.H",
    G162Pq => "G162.PQ",
    G162Split => "G162.SPLIT",
    G162V => "G162.V",
    G162W => "G162.W",
    G162A => "G162.A",
    G162F => "G162.F",
    G162B => "G162.B",
    G162I => "G162.I",
    G162J => "G162.J",
    G162Retract => "G162.RETRACT",
    G162NoStop => "G162.NOSTOP",
    G162Path => "G162.PATH",
    G32 => "G32",
    G33 => "G33",
    G34 => "G34",
    G90Format => "G90.FORMAT",
    G90Modal => "G90.MODAL",
    G90Path => "G90.PATH",
    G90Taper => "G90.TAPER",
    G90Example => "G90.EXAMPLE",
    G94Format => "G94.FORMAT",
    G94Modal => "G94.MODAL",
    G94Path => "G94.PATH",
    G94Taper => "G94.TAPER",
    G94Example => "G94.EXAMPLE",
    G50Coord => "G50.COORD",
    G50Smax => "G50.SMAX",
    TnrcCodes => "TNRC.CODES",
    TnrcNoarc => "TNRC.NOARC",
    TnrcSwitch => "TNRC.SWITCH",
    TnrcRadius => "TNRC.RADIUS",
    TnrcTip => "TNRC.TIP",
    ArcDir => "ARC.DIR",
    ArcFormat => "ARC.FORMAT",
    ArcIk => "ARC.IK",
    ArcR => "ARC.R",
    ArcTol => "ARC.TOL",
    CntPq => "CNT.PQ",
    CntRange => "CNT.RANGE",
    CntFind => "CNT.FIND",
    CntFlow => "CNT.FLOW",
    CntWords => "CNT.WORDS",
    CntNosub => "CNT.NOSUB",
    CntFst => "CNT.FST",
    CntFirst => "CNT.FIRST",
    CntMax => "CNT.MAX",
    CntModal => "CNT.MODAL",
    CycOneshot => "CYC.ONESHOT",
    G70Format => "G70.FORMAT",
    G70Path => "G70.PATH",
    G70Feed => "G70.FEED",
    G70Uw => "G70.UW",
    G70Return => "G70.RETURN",
    G71Format => "G71.FORMAT",
    G71Uw => "G71.UW",
    G71Depth => "G71.DEPTH",
    G71Retract => "G71.RETRACT",
    G71Param => "G71.PARAM",
    G71Allow => "G71.ALLOW",
    G71First => "G71.FIRST",
    G71Type2 => "G71.TYPE2",
    G71Monotone => "G71.MONOTONE",
    G71Layer => "G71.LAYER",
    G71Lastpass => "G71.LASTPASS",
    G71Return => "G71.RETURN",
    G71Example => "G71.EXAMPLE",
    G72Format => "G72.FORMAT",
    G72Depth => "G72.DEPTH",
    G72First => "G72.FIRST",
    G72Type2 => "G72.TYPE2",
    G72Monotone => "G72.MONOTONE",
    G72Layer => "G72.LAYER",
    G72Retract => "G72.RETRACT",
    G72Lastpass => "G72.LASTPASS",
    G72Return => "G72.RETURN",
    G72Example => "G72.EXAMPLE",
    G73Format => "G73.FORMAT",
    G73Uw => "G73.UW",
    G73Escape => "G73.ESCAPE",
    G73Count => "G73.COUNT",
    G73Depth => "G73.DEPTH",
    G73Path => "G73.PATH",
    G73Example => "G73.EXAMPLE",
    G73Use => "G73.USE",
    G74Format => "G74.FORMAT",
    G74E => "G74.E",
    G74Peck => "G74.PECK",
    G74Column => "G74.COLUMN",
    G74Relief => "G74.RELIEF",
    G74Example => "G74.EXAMPLE",
    G74Units => "G74.UNITS",
    G75Format => "G75.FORMAT",
    G75Peck => "G75.PECK",
    G75Column => "G75.COLUMN",
    G75Relief => "G75.RELIEF",
    G75Example => "G75.EXAMPLE",
    G83Format => "G83.FORMAT",
    G83Peck => "G83.PECK",
    G84Format => "G84.FORMAT",
    G84Path => "G84.PATH",
    G80 => "G80",
    G163 => "G163",
    SubCall => "SUB.CALL",
    SubFind => "SUB.FIND",
    SubReturn => "SUB.RETURN",
    SubNest => "SUB.NEST",
    G96Smax => "G96.SMAX",
    G96Rapid => "G96.RAPID",
    G96Speed => "G96.SPEED",
    T30 => "T30",
}

impl core::fmt::Display for Rule {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        f.write_str(self.id())
    }
}

#[cfg(feature = "std")]
impl serde::Serialize for Rule {
    fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        s.serialize_str(self.id())
    }
}

#[cfg(feature = "std")]
impl<'de> serde::Deserialize<'de> for Rule {
    fn deserialize<D: serde::Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        let id = <std::borrow::Cow<'de, str>>::deserialize(d)?;
        Rule::from_id(&id).ok_or_else(|| serde::de::Error::custom(format!("unknown rule ID {id}")))
    }
}

#[cfg(test)]
mod tests;
