//! # splinekit-studio
//!
//! The interactive editor behind `splinekit view`: a winit window presenting through wgpu,
//! egui panels (egui-winit, egui-wgpu) around a 3-D view drawn by the same
//! [`splinekit_render::Renderer`] as `splinekit render` (same pipelines, MSAA, colours
//! and cameras, so a screenshot of the view equals a render of the saved document).
//!
//! - Edits are commands on the scene document ([`edit::Edit`]): each sets one JSON value of
//!   one object and is kept only if the object still parses and builds; [`history::History`]
//!   undoes and redoes them, a drag being one step.
//! - Handles ([`handles`]) sit at the moved origins o_k + t_k of blending-spline local
//!   pieces and at control points; picking projects them with the renderer's view–projection
//!   matrix ([`view_camera::Projector`]). Moving a local piece edits its `transforms` entry
//!   as the format applies it (scale, rotate, translate about the origin,
//!   [`transform_edit`]).
//! - One registry of actions ([`actions`]: label, shortcut, menu, panel button, undoable)
//!   feeds the menus, the key bindings and the help overlay (`?`); menus, keys and panels
//!   all ask through [`command::Command`]s that the studio runs in one place.
//! - [`studio::Studio`] composes the parts of the studio's state, each its own type:
//!   [`document::Document`] (the scene, its file and undo history; every change goes
//!   through it), [`selection::Selection`] (the selected object and handles),
//!   [`view_caches::ViewCaches`] (the composition, the live surfaces, the handles as drawn,
//!   hover, bounds and the report's widget rectangles) and [`status::Status`] (messages);
//!   the panels reach only a [`panels::PanelContext`] (the document read-only, the
//!   selection, the messages and the command queue).
//! - Ctrl+S writes an ordinary scene document with the view's camera.
//! - [`live_surfaces`] keeps the window's blending-spline surfaces evaluated: after a frame
//!   moves only the rectangles it affects are re-evaluated, and it owns the one built
//!   surface per object (the edit's check, handles and meshing share it); during a drag
//!   [`live_view`] brings the composed scene up to date in place and lists what changed,
//!   which the window writes into the vertex buffers it keeps ([`gpu::keep_geometry`];
//!   benchmarked in `benches/live.rs`, `--features bench`).
//!
//! Everything but [`app`] and [`gpu`] runs without a window and is unit-tested.

#![warn(missing_docs)]

pub mod actions;
pub mod analysis;
pub mod app;
pub mod clock;
pub mod command;
pub mod document;
pub mod edit;
pub mod error;
pub mod export;
pub mod gesture;
pub mod gpu;
pub mod group_move;
pub mod handles;
pub mod history;
pub mod knot_edit;
pub mod knot_split;
pub mod live_surfaces;
pub mod live_view;
pub mod local_insert;
pub mod net_knot_edit;
pub mod options;
pub mod panels;
pub mod report;
pub mod selection;
pub mod snapping;
pub mod status;
pub mod studio;
pub mod transform_edit;
pub mod view_blit;
pub mod view_caches;
pub mod view_camera;
pub mod viewport;

pub use error::StudioError;
pub use options::Options;

use winit::event_loop::{ControlFlow, EventLoop};

/// Opens the studio window on the options' document and runs until it closes. Errors:
/// the document does not parse (its field named), there is no display, or no adapter.
pub fn run(options: Options) -> Result<(), StudioError> {
    let scene = match (&options.path, &options.text) {
        (Some(p), _) => document::read(p)?,
        (None, Some(text)) => document::parse(text)?,
        (None, None) => document::parse(document::STARTER)?,
    };
    let event_loop = EventLoop::new().map_err(|e| {
        StudioError::Graphics(format!(
            "view: cannot open a window ({e}); it needs a display (X11: set DISPLAY, or run under xvfb-run)"
        ))
    })?;
    event_loop.set_control_flow(ControlFlow::Wait);
    let mut app = app::App::new(studio::Studio::new(scene, options.path.clone()), options);
    event_loop.run_app(&mut app).map_err(|e| StudioError::Graphics(format!("view: {e}")))?;
    app.error.map_or(Ok(()), Err)
}
