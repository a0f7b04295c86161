//! # splinekit
//!
//! A geometric-modelling kernel for parametric curves and surfaces: Bézier, rational
//! Bézier, B-spline and NURBS curves and surfaces, Hermite and Catmull–Rom splines, model
//! curves and surfaces, surfaces made from curves (revolution, ruled, extrusion, sweep,
//! Coons, loft, trimmed), blending splines (GERBS/ERBS curves and surfaces with affine
//! frames and animation), least-squares fitting and interpolation, knot insertion and
//! removal, degree elevation, splitting and subdivision, and triangles (Bézier triangles,
//! sub-triangles, triangular B-functions and GERBS triangles).
//!
//! Points are `nalgebra` vectors [`Point<D>`] with a compile-time dimension. Every
//! constructor validates its input and returns [`Result`]; nothing here prints, reads
//! files or panics on user input.
//!
//! ```
//! use splinekit::{Point, curve::{BSplineCurve, Curve}};
//! let c = BSplineCurve::<2>::clamped_uniform(2, vec![
//!     Point::<2>::new(0.0, 0.0), Point::<2>::new(1.0, 2.0), Point::<2>::new(2.0, 0.0),
//! ]).unwrap();
//! // A clamped quadratic with 3 control points is the Bézier curve: c(½) = (1, 1).
//! assert!((c.point(0.5) - Point::<2>::new(1.0, 1.0)).norm() < 1e-15);
//! ```

#![warn(missing_docs)]

pub mod axes;
pub mod basis;
pub mod blend;
pub mod brep;
pub mod curve;
pub mod error;
pub mod fit;
pub mod frame;
pub mod interval;
pub mod ops;
pub mod quadrature;
pub mod query;
pub mod subdivision;
pub mod surface;
pub mod taylor;
#[cfg(test)]
mod test_stream;
pub mod tolerance;
pub mod triangle;
pub mod triangulation;

pub use error::{Error, Result};
pub use interval::{Interval, ParamRect};

/// The README's Rust examples, compiled and run as doctests.
#[doc = include_str!("../../../README.md")]
#[cfg(doctest)]
pub struct ReadmeDoctests;

/// The crate's own README (its crates.io page), compiled and run as doctests.
#[doc = include_str!("../README.md")]
#[cfg(doctest)]
pub struct CrateReadmeDoctests;

/// A point (or vector) in ℝᴰ.
pub type Point<const D: usize> = nalgebra::SVector<f64, D>;

/// Elements of a real vector space that splines can combine: points, scalars, homogeneous
/// points. Algorithms such as de Casteljau or knot insertion are written once over this.
pub trait Coefficient:
    Copy
    + std::ops::Add<Output = Self>
    + std::ops::Sub<Output = Self>
    + std::ops::Mul<f64, Output = Self>
    + std::ops::AddAssign
{
    /// The additive identity.
    fn zero() -> Self;
}

impl Coefficient for f64 {
    #[inline]
    fn zero() -> Self {
        0.0
    }
}

impl<const D: usize> Coefficient for Point<D> {
    #[inline]
    fn zero() -> Self {
        Point::<D>::zeros()
    }
}
