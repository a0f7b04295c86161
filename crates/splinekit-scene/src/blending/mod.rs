//! Blending-spline documents: `blending_spline` (curves) and `blending_spline_surface`,
//! with per-local `transforms` (rest frames) and an `animation` (tracks of motions evaluated
//! at a time T, see [`splinekit::blend::animation`]).

mod animation;
mod curve;
mod insert;
pub mod local_points;
mod split;
mod surface;

pub use animation::{MotionDoc, OscillateDoc, PulseDoc, RotateMotionDoc, SwingDoc, TrackDoc};
pub use curve::{BlendingSource, BlendingSplineDoc, KnotSpacingDoc, LocalCurves, LocalDoc};
pub use insert::{insert_knot_line, insert_local_curve};
pub use split::{knot_to_split, split_local_curve};
pub use surface::{BlendingSplineSurfaceDoc, LocalPatchDoc};

use crate::bfunctions::{BFunctionDoc, ErbsDoc};

/// The B-function of blending splines when none is given: ERBS with α = β = γ = 1, λ = ½.
pub const DEFAULT_BFUNCTION: BFunctionDoc =
    BFunctionDoc::Erbs(ErbsDoc { alpha: 1.0, beta: 1.0, gamma: 1.0, lambda: 0.5 });
