//! Blending splines from Python: the affine frames of their local pieces, their animation
//! clock, and the local pieces themselves. A blending spline c(t) = Σₖ B∘wₖ(t) ℓₖ(t)
//! blends local curves ℓₖ (surfaces: patches) with a B-function; each piece carries an
//! affine frame about its interpolation point. `set_transform` changes the object in place
//! (its document and the curve or surface built from it); `at_time` returns a new object.
//! The methods themselves, alike for `Curve` and `Surface`, are `shape_methods.rs`'s; this
//! file holds what they compute and check.

use numpy::{PyArray1, PyArrayDyn, PyArrayMethods};
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyList};
use splinekit::Point;
use splinekit_scene::budget::{Cost, F64, ShapeCost};
use splinekit_scene::curves::BlendingSplineDoc;
use splinekit_scene::surfaces::BlendingSplineSurfaceDoc;
use splinekit_scene::transforms::TransformDoc;

use crate::budget;
use crate::curve_kinds::document;
use crate::errors::{OrValueError, value_error};

/// The transform document `{"translate": …, "rotate": …, "scale": …}` from arguments,
/// parsed as a document's `transforms` entry is.
pub(crate) fn transform(
    translate: Option<&Bound<'_, PyAny>>,
    rotate: Option<&Bound<'_, PyAny>>,
    scale: Option<&Bound<'_, PyAny>>,
) -> PyResult<TransformDoc> {
    let mut value = document("", &[("translate", translate), ("rotate", rotate), ("scale", scale)])?;
    value.as_object_mut().expect("an object").remove("type");
    splinekit_scene::json::fields(value).or_value_error()
}

/// Replaces (or adds) the entry of `key` in a list of per-piece transforms.
pub(crate) fn put<K: PartialEq>(list: &mut Vec<(K, TransformDoc)>, key: K, t: TransformDoc) {
    list.retain(|(k, _)| *k != key);
    list.push((key, t));
}

fn as_array<'py>(py: Python<'py>, values: Vec<f64>, shape: Vec<usize>) -> PyResult<Bound<'py, PyArrayDyn<f64>>> {
    PyArray1::from_vec(py, values).reshape(shape).map_err(value_error)
}

/// One local piece as `local_pieces` returns it: `{"index", "support", "origin",
/// "points"}`, the points (row-major samples of D coordinates) shaped `shape`.
fn local_piece<'py>(
    py: Python<'py>,
    index: impl IntoPyObject<'py>,
    support: impl IntoPyObject<'py>,
    origin: &[f64],
    points: Vec<f64>,
    shape: Vec<usize>,
) -> PyResult<Bound<'py, PyDict>> {
    let d = PyDict::new(py);
    d.set_item("index", index)?;
    d.set_item("support", support)?;
    d.set_item("origin", PyArray1::from_slice(py, origin))?;
    d.set_item("points", as_array(py, points, shape)?)?;
    Ok(d)
}

/// A `local_pieces` call: the Python session, the cost of the shape (for the budget) and
/// the samples per piece, or per direction of a patch.
pub(crate) struct PieceSampling<'py, 'c> {
    /// The session the dicts and arrays are made in.
    pub py: Python<'py>,
    /// The shape's cost, for the budget check of the samples.
    pub cost: &'c ShapeCost,
    /// Samples per local curve, or per direction of a local patch (checked by
    /// [`check_samples`]).
    pub samples: usize,
}

impl<'py> PieceSampling<'py, '_> {
    /// The local curves of a blending-spline document: support, origin and `samples` points
    /// of each over its support.
    pub(crate) fn local_curves<const D: usize>(&self, doc: &BlendingSplineDoc) -> PyResult<Bound<'py, PyList>> {
        let c = doc.curve::<D>().or_value_error()?;
        let samples = self.samples;
        let mut v = [Point::<D>::zeros(); 1];
        self.pieces(c.local_count(), vec![samples, D], |k, points| {
            let support = c.local_support(k);
            for i in 0..samples {
                c.eval_local(k, support.lerp(i as f64 / (samples - 1) as f64), &mut v);
                points.extend(v[0].iter());
            }
            (k, (support.start, support.end), c.origin(k))
        })
    }

    /// The local patches of a blending-spline surface document: support, origin and a
    /// `samples` × `samples` grid of points of each over its support.
    pub(crate) fn local_patches<const D: usize>(&self, doc: &BlendingSplineSurfaceDoc) -> PyResult<Bound<'py, PyList>> {
        let s = doc.surface::<D>().or_value_error()?;
        let (nu, nv) = s.local_count();
        let samples = self.samples;
        let mut v = [Point::<D>::zeros(); 1];
        let at = |i: usize| i as f64 / (samples - 1) as f64;
        self.pieces(nu * nv, vec![samples, samples, D], |piece, points| {
            let (k, l) = (piece / nv, piece % nv);
            let rect = s.local_support(k, l);
            for (i, j) in (0..samples).flat_map(|i| (0..samples).map(move |j| (i, j))) {
                s.eval_local((k, l), (rect.u.lerp(at(i)), rect.v.lerp(at(j))), 0, 0, &mut v);
                points.extend(v[0].iter());
            }
            ((k, l), ((rect.u.start, rect.u.end), (rect.v.start, rect.v.end)), s.origin(k, l))
        })
    }

    /// The list of `count` local pieces, each of the points `shape` gives (the last entry
    /// D): refused over the budget before any is sampled, then piece i's dict from
    /// `sample(i, points)`, which writes its points' coordinates and returns its index,
    /// support and origin.
    fn pieces<const D: usize, K: IntoPyObject<'py>, S: IntoPyObject<'py>>(
        &self,
        count: usize,
        shape: Vec<usize>,
        mut sample: impl FnMut(usize, &mut Vec<f64>) -> (K, S, Point<D>),
    ) -> PyResult<Bound<'py, PyList>> {
        let per_piece: usize = shape[..shape.len() - 1].iter().product();
        check_pieces::<D>(self.cost, count, per_piece)?;
        let list = PyList::empty(self.py);
        for i in 0..count {
            let mut points = Vec::with_capacity(per_piece * D);
            let (index, support, origin) = sample(i, &mut points);
            list.append(local_piece(self.py, index, support, origin.as_slice(), points, shape.clone())?)?;
        }
        Ok(list)
    }
}

/// Refuses `pieces` local pieces of `points` sampled points each in `D` coordinates over
/// the budget (the points held and evaluated), naming `samples`.
fn check_pieces<const D: usize>(cost: &ShapeCost, pieces: usize, points: usize) -> PyResult<()> {
    let n = pieces as f64 * points as f64;
    let request = Cost::new(n * D as f64 * F64, cost.evaluations(n, 0));
    budget::check_request("samples", &format!("{pieces} local pieces of {points} points"), cost, request)
}

/// The error for a blending-spline `method` called on a shape of another type.
pub(crate) fn only_on(method: &str, kinds: &str, type_name: &str) -> PyErr {
    value_error(format!("type: {method} works on {kinds}, not {type_name}"))
}

/// Refuses a time that is not finite.
pub(crate) fn check_time(t: f64) -> PyResult<()> {
    if !t.is_finite() {
        return Err(value_error(format!("t: must be finite, got {t}")));
    }
    Ok(())
}

/// Refuses sample counts per piece outside 2 ..= 10 000.
pub(crate) fn check_samples(samples: usize) -> PyResult<()> {
    if !(2..=10_000).contains(&samples) {
        return Err(value_error(format!("samples: need 2 to 10000 samples per piece, got {samples}")));
    }
    Ok(())
}
