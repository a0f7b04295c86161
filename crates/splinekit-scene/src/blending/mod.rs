//! What blending-spline documents share: the `animation` (tracks of motions evaluated at a
//! time T, see [`splinekit::blend::animation`]), edited local control points, knot
//! insertion and knot splitting. The documents themselves, `blending_spline` and `blending_spline_surface`
//! (with per-local `transforms`, rest frames), are kinds of their family, declared in
//! `curves/blending.rs` and `surfaces/blending.rs` since their locals are documents of
//! that family; they are re-exported here.

mod animation;
mod insert;
pub mod local_points;
mod rebuilt;
mod split;
mod topology;

pub use crate::curves::{BlendingSource, BlendingSplineDoc, KnotSpacingDoc, LocalCurves, LocalDoc};
pub use crate::surfaces::{BlendingSplineSurfaceDoc, LocalPatchDoc};
pub(crate) use animation::tracks;
pub use animation::{MotionDoc, OscillateDoc, PulseDoc, RotateMotionDoc, SwingDoc, TrackDoc};
pub use insert::{insert_knot_line, insert_local_curve};
pub use split::{knot_to_split, split_local_curve};
pub use topology::{set_closed, split_knot_line};
