//! Commands: what the menus, the keys and the panels ask of the studio. Panels never edit
//! the document themselves; they queue commands ([`crate::studio::Studio::queue`]) that
//! the window runs after the panels are drawn ([`crate::studio::Studio::run_commands`]),
//! so that every change goes through one place (the history) whatever asked for it.

use crate::actions::Action;
use crate::edit::Edit;

/// A command of the window.
#[derive(Debug, Clone, PartialEq)]
pub enum Command {
    /// An action of the registry ([`crate::actions::ACTIONS`]).
    Action(Action),
    /// Open the document at this path.
    Open(String),
    /// Export the selected object to this mesh file (format by extension).
    Export(String),
    /// An edit of the document, asked for by a panel.
    Edit(FieldEdit),
    /// Select an object (or none), clearing the selected handles.
    SelectObject(Option<usize>),
}

/// An edit asked for by a panel: the field whose widget asked (its refusal message is
/// shown under that widget), and the object to select once the edit is done (a duplicate,
/// an added object; `Some(None)`: select nothing, after a deletion).
#[derive(Debug, Clone, PartialEq)]
pub struct FieldEdit {
    /// The edit.
    pub edit: Edit,
    /// The JSON pointer of the field that asked, for its message on refusal.
    pub field: Option<String>,
    /// The object selected after the edit is done.
    pub select: Option<Option<usize>>,
}

impl FieldEdit {
    /// An edit asked for by the widget of `field`.
    pub fn of_field(edit: Edit, field: &str) -> Self {
        FieldEdit { edit, field: Some(field.to_string()), select: None }
    }

    /// An edit that selects `select` once done.
    pub fn selecting(edit: Edit, select: Option<usize>) -> Self {
        FieldEdit { edit, field: None, select: Some(select) }
    }
}
