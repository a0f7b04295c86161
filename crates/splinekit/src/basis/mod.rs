//! Basis functions: Bernstein polynomials, the B-spline basis and knot vectors.

pub mod bernstein;
pub mod bfunction;
pub mod bspline_basis;
pub mod erbs;
pub mod knot_vector;
pub mod spline_axis;

pub use bernstein::{bernstein, bernstein_all, bernstein_derivatives, binomial};
pub use bfunction::BFunction;
pub use bspline_basis::{basis_derivatives, basis_function, basis_functions};
pub use knot_vector::{KnotVector, Side, advance_span, advance_span_side, find_span};
pub use spline_axis::SplineAxis;
