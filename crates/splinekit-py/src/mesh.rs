//! Tessellation: curves as polylines, surfaces as triangle meshes (regular grids with
//! welded seams, or adaptive quad-trees to a chord height), by the functions
//! ``splinekit tessellate`` calls, and the mesh's files by extension.

use numpy::{PyArray1, PyArray2, PyArrayDyn, PyArrayMethods};
use pyo3::prelude::*;
use splinekit::curve::Curve;
use splinekit::surface::Surface;
use splinekit_mesh::export::by_extension::{mesh_bytes, object_name};
use splinekit_mesh::export::{Format, Subject};
use splinekit_mesh::surface_mesh::{adaptive_with_limit, regular};
use splinekit_mesh::{AdaptiveTolerance, MeshOptions, Polyline, TriangleMesh};
use splinekit_scene::budget::{polyline, regular_mesh};
use splinekit_scene::{Curves, DimensionVisitor, Surfaces};

use crate::budget;
use crate::curve::PyCurve;
use crate::errors::{OrValueError, value_error};
use crate::surface::PySurface;

/// Most points of one polyline (as the command line).
pub(crate) const MAX_CURVE_POINTS: usize = 1_000_000;
/// Most cells per direction of a regular surface mesh (as the command line).
pub(crate) const MAX_DENSITY: usize = 2048;
/// Most quad-tree leaves of an adaptive mesh.
pub(crate) const MAX_ADAPTIVE_CELLS: usize = 1_000_000;

/// A triangle mesh: ``vertices`` (V, 3), ``faces`` (F, 3) int32 counter-clockwise around
/// their normal, unit vertex ``normals`` (V, 3), surface parameters ``uv`` (V, 2) on
/// [0, 1]² over the domain.
#[pyclass(frozen, module = "splinekit", name = "Mesh")]
pub struct PyMesh {
    pub(crate) mesh: TriangleMesh,
}

fn rows<'py, const N: usize, T: numpy::Element + Copy>(
    py: Python<'py>,
    v: &[[T; N]],
) -> PyResult<Bound<'py, PyArrayDyn<T>>> {
    let flat: Vec<T> = v.iter().flatten().copied().collect();
    PyArray1::from_vec(py, flat).reshape(vec![v.len(), N]).map_err(value_error)
}

#[pymethods]
impl PyMesh {
    /// Vertex positions, shape (V, 3).
    #[getter]
    fn vertices<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyArrayDyn<f64>>> {
        rows(py, &self.mesh.positions)
    }
    /// Triangles as vertex indices, shape (F, 3), int32.
    #[getter]
    fn faces<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyArrayDyn<i32>>> {
        let t: Vec<[i32; 3]> = self.mesh.triangles.iter().map(|f| f.map(|i| i as i32)).collect();
        rows(py, &t)
    }
    /// Unit vertex normals, shape (V, 3).
    #[getter]
    fn normals<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyArrayDyn<f64>>> {
        rows(py, &self.mesh.normals)
    }
    /// Surface parameters per vertex on [0, 1]², shape (V, 2).
    #[getter]
    fn uv<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyArrayDyn<f64>>> {
        rows(py, &self.mesh.uvs)
    }
    /// Writes the mesh; the extension picks the format: .obj (normals and uv), .stl
    /// (binary), .stla (ASCII STL), .ply (ASCII), .gltf or .glb.
    fn save(&self, path: std::path::PathBuf) -> PyResult<()> {
        let format = Subject::Mesh
            .check(Format::of_path(&path), &path.display().to_string())
            .map_err(|e| value_error(format!("path: {e}")))?;
        let bytes = mesh_bytes(std::borrow::Cow::Borrowed(&self.mesh), &object_name(&path), format).or_value_error()?;
        splinekit_scene::write_file(&path, &bytes)
            .map_err(|e| crate::errors::file_error(format!("path: cannot write '{}': {e}", path.display())))
    }
    fn __repr__(&self) -> String {
        format!("<splinekit Mesh of {} vertices, {} triangles>", self.mesh.positions.len(), self.mesh.triangles.len())
    }
}

/// The polyline of a curve: `density` segments, or adaptive to `tolerance`, or adaptive
/// to 1/1000 of the curve's size.
pub(crate) struct CurvePoints(pub Option<usize>, pub Option<f64>);

impl DimensionVisitor<Curves> for CurvePoints {
    type Output = splinekit::Result<(Vec<f64>, usize)>;
    fn visit<const D: usize>(self, c: &dyn Curve<D>) -> Self::Output {
        let poly = match (self.0, self.1) {
            (Some(n), _) if n > MAX_CURVE_POINTS => Err(splinekit::Error::invalid(
                "density",
                format!("at most {MAX_CURVE_POINTS} segments per polyline, got {n}"),
            )),
            (Some(n), _) => Polyline::regular(c, n),
            (None, Some(t)) => Polyline::adaptive_with_limit(c, t, MAX_CURVE_POINTS),
            (None, None) => Polyline::adaptive_by_size(c, MAX_CURVE_POINTS),
        }?;
        Ok((poly.points.iter().flat_map(|p| p.iter().copied()).collect(), D))
    }
}

/// The triangle mesh of a surface: `density` cells per direction, or adaptive to the
/// chord height `tolerance` with at most the given number of cells, or a regular 64 × 64
/// grid.
pub(crate) struct SurfaceTriangles(pub Option<usize>, pub Option<f64>, pub usize);

impl DimensionVisitor<Surfaces> for SurfaceTriangles {
    type Output = splinekit::Result<TriangleMesh>;
    fn visit<const D: usize>(self, s: &dyn Surface<D>) -> Self::Output {
        let options = MeshOptions { uv: true };
        match (self.0, self.1) {
            (Some(n), _) if n == 0 || n > MAX_DENSITY => Err(splinekit::Error::invalid(
                "density",
                format!("between 1 and {MAX_DENSITY} cells per direction, got {n}"),
            )),
            (Some(n), _) => regular(s, n, n, options),
            (None, Some(t)) => {
                let tolerance = AdaptiveTolerance { chord_height: t, normal_angle: 0.2, max_depth: 10 };
                adaptive_with_limit(s, (8, 8), tolerance, options, self.2)
            }
            (None, None) => regular(s, 64, 64, options),
        }
    }
}

#[pymethods]
impl PyCurve {
    /// The curve as a polyline, shape (N, D): ``density`` equal parameter steps, or
    /// adaptive so no chord is farther than ``tolerance`` from the curve (default: 1/1000
    /// of the curve's size). A closed curve's last point is not repeated.
    #[pyo3(signature = (density = None, tolerance = None))]
    fn tessellate<'py>(
        &self,
        py: Python<'py>,
        density: Option<usize>,
        tolerance: Option<f64>,
    ) -> PyResult<Bound<'py, PyArray2<f64>>> {
        let cost = self.doc.cost();
        let points = density.map_or(MAX_CURVE_POINTS, |n| n.min(MAX_CURVE_POINTS)) as f64 + 1.0;
        let field = if density.is_some() { "density" } else { "tolerance" };
        let what = format!("a polyline of up to {points} points");
        budget::check_request(field, &what, &cost, polyline(points, cost.eval))?;
        let curve = &self.curve;
        let (flat, d) = py.detach(|| curve.visit(CurvePoints(density, tolerance))).or_value_error()?;
        let n = flat.len() / d;
        PyArray1::from_vec(py, flat).reshape([n, d]).map_err(value_error)
    }
}

#[pymethods]
impl PySurface {
    /// The surface as a triangle ``Mesh``: a regular grid of ``density`` × ``density``
    /// cells (seams of closed directions welded), or an adaptive quad-tree to the chord
    /// height ``tolerance`` (crack-free), or 64 × 64 cells.
    #[pyo3(signature = (density = None, tolerance = None))]
    fn tessellate(&self, py: Python<'_>, density: Option<usize>, tolerance: Option<f64>) -> PyResult<PyMesh> {
        let cost = self.doc.cost();
        let mut cells = MAX_ADAPTIVE_CELLS;
        if density.is_some() || tolerance.is_none() {
            let n = density.unwrap_or(64).min(MAX_DENSITY);
            let what = format!("a mesh of {n}×{n} cells");
            budget::check_request("density", &what, &cost, regular_mesh(n, cost.eval))?;
        } else {
            cells = cells.min(budget::current()?.adaptive_cells(&cost));
        }
        let surface = &self.surface;
        let mesh = py.detach(|| surface.visit(SurfaceTriangles(density, tolerance, cells))).or_value_error()?;
        Ok(PyMesh { mesh })
    }
}
