//! The program writer of the structured generators: blocks of words in varied but legal
//! spellings, and the words every family writes alike (leads, axes, the program end).
//!
//! Two sources of variety: the writer's *style* (one knob: 0 is plain) rotates words and varies
//! some blocks' separators, case and endings and some lengths' forms; the *spelling*
//! ([`Spelling`], the case's last knobs) turns on program-wide the forms the lexer promises
//! (docs/INTERPRETATION.md, "Program text"). Both off is the plain program.

use super::{max_lead, Dice, LEAD_UNIT};
use cycle_vocab::text::fixed;
use cycle_vocab::Grid;

/// In how many cases in a hundred the program starts with a UTF-8 byte-order mark. Skipping it
/// is a rule both engines are adopting (PRJ.LEX); an engine without the rule stops at it with
/// BAD CHARACTER on line 1, so while only one engine has it, these cases diverge: 0 turns them off.
pub const BOM_PERCENT: u32 = 5;

/// The program-wide spellings, each turned on by its own knob (so shrinking turns each off on
/// its own); all off is the plain spelling.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Spelling {
    /// `X007.5`, `G0092`: zeros before the digits of every word.
    pub leading_zeros: bool,
    /// `X5.`: a point after every whole length.
    pub trailing_point: bool,
    /// `X58.7000000`: zeros after the last digit of every length with a point, past the grid's
    /// places (a value, not a precision error: the reader scales by the digits beyond the grid).
    pub trailing_zeros: bool,
    /// `X+.5`: a plus sign and no zero before every positive length below one.
    pub plus_point: bool,
    /// `R-0`: every zero length with a minus sign.
    pub minus_zero: bool,
    /// `g92 x58.7`: lower-case letters.
    pub lower_case: bool,
    /// `G0X1Z2`: no blanks between words.
    pub no_spaces: bool,
    /// `X1(c)Z2`: a comment between words.
    pub comments: bool,
    /// CR LF line ends.
    pub crlf: bool,
    /// A UTF-8 byte-order mark at the start ([`BOM_PERCENT`]).
    pub bom: bool,
}

impl Spelling {
    /// The spelling the dice choose.
    pub fn draw(d: &mut Dice) -> Spelling {
        Spelling {
            leading_zeros: d.chance(20),
            trailing_point: d.chance(20),
            plus_point: d.chance(20),
            minus_zero: d.chance(20),
            lower_case: d.chance(20),
            no_spaces: d.chance(20),
            comments: d.chance(20),
            crlf: d.chance(20),
            bom: d.chance(BOM_PERCENT),
            // Drawn last: the earlier spellings keep their knobs.
            trailing_zeros: d.chance(20),
        }
    }

    /// A length of `count` increments as the style wrote it (`text`), respelled.
    fn length(self, count: i64, decimals: u32, text: String) -> String {
        let one = 10i64.pow(decimals);
        let text = if self.plus_point && count > 0 && count < one {
            format!("+{}", fixed(count, decimals).trim_end_matches('0').trim_start_matches('0'))
        } else if self.minus_zero && count == 0 {
            format!("-{text}")
        } else {
            text
        };
        let text = if self.trailing_point && !text.contains('.') { format!("{text}.") } else { text };
        if self.trailing_zeros && text.contains('.') {
            format!("{text}000000")
        } else {
            text
        }
    }

    /// A word's value, respelled: zeros after the sign of a number.
    fn value(self, text: &str) -> String {
        let digits = text.trim_start_matches(['+', '-']);
        let is_number = digits.starts_with(|c: char| c.is_ascii_digit() || c == '.');
        if self.leading_zeros && is_number {
            format!("{}00{digits}", &text[..text.len() - digits.len()])
        } else {
            text.to_string()
        }
    }
}

/// Writes blocks of words in varied but legal spellings.
pub(super) struct Writer {
    out: String,
    /// 0: the plain style everywhere.
    style: u32,
    spelling: Spelling,
}

impl Writer {
    /// A writer with the style the dice choose and the case's spelling.
    pub(super) fn new(d: &mut Dice) -> Writer {
        let style = if d.chance(40) { d.range(1, u32::MAX as i64) as u32 } else { 0 };
        Writer { out: String::new(), style, spelling: Spelling::draw(&mut d.spelling()) }
    }

    /// A cheap, deterministic variation source (0 when the style is plain).
    fn vary(&mut self, n: u32) -> u32 {
        if self.style == 0 || n == 0 {
            return 0;
        }
        self.style ^= self.style << 13;
        self.style ^= self.style >> 17;
        self.style ^= self.style << 5;
        self.style % n
    }

    /// A length of `count` increments with `decimals` places: `60`, `58.7`, `58.700`,
    /// `58.7000`, `+58.7`, `.5`, `60.`, and the spelling's forms.
    pub(super) fn length(&mut self, count: i64, decimals: u32) -> String {
        let full = fixed(count, decimals);
        let trimmed = full.trim_end_matches('0').to_string();
        let integral = count % 10i64.pow(decimals) == 0;
        let text = match self.vary(6) {
            0 if integral => trimmed.trim_end_matches('.').to_string(),
            0 | 3 => trimmed,
            1 => full,
            2 => format!("{full}0"),
            4 if count > 0 => format!("+{trimmed}"),
            5 if count.abs() < 10i64.pow(decimals) && count != 0 => trimmed.replacen("0.", ".", 1),
            _ => trimmed,
        };
        self.spelling.length(count, decimals, text)
    }

    /// G76 P(k), Q(Δd), Q(Δdmin): under fanuc mostly the micron form (an integer count).
    pub(super) fn micron(&mut self, count: i64, decimals: u32, fanuc: bool) -> String {
        if fanuc && self.vary(4) != 1 {
            count.to_string()
        } else {
            let s = self.length(count, decimals);
            if fanuc && !s.contains('.') {
                format!("{s}.")
            } else {
                s
            }
        }
    }

    /// One block: its words (letter, value), in the given order or rotated, separated by spaces
    /// or not, sometimes lower case, ended by a newline or `;`.
    pub(super) fn block(&mut self, words: &[(char, String)]) {
        if words.is_empty() {
            return;
        }
        let rotate = if self.vary(4) == 0 { 0 } else { self.vary(words.len() as u32) as usize };
        let sep = if self.vary(5) == 1 || self.spelling.no_spaces { "" } else { " " };
        let lower = self.vary(6) == 1 || self.spelling.lower_case;
        for i in 0..words.len() {
            let (letter, value) = &words[(i + rotate) % words.len()];
            if i > 0 {
                self.out.push_str(sep);
                if self.spelling.comments {
                    self.out.push_str("(c)");
                }
            }
            self.out.push(if lower { letter.to_ascii_lowercase() } else { *letter });
            self.out.push_str(&self.spelling.value(value));
        }
        match self.vary(8) {
            1 => self.out.push_str(";\n"),
            2 => self.out.push_str("; "),
            3 => self.out.push_str(" (note)\n"),
            _ => self.out.push('\n'),
        }
    }

    /// A line as it is.
    pub(super) fn line(&mut self, text: &str) {
        self.out.push_str(text);
        self.out.push('\n');
    }

    /// The program: its lines with the spelling's line ends, after its byte-order mark.
    pub(super) fn finish(self) -> Vec<u8> {
        let bom = if self.spelling.bom { "\u{feff}" } else { "" };
        let ends = if self.spelling.crlf { "\r\n" } else { "\n" };
        format!("{bom}{}", self.out.replace('\n', ends)).into_bytes()
    }
}

/// A lead word: F (lead counts) or I (threads per inch, in 0.0001).
#[derive(Clone, Copy, Debug)]
pub(super) enum Lead {
    F(i64),
    I(i64),
}

pub(super) fn lead_word(w: &mut Writer, lead: Lead, grid: Grid) -> (char, String) {
    match lead {
        Lead::F(c) => ('F', w.length(c, grid.lead_decimals())),
        Lead::I(i4) => ('I', w.length(i4, 4)),
    }
}

/// A lead: mostly a legal F; sometimes I, sometimes just outside the range or finer than the
/// lead grid.
pub(super) fn lead(d: &mut Dice, grid: Grid) -> Result<Lead, String> {
    Ok(match d.weighted(&[80, 12, 2, 2, 2, 2]) {
        0 => Lead::F(d.range(LEAD_UNIT / 4, 6 * LEAD_UNIT)),
        1 => Lead::I(d.range(4, 80) * 10_000 + if d.chance(20) { d.range(1, 9999) } else { 0 }),
        2 => Lead::F(d.one_of(&[1, max_lead(grid)])),
        3 => return Err(d.one_of(&["0", "-1", "99999", "-0.5"]).to_string()),
        4 => return Err(format!("{}1", fixed(d.range(1, 3 * LEAD_UNIT), grid.lead_decimals()))),
        _ => Lead::I(d.one_of(&[0, 1, 254 * 10_000, 254 * 10_000 + 1, 100 * 10_000 + 1])),
    })
}

/// A written lead word, or a broken one (as text).
pub(super) fn lead_text(w: &mut Writer, l: &Result<Lead, String>, grid: Grid) -> (char, String) {
    match l {
        Ok(lead) => lead_word(w, *lead, grid),
        Err(text) => ('F', text.clone()),
    }
}

/// An axis word: absolute or incremental.
pub(super) fn axis(w: &mut Writer, d: &mut Dice, abs: char, inc: char, target: i64, current: i64, dec: u32) -> (char, String) {
    if d.chance(20) {
        (inc, w.length(target - current, dec))
    } else {
        (abs, w.length(target, dec))
    }
}

/// The program end: mostly `M30`, sometimes followed by text that must not be read, sometimes
/// nothing.
pub(super) fn tail(w: &mut Writer, d: &mut Dice) {
    match d.weighted(&[70, 15, 10, 5]) {
        0 => w.line("M30"),
        1 => {}
        2 => w.line("M30\nG92 X#junk after the end"),
        _ => w.line("M02\n%"),
    }
}

#[cfg(test)]
mod tests;
