//! The one registry of the studio's actions: each action's label, keyboard shortcuts, menu,
//! whether the Properties panel offers it as a button, and whether it changes the document
//! (undoable). The menus ([`crate::panels::menu_bar`]), the key bindings ([`pressed`]) and
//! the help overlay (`?`, [`crate::panels::help_overlay`]) are all drawn from [`ACTIONS`],
//! so a label or a shortcut is written once. What an action does is
//! [`crate::studio::Studio::run_action`] (or the window's, for the few that need it:
//! screenshots, closing, overlays).
//!
//! Shortcuts are ignored while a text field has the keyboard and are matched on each key
//! event's own modifiers (a quick Ctrl+S may be released before the frame that reads it),
//! the more specific first (Ctrl+Shift+Z before Ctrl+Z). The 3-D view's held keys (X/Y/Z
//! along an axis, R rotate, S scale, W weight) are read by [`crate::viewport`] while a
//! drag starts; they are listed in the help overlay from [`HELD_KEYS`].

use egui::{Key, KeyboardShortcut, Modifiers};

/// An action of the studio, without data (those with data, such as opening a path, are
/// [`crate::command::Command`]s of their own).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Action {
    /// Save the document (with the view's camera).
    Save,
    /// Save a screenshot of the 3-D view.
    Screenshot,
    /// Close the window.
    Quit,
    /// Undo the last edit.
    Undo,
    /// Redo the last undone edit.
    Redo,
    /// Look from the top (+z).
    LookTop,
    /// Look from the front (−y).
    LookFront,
    /// Look from the side (+x).
    LookSide,
    /// Back to the first camera.
    Home,
    /// Frame the selection (else the scene).
    Frame,
    /// Play or pause the animation.
    TogglePlay,
    /// Show or hide the frame-time overlay.
    FrameTimes,
    /// Show or hide the list of actions and keys.
    Help,
    /// Give the selected blending spline's local pieces a beat.
    AddBeat,
    /// Clear the selection.
    ClearSelection,
    /// Select every shown handle of the selected object.
    SelectAll,
    /// Move the selection along world axis `.0` by `.1` snapping steps.
    Nudge(usize, i32),
    /// The next click on the selected curve inserts a knot there; on a spline surface a
    /// u-knot (Shift + click: a v-knot) there.
    InsertKnot,
    /// The next click on the selected curve removes the knot nearest it (within the
    /// tolerance).
    RemoveKnot,
    /// Raise the selected curve's degree by one.
    ElevateDegree,
    /// The next click on the selected blending spline inserts a local curve there; on a
    /// blending surface a row of local patches along the u-isocurve (Shift + click: a
    /// column along the v-isocurve).
    InsertLocal,
    /// Split a knot of the selected blending-spline curve: that of the selected local
    /// curve at once, else the next click splits the knot nearest it.
    SplitKnot,
    /// Show or hide the curvature comb of the curves.
    ToggleComb,
    /// Show or hide the continuity at knots and junctions.
    ToggleContinuity,
}

/// The menus of the menu bar.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Menu {
    /// File: open, export, save, screenshot, quit.
    File,
    /// Edit: undo, redo and the edits of the selection.
    Edit,
    /// View: cameras, overlays, help.
    View,
}

/// What the registry knows about an action.
#[derive(Debug, Clone, Copy)]
pub struct ActionSpec {
    /// The action.
    pub action: Action,
    /// Its label in menus, buttons and the help overlay.
    pub label: &'static str,
    /// One line for the help overlay and hover texts.
    pub help: &'static str,
    /// Its keyboard shortcuts (the first is shown in menus).
    pub keys: &'static [(Modifiers, Key)],
    /// The menu it sits in, if any.
    pub menu: Option<Menu>,
    /// Whether the Properties panel offers it as a button.
    pub panel: bool,
    /// Whether it changes the document (one undo step).
    pub undoable: bool,
}

const NONE: Modifiers = Modifiers::NONE;
const CTRL: Modifiers = Modifiers::COMMAND;
const CTRL_SHIFT: Modifiers = Modifiers { shift: true, ..Modifiers::COMMAND };
const SHIFT: Modifiers = Modifiers::SHIFT;
const ALT: Modifiers = Modifiers::ALT;

/// A nudge of the selection by the snapping step (undoable, in no menu).
const fn nudge(action: Action, label: &'static str, keys: &'static [(Modifiers, Key)]) -> ActionSpec {
    ActionSpec {
        action,
        label,
        help: "move the selection by the snapping step (Shift: ten steps)",
        keys,
        menu: None,
        panel: false,
        undoable: true,
    }
}

/// Every action of the studio, in menu order.
pub const ACTIONS: &[ActionSpec] = &[
    ActionSpec {
        action: Action::Save,
        label: "Save",
        help: "write the document (with the view's camera) to the file it came from",
        keys: &[(CTRL, Key::S)],
        menu: Some(Menu::File),
        panel: false,
        undoable: false,
    },
    ActionSpec {
        action: Action::Screenshot,
        label: "Screenshot",
        help: "save the 3-D view as PNG",
        keys: &[(NONE, Key::F12)],
        menu: Some(Menu::File),
        panel: false,
        undoable: false,
    },
    ActionSpec {
        action: Action::Quit,
        label: "Quit",
        help: "close the window",
        keys: &[(CTRL, Key::Q)],
        menu: Some(Menu::File),
        panel: false,
        undoable: false,
    },
    ActionSpec {
        action: Action::Redo,
        label: "Redo",
        help: "redo the last undone edit",
        keys: &[(CTRL_SHIFT, Key::Z), (CTRL, Key::Y)],
        menu: Some(Menu::Edit),
        panel: false,
        undoable: false,
    },
    ActionSpec {
        action: Action::Undo,
        label: "Undo",
        help: "undo the last edit (a drag is one)",
        keys: &[(CTRL, Key::Z)],
        menu: Some(Menu::Edit),
        panel: false,
        undoable: false,
    },
    ActionSpec {
        action: Action::AddBeat,
        label: "Add a beat",
        help: "the selected blending spline's local pieces oscillate about its centre",
        keys: &[],
        menu: Some(Menu::Edit),
        panel: false,
        undoable: true,
    },
    ActionSpec {
        action: Action::ClearSelection,
        label: "Select none",
        help: "clear the selection",
        keys: &[(NONE, Key::Escape)],
        menu: Some(Menu::Edit),
        panel: false,
        undoable: false,
    },
    ActionSpec {
        action: Action::SelectAll,
        label: "Select all",
        help: "select every handle of the selected object",
        keys: &[(NONE, Key::A)],
        menu: Some(Menu::Edit),
        panel: false,
        undoable: false,
    },
    ActionSpec {
        action: Action::InsertKnot,
        label: "Insert knot",
        help: "click on the selected B-spline, NURBS or Bézier curve: a knot there; on such a surface: a u-knot \
               (Shift + click: a v-knot) along the isocurve through the click (the shape does not change)",
        keys: &[(NONE, Key::K)],
        menu: Some(Menu::Edit),
        panel: true,
        undoable: true,
    },
    ActionSpec {
        action: Action::RemoveKnot,
        label: "Remove knot",
        help: "click on the selected curve: its knot nearest there goes, if the curve moves by at most the tolerance",
        keys: &[(ALT, Key::K)],
        menu: Some(Menu::Edit),
        panel: true,
        undoable: true,
    },
    ActionSpec {
        action: Action::ElevateDegree,
        label: "Elevate degree",
        help: "raise the selected curve's degree by one (the curve does not change)",
        keys: &[(NONE, Key::E)],
        menu: Some(Menu::Edit),
        panel: true,
        undoable: true,
    },
    ActionSpec {
        action: Action::InsertLocal,
        label: "Insert local piece",
        help: "click on the selected blending spline: a local curve at that parameter; on a blending surface: a row \
               of local patches along the u-isocurve through the click (Shift + click: along v), each fitted to the \
               shape there (its Taylor polynomial), so the shape changes only between the neighbouring knots and little",
        keys: &[(NONE, Key::L)],
        menu: Some(Menu::Edit),
        panel: true,
        undoable: true,
    },
    ActionSpec {
        action: Action::SplitKnot,
        label: "Split knot",
        help: "double a knot of the selected blending-spline curve (that of the selected local curve, else the one \
               nearest the next click) and copy its local: the curve does not change, and each copy, dragged, turns \
               and scales about the joint (a corner that stays continuous)",
        keys: &[(NONE, Key::D)],
        menu: Some(Menu::Edit),
        panel: true,
        undoable: true,
    },
    nudge(Action::Nudge(0, -1), "Nudge −x", &[(NONE, Key::ArrowLeft)]),
    nudge(Action::Nudge(0, 1), "Nudge +x", &[(NONE, Key::ArrowRight)]),
    nudge(Action::Nudge(1, 1), "Nudge +y", &[(NONE, Key::ArrowUp)]),
    nudge(Action::Nudge(1, -1), "Nudge −y", &[(NONE, Key::ArrowDown)]),
    nudge(Action::Nudge(2, 1), "Nudge +z", &[(NONE, Key::PageUp)]),
    nudge(Action::Nudge(2, -1), "Nudge −z", &[(NONE, Key::PageDown)]),
    nudge(Action::Nudge(0, -10), "Nudge −x ×10", &[(SHIFT, Key::ArrowLeft)]),
    nudge(Action::Nudge(0, 10), "Nudge +x ×10", &[(SHIFT, Key::ArrowRight)]),
    nudge(Action::Nudge(1, 10), "Nudge +y ×10", &[(SHIFT, Key::ArrowUp)]),
    nudge(Action::Nudge(1, -10), "Nudge −y ×10", &[(SHIFT, Key::ArrowDown)]),
    nudge(Action::Nudge(2, 10), "Nudge +z ×10", &[(SHIFT, Key::PageUp)]),
    nudge(Action::Nudge(2, -10), "Nudge −z ×10", &[(SHIFT, Key::PageDown)]),
    ActionSpec {
        action: Action::LookTop,
        label: "Top",
        help: "look from above (+z)",
        keys: &[(NONE, Key::Num7)],
        menu: Some(Menu::View),
        panel: false,
        undoable: false,
    },
    ActionSpec {
        action: Action::LookFront,
        label: "Front",
        help: "look from the front (−y)",
        keys: &[(NONE, Key::Num1)],
        menu: Some(Menu::View),
        panel: false,
        undoable: false,
    },
    ActionSpec {
        action: Action::LookSide,
        label: "Side",
        help: "look from the side (+x)",
        keys: &[(NONE, Key::Num3)],
        menu: Some(Menu::View),
        panel: false,
        undoable: false,
    },
    ActionSpec {
        action: Action::Home,
        label: "Home",
        help: "back to the first camera",
        keys: &[(NONE, Key::Home)],
        menu: Some(Menu::View),
        panel: false,
        undoable: false,
    },
    ActionSpec {
        action: Action::Frame,
        label: "Frame selection",
        help: "fit the view to the selection (else the scene)",
        keys: &[(NONE, Key::F)],
        menu: Some(Menu::View),
        panel: false,
        undoable: false,
    },
    ActionSpec {
        action: Action::TogglePlay,
        label: "Play / pause",
        help: "play or pause the animation",
        keys: &[(NONE, Key::Space)],
        menu: Some(Menu::View),
        panel: false,
        undoable: false,
    },
    ActionSpec {
        action: Action::ToggleComb,
        label: "Curvature comb",
        help: "show or hide the curvature comb of every curve (its scale in the Analysis panel)",
        keys: &[(NONE, Key::C)],
        menu: Some(Menu::View),
        panel: false,
        undoable: false,
    },
    ActionSpec {
        action: Action::ToggleContinuity,
        label: "Continuity",
        help: "mark G0/G1/G2 at the knots and junctions of curves (numbers in the Analysis panel)",
        keys: &[(NONE, Key::G)],
        menu: Some(Menu::View),
        panel: false,
        undoable: false,
    },
    ActionSpec {
        action: Action::FrameTimes,
        label: "Frame times",
        help: "show or hide the frame-time overlay",
        keys: &[],
        menu: Some(Menu::View),
        panel: false,
        undoable: false,
    },
    ActionSpec {
        action: Action::Help,
        label: "Keys and actions",
        help: "show or hide this list",
        keys: &[(NONE, Key::Questionmark), (NONE, Key::F1)],
        menu: Some(Menu::View),
        panel: false,
        undoable: false,
    },
];

/// Keys held while a drag starts in the 3-D view (read by [`crate::viewport`]), for the
/// help overlay.
pub const HELD_KEYS: &[(&str, &str)] = &[
    ("click a handle", "select it (Shift + click: add it or take it out)"),
    ("Ctrl + drag on empty space", "select the handles in a box (Ctrl + Shift: add them)"),
    ("drag a handle", "move it in the view plane (a handle of the selection: all of it)"),
    ("X / Y / Z + drag", "move along that axis"),
    ("R + drag", "rotate a local piece about its origin (a selection about its centroid)"),
    ("S + drag", "scale a local piece about its origin (a selection about its centroid)"),
    ("W + drag up / down", "raise / lower the weight of a NURBS control point"),
    ("drag on empty space", "orbit"),
    ("Shift + drag, middle drag", "pan"),
    ("wheel", "zoom"),
];

/// The registry's entry of `action`.
pub fn spec(action: Action) -> &'static ActionSpec {
    ACTIONS.iter().find(|s| s.action == action).expect("every action is in the registry")
}

/// A shortcut as shown to the user (`Ctrl+Shift+Z`).
pub fn key_text(modifiers: Modifiers, key: Key) -> String {
    KeyboardShortcut::new(modifiers, key).format(&egui::ModifierNames::NAMES, false)
}

/// The label of `action` with its first shortcut (`Undo  Ctrl+Z`), as menus show it.
pub fn menu_label(action: Action) -> String {
    let s = spec(action);
    match s.keys.first() {
        Some(&(m, k)) => format!("{}  {}", s.label, key_text(m, k)),
        None => s.label.to_string(),
    }
}

/// The bindings, the more specific first: more modifiers before fewer, so that a press
/// matching several (egui ignores an extra Shift) goes to the one asked for.
fn bindings() -> Vec<(Modifiers, Key, Action)> {
    let mut all: Vec<(Modifiers, Key, Action)> =
        ACTIONS.iter().flat_map(|s| s.keys.iter().map(move |&(m, k)| (m, k, s.action))).collect();
    let weight = |m: &Modifiers| usize::from(m.shift) + usize::from(m.alt) + usize::from(m.command || m.ctrl);
    all.sort_by_key(|(m, _, _)| std::cmp::Reverse(weight(m)));
    all
}

/// The actions whose shortcuts were pressed since the last frame (each key press consumed);
/// none while a text field has the keyboard.
pub fn pressed(ctx: &egui::Context) -> Vec<Action> {
    if ctx.egui_wants_keyboard_input() {
        return Vec::new();
    }
    ctx.input_mut(|i| {
        bindings()
            .into_iter()
            .filter(|(m, k, _)| i.consume_shortcut(&KeyboardShortcut::new(*m, *k)))
            .map(|(_, _, a)| a)
            .collect()
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn no_shortcut_is_bound_twice_and_every_action_is_listed_once() {
        let all = bindings();
        for (i, a) in all.iter().enumerate() {
            for b in &all[i + 1..] {
                assert!(!(a.0 == b.0 && a.1 == b.1), "{:?} and {:?} share {}", a.2, b.2, key_text(a.0, a.1));
            }
        }
        for (i, s) in ACTIONS.iter().enumerate() {
            assert!(!s.label.is_empty() && !s.help.is_empty(), "{:?}", s.action);
            assert!(ACTIONS[i + 1..].iter().all(|t| t.action != s.action), "{:?} twice", s.action);
        }
        assert_eq!(menu_label(Action::Redo), "Redo  Ctrl+Shift+Z");
    }

    /// The actions of one frame with these key presses.
    fn frame_with(keys: &[(Modifiers, Key)]) -> Vec<Action> {
        let ctx = egui::Context::default();
        let events = keys
            .iter()
            .map(|&(modifiers, key)| egui::Event::Key {
                key,
                physical_key: None,
                pressed: true,
                repeat: false,
                modifiers,
            })
            .collect();
        let mut out = Vec::new();
        let mut output = ctx.run_ui(egui::RawInput { events, ..Default::default() }, |ui| out = pressed(ui.ctx()));
        output.textures_delta.clear();
        out
    }

    #[test]
    fn the_most_specific_binding_wins() {
        assert_eq!(frame_with(&[(CTRL_SHIFT, Key::Z)]), [Action::Redo]);
        assert_eq!(frame_with(&[(CTRL, Key::Z)]), [Action::Undo]);
        assert_eq!(frame_with(&[(NONE, Key::Questionmark)]), [Action::Help]);
        // `?` is typed with Shift on most keyboards.
        assert_eq!(frame_with(&[(Modifiers::SHIFT, Key::Questionmark)]), [Action::Help]);
        assert_eq!(frame_with(&[(NONE, Key::B)]), []);
    }
}
