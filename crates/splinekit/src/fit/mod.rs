//! Least-squares fitting and interpolation of B-spline curves.

pub mod banded_qr;
pub mod collocation;
pub mod interpolate;
pub mod lsq;
pub mod parametrize;
pub mod surface_fit;

pub use banded_qr::BandedLeastSquares;
pub use interpolate::{Interpolation, InterpolationOptions, interpolate};
pub use lsq::{Fit, FitOptions, FitWithKnotsOptions, check_data, fit, fit_curve, fit_with_knots};
pub use parametrize::{KnotPlacement, Parametrization, fit_knots, parametrize, periodic_knots};
pub use surface_fit::{SurfaceFitOptions, fit_surface, interpolate_surface, interpolate_surface_on_knots};
