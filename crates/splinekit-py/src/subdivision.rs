//! `splinekit.SubdivisionSurface`: a polygon cage (vertices, faces, creases, boundary
//! rule) under Catmull–Clark, Loop or bilinear subdivision, by the kernel's
//! `splinekit::subdivision::surface` — the code behind `splinekit subdivide-surface`.
//!
//! Refinement ([`SubdivisionSurface::subdivide`]) keeps vertex i of the cage as vertex i
//! of the result; limit points and normals come from the limit masks (eigen-analysis of
//! the local subdivision matrix: the dominant left eigenvector gives the limit point, the
//! two subdominant ones the tangents); `evaluate(face, u, v)` is exact (Stam's method:
//! the regular bicubic B-spline or quartic box-spline patch, reached by subdividing
//! around an extraordinary vertex until (u, v) lies in a regular sub-patch). The state
//! that pickles is the cage itself — coordinates as Python floats (exact doubles), faces
//! and crease vertices as ints, sharpness as floats — so an unpickled surface refines
//! and evaluates bit for bit as the original.

use numpy::{PyArray1, PyArrayDyn, PyArrayMethods};
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyTuple};
use splinekit::Point;
use splinekit::subdivision::surface::{BoundaryRule, Cage, Crease, LimitSample, Scheme, SubdivisionSurface as Kernel};
use splinekit_mesh::TriangleMesh;
use splinekit_mesh::limit_mesh::limit_mesh;

use splinekit_scene::budget::Cost;

use crate::arrays::Numbers;
use crate::budget;
use crate::errors::{OrValueError, value_error};
use crate::mesh::PyMesh;

/// A subdivision surface: its control cage and scheme.
#[pyclass(frozen, module = "splinekit", name = "SubdivisionSurface")]
pub struct PySubdivisionSurface {
    surface: Kernel,
}

fn scheme_from(name: &str) -> PyResult<Scheme> {
    match name {
        "catmull-clark" => Ok(Scheme::CatmullClark),
        "loop" => Ok(Scheme::Loop),
        "bilinear" => Ok(Scheme::Bilinear),
        other => {
            Err(value_error(format!("scheme: expected \"catmull-clark\", \"loop\" or \"bilinear\", got \"{other}\"")))
        }
    }
}

fn boundary_from(name: &str) -> PyResult<BoundaryRule> {
    match name {
        "edge-only" => Ok(BoundaryRule::EdgeOnly),
        "edge-and-corner" => Ok(BoundaryRule::EdgeAndCorner),
        other => Err(value_error(format!("boundary: expected \"edge-only\" or \"edge-and-corner\", got \"{other}\""))),
    }
}

fn boundary_name(b: BoundaryRule) -> &'static str {
    match b {
        BoundaryRule::EdgeOnly => "edge-only",
        BoundaryRule::EdgeAndCorner => "edge-and-corner",
    }
}

/// A vertex index named `field`: an int in 0..2³².
fn index(field: &str, i: i64) -> PyResult<u32> {
    u32::try_from(i).map_err(|_| value_error(format!("{field}: a vertex index must be ≥ 0 and below 2³², got {i}")))
}

/// Rows of 3 as an (n, 3) float64 array.
fn points<'py>(py: Python<'py>, p: impl Iterator<Item = Point<3>>) -> PyResult<Bound<'py, PyArrayDyn<f64>>> {
    let flat: Vec<f64> = p.flat_map(|q| [q.x, q.y, q.z]).collect();
    let n = flat.len() / 3;
    PyArray1::from_vec(py, flat).reshape(vec![n, 3]).map_err(value_error)
}

fn vector<'py>(py: Python<'py>, p: &Point<3>) -> Bound<'py, PyArray1<f64>> {
    PyArray1::from_vec(py, vec![p.x, p.y, p.z])
}

/// `{"position", "normal", "partials"}` as the command line's `--at` JSON, with arrays.
fn sample_dict<'py>(py: Python<'py>, s: &LimitSample) -> PyResult<Bound<'py, PyDict>> {
    let d = PyDict::new(py);
    d.set_item("position", vector(py, &s.position))?;
    d.set_item("normal", vector(py, &s.normal))?;
    match &s.partials {
        Some(p) => {
            let q = PyDict::new(py);
            for (k, v) in [("du", &p.du), ("dv", &p.dv), ("duu", &p.duu), ("duv", &p.duv), ("dvv", &p.dvv)] {
                q.set_item(k, vector(py, v))?;
            }
            d.set_item("partials", q)?;
        }
        None => d.set_item("partials", py.None())?,
    }
    Ok(d)
}

impl PySubdivisionSurface {
    /// Refuses `steps` steps over the command line's budget (`subdivide-surface --steps`):
    /// each step makes about four corners of every corner, each about 200 bytes and 300
    /// operations with its point and adjacency.
    fn check_steps(&self, steps: usize) -> PyResult<()> {
        let c = self.surface.cage();
        let out_corners = c.face_vertices.len() as f64 * 4f64.powi(steps.min(64) as i32);
        let what = format!("{steps} steps on {} faces", c.face_count());
        budget::current()?.check("steps", &what, Cost::new(out_corners * 200.0, out_corners * 300.0)).or_value_error()
    }

    /// The cage's arguments to the constructor: (vertices, faces, scheme, creases, boundary).
    fn arguments<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyTuple>> {
        let c = self.surface.cage();
        let vertices: Vec<[f64; 3]> = c.vertices.iter().map(|p| [p.x, p.y, p.z]).collect();
        let faces: Vec<Vec<u32>> = (0..c.face_count()).map(|f| c.face(f).to_vec()).collect();
        let creases: Vec<(u32, u32, f64)> = c.creases.iter().map(|k| (k.a, k.b, k.sharpness)).collect();
        (vertices, faces, self.surface.scheme().name(), creases, boundary_name(c.boundary)).into_pyobject(py)
    }
}

#[pymethods]
impl PySubdivisionSurface {
    /// A cage: ``vertices`` (V, 3), ``faces`` (lists of vertex indices, counter-clockwise
    /// seen from outside), ``scheme`` ``"catmull-clark"``, ``"loop"`` (triangles; set
    /// ``triangulate`` to split polygons into fans) or ``"bilinear"``, ``creases`` as
    /// ``(a, b, sharpness)`` edges (sharpness ≥ 10 or ``inf``: sharp; below: semi-sharp),
    /// ``boundary`` ``"edge-only"`` or ``"edge-and-corner"`` (corners of a single face
    /// interpolated).
    #[new]
    #[pyo3(signature = (vertices, faces, scheme = "catmull-clark", creases = None, boundary = "edge-only", triangulate = false))]
    fn new(
        vertices: &Bound<'_, PyAny>,
        faces: Vec<Vec<i64>>,
        scheme: &str,
        creases: Option<Vec<(i64, i64, f64)>>,
        boundary: &str,
        triangulate: bool,
    ) -> PyResult<Self> {
        let scheme = scheme_from(scheme)?;
        let boundary = boundary_from(boundary)?;
        let numbers = Numbers::new(vertices)?;
        let points: Vec<Point<3>> = if numbers.values().is_empty() && numbers.shape().first() == Some(&0) {
            Vec::new()
        } else {
            match numbers.rows("vertices")? {
                (_, 3) => numbers.values().chunks_exact(3).map(|c| Point::<3>::new(c[0], c[1], c[2])).collect(),
                (_, d) => return Err(value_error(format!("vertices: expected 3 coordinates per vertex, got {d}"))),
            }
        };
        let faces: Vec<Vec<u32>> = faces
            .iter()
            .enumerate()
            .map(|(f, face)| face.iter().map(|&i| index(&format!("faces[{f}]"), i)).collect())
            .collect::<PyResult<_>>()?;
        let creases: Vec<Crease> = creases
            .unwrap_or_default()
            .iter()
            .enumerate()
            .map(|(k, &(a, b, sharpness))| {
                Ok(Crease { a: index(&format!("creases[{k}]"), a)?, b: index(&format!("creases[{k}]"), b)?, sharpness })
            })
            .collect::<PyResult<_>>()?;
        let cage = Cage::new(points, &faces).with_creases(creases).with_boundary(boundary);
        Ok(PySubdivisionSurface { surface: Kernel::new(cage, scheme, triangulate).or_value_error()? })
    }

    /// Cage vertex positions, shape (V, 3).
    #[getter]
    fn vertices<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyArrayDyn<f64>>> {
        points(py, self.surface.cage().vertices.iter().copied())
    }
    /// Cage faces as lists of vertex indices.
    #[getter]
    fn faces(&self) -> Vec<Vec<u32>> {
        let c = self.surface.cage();
        (0..c.face_count()).map(|f| c.face(f).to_vec()).collect()
    }
    /// Creased edges as ``(a, b, sharpness)``.
    #[getter]
    fn creases(&self) -> Vec<(u32, u32, f64)> {
        self.surface.cage().creases.iter().map(|k| (k.a, k.b, k.sharpness)).collect()
    }
    /// ``"catmull-clark"``, ``"loop"`` or ``"bilinear"``.
    #[getter]
    fn scheme(&self) -> &'static str {
        self.surface.scheme().name()
    }
    /// ``"edge-only"`` or ``"edge-and-corner"``.
    #[getter]
    fn boundary(&self) -> &'static str {
        boundary_name(self.surface.cage().boundary)
    }

    /// The ``subdivision_surface`` document of this cage (docs/format.md), which scenes,
    /// ``splinekit.load`` and the command line read; sharpness 10 or more (infinitely
    /// sharp) is written as 10.
    fn to_dict<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        let cage = self.surface.cage();
        let vertices: Vec<[f64; 3]> = cage.vertices.iter().map(|p| [p.x, p.y, p.z]).collect();
        let creases: Vec<serde_json::Value> = cage
            .creases
            .iter()
            .map(|k| serde_json::json!({"edge": [k.a, k.b], "sharpness": k.sharpness.min(10.0)}))
            .collect();
        let doc = serde_json::json!({
            "type": "subdivision_surface",
            "vertices": vertices,
            "faces": self.faces(),
            "scheme": self.scheme(),
            "creases": creases,
            "boundary": self.boundary(),
        });
        crate::json_value::to_python(py, &doc)
    }

    /// ``steps`` subdivision steps: a new ``SubdivisionSurface`` whose cage is the refined
    /// mesh (vertex i of this cage stays vertex i; semi-sharp creases decay by 1 a step);
    /// refused over the command line's budget (``SPLINEKIT_MAX_MEMORY``, ``SPLINEKIT_MAX_WORK``).
    fn subdivide(&self, py: Python<'_>, steps: usize) -> PyResult<Self> {
        self.check_steps(steps)?;
        let s = &self.surface;
        Ok(PySubdivisionSurface { surface: py.detach(|| s.subdivide(steps)).or_value_error()? })
    }

    /// The limit point of every cage vertex, in vertex order, shape (V, 3) (limit masks;
    /// bilinear: the vertices themselves).
    fn limit_points<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyArrayDyn<f64>>> {
        let s = &self.surface;
        let frames = py.detach(|| s.limit_frames()).or_value_error()?;
        points(py, frames.iter().map(|f| f.position))
    }

    /// The unit limit normal at every cage vertex, in vertex order, shape (V, 3).
    fn limit_normals<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyArrayDyn<f64>>> {
        let s = &self.surface;
        let frames = py.detach(|| s.limit_frames()).or_value_error()?;
        points(py, frames.iter().map(|f| f.normal))
    }

    /// The limit surface at (``u``, ``v``) of quad ``face`` (Catmull–Clark, bilinear;
    /// [0, 1]²) or triangle ``face`` (Loop; u, v ≥ 0, u + v ≤ 1), exactly: a dict with
    /// ``position`` and unit ``normal`` (arrays of 3) and ``partials`` (a dict of ``du``,
    /// ``dv``, ``duu``, ``duv``, ``dvv``; ``None`` at an extraordinary vertex), as
    /// ``splinekit subdivide-surface --at FACE,U,V`` prints.
    fn evaluate<'py>(&self, py: Python<'py>, face: usize, u: f64, v: f64) -> PyResult<Bound<'py, PyDict>> {
        let s = &self.surface;
        let sample = py.detach(|| s.evaluate(face, u, v)).or_value_error()?;
        sample_dict(py, &sample)
    }

    /// A triangle ``Mesh`` of the cage after ``steps`` steps (polygons split into fans):
    /// with ``limit``, every vertex moved onto the limit surface with its limit normal
    /// (as ``subdivide-surface --limit``); else the refined cage with area-weighted
    /// normals.
    #[pyo3(signature = (steps = 3, limit = true))]
    fn to_mesh(&self, py: Python<'_>, steps: usize, limit: bool) -> PyResult<PyMesh> {
        self.check_steps(steps)?;
        let s = &self.surface;
        let mesh = py
            .detach(|| -> splinekit::Result<TriangleMesh> {
                let r = s.subdivide(steps)?;
                if limit {
                    return limit_mesh(&r).map(|m| m.triangles());
                }
                let c = r.cage();
                let poly = splinekit_mesh::subdivision_surface::PolygonMesh {
                    vertices: c.vertices.iter().map(|p| [p.x, p.y, p.z]).collect(),
                    faces: (0..c.face_count()).map(|f| c.face(f).to_vec()).collect(),
                };
                Ok(poly.triangulate())
            })
            .or_value_error()?;
        Ok(PyMesh { mesh })
    }

    /// The pickle state: the constructor's arguments (the cage: floats, ints, names).
    fn __reduce__<'py>(slf: &Bound<'py, Self>) -> PyResult<Bound<'py, PyTuple>> {
        let py = slf.py();
        let args = slf.borrow().arguments(py)?;
        PyTuple::new(py, [slf.get_type().into_any(), args.into_any()])
    }

    /// The same cage (vertices, faces, creases, boundary rule) and scheme.
    fn __eq__(&self, other: PyRef<'_, PySubdivisionSurface>) -> bool {
        self.surface.scheme() == other.surface.scheme() && self.surface.cage() == other.surface.cage()
    }

    fn __repr__(&self) -> String {
        let c = self.surface.cage();
        format!(
            "<splinekit SubdivisionSurface ({}) of {} vertices, {} faces, {} creases>",
            self.surface.scheme().name(),
            c.vertices.len(),
            c.face_count(),
            c.creases.len()
        )
    }
}
