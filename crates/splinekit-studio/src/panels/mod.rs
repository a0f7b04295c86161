//! The egui panels around the 3-D view: the menu bar, Objects, Properties, Animation and
//! the status line, and the help overlay. Each panel reaches only a [`PanelContext`]: it
//! reads the document as JSON and asks
//! for changes only by queuing [`crate::command::Command`]s (edits of the document,
//! actions of the registry), so every change can be undone and a refused value leaves the
//! document as it was, its message next to the field.

mod animation;
mod context;
mod fields;
mod help;
pub mod knots;
mod menu;
mod objects;
mod plot;
mod properties;

pub use animation::animation_panel;
pub use context::PanelContext;
pub use help::help_overlay;
pub use menu::{FileFields, menu_bar};
pub use objects::objects_panel;
pub use properties::properties_panel;

/// Width of the side panels in points (fixed, so the 3-D view's place is predictable).
pub const SIDE_WIDTH: f32 = 230.0;

/// A widget's rectangle (egui points: left, top, right, bottom), for
/// [`ViewCaches::widgets`](crate::view_caches::ViewCaches::widgets).
pub(crate) fn rect(response: &egui::Response) -> [f32; 4] {
    let r = response.rect;
    [r.left(), r.top(), r.right(), r.bottom()]
}
