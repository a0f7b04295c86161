//! Spline views: the control points, knots and weights a document holds, read without
//! matching on its kind. A kind declares its view in
//! [`DocumentKind::spline`](crate::registry::DocumentKind::spline); refinement, Python's
//! knot operations and properties, the studio's Properties and STEP's exact splines read it.
//!
//! A view is the B-spline (NURBS) c(t) = Σ N_{i,p}(t) wᵢ Pᵢ / Σ N_{i,p}(t) wᵢ; without
//! knots it is the Bézier curve of its points (the clamped knots of
//! [`bezier_knots`](splinekit::curve::bezier::bezier_knots) over [0, 1]), without weights
//! every wᵢ = 1.

use std::borrow::Cow;

use splinekit::curve::{BSplineCurve, NurbsCurve};
use splinekit::surface::NurbsSurface;

use crate::error::Result;
use crate::points::{from_points, to_points};

/// The spline data of a curve document.
#[derive(Debug, Clone, PartialEq)]
pub struct SplineView<'a> {
    /// Degree p (Bézier: the number of points less one).
    pub degree: usize,
    /// Control points Pᵢ, each of 1 to 4 coordinates.
    pub control_points: Cow<'a, [Vec<f64>]>,
    /// The knots t₀ … t_{n+p}; `None` for a Bézier curve.
    pub knots: Option<Cow<'a, [f64]>>,
    /// The weights wᵢ of a rational kind; `None` when every weight is 1.
    pub weights: Option<Cow<'a, [f64]>>,
    /// Whether the control points wrap around (a periodic B-spline).
    pub periodic: bool,
}

impl<'a> SplineView<'a> {
    /// The view of a document's own fields, borrowed from it: the B-spline of `degree`
    /// with `knots`, or the Bézier curve of the points without; rational with `weights`.
    pub fn borrowed(
        degree: usize,
        control_points: &'a [Vec<f64>],
        knots: Option<&'a [f64]>,
        weights: Option<&'a [f64]>,
        periodic: bool,
    ) -> Self {
        SplineView {
            degree,
            control_points: Cow::Borrowed(control_points),
            knots: knots.map(Cow::Borrowed),
            weights: weights.map(Cow::Borrowed),
            periodic,
        }
    }

    /// The view of a Bézier document's points (degree: their count less one), rational
    /// with `weights`.
    pub fn bezier(control_points: &'a [Vec<f64>], weights: Option<&'a [f64]>) -> Self {
        Self::borrowed(control_points.len().saturating_sub(1), control_points, None, weights, false)
    }

    /// The B-spline of a view with knots and without weights (checked as its document).
    pub fn bspline<const D: usize>(&self, knots: &[f64]) -> Result<BSplineCurve<D>> {
        crate::budget::check_degree("degree", self.degree)?;
        crate::points::check_finite_list("knots", knots)?;
        let points = to_points::<D>(&self.control_points);
        Ok(if self.periodic {
            BSplineCurve::new_periodic(self.degree, knots.to_vec(), points)?
        } else {
            BSplineCurve::new(self.degree, knots.to_vec(), points)?
        })
    }

    /// The NURBS curve of a view with knots and weights (checked as its document).
    pub fn nurbs<const D: usize>(&self, knots: &[f64], weights: &[f64]) -> Result<NurbsCurve<D>> {
        crate::budget::check_degree("degree", self.degree)?;
        crate::points::check_finite_list("knots", knots)?;
        crate::points::check_finite_list("weights", weights)?;
        let points = to_points::<D>(&self.control_points);
        let (knots, weights) = (knots.to_vec(), weights.to_vec());
        Ok(if self.periodic {
            NurbsCurve::new_periodic(self.degree, knots, points, weights)?
        } else {
            NurbsCurve::new(self.degree, knots, points, weights)?
        })
    }
}

/// Knots in u and in v.
pub type KnotPair<'a> = (Cow<'a, [f64]>, Cow<'a, [f64]>);

/// The spline data of a surface document: a control net, rows along u.
#[derive(Debug, Clone, PartialEq)]
pub struct NetView<'a> {
    /// Degrees (p, q) in u and v.
    pub degrees: (usize, usize),
    /// The net P_ij, i along u.
    pub control_points: Cow<'a, [Vec<Vec<f64>>]>,
    /// The knots in u and in v; `None` for a Bézier net.
    pub knots: Option<KnotPair<'a>>,
    /// The weights w_ij of a rational net; `None` when every weight is 1.
    pub weights: Option<Cow<'a, [Vec<f64>]>>,
    /// Whether the net wraps around in u and in v.
    pub periodic: (bool, bool),
}

impl<'a> NetView<'a> {
    /// The view of a document's own fields, borrowed from it: the tensor-product B-spline
    /// of `degrees` with `knots` (u, v), or the Bézier net without; rational with `weights`.
    pub fn borrowed(
        degrees: (usize, usize),
        control_points: &'a [Vec<Vec<f64>>],
        knots: Option<(&'a [f64], &'a [f64])>,
        weights: Option<&'a [Vec<f64>]>,
        periodic: (bool, bool),
    ) -> Self {
        NetView {
            degrees,
            control_points: Cow::Borrowed(control_points),
            knots: knots.map(|(u, v)| (Cow::Borrowed(u), Cow::Borrowed(v))),
            weights: weights.map(Cow::Borrowed),
            periodic,
        }
    }

    /// The view of a Bézier net (degrees: rows less one, points of the first row less one).
    pub fn bezier(control_points: &'a [Vec<Vec<f64>>]) -> Self {
        let (rows, cols) = (control_points.len(), control_points.first().map_or(0, Vec::len));
        Self::borrowed((rows.saturating_sub(1), cols.saturating_sub(1)), control_points, None, None, (false, false))
    }
}

impl NetView<'static> {
    /// The view of a kernel NURBS surface (its own copy): the exact form of a kind whose
    /// kernel object is a NURBS surface made from other fields.
    pub fn of_nurbs<const D: usize>(s: &NurbsSurface<D>) -> Self {
        let (ku, kv) = s.knots();
        NetView {
            degrees: s.degrees(),
            control_points: Cow::Owned(s.control_points().iter().map(|row| from_points(row)).collect()),
            knots: Some((Cow::Owned(ku.to_vec()), Cow::Owned(kv.to_vec()))),
            weights: Some(Cow::Owned(s.weights().to_vec())),
            periodic: s.periodic(),
        }
    }
}
