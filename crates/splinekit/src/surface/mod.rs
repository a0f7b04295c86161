//! Surfaces: the [`Surface`] trait, tensor-product Bézier, B-spline and NURBS surfaces,
//! and model surfaces.

pub(crate) mod axes;
pub mod bezier_surface;
pub mod bicubic_hermite;
pub mod bspline_surface;
pub mod curve_on_surface;
pub mod derived;
pub mod differential;
pub mod iso_curve;
pub mod loft;
pub mod model;
pub mod nurbs_surface;
#[cfg(feature = "parallel")]
pub mod parallel;
pub mod placed;
pub mod revolution;
pub mod samples;
pub mod surface_ops;
pub mod tensor;
pub mod traits;
pub mod trimmed;
pub(crate) mod unit_square;
pub mod wrapped;

pub use crate::query::extent::SurfaceExtent;
pub use crate::query::project_surface::SurfaceNearest;
pub use bezier_surface::BezierSurface;
pub use bicubic_hermite::HermiteCorner;
pub use bspline_surface::BSplineSurface;
pub use curve_on_surface::CurveOnSurface;
pub use derived::QuadSubSurface;
pub use differential::{Curvatures, FundamentalForms, unit_normal};
pub use iso_curve::{Direction, IsoCurve};
pub use nurbs_surface::NurbsSurface;
pub use placed::PlacedSurface;
pub use samples::SurfaceGridSamples;
pub use traits::{Surface, TrimLoops, normal_or_limit};
pub use trimmed::TrimmedSurface;
