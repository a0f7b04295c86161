//! Knot insertion, degree elevation, knot removal, splitting and Bézier decomposition of
//! Bézier, rational Bézier, B-spline and NURBS curves: the document operations of
//! ``splinekit refine`` and the kernel's split and decomposition. Each returns new curves;
//! the shape is unchanged (removal: within the tolerance).

use pyo3::prelude::*;
use pyo3::types::PyList;
use splinekit::curve::bezier::bezier_knots;
use splinekit::curve::{BSplineCurve, BezierCurve, NurbsCurve, RationalBezierCurve};
use splinekit_scene::curves::{BezierDoc, RationalBezierDoc};
use splinekit_scene::points::{from_points, to_points};
use splinekit_scene::refine::{Refinement, bspline_doc, nurbs_doc, refine};
use splinekit_scene::{CurveDocument, with_dimension};

use crate::curve::PyCurve;
use crate::curve_kinds::curve_object;
use crate::errors::{OrValueError, value_error};

/// Most knots one insertion may add (as ``splinekit refine``).
const MAX_INSERTIONS: usize = 1_000_000;

/// The control-point kinds as kernel curves: polynomial ones as B-splines, rational ones
/// as NURBS (Bézier curves on clamped knots over [0, 1]).
enum Spline<const D: usize> {
    Polynomial(BSplineCurve<D>),
    Rational(NurbsCurve<D>),
}

fn spline<const D: usize>(doc: &CurveDocument) -> PyResult<Spline<D>> {
    let Some(view) = doc.spline() else {
        return Err(value_error(format!(
            "type: this works on bezier, rational_bezier, bspline and nurbs curves, not {}",
            doc.type_name()
        )));
    };
    Ok(match (&view.knots, &view.weights) {
        (Some(knots), None) => Spline::Polynomial(view.bspline::<D>(knots).or_value_error()?),
        (Some(knots), Some(weights)) => Spline::Rational(view.nurbs::<D>(knots, weights).or_value_error()?),
        (None, None) => {
            let b = BezierCurve::<D>::new(to_points(&view.control_points)).or_value_error()?;
            Spline::Polynomial(
                BSplineCurve::new(b.degree(), bezier_knots(b.degree()), b.control_points().to_vec())
                    .or_value_error()?,
            )
        }
        (None, Some(weights)) => {
            let b =
                RationalBezierCurve::<D>::new(to_points(&view.control_points), weights.to_vec()).or_value_error()?;
            let n = NurbsCurve::new(
                b.degree(),
                bezier_knots(b.degree()),
                b.control_points().to_vec(),
                b.weights().to_vec(),
            );
            Spline::Rational(n.or_value_error()?)
        }
    })
}

/// Left and right documents of a split (right is None for a periodic curve, cut open).
type Halves = (CurveDocument, Option<CurveDocument>);

fn split_docs<const D: usize>(doc: &CurveDocument, t: f64) -> PyResult<Halves> {
    Ok(match spline::<D>(doc)? {
        Spline::Polynomial(c) => {
            let (l, r) = c.split(t).or_value_error()?;
            (bspline_doc(&l), r.as_ref().map(bspline_doc))
        }
        Spline::Rational(c) => {
            let (l, r) = c.split(t).or_value_error()?;
            (nurbs_doc(&l), r.as_ref().map(nurbs_doc))
        }
    })
}

fn bezier_docs<const D: usize>(doc: &CurveDocument) -> PyResult<Vec<CurveDocument>> {
    Ok(match spline::<D>(doc)? {
        Spline::Polynomial(c) => c
            .bezier_segments()
            .or_value_error()?
            .into_iter()
            .map(|(_, b)| CurveDocument::Bezier(BezierDoc { control_points: from_points(b.control_points()) }))
            .collect(),
        Spline::Rational(c) => c
            .bezier_segments()
            .or_value_error()?
            .into_iter()
            .map(|(_, b)| {
                let (control_points, weights) = (from_points(b.control_points()), b.weights().to_vec());
                CurveDocument::RationalBezier(RationalBezierDoc { control_points, weights })
            })
            .collect(),
    })
}

impl PyCurve {
    fn refined<'py>(&self, py: Python<'py>, r: Refinement) -> PyResult<Bound<'py, PyAny>> {
        let out = refine(&self.doc, &r).or_value_error()?;
        curve_object(py, out.document)
    }
}

#[pymethods]
impl PyCurve {
    /// The same curve with knot t inserted `times` times (Boehm's algorithm): each
    /// insertion replaces p control points by p + 1 convex combinations of them. Bézier
    /// curves become clamped B-splines (NURBS) on [0, 1].
    #[pyo3(signature = (t, times = 1))]
    fn insert_knot<'py>(&self, py: Python<'py>, t: f64, times: usize) -> PyResult<Bound<'py, PyAny>> {
        if times > MAX_INSERTIONS {
            return Err(value_error(format!("times: {times} is more than the limit of {MAX_INSERTIONS}")));
        }
        self.refined(py, Refinement::Insert(vec![t; times]))
    }

    /// The same curve with its degree raised by `times` (Bézier segments elevated:
    /// Qᵢ = i/(n+1) Pᵢ₋₁ + (1 − i/(n+1)) Pᵢ, then knots merged again).
    #[pyo3(signature = (times = 1))]
    fn elevate_degree<'py>(&self, py: Python<'py>, times: usize) -> PyResult<Bound<'py, PyAny>> {
        self.refined(py, Refinement::Elevate(times))
    }

    /// The curve with knot t removed up to `times` times where that moves the curve by at
    /// most `tolerance` (*The NURBS Book* A5.8); a knot that cannot be removed within the
    /// tolerance stays (compare ``len(knots)``).
    #[pyo3(signature = (t, tolerance = 1e-9, times = 1))]
    fn remove_knot<'py>(&self, py: Python<'py>, t: f64, tolerance: f64, times: usize) -> PyResult<Bound<'py, PyAny>> {
        if !(tolerance.is_finite() && tolerance >= 0.0) {
            return Err(value_error(format!("tolerance: must be finite and ≥ 0, got {tolerance}")));
        }
        if times > MAX_INSERTIONS {
            return Err(value_error(format!("times: {times} is more than the limit of {MAX_INSERTIONS}")));
        }
        self.refined(py, Refinement::Remove { knots: vec![t; times], tolerance })
    }

    /// ``(left, right)``: the curves on [a, t] and [t, b] (knot t inserted to full
    /// multiplicity). A closed curve is cut open at t instead: ``(open_curve, None)``.
    fn split<'py>(&self, py: Python<'py>, t: f64) -> PyResult<(Bound<'py, PyAny>, Option<Bound<'py, PyAny>>)> {
        self.check_params("t", &[t])?;
        let (left, right) =
            with_dimension!(self.dimension(), "control_points", D => split_docs::<D>(&self.doc, t), or value_error)?;
        Ok((curve_object(py, left)?, right.map(|r| curve_object(py, r)).transpose()?))
    }

    /// The Bézier (rational Bézier) segments of the curve in order, each on [0, 1]
    /// (every interior knot raised to multiplicity p).
    fn to_bezier<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyList>> {
        let docs =
            with_dimension!(self.dimension(), "control_points", D => bezier_docs::<D>(&self.doc), or value_error)?;
        let objects = docs.into_iter().map(|d| curve_object(py, d)).collect::<PyResult<Vec<_>>>()?;
        PyList::new(py, objects)
    }
}
