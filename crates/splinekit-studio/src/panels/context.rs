//! What a panel reaches of the studio ([`PanelContext`]): the document and the selection to
//! read, the time the scene is posed at, the armed knot tool, the messages, the named
//! widgets of the frame, the command queue, and the two settings panels change in place
//! (the clock, the knot-removal tolerance). Not the document to change (a change is a
//! queued command, so it goes through the history), nor the history, the camera, the drag
//! or the view's caches.

use splinekit_scene::scenes::SceneDocument;

use crate::clock::Clock;
use crate::command::Command;
use crate::knot_edit::KnotTool;
use crate::selection::Selection;
use crate::status::Status;
use crate::studio::Studio;

/// The parts of the studio a panel reaches, borrowed for one frame.
pub struct PanelContext<'a> {
    /// The document's scene, read only.
    pub scene: &'a SceneDocument,
    /// The selection, read only (a click on an object queues its selection).
    pub selection: &'a Selection,
    /// The time the scene is posed at ([`Studio::time`]).
    pub time: Option<f64>,
    /// The armed knot tool (its button is shown selected).
    pub knot_tool: Option<KnotTool>,
    /// How far a knot removal may move the curve.
    pub knot_tolerance: &'a mut f64,
    /// The animation clock (play, speed, time).
    pub clock: &'a mut Clock,
    /// The messages (a choice refused before it becomes an edit leaves one).
    pub status: &'a mut Status,
    /// Named widgets drawn in this frame and their rectangles, for the handle report.
    pub widgets: &'a mut Vec<(String, [f32; 4])>,
    commands: &'a mut Vec<Command>,
}

impl<'a> PanelContext<'a> {
    /// The studio's parts a panel reaches.
    pub fn of(studio: &'a mut Studio) -> Self {
        let time = studio.time();
        PanelContext {
            scene: studio.document.scene(),
            selection: &studio.selection,
            time,
            knot_tool: studio.knot_tool,
            knot_tolerance: &mut studio.knot_tolerance,
            clock: &mut studio.clock,
            status: &mut studio.status,
            widgets: &mut studio.view.widgets,
            commands: &mut studio.commands,
        }
    }

    /// Queues a command, run by [`Studio::run_commands`] after the panels are drawn.
    pub fn queue(&mut self, command: Command) {
        self.commands.push(command);
    }
}
