//! Keyboard shortcuts of the window (the 3-D view's drag modifiers X/Y/Z/R/S are read by
//! [`crate::viewport`]). Shortcuts are ignored while a text field has the keyboard, and are
//! matched on each key event's own modifiers (a quick Ctrl+S may be released before the
//! frame that reads it).

use egui::{Key, KeyboardShortcut, Modifiers};

use crate::panels::MenuAction;
use crate::view_camera::StandardView;

/// A command of the window.
#[derive(Debug, Clone, PartialEq)]
pub enum Command {
    /// A menu action (also reached by its shortcut).
    Menu(MenuAction),
    /// Play or pause the animation (Space).
    TogglePlay,
    /// Close (Ctrl+Q, Escape, or the window's close button).
    Quit,
}

/// The shortcuts, the more specific first (Ctrl+Shift+Z before Ctrl+Z).
fn table() -> [(Modifiers, Key, Command); 12] {
    let ctrl = Modifiers::COMMAND;
    let none = Modifiers::NONE;
    [
        (ctrl | Modifiers::SHIFT, Key::Z, Command::Menu(MenuAction::Redo)),
        (ctrl, Key::Z, Command::Menu(MenuAction::Undo)),
        (ctrl, Key::S, Command::Menu(MenuAction::Save)),
        (ctrl, Key::Q, Command::Quit),
        (none, Key::Escape, Command::Quit),
        (none, Key::F12, Command::Menu(MenuAction::Screenshot)),
        (none, Key::F, Command::Menu(MenuAction::Frame)),
        (none, Key::Home, Command::Menu(MenuAction::Home)),
        (none, Key::Num7, Command::Menu(MenuAction::Look(StandardView::Top))),
        (none, Key::Num1, Command::Menu(MenuAction::Look(StandardView::Front))),
        (none, Key::Num3, Command::Menu(MenuAction::Look(StandardView::Side))),
        (none, Key::Space, Command::TogglePlay),
    ]
}

/// The commands of the keys pressed since the last frame (each key press consumed).
pub fn shortcuts(ctx: &egui::Context) -> Vec<Command> {
    if ctx.egui_wants_keyboard_input() {
        return Vec::new();
    }
    ctx.input_mut(|i| {
        table()
            .into_iter()
            .filter(|(m, k, _)| i.consume_shortcut(&KeyboardShortcut::new(*m, *k)))
            .map(|(_, _, c)| c)
            .collect()
    })
}
