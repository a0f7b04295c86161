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
use splinekit::query::offset::hermite_fit::MAX_TOTAL_PIECES;
use splinekit::query::offset::surface_offset::MAX_GRID_POINTS;
use splinekit::query::{
    ArcLengthTable, CurveIntersections, CurveProjector, CurveSurfaceIntersection, EarlyStop, IntersectionBranch,
    IntersectionKind, Nearest, NearestOnSurface, SurfaceProjector, intersect_curve_surface, intersect_curves,
    intersect_surfaces, offset_curve, offset_surface, self_intersections,
};
use splinekit::surface::Surface;
use splinekit::surface::model::Plane;
use splinekit_scene::budget::Cost;
use splinekit_scene::points::from_points;
use splinekit_scene::refine::bspline_doc;
use splinekit_scene::surfaces::BSplineSurfaceDoc;
use splinekit_scene::{CurveDocument, Curves, DimensionVisitor, ShapeDocument, SurfaceDocument, Surfaces};

use crate::arrays::Numbers;
use crate::budget;
use crate::curve::PyCurve;
use crate::documents::any_document;
use crate::errors::{OrValueError, value_error};
use crate::json_value::to_python;

type Answer = Result<Value, String>;

/// The shape document of a Python argument (a curve, a surface, or what `load` takes);
/// errors name the argument.
fn shape_document(ob: &Bound<'_, PyAny>, name: &str) -> PyResult<ShapeDocument> {
    let value = any_document(ob)?;
    ShapeDocument::from_value(value).map_err(|e| value_error(format!("{name}: {e}")))
}

/// A number > 0 (`splinekit intersect`'s `positive`), named as the argument.
fn positive(name: &str, x: f64) -> PyResult<f64> {
    if x > 0.0 && x.is_finite() {
        Ok(x)
    } else {
        Err(value_error(format!("{name}: expected one number > 0, got '{x}'")))
    }
}

fn kind_name(kind: IntersectionKind) -> &'static str {
    match kind {
        IntersectionKind::Crossing => "crossing",
        IntersectionKind::Tangent => "tangent",
    }
}

fn curve_surface_json(r: &[CurveSurfaceIntersection]) -> Value {
    let points: Vec<Value> = r
        .iter()
        .map(|p| json!({"params": [p.t, p.u, p.v], "point": [p.point.x, p.point.y, p.point.z], "kind": kind_name(p.kind)}))
        .collect();
    json!({"points": points, "overlaps": [], "curves": []})
}

/// Intersection branches as `splinekit intersect` writes them, each with its fitted
/// B-spline.
fn branches_json(branches: &[IntersectionBranch], fit: f64) -> Result<Vec<Value>, String> {
    branches
        .iter()
        .map(|b| {
            let stop = b.early_stop.map(|s| match s {
                EarlyStop::Tangential => "tangential",
                EarlyStop::StepLimit => "step_limit",
                EarlyStop::PointLimit => "point_limit",
            });
            let points: Vec<[f64; 3]> = b.points.iter().map(|p| [p.x, p.y, p.z]).collect();
            let (bspline, error) = match b.points.len() {
                0 | 1 => (Value::Null, Value::Null),
                _ => {
                    let f = b.fit_bspline(fit).map_err(|e| e.to_string())?;
                    (bspline_doc(&f.curve).to_value(), json!(f.max_error))
                }
            };
            Ok(json!({"points": points, "params_a": b.params_a, "params_b": b.params_b, "closed": b.closed,
                "tangent": b.tangent, "early_stop": stop, "bspline": bspline, "fit_error": error}))
        })
        .collect()
}

fn curves_json<const D: usize>(r: &CurveIntersections<D>) -> Value {
    let points: Vec<Value> = r
        .points
        .iter()
        .map(|p| {
            json!({"params": [p.t_a, p.t_b], "point": p.point.iter().collect::<Vec<_>>(), "kind": kind_name(p.kind)})
        })
        .collect();
    let overlaps: Vec<Value> =
        r.overlaps.iter().map(|o| json!({"params_a": [o.a.start, o.a.end], "params_b": [o.b.0, o.b.1]})).collect();
    json!({"points": points, "overlaps": overlaps, "curves": []})
}

struct IntersectCurves<'a> {
    b: Option<&'a CurveDocument>,
    tolerance: f64,
}

impl DimensionVisitor<Curves> for IntersectCurves<'_> {
    type Output = Answer;
    fn visit<const D: usize>(self, a: &dyn Curve<D>) -> Answer {
        let Some(doc) = self.b else {
            return Ok(curves_json(&self_intersections(a, self.tolerance).map_err(|e| e.to_string())?));
        };
        let dim = doc.dimension().map_err(|e| format!("b: {e}"))?;
        if dim != D {
            return Err(format!("b: the curves must have the same dimension, a is {D}-D and b is {dim}-D"));
        }
        let b = doc.build_in::<D>().map_err(|e| format!("b: {e}"))?;
        Ok(curves_json(&intersect_curves(a, b.as_ref(), self.tolerance).map_err(|e| e.to_string())?))
    }
}

fn curve_and_surface(c: &CurveDocument, s: &SurfaceDocument, (name_c, name_s): (&str, &str), tolerance: f64) -> Answer {
    for (name, dim) in [(name_c, c.dimension()), (name_s, s.dimension())] {
        let dim = dim.map_err(|e| format!("{name}: {e}"))?;
        if dim != 3 {
            return Err(format!("{name}: a curve and a surface intersect in 3-D only, this shape is {dim}-D"));
        }
    }
    let curve = c.build_in::<3>().map_err(|e| format!("{name_c}: {e}"))?;
    let surface = s.build_in::<3>().map_err(|e| format!("{name_s}: {e}"))?;
    Ok(curve_surface_json(
        &intersect_curve_surface(curve.as_ref(), surface.as_ref(), tolerance).map_err(|e| e.to_string())?,
    ))
}

fn two_surfaces(a: &SurfaceDocument, b: &SurfaceDocument, tolerance: f64, chord: f64) -> Answer {
    for (name, dim) in [("a", a.dimension()), ("b", b.dimension())] {
        let dim = dim.map_err(|e| format!("{name}: {e}"))?;
        if dim != 3 {
            return Err(format!("{name}: surfaces intersect in 3-D only, this surface is {dim}-D"));
        }
    }
    let sa = a.build_in::<3>().map_err(|e| format!("a: {e}"))?;
    let sb = b.build_in::<3>().map_err(|e| format!("b: {e}"))?;
    let branches = intersect_surfaces(sa.as_ref(), sb.as_ref(), tolerance, chord).map_err(|e| e.to_string())?;
    Ok(json!({"points": [], "overlaps": [], "curves": branches_json(&branches, chord)?}))
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
    let value = py
        .detach(|| -> Answer {
            match (&a, &b) {
                (ShapeDocument::Curve(a), b) => {
                    let b = match b {
                        None => None,
                        Some(ShapeDocument::Curve(b)) => Some(b),
                        Some(ShapeDocument::Surface(s)) => return curve_and_surface(a, s, ("a", "b"), tolerance),
                    };
                    a.build().map_err(|e| format!("a: {e}"))?.visit(IntersectCurves { b, tolerance })
                }
                (ShapeDocument::Surface(s), Some(ShapeDocument::Curve(c))) => {
                    curve_and_surface(c, s, ("b", "a"), tolerance)
                }
                (ShapeDocument::Surface(_), None) => {
                    Err("b: a surface needs a second shape (self-intersections of surfaces are not computed)".into())
                }
                (ShapeDocument::Surface(a), Some(ShapeDocument::Surface(b))) => two_surfaces(a, b, tolerance, chord),
            }
        })
        .map_err(value_error)?;
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

/// Most planes one call may cut with (as `splinekit section --levels`).
const MAX_LEVELS: usize = 100;

/// Heights (along n, from o) of the cuts, and the surface's centre and size (as
/// `splinekit section`).
fn levels(s: &dyn Surface<3>, o: &Point<3>, n: &Point<3>, count: usize) -> (Vec<f64>, Point<3>, f64) {
    let (du, dv) = (s.domain_u(), s.domain_v());
    let pts: Vec<Point<3>> =
        (0..33 * 33).map(|k| s.point(du.lerp((k / 33) as f64 / 32.0), dv.lerp((k % 33) as f64 / 32.0))).collect();
    let heights: Vec<f64> = pts.iter().map(|p| (p - o).dot(n)).collect();
    let (lo, hi) = heights.iter().fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &h| (a.min(h), b.max(h)));
    let centre = pts.iter().fold(Point::<3>::zeros(), |c, p| c + p) / pts.len() as f64;
    let size = splinekit::query::Aabb::around(&pts, 0.0).diagonal().max(1.0);
    let cuts = if count == 1 {
        vec![0.0]
    } else {
        (0..count).map(|k| lo + (hi - lo) * (k as f64 + 0.5) / count as f64).collect()
    };
    (cuts, centre, size)
}

/// A square plane at height h, centred on the surface and far larger than it.
fn big_plane(o: &Point<3>, n: &Point<3>, h: f64, centre: &Point<3>, size: f64) -> splinekit::Result<Plane> {
    let helper = if n.x.abs() < 0.9 { Point::<3>::x() } else { Point::<3>::y() };
    let (a, b) = (n.cross(&helper).normalize(), n.cross(&helper).normalize().cross(n));
    let foot = centre - n * ((centre - o).dot(n) - h);
    let (a, b) = (a * (4.0 * size), b * (4.0 * size));
    Plane::new(foot - (a + b) * 0.5, a, b)
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
    if levels == 0 || levels > MAX_LEVELS {
        return Err(value_error(format!("levels: expected 1 … {MAX_LEVELS}, got {levels}")));
    }
    let ShapeDocument::Surface(doc) = shape_document(surface, "surface")? else {
        return Err(value_error("surface: section cuts surfaces, this document is a curve"));
    };
    let dim = doc.dimension().or_value_error()?;
    if dim != 3 {
        return Err(value_error(format!("surface: sections are of 3-D surfaces, this one is {dim}-D")));
    }
    let value = py
        .detach(|| -> Answer {
            let s = doc.build_in::<3>().map_err(|e| format!("surface: {e}"))?;
            let (cuts, centre, size) = self::levels(s.as_ref(), &o, &n, levels);
            let mut sections = Vec::with_capacity(cuts.len());
            for h in cuts {
                let plane = big_plane(&o, &n, h, &centre, size).map_err(|e| e.to_string())?;
                let branches = intersect_surfaces(s.as_ref(), &plane, tolerance, chord).map_err(|e| e.to_string())?;
                let curves: Vec<Value> = branches_json(&branches, chord)?
                    .into_iter()
                    .map(|mut c| {
                        if let Some(m) = c.as_object_mut() {
                            m.remove("params_b");
                            if let Some(p) = m.remove("params_a") {
                                m.insert("params".into(), p);
                            }
                        }
                        c
                    })
                    .collect();
                let origin = o + n * h;
                sections.push(
                    json!({"origin": [origin.x, origin.y, origin.z], "normal": [n.x, n.y, n.z], "curves": curves}),
                );
            }
            Ok(json!({ "sections": sections }))
        })
        .map_err(value_error)?;
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
    ) -> Result<Projected, String> {
        let queries = self.points.chunks_exact(self.dim).map(Point::<D>::from_column_slice);
        if self.all {
            let mut out = Vec::new();
            for q in queries {
                out.push(Value::Array(
                    minima(&q, self.accuracy).map_err(|e| e.to_string())?.iter().map(&entry).collect(),
                ));
            }
            return Ok(Projected::Minima(Value::Array(out)));
        }
        let mut out: Flat = Default::default();
        for q in queries {
            flat(&nearest(&q, self.accuracy).map_err(|e| e.to_string())?, &mut out);
        }
        Ok(Projected::Nearest(out))
    }
}

fn coords<const D: usize>(p: &Point<D>) -> Vec<f64> {
    p.iter().copied().collect()
}

impl DimensionVisitor<Curves> for Project<'_> {
    type Output = Result<Projected, String>;
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
    type Output = Result<Projected, String>;
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
        .detach(|| -> Result<Projected, String> {
            match &doc {
                ShapeDocument::Curve(c) => c.build().map_err(|e| e.to_string())?.visit(query),
                ShapeDocument::Surface(s) => s.build().map_err(|e| e.to_string())?.visit(query),
            }
        })
        .map_err(value_error)?;
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

/// The argument a kernel error of an offset is about.
fn offset_error(e: splinekit::Error) -> String {
    let message = e.to_string();
    for field in ["distance", "tolerance", "normal"] {
        if message.strip_prefix(field).is_some_and(|r| r.starts_with(':')) {
            return message;
        }
    }
    format!("shape: {message}")
}

struct OffsetCurve {
    distance: f64,
    tolerance: f64,
    normal: Option<Point<3>>,
}

impl DimensionVisitor<Curves> for OffsetCurve {
    type Output = Result<(Vec<Value>, String), String>;
    fn visit<const D: usize>(self, curve: &dyn Curve<D>) -> Self::Output {
        let normal = if D == 3 { self.normal.or(Some(Point::<3>::z())) } else { self.normal };
        let off = offset_curve(curve, self.distance, normal, self.tolerance).map_err(offset_error)?;
        let report = format!(
            "offset: {} piece{}, max error {:.3e} (tolerance {:e}), {} cusps and {} self-intersections of the raw offset trimmed",
            off.pieces.len(),
            if off.pieces.len() == 1 { "" } else { "s" },
            off.max_error,
            self.tolerance,
            off.cusps.len(),
            off.crossings.len()
        );
        Ok((off.pieces.iter().map(|p| bspline_doc(&p.curve).to_value()).collect(), report))
    }
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
            let work = MAX_TOTAL_PIECES as f64 * 8.0 * 3.0 * cost.eval;
            let request = Cost::new(MAX_TOTAL_PIECES as f64 * 200.0, work);
            budget::check_request("tolerance", "the offset's refinement", &cost, request)?;
            let curve = c.build().or_value_error()?;
            let (pieces, report) =
                py.detach(|| curve.visit(OffsetCurve { distance, tolerance, normal })).map_err(value_error)?;
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
            let samples = 4.0 * 1.34 * MAX_GRID_POINTS as f64;
            let request = Cost::new(samples * 200.0, samples * 12.0 * cost.eval);
            budget::check_request("tolerance", "the offset's refinement", &cost, request)?;
            let surface = s.build_in::<3>().map_err(|e| value_error(format!("shape: {e}")))?;
            let off = py
                .detach(|| offset_surface(surface.as_ref(), distance, tolerance))
                .map_err(|e| value_error(offset_error(e)))?;
            let report = format!(
                "offset: max error {:.3e} (tolerance {:e}), {} × {} grid",
                off.max_error, tolerance, off.grid.0, off.grid.1
            );
            let b = &off.surface;
            let (ku, kv) = b.knots();
            let doc = SurfaceDocument::BsplineSurface(BSplineSurfaceDoc {
                degree_u: b.degrees().0,
                degree_v: b.degrees().1,
                knots_u: ku.to_vec(),
                knots_v: kv.to_vec(),
                control_points: b.control_points().iter().map(|row| from_points(row)).collect(),
                periodic_u: false,
                periodic_v: false,
            });
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
