//! Errors across the boundary: every error becomes an exception under
//! `splinekit.SplinekitError` whose message is the one line the command line prints after
//! `error: ` (the field, then what is wrong with the numbers). The classes are defined in
//! Python (`splinekit/_errors.py`, so that they can subclass two built-in exceptions at
//! once) and raised from here by the kind of the error:
//!
//! | class | raised for | also a |
//! | --- | --- | --- |
//! | `DocumentError` | a bad document or argument (the kernel's `Count`, `NotFinite`, `Invalid`; a document's fields; a malformed STEP file) | `ValueError` |
//! | `NumericalError` | a computation that did not converge or has no finite value (the kernel's `Numerical`; a result a file format cannot hold) | `ValueError` |
//! | `BudgetError` | a request over the memory or work budget | `ValueError` |
//! | `FileError` | a file that cannot be read or written | `OSError`, `ValueError` |
//! | `RenderError` | no renderer in the build, or no graphics adapter | `RuntimeError` |
//!
//! Each subclasses what was raised for it before the classes existed, so `except
//! ValueError` keeps catching what it caught.

use std::fmt::Display;

use pyo3::PyErr;
use splinekit_mesh::export::ExportError;
use splinekit_scene::ErrorKind;

pyo3::import_exception!(splinekit._errors, DocumentError);
pyo3::import_exception!(splinekit._errors, NumericalError);
pyo3::import_exception!(splinekit._errors, BudgetError);
pyo3::import_exception!(splinekit._errors, FileError);
pyo3::import_exception!(splinekit._errors, RenderError);

/// An error of a kind with its one-line message: what every Rust error becomes before it
/// is raised.
#[derive(Debug, Clone, PartialEq)]
pub struct Failure {
    /// Which exception class it is raised as.
    pub kind: ErrorKind,
    /// The line.
    pub message: String,
}

impl Failure {
    /// The same failure as said about `name` (`point_sets[3]: …`).
    pub fn about(self, name: &str) -> Self {
        Failure { message: format!("{name}: {}", self.message), ..self }
    }

    /// The exception.
    pub fn into_py(self) -> PyErr {
        match self.kind {
            ErrorKind::Document => DocumentError::new_err(self.message),
            ErrorKind::Numerical => NumericalError::new_err(self.message),
            ErrorKind::Budget => BudgetError::new_err(self.message),
            ErrorKind::File => FileError::new_err(self.message),
        }
    }
}

impl From<splinekit_scene::DocumentError> for Failure {
    fn from(e: splinekit_scene::DocumentError) -> Self {
        Failure { kind: e.kind, message: e.to_string() }
    }
}

impl From<splinekit::Error> for Failure {
    fn from(e: splinekit::Error) -> Self {
        Failure { kind: ErrorKind::of_kernel(&e), message: e.to_string() }
    }
}

impl From<ExportError> for Failure {
    /// A value a format cannot hold (a non-finite or too large number) is numerical; a
    /// failed write is a file error.
    fn from(e: ExportError) -> Self {
        let kind = match e {
            ExportError::Unrepresentable { .. } => ErrorKind::Numerical,
            ExportError::Io(_) => ErrorKind::File,
        };
        Failure { kind, message: e.to_string() }
    }
}

impl From<splinekit_step::StepError> for Failure {
    fn from(e: splinekit_step::StepError) -> Self {
        Failure { kind: ErrorKind::Document, message: e.to_string() }
    }
}

impl From<String> for Failure {
    /// A message made here: about an argument.
    fn from(message: String) -> Self {
        Failure { kind: ErrorKind::Document, message }
    }
}

impl From<&str> for Failure {
    fn from(message: &str) -> Self {
        Failure::from(message.to_string())
    }
}

/// A `DocumentError` (a `ValueError`) with the message: a bad document or argument.
pub fn value_error(e: impl Display) -> PyErr {
    DocumentError::new_err(e.to_string())
}

/// The exception of a document error, by its kind.
pub fn document_error(e: splinekit_scene::DocumentError) -> PyErr {
    Failure::from(e).into_py()
}

/// A `FileError` (an `OSError` and a `ValueError`) with the message.
pub fn file_error(e: impl Display) -> PyErr {
    FileError::new_err(e.to_string())
}

/// A `RenderError` (a `RuntimeError`) with the message.
pub fn render_error(e: impl Display) -> PyErr {
    RenderError::new_err(e.to_string())
}

/// `Result<T, E>` → `PyResult<T>`, raising the exception of the error's kind.
pub trait OrValueError<T> {
    /// The value, or the exception of the error's kind with its message.
    fn or_value_error(self) -> pyo3::PyResult<T>;
}

impl<T, E: Into<Failure>> OrValueError<T> for Result<T, E> {
    fn or_value_error(self) -> pyo3::PyResult<T> {
        self.map_err(|e| e.into().into_py())
    }
}
