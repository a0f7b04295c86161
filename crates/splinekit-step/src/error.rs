//! Errors of STEP reading and writing.

use std::fmt;

/// Where in a STEP file something went wrong: the line and, when known, the entity
/// instance (`#id`) being read.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct Location {
    /// 1-based line number (0 when the problem has no place in a file).
    pub line: u32,
    /// The entity instance name `#id`, when the problem lies inside one.
    pub entity: Option<u64>,
}

/// A STEP error: one line that names the place (line number and entity) and the problem.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub struct StepError {
    /// Where the problem is.
    pub location: Location,
    /// What is wrong, with the numbers.
    pub message: String,
}

impl StepError {
    /// An error at `line`, inside entity `entity` if given.
    pub fn at(line: u32, entity: Option<u64>, message: impl Into<String>) -> Self {
        StepError { location: Location { line, entity }, message: message.into() }
    }

    /// An error without a place in a file (e.g. a document that cannot be exported).
    pub fn plain(message: impl Into<String>) -> Self {
        StepError { location: Location::default(), message: message.into() }
    }

    /// The same error, placed at `entity` (and its line) unless it already has a place.
    pub fn within(mut self, line: u32, entity: u64) -> Self {
        if self.location.entity.is_none() {
            self.location = Location { line, entity: Some(entity) };
        }
        self
    }
}

impl fmt::Display for StepError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let Location { line, entity } = self.location;
        match (line, entity) {
            (0, None) => write!(f, "{}", self.message),
            (0, Some(id)) => write!(f, "#{id}: {}", self.message),
            (l, None) => write!(f, "line {l}: {}", self.message),
            (l, Some(id)) => write!(f, "line {l}: #{id}: {}", self.message),
        }
    }
}

impl From<std::io::Error> for StepError {
    fn from(e: std::io::Error) -> Self {
        StepError::plain(format!("cannot read: {e}"))
    }
}

/// Result with [`StepError`].
pub type Result<T> = std::result::Result<T, StepError>;
