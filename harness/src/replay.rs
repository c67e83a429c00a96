//! The replay source: a committed case's decoded draws, given back to the harness body.

use crate::source::Source;

/// Replays a list of draws. Past the end of the list each draw is its range's low end (as past
/// the end of a fuzz input: a case found failing stops drawing at its failure). A listed value
/// outside the range asked for, or values left unused, mean the harness draws differently now:
/// [`ReplaySource::finish`] reports it.
pub struct ReplaySource {
    draws: Vec<i128>,
    pos: usize,
    misfit: Option<String>,
    /// The program text the body built, if it noted one.
    pub program: Option<Vec<u8>>,
}

impl ReplaySource {
    pub fn new(draws: Vec<i128>) -> ReplaySource {
        ReplaySource { draws, pos: 0, misfit: None, program: None }
    }

    /// After the body ran: `Ok` when every listed draw was used and lay in its range.
    pub fn finish(&self) -> Result<(), String> {
        if let Some(m) = &self.misfit {
            return Err(m.clone());
        }
        if self.pos < self.draws.len() {
            return Err(format!(
                "the harness drew {} values, the case lists {}: it draws differently now",
                self.pos,
                self.draws.len()
            ));
        }
        Ok(())
    }
}

impl Source for ReplaySource {
    fn bounded_i128(&mut self, lo: i128, hi: i128) -> i128 {
        let i = self.pos;
        self.pos += 1;
        match self.draws.get(i) {
            None => lo,
            Some(&v) if (lo..=hi).contains(&v) => v,
            Some(&v) => {
                if self.misfit.is_none() {
                    self.misfit = Some(format!("draw {i} is {v}, outside {lo}..={hi}: the harness draws differently now"));
                }
                lo
            }
        }
    }

    fn note_program(&mut self, program: &[u8]) {
        self.program = Some(program.to_vec());
    }
}

#[cfg(test)]
mod tests;
