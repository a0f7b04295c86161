//! Undo and redo: the edits done (each with its inverse) and the edits undone. A drag
//! makes many edits of one value; [`History::apply`] with `merge` keeps them as one step.

use splinekit_scene::scenes::SceneDocument;

use crate::edit::{BuildCheck, Edit, EditError};

/// One step: the edit as done and the edit that undoes it.
#[derive(Debug, Clone)]
struct Step {
    done: Edit,
    undo: Edit,
}

/// The undo and redo stacks of a document.
#[derive(Debug, Clone, Default)]
pub struct History {
    done: Vec<Step>,
    undone: Vec<Step>,
    /// Whether the next edit of the same value continues the last step (during a drag).
    open: bool,
}

impl History {
    /// Applies `edit`; with `merge`, an edit of the same value as the last step joins it
    /// (its undo still restores the value from before the first). Clears the redo stack.
    pub fn apply(&mut self, scene: &mut SceneDocument, edit: Edit, merge: bool) -> Result<(), EditError> {
        self.apply_with(scene, edit, merge, &mut |_, shape| crate::edit::check_builds(shape))
    }

    /// [`Self::apply`] with the edited shape built by `check` ([`Edit::apply_with`]).
    pub fn apply_with(
        &mut self,
        scene: &mut SceneDocument,
        edit: Edit,
        merge: bool,
        check: &mut BuildCheck<'_>,
    ) -> Result<(), EditError> {
        let undo = edit.apply_with(scene, check)?;
        self.undone.clear();
        match self.done.last_mut() {
            Some(last) if merge && self.open && last.done.same_target(&edit) => last.done = edit,
            _ => self.done.push(Step { done: edit, undo }),
        }
        self.open = merge;
        Ok(())
    }

    /// Ends a run of merged edits (the mouse button went up).
    pub fn close(&mut self) {
        self.open = false;
    }

    /// Undoes the last step; `false` when there is none.
    pub fn undo(&mut self, scene: &mut SceneDocument) -> Result<bool, EditError> {
        self.open = false;
        replay(scene, &mut self.done, &mut self.undone, |step| &step.undo)
    }

    /// Redoes the last undone step; `false` when there is none.
    pub fn redo(&mut self, scene: &mut SceneDocument) -> Result<bool, EditError> {
        self.open = false;
        replay(scene, &mut self.undone, &mut self.done, |step| &step.done)
    }

    /// Whether there is something to undo.
    pub fn can_undo(&self) -> bool {
        !self.done.is_empty()
    }

    /// Whether there is something to redo.
    pub fn can_redo(&self) -> bool {
        !self.undone.is_empty()
    }
}

/// Undo and redo alike: applies `edit` of the last step of `from` (its undo, or its edit as
/// done) and moves the step to `to`; a step whose edit fails stays on `from`. `false` when
/// `from` is empty.
fn replay(
    scene: &mut SceneDocument,
    from: &mut Vec<Step>,
    to: &mut Vec<Step>,
    edit: fn(&Step) -> &Edit,
) -> Result<bool, EditError> {
    let Some(step) = from.pop() else { return Ok(false) };
    match edit(&step).apply(scene) {
        Ok(_) => {
            to.push(step);
            Ok(true)
        }
        Err(e) => {
            from.push(step);
            Err(e)
        }
    }
}
