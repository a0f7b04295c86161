//! Errors of shape documents: a path to the offending field and a message with the numbers.

use std::fmt;

/// What kind of problem an error is, for front ends that keep them apart (Python's
/// `DocumentError`, `NumericalError`, `BudgetError`, `FileError`); the message is the
/// same whatever the kind.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum ErrorKind {
    /// A bad document or argument: a missing or malformed field, a value out of range.
    #[default]
    Document,
    /// A computation that did not converge or gave no finite value
    /// ([`splinekit::Error::Numerical`]).
    Numerical,
    /// A request over the memory or work budget ([`crate::budget`]).
    Budget,
    /// A file that could not be read or written.
    File,
}

impl ErrorKind {
    /// The kind of a kernel error: numerical failures, else a bad argument.
    pub fn of_kernel(e: &splinekit::Error) -> ErrorKind {
        match e {
            splinekit::Error::Numerical { .. } => ErrorKind::Numerical,
            _ => ErrorKind::Document,
        }
    }
}

/// A problem with a shape document, located by a field path such as
/// `control_points[2][1]` or `first.knots`.
#[derive(Debug, Clone, PartialEq)]
pub struct DocumentError {
    /// Path of the offending field (empty for the document as a whole).
    pub path: String,
    /// What is wrong.
    pub message: String,
    /// What kind of problem it is ([`ErrorKind::Document`] unless made otherwise).
    pub kind: ErrorKind,
}

impl DocumentError {
    /// An error at `path`.
    pub fn new(path: impl Into<String>, message: impl Into<String>) -> Self {
        DocumentError { path: path.into(), message: message.into(), kind: ErrorKind::Document }
    }

    /// A request at `path` over the budget.
    pub fn budget(path: impl Into<String>, message: impl Into<String>) -> Self {
        DocumentError::new(path, message).of_kind(ErrorKind::Budget)
    }

    /// The same error, of `kind`.
    pub fn of_kind(mut self, kind: ErrorKind) -> Self {
        self.kind = kind;
        self
    }

    /// The error whole, as said about `name` (`A` and `knots: …` make `A: knots: …`),
    /// keeping its kind.
    pub fn about(self, name: &str) -> Self {
        DocumentError { path: name.to_string(), message: self.to_string(), kind: self.kind }
    }

    /// The same error seen from a parent document field `prefix` (`first` and
    /// `knots` make `first.knots`; `holes` and `[2].type` make `holes[2].type`).
    pub fn within(mut self, prefix: &str) -> Self {
        if !prefix.is_empty() {
            self.path = match self.path.as_str() {
                "" => prefix.to_string(),
                index if index.starts_with('[') => format!("{prefix}{index}"),
                field => format!("{prefix}.{field}"),
            };
        }
        self
    }
}

impl fmt::Display for DocumentError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if self.path.is_empty() { write!(f, "{}", self.message) } else { write!(f, "{}: {}", self.path, self.message) }
    }
}

impl std::error::Error for DocumentError {}

impl From<splinekit::Error> for DocumentError {
    /// Kernel errors already start with their field name; numerical failures keep their
    /// kind.
    fn from(e: splinekit::Error) -> Self {
        DocumentError { path: String::new(), message: e.to_string(), kind: ErrorKind::of_kernel(&e) }
    }
}

/// `Result` with [`DocumentError`].
pub type Result<T> = std::result::Result<T, DocumentError>;
