//! The command line's geometric queries for Python: intersections (`splinekit intersect`),
//! plane sections (`section`), projections of many points (`project`), offsets
//! (`offset`) and arc length (`eval --arc-length`), each by the kernel calls the command
//! makes and answered in the command's JSON (`splinekit._splinekit._intersect` and the
//! other underscored functions), which `splinekit/_queries.py` turns into numpy arrays and
//! splinekit objects. Errors are the command's messages with its flags named as the Python
//! arguments (`tolerance: expected one number > 0, got '0'`).

use numpy::{PyArray1, PyArrayMethods};
use pyo3::prelude::*;
use serde_json::{Value, json};
use splinekit::Point;
use splinekit::curve::{Curve, CurveArcLength};
use splinekit::query::{ArcLengthTable, CurveProjector, Nearest, NearestOnSurface, SurfaceProjector};
use splinekit::surface::Surface;
use splinekit_scene::answers::{
    MAX_SECTION_LEVELS, OffsetCurve, intersect, offset_argument, offset_surface_document, sections,
};
use splinekit_scene::{CurveDocument, Curves, DimensionVisitor, DocumentError, ShapeDocument, Surfaces};

use crate::arrays::Numbers;
use crate::budget;
use crate::curve::PyCurve;
use crate::documents::any_document;
use crate::errors::{Failure, OrValueError, document_error, value_error};
use crate::json_value::to_python;

/// The shape document of a Python argument (a curve, a surface, or what `load` takes);
/// errors name the argument.
fn shape_document(ob: &Bound<'_, PyAny>, name: &str) -> PyResult<ShapeDocument> {
    let value = any_document(ob)?;
    ShapeDocument::from_value(value).map_err(|e| document_error(e.about(name)))
}

/// A number > 0 (`splinekit intersect`'s `positive`), named as the argument.
fn positive(name: &str, x: f64) -> PyResult<f64> {
    if x > 0.0 && x.is_finite() {
        Ok(x)
    } else {
        Err(value_error(format!("{name}: expected one number > 0, got '{x}'")))
    }
}

/// `splinekit intersect A [B]` as a dict of the command's JSON (the arguments `a`, `b`
/// name the shapes where the command says `A`, `B`).
#[pyfunction]
#[pyo3(signature = (a, b = None, tolerance = 1e-9, chord = 1e-4))]
pub fn _intersect<'py>(
    a: &Bound<'py, PyAny>,
    b: Option<&Bound<'py, PyAny>>,
    tolerance: f64,
    chord: f64,
) -> PyResult<Bound<'py, PyAny>> {
    let py = a.py();
    let (tolerance, chord) = (positive("tolerance", tolerance)?, positive("chord", chord)?);
    let a = shape_document(a, "a")?;
    let b = b.map(|b| shape_document(b, "b")).transpose()?;
    let value = py.detach(|| intersect(&a, b.as_ref(), ("a", "b"), tolerance, chord)).map_err(document_error)?;
    to_python(py, &value)
}

/// A 3-vector argument.
fn vector3(name: &str, ob: &Bound<'_, PyAny>) -> PyResult<Point<3>> {
    let numbers = Numbers::new(ob)?;
    match numbers.values() {
        [x, y, z] if x.is_finite() && y.is_finite() && z.is_finite() => Ok(Point::<3>::new(*x, *y, *z)),
        [_, _, _] => Err(value_error(format!("{name}: coordinates must be finite, got {:?}", numbers.values()))),
        v => Err(value_error(format!("{name}: expected 3 coordinates, got {}", v.len()))),
    }
}

/// `splinekit section SURFACE --plane O/N --levels L` as a dict `{"sections": […]}`.
#[pyfunction]
#[pyo3(signature = (surface, origin, normal, levels = 1, tolerance = 1e-9, chord = 1e-4))]
pub fn _section<'py>(
    surface: &Bound<'py, PyAny>,
    origin: &Bound<'py, PyAny>,
    normal: &Bound<'py, PyAny>,
    levels: usize,
    tolerance: f64,
    chord: f64,
) -> PyResult<Bound<'py, PyAny>> {
    let py = surface.py();
    let o = vector3("origin", origin)?;
    let n = vector3("normal", normal)?;
    if !(n.norm() > 0.0 && n.norm().is_finite()) {
        return Err(value_error(format!("normal: the normal must be a non-zero finite vector, got {n:?}")));
    }
    let n = n.normalize();
    let (tolerance, chord) = (positive("tolerance", tolerance)?, positive("chord", chord)?);
    if levels == 0 || levels > MAX_SECTION_LEVELS {
        return Err(value_error(format!("levels: expected 1 … {MAX_SECTION_LEVELS}, got {levels}")));
    }
    let doc = shape_document(surface, "surface")?;
    let value = py.detach(|| sections(doc, "surface", (&o, &n), levels, tolerance, chord)).map_err(document_error)?;
    to_python(py, &value)
}

/// `splinekit measure SHAPE [--tolerance T]` as a dict: a solid's (`brep`'s) topology,
/// exact area and volume and its watertight mesh's measures; another surface's adaptive
/// mesh measures; a scene's objects as `{"objects": […]}`.
#[pyfunction]
#[pyo3(signature = (shape, tolerance = None))]
pub fn _measure<'py>(shape: &Bound<'py, PyAny>, tolerance: Option<f64>) -> PyResult<Bound<'py, PyAny>> {
    let py = shape.py();
    // Each shape's box where its placement puts it (as `splinekit measure`).
    let one = |doc: ShapeDocument, placement: Option<&splinekit_scene::placement::PlacementDoc>| -> PyResult<Value> {
        let placement = placement.map(|p| p.transform()).transpose().map_err(document_error)?;
        let motion = placement.as_ref().map(|t| move |p: [f64; 3]| t.apply(p));
        let motion = motion.as_ref().map(|f| f as &(dyn Fn([f64; 3]) -> [f64; 3] + Sync));
        match doc {
            ShapeDocument::Surface(s) => {
                if let splinekit_scene::SurfaceDocument::Brep(d) = &s {
                    let brep = d.build().map_err(document_error)?;
                    return py
                        .detach(|| splinekit_mesh::measure::measure_brep(&brep, tolerance, motion))
                        .or_value_error();
                }
                budget::current()?.check_shape(&s.cost()).or_value_error()?;
                let surface = s.build_in::<3>().map_err(document_error)?;
                py.detach(|| splinekit_mesh::measure::measure_surface(surface.as_ref(), tolerance, motion))
                    .or_value_error()
            }
            ShapeDocument::Curve(c) => {
                Err(value_error(format!("shape: a {} is a curve; measure takes surfaces and solids", c.type_name())))
            }
        }
    };
    let value = match splinekit_scene::SceneOrShape::from_value(any_document(shape)?).map_err(document_error)? {
        splinekit_scene::SceneOrShape::Shape(doc) => one(doc, None)?,
        splinekit_scene::SceneOrShape::Scene(scene) => {
            let mut objects = Vec::with_capacity(scene.objects.len());
            for (i, o) in scene.objects.into_iter().enumerate() {
                let placement = o.placement.clone();
                objects.push(
                    one(o.shape, placement.as_ref()).map_err(|e| value_error(format!("objects[{i}].shape: {e}")))?,
                );
            }
            json!({ "objects": objects })
        }
    };
    to_python(py, &value)
}

/// Most points one call may project (as `splinekit project --points`).
const MAX_POINTS: usize = 1_000_000;

/// The nearest points of many query points, flat: parameters (1 or 2 a point), points
/// (D a point) and distances.
type Flat = (Vec<f64>, Vec<f64>, Vec<f64>);

/// Projects every query point: nearest points (flat) or every local minimum (JSON entries,
/// as `splinekit project --all`).
struct Project<'a> {
    points: &'a [f64],
    dim: usize,
    all: bool,
    accuracy: f64,
}

enum Projected {
    Nearest(Flat),
    Minima(Value),
}

impl Project<'_> {
    fn run<const D: usize, N>(
        &self,
        nearest: impl Fn(&Point<D>, f64) -> splinekit::Result<N>,
        minima: impl Fn(&Point<D>, f64) -> splinekit::Result<Vec<N>>,
        flat: impl Fn(&N, &mut Flat),
        entry: impl Fn(&N) -> Value,
    ) -> Result<Projected, Failure> {
        let queries = self.points.chunks_exact(self.dim).map(Point::<D>::from_column_slice);
        if self.all {
            let mut out = Vec::new();
            for q in queries {
                out.push(Value::Array(minima(&q, self.accuracy)?.iter().map(&entry).collect()));
            }
            return Ok(Projected::Minima(Value::Array(out)));
        }
        let mut out: Flat = Default::default();
        for q in queries {
            flat(&nearest(&q, self.accuracy)?, &mut out);
        }
        Ok(Projected::Nearest(out))
    }
}

fn coords<const D: usize>(p: &Point<D>) -> Vec<f64> {
    p.iter().copied().collect()
}

impl DimensionVisitor<Curves> for Project<'_> {
    type Output = Result<Projected, Failure>;
    fn visit<const D: usize>(self, curve: &dyn Curve<D>) -> Self::Output {
        let projector = CurveProjector::new(curve);
        self.run::<D, Nearest<D>>(
            |q, a| projector.nearest(q, a),
            |q, a| projector.local_minima(q, a),
            |n, out| {
                out.0.push(n.t);
                out.1.extend(n.point.iter());
                out.2.push(n.distance);
            },
            |n| json!({"t": n.t, "point": coords(&n.point), "distance": n.distance}),
        )
    }
}

impl DimensionVisitor<Surfaces> for Project<'_> {
    type Output = Result<Projected, Failure>;
    fn visit<const D: usize>(self, surface: &dyn Surface<D>) -> Self::Output {
        let projector = SurfaceProjector::new(surface);
        self.run::<D, NearestOnSurface<D>>(
            |q, a| projector.nearest(q, a),
            |q, a| projector.local_minima(q, a),
            |n, out| {
                out.0.extend([n.u, n.v]);
                out.1.extend(n.point.iter());
                out.2.push(n.distance);
            },
            |n| json!({"u": n.u, "v": n.v, "point": coords(&n.point), "distance": n.distance}),
        )
    }
}

/// `splinekit project SHAPE --points … [--all] [--accuracy E]`: for the nearest points the
/// tuple (params, points, distances) of arrays ((N,) or (N, 2), (N, D), (N,)); with `all`
/// the list of every point's local minima as the command writes them.
#[pyfunction]
#[pyo3(signature = (shape, points, all = false, accuracy = 0.0))]
pub fn _project<'py>(
    shape: &Bound<'py, PyAny>,
    points: &Bound<'py, PyAny>,
    all: bool,
    accuracy: f64,
) -> PyResult<Bound<'py, PyAny>> {
    let py = shape.py();
    if !(accuracy >= 0.0 && accuracy.is_finite()) {
        return Err(value_error(format!("accuracy: expected one number ≥ 0, got '{accuracy}'")));
    }
    let doc = shape_document(shape, "shape")?;
    let numbers = Numbers::new(points)?;
    let (n, d) = if numbers.shape().len() == 1 { (1, numbers.values().len()) } else { numbers.rows("points")? };
    crate::arrays::check_finite("points", numbers.values())?;
    if n > MAX_POINTS {
        return Err(value_error(format!("points: {n} points is more than the limit of {MAX_POINTS}")));
    }
    let dim = match &doc {
        ShapeDocument::Curve(c) => c.dimension(),
        ShapeDocument::Surface(s) => s.dimension(),
    }
    .or_value_error()?;
    if d != dim {
        return Err(value_error(format!("points: the shape is {dim}-D, the point has {d} coordinates")));
    }
    let values = numbers.values();
    let query = Project { points: values, dim, all, accuracy };
    let result = py
        .detach(|| -> Result<Projected, Failure> {
            match &doc {
                ShapeDocument::Curve(c) => c.build()?.visit(query),
                ShapeDocument::Surface(s) => s.build()?.visit(query),
            }
        })
        .map_err(Failure::into_py)?;
    match result {
        Projected::Minima(v) => to_python(py, &v),
        Projected::Nearest((params, pts, dist)) => {
            let per = params.len() / n.max(1);
            let params = PyArray1::from_vec(py, params);
            let params = if per == 2 { params.reshape([n, 2])?.into_any() } else { params.into_any() };
            let pts = PyArray1::from_vec(py, pts).reshape([n, dim])?;
            Ok((params, pts, PyArray1::from_vec(py, dist)).into_pyobject(py)?.into_any())
        }
    }
}

/// The error of an offset, named as the argument it is about (`tolerance: …`) or else as
/// about the shape (`shape: …`).
fn offset_error(e: splinekit::Error) -> PyErr {
    let named = match offset_argument(&e) {
        Some(_) => DocumentError::from(e),
        None => DocumentError::from(e).about("shape"),
    };
    document_error(named)
}

/// `splinekit offset SHAPE --distance D [--tolerance E] [--normal N]`: the documents of the
/// pieces (a list for a curve, one for a surface) and the line the command prints on
/// standard error.
#[pyfunction]
#[pyo3(signature = (shape, distance, tolerance = 1e-6, normal = None))]
pub fn _offset<'py>(
    shape: &Bound<'py, PyAny>,
    distance: f64,
    tolerance: f64,
    normal: Option<&Bound<'py, PyAny>>,
) -> PyResult<(Bound<'py, PyAny>, String)> {
    let py = shape.py();
    if !distance.is_finite() {
        return Err(value_error(format!("distance: expected one number, got '{distance}'")));
    }
    let tolerance = positive("tolerance", tolerance)?;
    let normal = normal
        .map(|n| {
            let numbers = Numbers::new(n)?;
            match numbers.values() {
                [x, y, z] => Ok(Point::<3>::new(*x, *y, *z)),
                other => Err(value_error(format!("normal: expected X,Y,Z, got {} numbers", other.len()))),
            }
        })
        .transpose()?;
    let doc = shape_document(shape, "shape")?;
    let cost = doc.cost();
    budget::current()?.check_shape(&cost).or_value_error()?;
    let (value, report) = match doc {
        ShapeDocument::Curve(c) => {
            let request = splinekit_scene::budget::offset_curve(cost.eval);
            budget::check_request("tolerance", "the offset's refinement", &cost, request)?;
            let curve = c.build().or_value_error()?;
            let (pieces, report) =
                py.detach(|| curve.visit(OffsetCurve { distance, tolerance, normal })).map_err(offset_error)?;
            let pieces = pieces.iter().map(CurveDocument::to_value).collect();
            (Value::Array(pieces), report)
        }
        ShapeDocument::Surface(s) => {
            if normal.is_some() {
                return Err(value_error(
                    "normal: only curves take a plane normal; a surface is offset along its own normal",
                ));
            }
            let dim = s.dimension().or_value_error()?;
            if dim != 3 {
                return Err(value_error(format!("shape: surface offsets are of 3-D surfaces, this one is {dim}-D")));
            }
            let request = splinekit_scene::budget::offset_surface(cost.eval);
            budget::check_request("tolerance", "the offset's refinement", &cost, request)?;
            let surface = s.build_in::<3>().map_err(|e| document_error(e.about("shape")))?;
            let (doc, report) =
                py.detach(|| offset_surface_document(surface.as_ref(), distance, tolerance)).map_err(offset_error)?;
            (doc.to_value(), report)
        }
    };
    Ok((to_python(py, &value)?, report))
}

/// Relative accuracy of the arc lengths behind `eval --arc-length` (of the curve's length).
const RELATIVE_ACCURACY: f64 = 1e-10;

/// The arc-length table's accuracy for a curve: `accuracy`, or [`RELATIVE_ACCURACY`] of a
/// rough length (as `splinekit eval --arc-length`).
fn table_accuracy<const D: usize>(curve: &dyn Curve<D>, accuracy: Option<f64>) -> f64 {
    accuracy.unwrap_or_else(|| RELATIVE_ACCURACY * curve.length(1e-6).max(f64::MIN_POSITIVE.sqrt()))
}

/// What one arc-length request computes.
enum ArcLength<'a> {
    /// Lengths from the start of the domain to each parameter.
    LengthsTo(&'a [f64], f64),
    /// Parameters at each length.
    ParamsAt(&'a [f64], Option<f64>),
    /// n parameters at equal spacing.
    Equal(usize),
}

impl DimensionVisitor<Curves> for ArcLength<'_> {
    type Output = splinekit::Result<Vec<f64>>;
    fn visit<const D: usize>(self, c: &dyn Curve<D>) -> Self::Output {
        let a = c.domain().start;
        match self {
            ArcLength::LengthsTo(ts, tolerance) => Ok(ts
                .iter()
                .map(|&t| {
                    let l = splinekit::ops::length::arc_length(c, splinekit::Interval::new(a, t.max(a)), tolerance);
                    if t < a { 0.0 } else { l }
                })
                .collect()),
            ArcLength::ParamsAt(ss, accuracy) => {
                let table = ArcLengthTable::new(c, table_accuracy(c, accuracy))?;
                ss.iter().map(|&s| table.parameter_at(s)).collect()
            }
            ArcLength::Equal(n) => ArcLengthTable::new(c, table_accuracy(c, None))?.equal_length_parameters(n),
        }
    }
}

/// A list of numbers out as a number or a 1-D array, as they came in.
fn shaped_like<'py>(py: Python<'py>, scalar: bool, v: Vec<f64>) -> PyResult<Bound<'py, PyAny>> {
    if scalar { Ok(v[0].into_pyobject(py)?.into_any()) } else { Ok(PyArray1::from_vec(py, v).into_any()) }
}

/// Most parameters one arc-length call may ask for (as `splinekit eval --samples`).
const MAX_SAMPLES: usize = 10_000_000;

#[pymethods]
impl PyCurve {
    /// Arc length from the start a of the domain to t, ∫ₐᵗ |c'|, to the absolute
    /// `tolerance`: a number for a number, an array (N,) for N parameters.
    #[pyo3(signature = (t, tolerance = 1e-10))]
    fn length_at<'py>(&self, t: &Bound<'py, PyAny>, tolerance: f64) -> PyResult<Bound<'py, PyAny>> {
        let py = t.py();
        if !(tolerance.is_finite() && tolerance > 0.0) {
            return Err(value_error(format!("tolerance: must be finite and > 0, got {tolerance}")));
        }
        let numbers = Numbers::new(t)?;
        let ts = numbers.list("t")?;
        crate::arrays::check_params("t", ts, Some(self.domain), "curve")?;
        let curve = &self.curve;
        let out = py.detach(|| curve.visit(ArcLength::LengthsTo(ts, tolerance))).or_value_error()?;
        shaped_like(py, numbers.is_scalar(), out)
    }

    /// The inverse of arc length: the parameter t with ``length_at(t) = s`` for 0 ≤ s ≤ L,
    /// within `accuracy` of length (default 10⁻¹⁰ of L, as ``eval --arc-length``); a
    /// number for a number, an array (N,) for N lengths.
    #[pyo3(signature = (s, accuracy = None))]
    fn param_at_length<'py>(&self, s: &Bound<'py, PyAny>, accuracy: Option<f64>) -> PyResult<Bound<'py, PyAny>> {
        let py = s.py();
        let numbers = Numbers::new(s)?;
        let ss = numbers.list("s")?;
        crate::arrays::check_finite("s", ss)?;
        let curve = &self.curve;
        let out = py.detach(|| curve.visit(ArcLength::ParamsAt(ss, accuracy))).or_value_error()?;
        shaped_like(py, numbers.is_scalar(), out)
    }

    /// n ≥ 2 parameters at equal arc-length spacing, ends included: those of ``splinekit
    /// eval --samples n --arc-length`` (consecutive lengths agree to 10⁻¹⁰ of the length).
    fn arc_length_params<'py>(&self, py: Python<'py>, n: usize) -> PyResult<Bound<'py, PyArray1<f64>>> {
        if n > MAX_SAMPLES {
            return Err(value_error(format!("n: {n} is more than the limit of {MAX_SAMPLES}")));
        }
        let curve = &self.curve;
        let out = if n < 2 {
            // As the command line: fewer than two samples are spread, not measured.
            let d = self.domain;
            (0..n).map(|_| d.start).collect()
        } else {
            py.detach(|| curve.visit(ArcLength::Equal(n))).or_value_error()?
        };
        Ok(PyArray1::from_vec(py, out))
    }
}

/// `splinekit._queries.NAME`: the methods below are these functions with the shape first.
fn query<'py>(py: Python<'py>, name: &str) -> PyResult<Bound<'py, PyAny>> {
    py.import("splinekit._queries")?.getattr(name)
}

macro_rules! query_methods {
    ($Class:ty) => {
        #[pymethods]
        impl $Class {
            /// ``splinekit.intersect(self, other, tolerance, chord)``: where this shape meets
            /// ``other`` (a curve without ``other``: where it crosses itself).
            #[pyo3(signature = (other = None, tolerance = 1e-9, chord = 1e-4))]
            fn intersect<'py>(
                slf: &Bound<'py, Self>,
                other: Option<&Bound<'py, PyAny>>,
                tolerance: f64,
                chord: f64,
            ) -> PyResult<Bound<'py, PyAny>> {
                query(slf.py(), "intersect")?.call1((slf, other, tolerance, chord))
            }

            /// ``splinekit.project(self, points, all, accuracy)``: the nearest points to many
            /// points at once.
            #[pyo3(signature = (points, all = false, accuracy = 0.0))]
            fn project<'py>(
                slf: &Bound<'py, Self>,
                points: &Bound<'py, PyAny>,
                all: bool,
                accuracy: f64,
            ) -> PyResult<Bound<'py, PyAny>> {
                query(slf.py(), "project")?.call1((slf, points, all, accuracy))
            }

            /// ``splinekit.offset(self, distance, tolerance, normal, report)``: the offset at a
            /// signed distance, as B-splines.
            #[pyo3(signature = (distance, tolerance = 1e-6, normal = None, report = false))]
            fn offset<'py>(
                slf: &Bound<'py, Self>,
                distance: f64,
                tolerance: f64,
                normal: Option<&Bound<'py, PyAny>>,
                report: bool,
            ) -> PyResult<Bound<'py, PyAny>> {
                query(slf.py(), "offset")?.call1((slf, distance, tolerance, normal, report))
            }
        }
    };
}

query_methods!(PyCurve);
query_methods!(crate::surface::PySurface);

#[pymethods]
impl crate::surface::PySurface {
    /// ``splinekit.section(self, origin, normal, levels, tolerance, chord)``: plane
    /// sections (contours).
    #[pyo3(signature = (origin, normal, levels = 1, tolerance = 1e-9, chord = 1e-4))]
    fn section<'py>(
        slf: &Bound<'py, Self>,
        origin: &Bound<'py, PyAny>,
        normal: &Bound<'py, PyAny>,
        levels: usize,
        tolerance: f64,
        chord: f64,
    ) -> PyResult<Bound<'py, PyAny>> {
        query(slf.py(), "section")?.call1((slf, origin, normal, levels, tolerance, chord))
    }
}
