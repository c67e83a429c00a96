//! Operator actions as text (OP.SCRIPT), the form `--op` takes and reports print:
//!
//! | text | action |
//! |---|---|
//! | `hold:E@F` | feed hold at the fraction F of move E of the uninterrupted trace |
//! | `reset:E@F` | reset there |
//! | `start` | cycle start at the next feed-hold stop |
//! | `single:on@B`, `single:off@B` | single block switched before event B |
//!
//! E and B are 0-based indices into the uninterrupted trace's events (`expand --format json`
//! lists them; in the canonical G-code, event i is line i + 2). F is `NUM/DEN`, or a decimal
//! from 0 to 1 with at most six decimals (`0.5` is 5/10): exact either way.

use cycle_vocab::operator::ALONG_DEN_MAX;
use cycle_vocab::{Action, Along, Script};

/// Reads one action.
pub fn parse_action(text: &str) -> Result<Action, String> {
    let t = text.trim();
    if t == "start" {
        return Ok(Action::Start);
    }
    let (verb, rest) = t.split_once(':').ok_or_else(|| format!("{t:?}: not hold:E@F, reset:E@F, start or single:on|off@B"))?;
    match verb {
        "hold" => Ok(Action::Hold(along(rest)?)),
        "reset" => Ok(Action::Reset(along(rest)?)),
        "single" => {
            let (mode, before) = rest.split_once('@').ok_or_else(|| format!("{t:?}: single takes on@B or off@B"))?;
            let on = match mode {
                "on" => true,
                "off" => false,
                _ => return Err(format!("{t:?}: single takes on@B or off@B")),
            };
            Ok(Action::SingleBlock { on, before: index(before)? })
        }
        _ => Err(format!("{t:?}: unknown action {verb:?} (hold, reset, start, single)")),
    }
}

/// Reads a script: the actions in order.
pub fn parse_script<S: AsRef<str>>(texts: &[S]) -> Result<Script, String> {
    let mut script = Script::EMPTY;
    for t in texts {
        script.push(parse_action(t.as_ref())?).map_err(|e| e.to_string())?;
    }
    Ok(script)
}

/// The text of an action, as [`parse_action`] reads it back.
pub fn action_text(a: &Action) -> String {
    match a {
        Action::Hold(at) => format!("hold:{}@{}/{}", at.event, at.num, at.den),
        Action::Reset(at) => format!("reset:{}@{}/{}", at.event, at.num, at.den),
        Action::Start => "start".to_string(),
        Action::SingleBlock { on, before } => format!("single:{}@{before}", if *on { "on" } else { "off" }),
    }
}

/// The `--op` options that give a script.
pub fn script_args(s: &Script) -> String {
    s.actions().iter().map(|a| format!(" --op {}", action_text(a))).collect()
}

fn index(text: &str) -> Result<u32, String> {
    text.parse::<u32>().map_err(|_| format!("{text:?}: not an event index"))
}

fn along(text: &str) -> Result<Along, String> {
    let (event, f) = text.split_once('@').ok_or_else(|| format!("{text:?}: takes E@F (event index @ fraction)"))?;
    let event = index(event)?;
    let (num, den) = match f.split_once('/') {
        Some((n, d)) => (n.parse::<u32>().ok(), d.parse::<u32>().ok()),
        None => decimal(f),
    };
    let (Some(num), Some(den)) = (num, den) else {
        return Err(format!("{f:?}: not a fraction NUM/DEN or a decimal 0…1"));
    };
    let at = Along { event, num, den };
    if !at.is_legal() {
        return Err(format!("{f:?}: the fraction must lie in 0…1 with 1 ≤ DEN ≤ {ALONG_DEN_MAX}"));
    }
    Ok(at)
}

/// `0.25` → (25, 100); at most six decimals.
fn decimal(f: &str) -> (Option<u32>, Option<u32>) {
    let (int, frac) = f.split_once('.').unwrap_or((f, ""));
    if frac.len() > 6 || !(int.bytes().chain(frac.bytes())).all(|b| b.is_ascii_digit()) || int.is_empty() && frac.is_empty() {
        return (None, None);
    }
    let den = 10u32.pow(frac.len() as u32);
    let int: Option<u32> = if int.is_empty() { Some(0) } else { int.parse().ok() };
    let frac: u32 = if frac.is_empty() { 0 } else { frac.parse().unwrap_or(u32::MAX) };
    (int.and_then(|i| i.checked_mul(den)).and_then(|i| i.checked_add(frac)), Some(den))
}

#[cfg(test)]
mod tests;
