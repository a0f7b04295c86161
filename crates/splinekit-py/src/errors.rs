//! Errors across the boundary: every kernel or document error becomes a `ValueError`
//! whose message is the one line the command line prints after `error: `.

use std::fmt::Display;

use pyo3::PyErr;
use pyo3::exceptions::PyValueError;

/// A `ValueError` with the error's one-line message (field, then what is wrong with the
/// numbers).
pub fn value_error(e: impl Display) -> PyErr {
    PyValueError::new_err(e.to_string())
}

/// `Result<T, E>` → `PyResult<T>` with [`value_error`].
pub trait OrValueError<T> {
    /// The value, or a `ValueError` with the error's message.
    fn or_value_error(self) -> pyo3::PyResult<T>;
}

impl<T, E: Display> OrValueError<T> for Result<T, E> {
    fn or_value_error(self) -> pyo3::PyResult<T> {
        self.map_err(value_error)
    }
}
