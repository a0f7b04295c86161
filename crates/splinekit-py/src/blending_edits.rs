//! Local insertion and knot splitting on blending-spline curves from Python: the scene's
//! [`insert_local_curve`] and [`split_local_curve`] (the kernel's
//! `BlendingSplineCurve::insert_local` and `split_knot`, where the methods and what they
//! keep are stated), each returning a new curve as the other operations do. Errors are
//! `ValueError`s with the library's message, naming the field (`t`, `k`, `local_curves`).

use pyo3::prelude::*;
use splinekit_scene::CurveDocument;
use splinekit_scene::blending::{insert_local_curve, split_local_curve};

use crate::blending::only_on;
use crate::curve::PyCurve;
use crate::curve_kinds::curve_object;
use crate::errors::OrValueError;

/// The blending-spline document of `doc`, or the error naming what `method` works on.
fn blending(doc: &CurveDocument, method: &str) -> PyResult<splinekit_scene::blending::BlendingSplineDoc> {
    match doc {
        CurveDocument::BlendingSpline(d) => Ok(d.clone()),
        other => Err(only_on(method, "blending_spline curves", other.type_name())),
    }
}

#[pymethods]
impl PyCurve {
    /// ``(curve, k)``: a new blending spline with a local curve inserted at the new knot t
    /// (strictly inside a knot interval), and the new local's index k. The new local is the
    /// Bézier of the locals' degree d fitted to the curve's value and first d derivatives
    /// at t (sub-curve and arc locals: one of their kind from the model); with ERBS the
    /// curve is unchanged outside the two neighbouring knots, and untransformed sub-curve
    /// locals do not change it at all. Blending splines built from a model only.
    fn insert_local<'py>(&self, py: Python<'py>, t: f64) -> PyResult<(Bound<'py, PyAny>, usize)> {
        let doc = blending(&self.doc, "insert_local")?;
        let (out, k) = insert_local_curve(&doc, t).or_value_error()?;
        Ok((curve_object(py, CurveDocument::BlendingSpline(out))?, k))
    }

    /// A new blending spline with interior knot k doubled and local curve k copied to
    /// k + 1: the same curve, with a joint at the knot where the two copies meet (turning or
    /// scaling one copy about its origin with ``set_transform`` makes a corner, C⁰).
    /// Blending splines built from a model only; end knots and knots already double are
    /// refused.
    fn split_knot<'py>(&self, py: Python<'py>, k: usize) -> PyResult<Bound<'py, PyAny>> {
        let doc = blending(&self.doc, "split_knot")?;
        let out = split_local_curve(&doc, k).or_value_error()?;
        curve_object(py, CurveDocument::BlendingSpline(out))
    }
}
