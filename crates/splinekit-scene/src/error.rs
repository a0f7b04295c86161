//! Errors of shape documents: a path to the offending field and a message with the numbers.

use std::fmt;

/// A problem with a shape document, located by a field path such as
/// `control_points[2][1]` or `first.knots`.
#[derive(Debug, Clone, PartialEq)]
pub struct DocumentError {
    /// Path of the offending field (empty for the document as a whole).
    pub path: String,
    /// What is wrong.
    pub message: String,
}

impl DocumentError {
    /// An error at `path`.
    pub fn new(path: impl Into<String>, message: impl Into<String>) -> Self {
        DocumentError { path: path.into(), message: message.into() }
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
    /// Kernel errors already start with their field name.
    fn from(e: splinekit::Error) -> Self {
        DocumentError { path: String::new(), message: e.to_string() }
    }
}

/// `Result` with [`DocumentError`].
pub type Result<T> = std::result::Result<T, DocumentError>;
