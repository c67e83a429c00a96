//! Program text built from drawn values in a fixed buffer: no allocation, so a Kani harness
//! builds its symbolic program without a heap model, and every loop has a small fixed bound
//! (at most 20 digits per number).

/// The largest program a harness builds.
pub const CAPACITY: usize = 256;

/// A program under construction. Writing past [`CAPACITY`] sets `overflow` and drops the byte;
/// a harness checks that it never happens.
pub struct Program {
    buf: [u8; CAPACITY],
    len: usize,
    overflow: bool,
}

impl Default for Program {
    fn default() -> Program {
        Program::new()
    }
}

impl Program {
    pub const fn new() -> Program {
        Program { buf: [0; CAPACITY], len: 0, overflow: false }
    }

    /// The text written so far.
    pub fn bytes(&self) -> &[u8] {
        &self.buf[..self.len]
    }

    pub fn len(&self) -> usize {
        self.len
    }

    pub fn is_empty(&self) -> bool {
        self.len == 0
    }

    /// Whether a write did not fit.
    pub fn overflowed(&self) -> bool {
        self.overflow
    }

    pub fn byte(&mut self, b: u8) {
        if self.len < CAPACITY {
            self.buf[self.len] = b;
            self.len += 1;
        } else {
            self.overflow = true;
        }
    }

    pub fn text(&mut self, s: &[u8]) {
        for &b in s {
            self.byte(b);
        }
    }

    /// `v` in decimal, with a `-` when negative, and a decimal point `decimals` digits from the
    /// right when `decimals > 0` (`fixed(-1500, 3)` is `-1.500`, `fixed(7, 0)` is `7`).
    pub fn fixed(&mut self, v: i64, decimals: u32) {
        let mut digits = [0u8; 20];
        let mut n = v.unsigned_abs();
        let mut count = 0usize;
        // At least decimals + 1 digits, so 7 at 3 decimals is 0.007.
        while count < 20 && (n != 0 || count <= decimals as usize) {
            digits[count] = b'0' + (n % 10) as u8;
            n /= 10;
            count += 1;
        }
        if v < 0 {
            self.byte(b'-');
        }
        let mut i = count;
        while i > 0 {
            i -= 1;
            self.byte(digits[i]);
            if decimals > 0 && i == decimals as usize {
                self.byte(b'.');
            }
        }
    }

    /// An address with an integer (no decimal point): `G76`, `L3`.
    pub fn int_word(&mut self, letter: u8, v: i64) {
        self.byte(letter);
        self.fixed(v, 0);
    }

    /// An address with a length in increments written with the grid's decimals: with 3
    /// decimals, `len_word(b'U', -4500, 3)` is `U-4.500` — exact, so no PRECISION alarm.
    pub fn len_word(&mut self, letter: u8, v: i64, decimals: u32) {
        self.byte(letter);
        self.fixed(v, decimals);
    }

    /// `P` of a first cycle block: six digits `mm rr aa`, leading zeros written.
    pub fn six_digits(&mut self, letter: u8, hi: u32, mid: u32, lo: u32) {
        self.byte(letter);
        for v in [hi, mid, lo] {
            self.byte(b'0' + (v / 10 % 10) as u8);
            self.byte(b'0' + (v % 10) as u8);
        }
    }

    pub fn end_block(&mut self) {
        self.byte(b'\n');
    }
}

#[cfg(test)]
mod tests;
