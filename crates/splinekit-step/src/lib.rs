//! # splinekit-step
//!
//! STEP (ISO 10303-21, AP214/AP242 geometry) for splinekit: a streaming Part 21 reader and
//! writer, and the mapping between STEP geometry entities and splinekit's curves and
//! surfaces.

#![warn(missing_docs)]

pub mod error;
pub mod part21;

pub use error::{Result, StepError};
pub mod approximate;
pub mod assembly;
pub mod documents;
pub mod evaluate;
pub mod export;
pub mod geometry;
pub mod import;
pub mod kernel;
pub mod pcurve;
pub mod placement;
pub mod structure;
pub mod styles;
pub mod units;
pub mod wrapping_loops;
