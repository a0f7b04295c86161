//! Local insertion and knot splitting on blending-spline curves from Python: the scene's
//! [`insert_local_curve`] and [`split_local_curve`] (the kernel's
//! `BlendingSplineCurve::insert_local` and `split_knot`, where the methods and what they
//! keep are stated), each returning a new curve as the other operations do. Errors are
//! `ValueError`s with the library's message, naming the field (`t`, `k`, `local_curves`).

use pyo3::prelude::*;
use splinekit::surface::Direction;
use splinekit_scene::blending::{insert_knot_line, insert_local_curve, set_closed, split_knot_line, split_local_curve};
use splinekit_scene::{CurveDocument, SurfaceDocument};

use crate::blending::only_on;
use crate::curve::PyCurve;
use crate::curve_kinds::curve_object;
use crate::errors::{OrValueError, value_error};
use crate::surface::PySurface;
use crate::surface_kinds::surface_object;

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

    /// A new blending spline turned open (``closed=False``) or closed, keeping the locals it
    /// can (GMlib's ``toggleClose``): opening copies local 0 one period on to the end (the
    /// same curve); closing drops the last local where the ends meet (value and first
    /// derivative), else keeps every local and bridges from the end to the start over one
    /// more interval (a model-built spline drops its last local in any case). Explicit local
    /// curves refuse it.
    fn set_closed<'py>(&self, py: Python<'py>, closed: bool) -> PyResult<Bound<'py, PyAny>> {
        let doc = blending(&self.doc, "set_closed")?;
        let out = set_closed(&doc, closed).or_value_error()?;
        curve_object(py, CurveDocument::BlendingSpline(out))
    }
}

/// The blending-spline surface document of `doc`, or the error naming what `method` works on.
fn blending_surface(
    doc: &SurfaceDocument,
    method: &str,
) -> PyResult<splinekit_scene::blending::BlendingSplineSurfaceDoc> {
    match doc {
        SurfaceDocument::BlendingSplineSurface(d) => Ok(d.clone()),
        other => Err(only_on(method, "blending_spline_surface surfaces", other.type_name())),
    }
}

/// `"u"` or `"v"` as a direction.
fn direction(d: &str) -> PyResult<Direction> {
    match d {
        "u" => Ok(Direction::U),
        "v" => Ok(Direction::V),
        other => Err(value_error(format!("direction: must be \"u\" or \"v\", got \"{other}\""))),
    }
}

#[pymethods]
impl PySurface {
    /// ``(surface, k)``: a new blending-spline surface with the knot line ``direction`` =
    /// t inserted (``"u"``: a row of patches fitted to the surface at u = t; ``"v"``: a
    /// column), and the new row's (column's) index k.
    fn insert_knot_line<'py>(&self, py: Python<'py>, direction: &str, t: f64) -> PyResult<(Bound<'py, PyAny>, usize)> {
        let doc = blending_surface(&self.doc, "insert_knot_line")?;
        let (out, k) = insert_knot_line(&doc, self::direction(direction)?, t).or_value_error()?;
        Ok((surface_object(py, SurfaceDocument::BlendingSplineSurface(out))?, k))
    }

    /// A new blending-spline surface with knot line k of ``direction`` (``"u"`` or
    /// ``"v"``) split along the other direction (GMlib's ``splitKnotAlong``): the knot
    /// doubled and its row (column) of patches copied, the same surface, whose copies
    /// ``set_transform`` can turn into a crease at the knot pairs.
    fn split_knot_line<'py>(&self, py: Python<'py>, direction: &str, k: usize) -> PyResult<Bound<'py, PyAny>> {
        let doc = blending_surface(&self.doc, "split_knot_line")?;
        let out = split_knot_line(&doc, self::direction(direction)?, k).or_value_error()?;
        surface_object(py, SurfaceDocument::BlendingSplineSurface(out))
    }
}
