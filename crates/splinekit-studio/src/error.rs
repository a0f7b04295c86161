//! The studio's one error type: what an action, an edit, a file or the window could not
//! do, kept apart by kind (a document's field, a kernel operation, a file, a refused
//! action, the graphics) while its message stays the one line the status bar shows.

use std::path::{Path, PathBuf};

use splinekit_scene::DocumentError;

use crate::edit::EditError;

/// Why something the user asked for did not happen.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum StudioError {
    /// A document's field, or an edit the document refuses (its path and message).
    #[error("{0}")]
    Document(#[from] DocumentError),
    /// A kernel operation on a shape (its field or operation and message).
    #[error("{0}")]
    Kernel(#[from] splinekit::Error),
    /// An edit the document's history refuses (the document is unchanged).
    #[error("{0}")]
    Edit(#[from] EditError),
    /// A file that cannot be read or written.
    #[error("{}: {message}", path.display())]
    File {
        /// The file.
        path: PathBuf,
        /// What went wrong (`cannot read: …`).
        message: String,
    },
    /// An output file named by an option (`--screenshot`) that cannot be written.
    #[error("{option}: cannot write {}: {message}", path.display())]
    Output {
        /// The option.
        option: &'static str,
        /// The file.
        path: PathBuf,
        /// Why.
        message: String,
    },
    /// An action the selection, the tool or the click does not allow; the message says
    /// what to do instead (`select a blending-spline curve first`).
    #[error("{0}")]
    Refused(String),
    /// The window, the graphics adapter or a picture that could not be made.
    #[error("{0}")]
    Graphics(String),
    /// A shape a file format cannot hold (a number out of its range), or a failed write
    /// of the bytes.
    #[error("{0}")]
    Export(String),
    /// An action (`split knot`, `insert local piece`, `export`) that failed, and why.
    #[error("{action}: {source}")]
    Action {
        /// The action, as the status line names it.
        action: &'static str,
        /// Why it failed.
        source: Box<StudioError>,
    },
}

impl StudioError {
    /// A refusal with `message`.
    pub fn refused(message: impl Into<String>) -> Self {
        StudioError::Refused(message.into())
    }

    /// A file error of `path`.
    pub fn file(path: &Path, message: impl Into<String>) -> Self {
        StudioError::File { path: path.to_path_buf(), message: message.into() }
    }

    /// The same error as the failure of `action`.
    pub fn of_action(self, action: &'static str) -> Self {
        StudioError::Action { action, source: Box::new(self) }
    }
}

impl From<&str> for StudioError {
    /// A refusal.
    fn from(message: &str) -> Self {
        StudioError::refused(message)
    }
}

/// `Result` with [`StudioError`].
pub type Result<T> = std::result::Result<T, StudioError>;
