//! The byte-driven source: a harness body run by libFuzzer, which steers each draw by coverage.
//!
//! Each draw reads a mode byte, then its value:
//! - mode 1 (mod 4): the low end plus the next byte mod 16; mode 2: the high end minus it (the
//!   edges where overflow and off-by-one errors live);
//! - modes 0 and 3: the next 16 bytes as a little-endian `i128`, taken as it is when it lies in
//!   the range (so libFuzzer's inserted comparison operands hit exactly), else reduced into it.
//!
//! Past the end of the input every draw is the range's low end, so short inputs are the plainest
//! cases. [`FuzzSource::encode`] writes draws back as bytes: the seed corpus is encoded from
//! decoded seeds (lists of draws) this way.

use crate::source::Source;

/// Values drawn from fuzz input; records the draws and the program the body noted.
pub struct FuzzSource<'a> {
    data: &'a [u8],
    pos: usize,
    /// Every value drawn so far, in order.
    pub draws: Vec<i128>,
    /// The program text the body built, if it noted one.
    pub program: Option<Vec<u8>>,
}

impl<'a> FuzzSource<'a> {
    pub fn new(data: &'a [u8]) -> FuzzSource<'a> {
        FuzzSource { data, pos: 0, draws: Vec::new(), program: None }
    }

    fn byte(&mut self) -> Option<u8> {
        let b = self.data.get(self.pos).copied();
        self.pos += usize::from(b.is_some());
        b
    }

    /// Bytes from which this source draws `draws` again, under any ranges that contain them.
    pub fn encode(draws: &[i128]) -> Vec<u8> {
        let mut out = Vec::with_capacity(17 * draws.len());
        for v in draws {
            out.push(0);
            out.extend_from_slice(&v.to_le_bytes());
        }
        out
    }

    fn value(&mut self, lo: i128, hi: i128) -> i128 {
        let Some(mode) = self.byte() else { return lo };
        match mode % 4 {
            1 => lo.saturating_add(i128::from(self.byte().unwrap_or(0) % 16)).min(hi),
            2 => hi.saturating_sub(i128::from(self.byte().unwrap_or(0) % 16)).max(lo),
            _ => {
                let mut raw = [0u8; 16];
                for b in &mut raw {
                    *b = self.byte().unwrap_or(0);
                }
                let raw = i128::from_le_bytes(raw);
                if (lo..=hi).contains(&raw) {
                    return raw;
                }
                // hi − lo + 1, where 0 stands for 2^128 (every i128 is in range then).
                match hi.abs_diff(lo).wrapping_add(1) {
                    0 => raw,
                    size => lo.wrapping_add((raw as u128 % size) as i128),
                }
            }
        }
    }
}

impl Source for FuzzSource<'_> {
    fn bounded_i128(&mut self, lo: i128, hi: i128) -> i128 {
        let v = self.value(lo, hi);
        self.draws.push(v);
        v
    }

    fn note_program(&mut self, program: &[u8]) {
        self.program = Some(program.to_vec());
    }
}

#[cfg(test)]
mod tests;
