//! Surfaces made from curves: revolution, ruled surfaces, extrusions, sweeps, Coons
//! patches and Hermite surfaces of boundary and cross-derivative curves; and sub-surfaces over a quadrilateral of another surface's domain. Their partials of every order come from the curves' derivatives (curves used
//! on [0, 1] are [`crate::curve::Reparametrized`] there).

pub mod coons;
pub mod extrusion;
pub mod hermite_curves;
pub mod quad_sub_surface;
pub mod revolved;
pub mod ruled;
pub mod sweep;

pub use coons::{CoonsBlend, CoonsPatch};
pub use extrusion::Extrusion;
pub use hermite_curves::HermiteCurveSurface;
pub use quad_sub_surface::QuadSubSurface;
pub use revolved::RevolvedSurface;
pub use ruled::RuledSurface;
pub use sweep::SweepSurface;
