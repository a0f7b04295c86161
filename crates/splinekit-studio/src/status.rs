//! What the studio tells the user: the status line's last message, a document that failed
//! to open, and the field whose last change was refused.

use crate::error::StudioError;

/// The studio's messages.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Status {
    /// The last message for the status line (an edit refused, a file saved, …).
    pub message: Option<String>,
    /// A document that failed to open: its error, shown instead of the view.
    pub load_error: Option<String>,
    /// The field (JSON pointer) whose last change was refused, and the message.
    pub field_error: Option<(String, String)>,
}

impl Status {
    /// The value of `result`; its error instead becomes the status line's message (`None`).
    pub fn said<T>(&mut self, result: Result<T, StudioError>) -> Option<T> {
        result.map_err(|e| self.say(&e)).ok()
    }

    /// Shows why something did not happen on the status line.
    pub fn say(&mut self, e: &StudioError) {
        self.message = Some(e.to_string());
    }
}
