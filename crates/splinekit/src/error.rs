//! The one error type of the kernel.
//!
//! Every constructor and fallible operation returns [`Result<T>`]. Messages name the
//! offending field and the numbers involved, so that a command-line front end can print
//! them unchanged (`knots: expected 12 values for 8 control points of degree 3, got 11`).

use thiserror::Error;

/// Errors raised by splinekit constructors and operations.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum Error {
    /// A field has the wrong number of entries.
    #[error("{field}: expected {expected}, got {got}")]
    Count {
        /// The field, as named in shape documents (`knots`, `weights`, ...).
        field: String,
        /// What was expected, in words with the numbers (`12 values for 8 control points of degree 3`).
        expected: String,
        /// How many there were.
        got: usize,
    },
    /// A value is NaN or infinite.
    #[error("{field}: value {index} is not finite ({value})")]
    NotFinite {
        /// The field.
        field: String,
        /// Position of the value (flattened for nested arrays).
        index: usize,
        /// The value.
        value: f64,
    },
    /// A value or combination of values is out of the allowed range.
    #[error("{field}: {message}")]
    Invalid {
        /// The field.
        field: String,
        /// What is wrong, with the numbers.
        message: String,
    },
    /// A numerical procedure could not produce a trustworthy answer.
    #[error("{operation}: {message}")]
    Numerical {
        /// The operation (`fit`, `knot removal`, ...).
        operation: String,
        /// What failed, with the numbers.
        message: String,
    },
}

impl Error {
    /// Shorthand for [`Error::Invalid`].
    pub fn invalid(field: impl Into<String>, message: impl Into<String>) -> Self {
        Error::Invalid { field: field.into(), message: message.into() }
    }

    /// Shorthand for [`Error::Count`].
    pub fn count(field: impl Into<String>, expected: impl Into<String>, got: usize) -> Self {
        Error::Count { field: field.into(), expected: expected.into(), got }
    }

    /// Shorthand for [`Error::Numerical`].
    pub fn numerical(operation: impl Into<String>, message: impl Into<String>) -> Self {
        Error::Numerical { operation: operation.into(), message: message.into() }
    }
}

/// `Result` with the kernel's [`Error`](enum@Error).
pub type Result<T> = std::result::Result<T, Error>;

/// Checks that every value is finite; names the field and the first bad index.
pub fn check_finite<'a>(field: &str, values: impl IntoIterator<Item = &'a f64>) -> Result<()> {
    for (index, &value) in values.into_iter().enumerate() {
        if !value.is_finite() {
            return Err(Error::NotFinite { field: field.to_string(), index, value });
        }
    }
    Ok(())
}

/// Checks that the field `degree` is at least 1: the fits, the interpolation and
/// Lane–Riesenfeld subdivision have no meaning for degree 0.
pub(crate) fn check_degree(degree: usize) -> Result<()> {
    if degree == 0 { Err(Error::invalid("degree", "must be at least 1")) } else { Ok(()) }
}

/// Checks that every coordinate of every point is finite.
pub fn check_points_finite<const D: usize>(field: &str, points: &[crate::Point<D>]) -> Result<()> {
    for (i, p) in points.iter().enumerate() {
        for (j, &value) in p.iter().enumerate() {
            if !value.is_finite() {
                return Err(Error::invalid(
                    format!("{field}[{i}][{j}]"),
                    format!("coordinate is not finite ({value})"),
                ));
            }
        }
    }
    Ok(())
}
