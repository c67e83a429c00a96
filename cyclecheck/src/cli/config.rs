//! The configuration of `expand` and `diff` from the command line, and reading programs.

use crate::cli::args::ConfigArgs;
use crate::cli::{bad, Bad};
use cycle_spec::words::N as MAX_LENGTH;
use cycle_vocab::{Config, Grid, Increment, Units};

/// The configuration the options name; a value out of the reference's ranges is refused.
pub fn config(a: &ConfigArgs) -> Result<Config, Bad> {
    let mut c = Config { dialect: a.dialect.into(), ..Config::default() };
    c.grid = Grid {
        units: match a.units {
            crate::cli::args::UnitsArg::Metric => Units::Metric,
            crate::cli::args::UnitsArg::Inch => Units::Inch,
        },
        increment: match a.increment {
            crate::cli::args::IncrementArg::Isb => Increment::Isb,
            crate::cli::args::IncrementArg::Isc => Increment::Isc,
        },
    };
    for p in &a.params {
        let Some((n, v)) = p.split_once('=') else {
            return bad(format!("--param takes N=V, not {p:?}"));
        };
        let Ok(v) = v.trim().parse::<i64>() else {
            return bad(format!("--param {n}: {v:?} is not an integer"));
        };
        if c.params.set(n.trim(), v).is_err() {
            let names = cycle_vocab::Params::NAMES.join(", ");
            return bad(format!("--param {n}: unknown parameter (one of {names})"));
        }
    }
    c.operator = cycle_kernel::operator::parse_script(&a.ops).map_err(|e| Bad(format!("--op {e}")))?;
    c.readings = cycle_kernel::readings::Pins::parse(&a.readings).map_err(Bad)?.apply(c.readings);
    let decimals = c.grid.decimals();
    c.start_x = grid_value(&a.start_x, decimals).map_err(|e| Bad(format!("--start-x {:?}: {e}", a.start_x)))?;
    c.start_z = grid_value(&a.start_z, decimals).map_err(|e| Bad(format!("--start-z {:?}: {e}", a.start_z)))?;
    // The reference's own ranges decide which parameter values are legal.
    if let Err(alarm) = cycle_spec::config::check(&c) {
        return bad(format!("the configuration is refused: {alarm}"));
    }
    Ok(c)
}

/// A decimal in mm (inch) as a count of the least increment: exact, within ±N.
pub fn grid_value(text: &str, decimals: u32) -> Result<i64, String> {
    let (negative, digits) = match text.as_bytes().first() {
        Some(b'-') => (true, &text[1..]),
        Some(b'+') => (false, &text[1..]),
        _ => (false, text),
    };
    let (int, frac) = digits.split_once('.').unwrap_or((digits, ""));
    let all_digits = |s: &str| s.bytes().all(|b| b.is_ascii_digit());
    if int.is_empty() && frac.is_empty() || !all_digits(int) || !all_digits(frac) {
        return Err("not a decimal number".to_string());
    }
    let frac = frac.trim_end_matches('0');
    if frac.len() > decimals as usize {
        return Err(format!("more than {decimals} decimals (the least increment)"));
    }
    let too_large = || format!("outside ±{}", cycle_vocab::text::fixed(MAX_LENGTH, decimals));
    let int = int.trim_start_matches('0');
    if int.len() > 18 {
        return Err(too_large());
    }
    let int: i64 = if int.is_empty() { 0 } else { int.parse().map_err(|_| too_large())? };
    let frac_count: i64 = if frac.is_empty() { 0 } else { frac.parse::<i64>().map_err(|_| too_large())? };
    let scale = 10i64.pow(decimals);
    let count = int
        .checked_mul(scale)
        .and_then(|v| v.checked_add(frac_count * 10i64.pow(decimals - frac.len() as u32)))
        .filter(|v| *v <= MAX_LENGTH)
        .ok_or_else(too_large)?;
    Ok(if negative { -count } else { count })
}

/// A program's bytes: the file, or standard input for `-`.
pub fn read_program(file: &str) -> Result<Vec<u8>, Bad> {
    if file == "-" {
        let mut bytes = Vec::new();
        std::io::Read::read_to_end(&mut std::io::stdin().lock(), &mut bytes).map_err(|e| Bad(format!("cannot read standard input: {e}")))?;
        return Ok(bytes);
    }
    std::fs::read(file).map_err(|e| Bad(format!("cannot read {file}: {e}")))
}

/// Refuses, before anything runs, a file that cannot be opened or a `-` given twice.
pub fn check_files(files: &[String]) -> Result<(), Bad> {
    if files.iter().filter(|f| *f == "-").count() > 1 {
        return bad("- (standard input) can be given once");
    }
    for f in files.iter().filter(|f| *f != "-") {
        std::fs::File::open(f).map_err(|e| Bad(format!("cannot read {f}: {e}")))?;
    }
    Ok(())
}

#[cfg(test)]
mod tests;
