//! The curve kinds with their own constructors and properties: `BSpline`, `NURBS`,
//! `Bezier`, `RationalBezier`, `Hermite`, `CatmullRom`. Each builds the shape document
//! of its kind from the arguments and parses it like a JSON file, so every check and
//! message is the command line's.

use numpy::{PyArray1, PyArray2};
use pyo3::prelude::*;
use serde_json::{Map, Value};
use splinekit_scene::{CurveDocument, SplineView};

use crate::curve::PyCurve;
use crate::errors::{OrValueError, value_error};
use crate::fit_report::FitReport;
use crate::json_value::to_value;
use crate::kind_classes::{OwnClass, stateless_own_classes};

/// The document `{"type": ty, name: value, …}` from Python arguments (None skipped).
pub fn document(ty: &str, fields: &[(&str, Option<&Bound<'_, PyAny>>)]) -> PyResult<Value> {
    let mut map = Map::new();
    map.insert("type".into(), Value::String(ty.into()));
    for (name, value) in fields {
        if let Some(v) = value {
            if !v.is_none() {
                map.insert((*name).into(), to_value(v, name)?);
            }
        }
    }
    Ok(Value::Object(map))
}

/// The base object of a curve document given as JSON.
pub fn base(doc: Value) -> PyResult<PyClassInitializer<PyCurve>> {
    let doc = CurveDocument::from_value(doc).or_value_error()?;
    Ok(PyClassInitializer::from(PyCurve::new(doc)?))
}

/// Points as an (n, D) array.
pub fn points_array<'py>(py: Python<'py>, points: &[Vec<f64>]) -> PyResult<Bound<'py, PyArray2<f64>>> {
    PyArray2::from_vec2(py, points).map_err(value_error)
}

/// Properties shared by the four control-point kinds (the base class's document).
#[pymethods]
impl PyCurve {
    /// The control points P_i, shape (n, D) (Bézier, rational Bézier, B-spline, NURBS).
    #[getter]
    fn control_points<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyArray2<f64>>> {
        points_array(py, &self.fields("control_points")?.control_points)
    }
    /// The knot vector t_0 … t_{n+p}, shape (n + p + 1,) (B-spline and NURBS).
    #[getter]
    fn knots<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyArray1<f64>>> {
        let knots = self.fields("knots")?.knots.ok_or_else(|| no_field(&self.doc, "knots"))?;
        Ok(PyArray1::from_slice(py, &knots))
    }
    /// The weights w_i > 0, shape (n,) (rational kinds; 1 for the others).
    #[getter]
    fn weights<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyArray1<f64>>> {
        let f = self.fields("weights")?;
        let w = f.weights.map(|w| w.to_vec()).unwrap_or_else(|| vec![1.0; f.control_points.len()]);
        Ok(PyArray1::from_vec(py, w))
    }
    /// The degree p.
    #[getter]
    fn degree(&self) -> PyResult<usize> {
        Ok(self.fields("degree")?.degree)
    }
}

impl PyCurve {
    fn fields(&self, name: &str) -> PyResult<SplineView<'_>> {
        self.doc.spline().ok_or_else(|| no_field(&self.doc, name))
    }
}

fn no_field(doc: &CurveDocument, name: &str) -> PyErr {
    pyo3::exceptions::PyAttributeError::new_err(format!("a {} curve has no {name}", doc.type_name()))
}

/// B-spline curve c(t) = Σᵢ N_{i,p}(t) Pᵢ on [t_p, t_n], n control points, n + p + 1
/// knots (scipy's ``BSpline(t, c, k)`` order). ``periodic=True`` makes it closed: the
/// control points wrap around and the knots must repeat their spacing with period n.
#[pyclass(extends = PyCurve, module = "splinekit", name = "BSpline")]
pub struct PyBSpline {
    pub(crate) report: Option<Py<FitReport>>,
}

#[pymethods]
impl PyBSpline {
    #[new]
    #[pyo3(signature = (knots, control_points, degree, periodic = false))]
    fn new(
        knots: &Bound<'_, PyAny>,
        control_points: &Bound<'_, PyAny>,
        degree: &Bound<'_, PyAny>,
        periodic: bool,
    ) -> PyResult<PyClassInitializer<Self>> {
        let py = knots.py();
        let periodic = periodic.into_pyobject(py)?.to_owned().into_any();
        let doc = document(
            "bspline",
            &[
                ("degree", Some(degree)),
                ("knots", Some(knots)),
                ("control_points", Some(control_points)),
                ("periodic", Some(&periodic)),
            ],
        )?;
        Ok(base(doc)?.add_subclass(PyBSpline { report: None }))
    }
    /// The fit's quality (RMS and maximum error, condition estimate) for a curve made by
    /// ``splinekit.fit``; None otherwise.
    #[getter]
    fn fit_report(&self, py: Python<'_>) -> Option<Py<FitReport>> {
        self.report.as_ref().map(|r| r.clone_ref(py))
    }
}

/// NURBS curve C(t) = Σ N_{i,p}(t) wᵢ Pᵢ / Σ N_{i,p}(t) wᵢ with weights wᵢ > 0.
#[pyclass(extends = PyCurve, module = "splinekit", name = "NURBS")]
pub struct PyNurbs;

#[pymethods]
impl PyNurbs {
    #[new]
    #[pyo3(signature = (knots, control_points, weights, degree, periodic = false))]
    fn new(
        knots: &Bound<'_, PyAny>,
        control_points: &Bound<'_, PyAny>,
        weights: &Bound<'_, PyAny>,
        degree: &Bound<'_, PyAny>,
        periodic: bool,
    ) -> PyResult<PyClassInitializer<Self>> {
        let periodic = periodic.into_pyobject(knots.py())?.to_owned().into_any();
        let doc = document(
            "nurbs",
            &[
                ("degree", Some(degree)),
                ("knots", Some(knots)),
                ("control_points", Some(control_points)),
                ("weights", Some(weights)),
                ("periodic", Some(&periodic)),
            ],
        )?;
        Ok(base(doc)?.add_subclass(PyNurbs))
    }
}

/// Bézier curve c(t) = Σᵢ B_{i,n}(t) Pᵢ on [0, 1], Bernstein polynomials
/// B_{i,n}(t) = C(n, i) tⁱ (1 − t)ⁿ⁻ⁱ (evaluated by de Casteljau).
#[pyclass(extends = PyCurve, module = "splinekit", name = "Bezier")]
pub struct PyBezier;

#[pymethods]
impl PyBezier {
    #[new]
    fn new(control_points: &Bound<'_, PyAny>) -> PyResult<PyClassInitializer<Self>> {
        Ok(base(document("bezier", &[("control_points", Some(control_points))])?)?.add_subclass(PyBezier))
    }
}

/// Rational Bézier curve c(t) = Σ B_{i,n}(t) wᵢ Pᵢ / Σ B_{i,n}(t) wᵢ on [0, 1] (conics
/// exactly: a quadratic with middle weight cos(θ/2) is a circular arc of sweep θ).
#[pyclass(extends = PyCurve, module = "splinekit", name = "RationalBezier")]
pub struct PyRationalBezier;

#[pymethods]
impl PyRationalBezier {
    #[new]
    fn new(control_points: &Bound<'_, PyAny>, weights: &Bound<'_, PyAny>) -> PyResult<PyClassInitializer<Self>> {
        let doc = document("rational_bezier", &[("control_points", Some(control_points)), ("weights", Some(weights))])?;
        Ok(base(doc)?.add_subclass(PyRationalBezier))
    }
}

/// Piecewise cubic Hermite spline through ``points`` with first derivatives ``tangents``
/// at the parameters ``params`` (default 0, 1, …, m − 1): on [tᵢ, tᵢ₊₁] with h = tᵢ₊₁ − tᵢ
/// and s = (t − tᵢ)/h, c = h₀₀(s)Pᵢ + h h₁₀(s)Tᵢ + h₀₁(s)Pᵢ₊₁ + h h₁₁(s)Tᵢ₊₁.
#[pyclass(extends = PyCurve, module = "splinekit", name = "Hermite")]
pub struct PyHermite;

#[pymethods]
impl PyHermite {
    #[new]
    #[pyo3(signature = (points, tangents, params = None))]
    fn new(
        points: &Bound<'_, PyAny>,
        tangents: &Bound<'_, PyAny>,
        params: Option<&Bound<'_, PyAny>>,
    ) -> PyResult<PyClassInitializer<Self>> {
        let doc = document("hermite", &[("points", Some(points)), ("tangents", Some(tangents)), ("params", params)])?;
        Ok(base(doc)?.add_subclass(PyHermite))
    }
}

/// Catmull–Rom spline through ``points``: α = 0 uniform, ½ centripetal, 1 chordal
/// parameters (Barry–Goldman pyramid); ``closed=True`` joins the last point to the first.
#[pyclass(extends = PyCurve, module = "splinekit", name = "CatmullRom")]
pub struct PyCatmullRom;

#[pymethods]
impl PyCatmullRom {
    #[new]
    #[pyo3(signature = (points, alpha = 0.0, closed = false))]
    fn new(points: &Bound<'_, PyAny>, alpha: f64, closed: bool) -> PyResult<PyClassInitializer<Self>> {
        let py = points.py();
        let alpha = alpha.into_pyobject(py)?.into_any();
        let closed = closed.into_pyobject(py)?.to_owned().into_any();
        let doc =
            document("catmull_rom", &[("points", Some(points)), ("alpha", Some(&alpha)), ("closed", Some(&closed))])?;
        Ok(base(doc)?.add_subclass(PyCatmullRom))
    }
}

/// The Python object of a curve document: its kind's class, else a plain `Curve`.
pub fn curve_object(py: Python<'_>, doc: CurveDocument) -> PyResult<Bound<'_, PyAny>> {
    wrap(py, PyCurve::new(doc)?, None)
}

impl OwnClass for PyBSpline {
    fn made(report: Option<Py<FitReport>>) -> Self {
        PyBSpline { report }
    }
}

stateless_own_classes!(PyNurbs, PyBezier, PyRationalBezier, PyHermite, PyCatmullRom);

/// The hand-written classes by the name of their kind's variant (`python(own)` in the
/// registry).
mod own {
    pub use super::PyBSpline as Bspline;
    pub use super::PyBezier as Bezier;
    pub use super::PyCatmullRom as CatmullRom;
    pub use super::PyHermite as Hermite;
    pub use super::PyNurbs as Nurbs;
    pub use super::PyRationalBezier as RationalBezier;
}

/// The base class of curve kinds.
type Base = PyCurve;

splinekit_scene::curve_kinds!(crate::kind_classes::python_classes);
