//! The cap on a subdivision search over pairs of pieces (curve–curve, curve–surface and
//! the seeds of surface–surface intersection): each pair taken from the stack is counted,
//! and a search that examines more than its limit ends with an error instead of running on.

use crate::error::{Error, Result};

/// Counts the pairs a subdivision search examines against its limit.
pub(crate) struct PairCount {
    examined: usize,
    limit: usize,
}

impl PairCount {
    /// No pair examined yet; at most `limit` allowed.
    pub(crate) fn new(limit: usize) -> Self {
        PairCount { examined: 0, limit }
    }

    /// Counts one more pair. Past the limit: the numerical error of `operation` with the
    /// message "more than {limit} {what}".
    pub(crate) fn next(&mut self, operation: &str, what: &str) -> Result<()> {
        self.examined += 1;
        if self.examined > self.limit {
            let limit = self.limit;
            return Err(Error::numerical(operation, format!("more than {limit} {what}")));
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn allows_the_limit_and_fails_one_past_it_with_the_callers_words() {
        let mut count = PairCount::new(2);
        assert!(count.next("intersection", "pairs of pieces").is_ok());
        assert!(count.next("intersection", "pairs of pieces").is_ok());
        assert_eq!(
            count.next("intersection", "pairs of pieces"),
            Err(Error::numerical("intersection", "more than 2 pairs of pieces"))
        );
    }
}
