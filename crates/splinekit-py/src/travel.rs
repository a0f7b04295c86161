//! Objects that travel: `pickle` (any protocol, 5 included), `copy.copy`, `copy.deepcopy`
//! and `==` for curves, surfaces, scenes and meshes (fit reports: `fit_report.rs`; `==` of
//! curves and surfaces: `shape_methods.rs`).
//!
//! A shape's state is its shape document — the JSON the command line reads — as a dict of
//! Python floats, which pickle stores as exact doubles; the object is rebuilt from it by
//! the same parser and builder that made the original, so an object unpickled in another
//! process evaluates bit for bit as the original. A `BSpline` made by `fit` carries its
//! `FitReport` along. Meshes, which have no document, travel as their arrays' bytes.
//! Two objects are `==` when their documents (meshes: their arrays) are equal.

use pyo3::prelude::*;
use pyo3::types::{PyBytes, PyTuple};
use splinekit_mesh::TriangleMesh;
use splinekit_scene::{CurveDocument, SceneDocument, SurfaceDocument};

use crate::curve::PyCurve;
use crate::curve_kinds::{PyBSpline, wrap};
use crate::documents::PyScene;
use crate::errors::{OrValueError, value_error};
use crate::fit_report::FitReport;
use crate::json_value::{to_python, to_value};
use crate::mesh::PyMesh;
use crate::surface::PySurface;
use crate::surface_kinds::surface_object;

/// `(splinekit._splinekit._restore, (tag, state, extra))`: what `__reduce__` returns.
fn reduce<'py>(
    py: Python<'py>,
    tag: &str,
    state: Bound<'py, PyAny>,
    extra: Bound<'py, PyAny>,
) -> PyResult<Bound<'py, PyTuple>> {
    let restore = py.import("splinekit._splinekit")?.getattr("_restore")?;
    let args = PyTuple::new(py, [tag.into_pyobject(py)?.into_any(), state, extra])?;
    PyTuple::new(py, [restore, args.into_any()])
}

/// Rebuilds an object from the state its `__reduce__` gave (the pickle protocol calls
/// this; it is not meant to be called by hand): `tag` is ``"curve"``, ``"surface"``,
/// ``"scene"``, ``"mesh"`` or ``"fit_report"``.
#[pyfunction]
pub fn _restore<'py>(
    py: Python<'py>,
    tag: &str,
    state: &Bound<'py, PyAny>,
    extra: &Bound<'py, PyAny>,
) -> PyResult<Bound<'py, PyAny>> {
    match tag {
        "curve" => {
            let doc = CurveDocument::from_value(to_value(state, "")?).or_value_error()?;
            let report = if extra.is_none() { None } else { Some(extra.cast::<FitReport>()?.clone().unbind()) };
            wrap(py, PyCurve::new(doc)?, report)
        }
        "surface" => surface_object(py, SurfaceDocument::from_value(to_value(state, "")?).or_value_error()?),
        "scene" => {
            let value = to_value(state, "")?;
            let doc = SceneDocument::from_value(value.clone()).or_value_error()?;
            Ok(Bound::new(py, PyScene { value, doc })?.into_any())
        }
        "mesh" => Ok(Bound::new(py, PyMesh { mesh: mesh_from_bytes(state)? })?.into_any()),
        "fit_report" => Ok(Bound::new(py, FitReport::from_state(state)?)?.into_any()),
        other => Err(value_error(format!("state: unknown object kind \"{other}\""))),
    }
}

#[pymethods]
impl PyCurve {
    /// The pickle state: the shape document (and a fitted B-spline's report).
    fn __reduce__<'py>(slf: &Bound<'py, Self>) -> PyResult<Bound<'py, PyTuple>> {
        let py = slf.py();
        let state = to_python(py, &slf.borrow().doc.to_value())?;
        let report = match slf.cast::<PyBSpline>() {
            Ok(b) => b.borrow().report.as_ref().map(|r| r.bind(py).clone().into_any()),
            Err(_) => None,
        };
        reduce(py, "curve", state, report.unwrap_or_else(|| py.None().into_bound(py)))
    }
}

#[pymethods]
impl PySurface {
    /// The pickle state: the shape document.
    fn __reduce__<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyTuple>> {
        reduce(py, "surface", to_python(py, &self.doc.to_value())?, py.None().into_bound(py))
    }
}

#[pymethods]
impl PyScene {
    /// The pickle state: the scene document as given.
    fn __reduce__<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyTuple>> {
        reduce(py, "scene", to_python(py, &self.value)?, py.None().into_bound(py))
    }

    /// Equal documents.
    fn __eq__(&self, other: PyRef<'_, PyScene>) -> bool {
        self.value == other.value
    }
}

#[pymethods]
impl PyMesh {
    /// The pickle state: positions, normals, uv, colours and triangles as little-endian
    /// bytes (exact, and compact under protocol 5).
    fn __reduce__<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyTuple>> {
        let m = &self.mesh;
        let parts = [
            bytes(py, m.positions.iter().flatten().flat_map(|x| x.to_le_bytes())),
            bytes(py, m.normals.iter().flatten().flat_map(|x| x.to_le_bytes())),
            bytes(py, m.uvs.iter().flatten().flat_map(|x| x.to_le_bytes())),
            bytes(py, m.colors.iter().flatten().flat_map(|x| x.to_le_bytes())),
            bytes(py, m.triangles.iter().flatten().flat_map(|x| x.to_le_bytes())),
        ];
        reduce(py, "mesh", PyTuple::new(py, parts)?.into_any(), py.None().into_bound(py))
    }

    /// The same vertices, normals, uv, colours and triangles.
    fn __eq__(&self, other: PyRef<'_, PyMesh>) -> bool {
        self.mesh == other.mesh
    }
}

fn bytes(py: Python<'_>, data: impl Iterator<Item = u8>) -> Bound<'_, PyAny> {
    PyBytes::new(py, &data.collect::<Vec<u8>>()).into_any()
}

/// Fixed-size little-endian records of `N` bytes read back as `T`.
fn records<T, const N: usize>(field: &str, b: &[u8], read: impl Fn([u8; N]) -> T) -> PyResult<Vec<T>> {
    if b.len() % N != 0 {
        return Err(value_error(format!("{field}: {} bytes are not whole values of {N} bytes", b.len())));
    }
    Ok(b.chunks_exact(N).map(|c| read(c.try_into().expect("N bytes"))).collect())
}

/// Groups of `K` values.
fn groups<T: Copy + Default, const K: usize>(field: &str, v: Vec<T>) -> PyResult<Vec<[T; K]>> {
    if v.len() % K != 0 {
        return Err(value_error(format!("{field}: {} values are not whole groups of {K}", v.len())));
    }
    Ok(v.chunks_exact(K).map(|c| c.try_into().expect("K values")).collect())
}

/// The mesh of a `PyMesh.__reduce__` state.
fn mesh_from_bytes(state: &Bound<'_, PyAny>) -> PyResult<TriangleMesh> {
    type Five<'py> =
        (Bound<'py, PyBytes>, Bound<'py, PyBytes>, Bound<'py, PyBytes>, Bound<'py, PyBytes>, Bound<'py, PyBytes>);
    let (p, n, uv, c, t): Five<'_> = state.extract()?;
    let mesh = TriangleMesh {
        positions: groups("positions", records("positions", p.as_bytes(), f64::from_le_bytes)?)?,
        normals: groups("normals", records("normals", n.as_bytes(), f64::from_le_bytes)?)?,
        uvs: groups("uv", records("uv", uv.as_bytes(), f64::from_le_bytes)?)?,
        colors: groups("colors", records("colors", c.as_bytes(), f32::from_le_bytes)?)?,
        triangles: groups("triangles", records("triangles", t.as_bytes(), u32::from_le_bytes)?)?,
    };
    let v = mesh.positions.len();
    if mesh.triangles.iter().flatten().any(|&i| i as usize >= v) {
        return Err(value_error(format!("triangles: a vertex index is not below the {v} vertices")));
    }
    Ok(mesh)
}
