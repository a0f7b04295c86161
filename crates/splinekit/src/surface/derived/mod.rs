//! Surfaces made from curves: revolution, ruled surfaces, extrusions, sweeps and Coons
//! patches. Their partials of every order come from the curves' derivatives (curves used
//! on [0, 1] are [`crate::curve::Reparametrized`] there).

pub mod coons;
pub mod extrusion;
pub mod revolved;
pub mod ruled;
pub mod sweep;

pub use coons::{CoonsBlend, CoonsPatch};
pub use extrusion::Extrusion;
pub use revolved::RevolvedSurface;
pub use ruled::RuledSurface;
pub use sweep::SweepSurface;
