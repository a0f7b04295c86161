//! The surface kinds with their own constructors and properties: `BSplineSurface`,
//! `NURBSSurface`, `BezierSurface` (control nets of shape (nu, nv, D), the first index
//! along u), each parsed as its shape document.

use numpy::{PyArray1, PyArrayDyn, PyArrayMethods};
use pyo3::prelude::*;
use splinekit_scene::{NetView, SurfaceDocument};

use crate::curve_kinds::document;
use crate::errors::{OrValueError, value_error};
use crate::kind_classes::stateless_own_classes;
use crate::surface::PySurface;

/// Knots in u and in v.
type KnotPair<'py> = (Bound<'py, PyArray1<f64>>, Bound<'py, PyArray1<f64>>);

/// The base object of a surface document given as JSON.
fn base(doc: serde_json::Value) -> PyResult<PyClassInitializer<PySurface>> {
    let doc = SurfaceDocument::from_value(doc).or_value_error()?;
    Ok(PyClassInitializer::from(PySurface::new(doc)?))
}

fn flag<'py>(py: Python<'py>, b: bool) -> PyResult<Bound<'py, PyAny>> {
    Ok(b.into_pyobject(py)?.to_owned().into_any())
}

impl PySurface {
    fn net(&self, name: &str) -> PyResult<NetView<'_>> {
        self.doc.spline().ok_or_else(|| {
            pyo3::exceptions::PyAttributeError::new_err(format!("a {} surface has no {name}", self.doc.type_name()))
        })
    }
}

#[pymethods]
impl PySurface {
    /// The control net P_ij, shape (nu, nv, D).
    #[getter]
    fn control_points<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyArrayDyn<f64>>> {
        let net = self.net("control_points")?.control_points;
        let net = &net[..];
        let (nu, nv, d) = (net.len(), net[0].len(), net[0][0].len());
        let flat: Vec<f64> = net.iter().flatten().flatten().copied().collect();
        PyArray1::from_vec(py, flat).reshape(vec![nu, nv, d]).map_err(value_error)
    }
    /// The knots in u and in v.
    #[getter]
    fn knots<'py>(&self, py: Python<'py>) -> PyResult<KnotPair<'py>> {
        let (u, v) = self
            .net("knots")?
            .knots
            .ok_or_else(|| pyo3::exceptions::PyAttributeError::new_err("a Bézier surface has no knots"))?;
        Ok((PyArray1::from_slice(py, &u), PyArray1::from_slice(py, &v)))
    }
    /// The weights w_ij, shape (nu, nv) (1 for non-rational nets).
    #[getter]
    fn weights<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyArrayDyn<f64>>> {
        let net = self.net("weights")?;
        let (nu, nv) = (net.control_points.len(), net.control_points[0].len());
        let flat: Vec<f64> = match net.weights {
            Some(w) => w.iter().flatten().copied().collect(),
            None => vec![1.0; nu * nv],
        };
        PyArray1::from_vec(py, flat).reshape(vec![nu, nv]).map_err(value_error)
    }
    /// The degrees (p, q) in u and v.
    #[getter]
    fn degrees(&self) -> PyResult<(usize, usize)> {
        Ok(self.net("degrees")?.degrees)
    }
}

/// The arguments of a tensor-product spline net (B-spline or NURBS), by field name: knots,
/// degrees and periodic flags in u and in v.
struct SplineNet<'a, 'py> {
    knots: [&'a Bound<'py, PyAny>; 2],
    control_points: &'a Bound<'py, PyAny>,
    weights: Option<&'a Bound<'py, PyAny>>,
    degrees: [&'a Bound<'py, PyAny>; 2],
    periodic: [bool; 2],
}

impl<'a, 'py> SplineNet<'a, 'py> {
    /// The arguments of a net without weights (a NURBS net adds them).
    fn new(
        knots: [&'a Bound<'py, PyAny>; 2],
        control_points: &'a Bound<'py, PyAny>,
        degrees: [&'a Bound<'py, PyAny>; 2],
        periodic: [bool; 2],
    ) -> Self {
        SplineNet { knots, control_points, weights: None, degrees, periodic }
    }

    /// The same net with weights (a NURBS net).
    fn weighted(self, weights: &'a Bound<'py, PyAny>) -> Self {
        SplineNet { weights: Some(weights), ..self }
    }

    /// The base object of the net's document of type `ty`.
    fn base(&self, ty: &str) -> PyResult<PyClassInitializer<PySurface>> {
        let py = self.control_points.py();
        let (pu, pv) = (flag(py, self.periodic[0])?, flag(py, self.periodic[1])?);
        base(document(
            ty,
            &[
                ("degree_u", Some(self.degrees[0])),
                ("degree_v", Some(self.degrees[1])),
                ("knots_u", Some(self.knots[0])),
                ("knots_v", Some(self.knots[1])),
                ("control_points", Some(self.control_points)),
                ("weights", self.weights),
                ("periodic_u", Some(&pu)),
                ("periodic_v", Some(&pv)),
            ],
        )?)
    }
}

/// The `#[new]` of a tensor-product spline-net class: `(knots_u, knots_v, control_points,
/// [weights,] degree_u, degree_v, periodic_u=False, periodic_v=False)`, the arguments
/// gathered in a [`SplineNet`] (weighted when the class takes `weights`) and parsed as the
/// document of type `$ty`. The one declaration of those arguments for `BSplineSurface` and
/// `NURBSSurface`, which differ only by the weights.
macro_rules! spline_net_new {
    ($Class:ident, $ty:literal $(, $weights:ident)?) => {
        #[pymethods]
        impl $Class {
            #[new]
            #[pyo3(signature = (knots_u, knots_v, control_points, $($weights,)? degree_u, degree_v, periodic_u = false, periodic_v = false))]
            #[allow(clippy::too_many_arguments)]
            fn new(
                knots_u: &Bound<'_, PyAny>,
                knots_v: &Bound<'_, PyAny>,
                control_points: &Bound<'_, PyAny>,
                $($weights: &Bound<'_, PyAny>,)?
                degree_u: &Bound<'_, PyAny>,
                degree_v: &Bound<'_, PyAny>,
                periodic_u: bool,
                periodic_v: bool,
            ) -> PyResult<PyClassInitializer<Self>> {
                let net = SplineNet::new([knots_u, knots_v], control_points, [degree_u, degree_v], [periodic_u, periodic_v]);
                $(let net = net.weighted($weights);)?
                Ok(net.base($ty)?.add_subclass($Class))
            }
        }
    };
}

/// Tensor-product B-spline surface S(u, v) = Σᵢ Σⱼ N_{i,p}(u) N_{j,q}(v) P_ij.
#[pyclass(extends = PySurface, module = "splinekit", name = "BSplineSurface")]
pub struct PyBSplineSurface;

spline_net_new!(PyBSplineSurface, "bspline_surface");

/// NURBS surface S(u, v) = Σ N_{i,p}(u) N_{j,q}(v) w_ij P_ij / Σ N_{i,p}(u) N_{j,q}(v) w_ij.
#[pyclass(extends = PySurface, module = "splinekit", name = "NURBSSurface")]
pub struct PyNurbsSurface;

spline_net_new!(PyNurbsSurface, "nurbs_surface", weights);

/// Tensor-product Bézier surface S(u, v) = Σ B_{i,n}(u) B_{j,m}(v) P_ij on [0, 1]².
#[pyclass(extends = PySurface, module = "splinekit", name = "BezierSurface")]
pub struct PyBezierSurface;

#[pymethods]
impl PyBezierSurface {
    #[new]
    fn new(control_points: &Bound<'_, PyAny>) -> PyResult<PyClassInitializer<Self>> {
        Ok(base(document("bezier_surface", &[("control_points", Some(control_points))])?)?
            .add_subclass(PyBezierSurface))
    }
}

stateless_own_classes!(PyBSplineSurface, PyNurbsSurface, PyBezierSurface);

/// The hand-written classes by the name of their kind's variant (`python(own)` in the
/// registry).
mod own {
    pub use super::PyBSplineSurface as BsplineSurface;
    pub use super::PyBezierSurface as BezierSurface;
    pub use super::PyNurbsSurface as NurbsSurface;
}

/// The base class of surface kinds.
type Base = PySurface;

splinekit_scene::surface_kinds!(crate::kind_classes::python_classes);

/// The Python object of a surface document: its kind's class (the registry's `python(…)`).
pub fn surface_object(py: Python<'_>, doc: SurfaceDocument) -> PyResult<Bound<'_, PyAny>> {
    wrap(py, PySurface::new(doc)?, None)
}
