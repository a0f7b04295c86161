//! Exact forms: what a shape is in the classical vocabulary of geometry (a spline, a conic,
//! a quadric, a swept surface), declared by its kind in
//! [`DocumentKind::exact_form`](crate::registry::DocumentKind::exact_form). Exporters write
//! the form's own entity (STEP: `B_SPLINE_CURVE_WITH_KNOTS`, `CIRCLE`, `TOROIDAL_SURFACE`,
//! …) and approximate only [`CurveForm::Approximate`] and [`SurfaceForm::Approximate`];
//! a new kind chooses among these forms, so an exporter needs no edit for it.
//!
//! Every form has the document's parametrisation up to the affine maps the exporter names.

use crate::blending::{BlendingSplineDoc, BlendingSplineSurfaceDoc};
use crate::surfaces::{ExtrusionDoc, PlacedDoc, RevolutionDoc, TrimmedDoc};
use crate::views::{NetView, SplineView};

/// The exact form of a curve document.
#[derive(Debug, Clone)]
pub enum CurveForm<'a> {
    /// A B-spline, NURBS or (rational) Bézier curve with these points, knots and weights.
    Spline(SplineView<'a>),
    /// The segment from + t (to − from), t ∈ [0, 1].
    Line {
        /// c(0).
        from: &'a [f64],
        /// c(1).
        to: &'a [f64],
    },
    /// (r cos t, r sin t, 0), t ∈ [0, 2π].
    Circle {
        /// r.
        radius: f64,
    },
    /// (a cos t, b sin t, 0), t ∈ [0, 2π].
    Ellipse {
        /// Semi-axis along x.
        a: f64,
        /// Semi-axis along y.
        b: f64,
    },
    /// A blending spline: a piecewise polynomial (a B-spline) when its locals are Bézier
    /// curves or lines and its B-function is a polynomial, else approximated.
    BlendingSpline(&'a BlendingSplineDoc),
    /// No exact form: exporters approximate the curve within a tolerance.
    Approximate,
}

/// The exact form of a surface document.
#[derive(Debug, Clone)]
pub enum SurfaceForm<'a> {
    /// A B-spline, NURBS or Bézier net.
    Spline(NetView<'a>),
    /// origin + u U + v V, (u, v) ∈ [0, 1]².
    Plane {
        /// S(0, 0).
        origin: &'a [f64],
        /// U.
        u_axis: &'a [f64],
        /// V.
        v_axis: &'a [f64],
    },
    /// (r cos u, r sin u, h v), u ∈ [0, 2π], v ∈ [0, 1].
    Cylinder {
        /// r.
        radius: f64,
        /// h.
        height: f64,
    },
    /// (r (1 − v) cos u, r (1 − v) sin u, h v), u ∈ [0, 2π], v ∈ [0, 1].
    Cone {
        /// r.
        radius: f64,
        /// h.
        height: f64,
    },
    /// The sphere of radius r about the origin, u the longitude, v ∈ [−π/2, π/2] the latitude.
    Sphere {
        /// r.
        radius: f64,
    },
    /// ((R + r cos v) cos u, (R + r cos v) sin u, r sin v), (u, v) ∈ [0, 2π]².
    Torus {
        /// R.
        major_radius: f64,
        /// r.
        minor_radius: f64,
    },
    /// A curve turned about an axis.
    Revolution(&'a RevolutionDoc),
    /// A curve moved along a direction.
    Extrusion(&'a ExtrusionDoc),
    /// A surface cut by loops of curves.
    Trimmed(&'a TrimmedDoc),
    /// A surface moved rigidly into a frame.
    Placed(&'a PlacedDoc),
    /// A blending-spline surface: a B-spline when its locals are Bézier patches and its
    /// B-function a polynomial, else approximated.
    BlendingSpline(&'a BlendingSplineSurfaceDoc),
    /// No exact form: exporters approximate the surface within a tolerance.
    Approximate,
}
