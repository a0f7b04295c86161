//! Blending splines from Python: the affine frames of their local pieces, their animation
//! clock, and the local pieces themselves. A blending spline c(t) = Σₖ B∘wₖ(t) ℓₖ(t)
//! blends local curves ℓₖ (surfaces: patches) with a B-function; each piece carries an
//! affine frame about its interpolation point. Objects are immutable: these methods return
//! a new object built from the changed document.

use numpy::{PyArray1, PyArrayDyn, PyArrayMethods};
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyList};
use splinekit::Point;
use splinekit_scene::transforms::TransformDoc;
use splinekit_scene::{CurveDocument, SurfaceDocument};

use crate::curve::PyCurve;
use crate::curve_kinds::{curve_object, document};
use crate::dimension::by_dimension;
use crate::errors::{OrValueError, value_error};
use crate::surface::PySurface;
use crate::surface_kinds::surface_object;

/// The transform document `{"translate": …, "rotate": …, "scale": …}` from arguments,
/// parsed as a document's `transforms` entry is.
fn transform(
    translate: Option<&Bound<'_, PyAny>>,
    rotate: Option<&Bound<'_, PyAny>>,
    scale: Option<&Bound<'_, PyAny>>,
) -> PyResult<TransformDoc> {
    let mut value = document("", &[("translate", translate), ("rotate", rotate), ("scale", scale)])?;
    value.as_object_mut().expect("an object").remove("type");
    splinekit_scene::json::fields(value).or_value_error()
}

/// Replaces (or adds) the entry of `key` in a list of per-piece transforms.
fn put<K: PartialEq>(list: &mut Vec<(K, TransformDoc)>, key: K, t: TransformDoc) {
    list.retain(|(k, _)| *k != key);
    list.push((key, t));
}

fn as_array<'py>(py: Python<'py>, values: Vec<f64>, shape: Vec<usize>) -> PyResult<Bound<'py, PyArrayDyn<f64>>> {
    PyArray1::from_vec(py, values).reshape(shape).map_err(value_error)
}

/// The local curves of a blending-spline document: support, origin and `samples` points
/// of each over its support.
fn local_curves<'py, const D: usize>(
    py: Python<'py>,
    doc: &splinekit_scene::curves::BlendingSplineDoc,
    samples: usize,
) -> PyResult<Bound<'py, PyList>> {
    let c = doc.curve::<D>().or_value_error()?;
    let list = PyList::empty(py);
    let mut v = [Point::<D>::zeros(); 1];
    for k in 0..c.local_count() {
        let support = c.local_support(k);
        let mut points = Vec::with_capacity(samples * D);
        for i in 0..samples {
            c.eval_local(k, support.lerp(i as f64 / (samples - 1) as f64), &mut v);
            points.extend(v[0].iter());
        }
        let d = PyDict::new(py);
        d.set_item("index", k)?;
        d.set_item("support", (support.start, support.end))?;
        d.set_item("origin", PyArray1::from_iter(py, c.origin(k).iter().copied()))?;
        d.set_item("points", as_array(py, points, vec![samples, D])?)?;
        list.append(d)?;
    }
    Ok(list)
}

/// The local patches of a blending-spline surface document: support, origin and a
/// `samples` × `samples` grid of points of each over its support.
fn local_patches<'py, const D: usize>(
    py: Python<'py>,
    doc: &splinekit_scene::surfaces::BlendingSplineSurfaceDoc,
    samples: usize,
) -> PyResult<Bound<'py, PyList>> {
    let s = doc.surface::<D>().or_value_error()?;
    let (nu, nv) = s.local_count();
    let list = PyList::empty(py);
    let mut v = [Point::<D>::zeros(); 1];
    let at = |i: usize| i as f64 / (samples - 1) as f64;
    for (k, l) in (0..nu).flat_map(|k| (0..nv).map(move |l| (k, l))) {
        let rect = s.local_support(k, l);
        let mut points = Vec::with_capacity(samples * samples * D);
        for (i, j) in (0..samples).flat_map(|i| (0..samples).map(move |j| (i, j))) {
            s.eval_local((k, l), (rect.u.lerp(at(i)), rect.v.lerp(at(j))), 0, 0, &mut v);
            points.extend(v[0].iter());
        }
        let d = PyDict::new(py);
        d.set_item("index", (k, l))?;
        d.set_item("support", ((rect.u.start, rect.u.end), (rect.v.start, rect.v.end)))?;
        d.set_item("origin", PyArray1::from_iter(py, s.origin(k, l).iter().copied()))?;
        d.set_item("points", as_array(py, points, vec![samples, samples, D])?)?;
        list.append(d)?;
    }
    Ok(list)
}

fn check_samples(samples: usize) -> PyResult<()> {
    if !(2..=10_000).contains(&samples) {
        return Err(value_error(format!("samples: need 2 to 10000 samples per piece, got {samples}")));
    }
    Ok(())
}

#[pymethods]
impl PyCurve {
    /// A copy with the affine frame of local curve `k` set: ``translate`` (D numbers),
    /// ``rotate`` (``{"axis": [..], "angle": radians, "pivot": [..]}``), ``scale`` (a
    /// number), applied in the local curve's own frame about its interpolation point.
    #[pyo3(signature = (k, translate = None, rotate = None, scale = None))]
    fn set_transform<'py>(
        &self,
        py: Python<'py>,
        k: usize,
        translate: Option<&Bound<'py, PyAny>>,
        rotate: Option<&Bound<'py, PyAny>>,
        scale: Option<&Bound<'py, PyAny>>,
    ) -> PyResult<Bound<'py, PyAny>> {
        let CurveDocument::BlendingSpline(mut d) = self.doc.clone() else {
            return Err(value_error(format!(
                "type: set_transform works on blending_spline curves, not {}",
                self.doc.type_name()
            )));
        };
        put(&mut d.transforms, k, transform(translate, rotate, scale)?);
        curve_object(py, CurveDocument::BlendingSpline(d))
    }

    /// A copy posed at time `t` (seconds) by the document's animation tracks, as
    /// ``splinekit eval --time``; shapes without animation are unchanged.
    fn at_time<'py>(&self, py: Python<'py>, t: f64) -> PyResult<Bound<'py, PyAny>> {
        if !t.is_finite() {
            return Err(value_error(format!("t: must be finite, got {t}")));
        }
        let mut doc = self.doc.clone();
        doc.set_time(t);
        curve_object(py, doc)
    }

    /// The local curves ℓₖ of a blending spline: a list of dicts with ``index`` k,
    /// ``support`` (tₖ₋₁, tₖ₊₁), ``origin`` ℓₖ's interpolation point, and ``points``
    /// (samples, D) of ℓₖ over its support (at the global parameter, frame applied).
    #[pyo3(signature = (samples = 97))]
    fn local_pieces<'py>(&self, py: Python<'py>, samples: usize) -> PyResult<Bound<'py, PyList>> {
        check_samples(samples)?;
        let CurveDocument::BlendingSpline(d) = &self.doc else {
            return Err(value_error(format!(
                "type: local_pieces works on blending_spline curves, not {}",
                self.doc.type_name()
            )));
        };
        by_dimension!(self.dimension(), "control_points", D => local_curves::<D>(py, d, samples))
    }
}

#[pymethods]
impl PySurface {
    /// A copy with the affine frame of local patch ``k = (i, j)`` set (see
    /// ``Curve.set_transform``).
    #[pyo3(signature = (k, translate = None, rotate = None, scale = None))]
    fn set_transform<'py>(
        &self,
        py: Python<'py>,
        k: (usize, usize),
        translate: Option<&Bound<'py, PyAny>>,
        rotate: Option<&Bound<'py, PyAny>>,
        scale: Option<&Bound<'py, PyAny>>,
    ) -> PyResult<Bound<'py, PyAny>> {
        let SurfaceDocument::BlendingSplineSurface(mut d) = self.doc.clone() else {
            return Err(value_error(format!(
                "type: set_transform works on blending_spline_surface surfaces, not {}",
                self.doc.type_name()
            )));
        };
        put(&mut d.transforms, k, transform(translate, rotate, scale)?);
        surface_object(py, SurfaceDocument::BlendingSplineSurface(d))
    }

    /// A copy posed at time `t` (seconds) by the document's animation tracks.
    fn at_time<'py>(&self, py: Python<'py>, t: f64) -> PyResult<Bound<'py, PyAny>> {
        if !t.is_finite() {
            return Err(value_error(format!("t: must be finite, got {t}")));
        }
        let mut doc = self.doc.clone();
        doc.set_time(t);
        surface_object(py, doc)
    }

    /// The local patches of a blending-spline surface: dicts with ``index`` (i, j),
    /// ``support`` ((u0, u1), (v0, v1)), ``origin``, and ``points`` (samples, samples, D).
    #[pyo3(signature = (samples = 17))]
    fn local_pieces<'py>(&self, py: Python<'py>, samples: usize) -> PyResult<Bound<'py, PyList>> {
        check_samples(samples)?;
        let SurfaceDocument::BlendingSplineSurface(d) = &self.doc else {
            return Err(value_error(format!(
                "type: local_pieces works on blending_spline_surface surfaces, not {}",
                self.doc.type_name()
            )));
        };
        by_dimension!(self.surface.dimension(), "control_points", D => local_patches::<D>(py, d, samples))
    }
}
