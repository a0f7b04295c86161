//! Files and formats for Python, by the code the command line runs: STEP in and out
//! (`splinekit convert`, through splinekit-step's public API), shapes and scenes to mesh
//! files (`splinekit tessellate`), glTF bytes of anything drawable (the notebook views),
//! SVG of plane curves, and subdivision curves (`splinekit subdivide`).

use std::path::{Path, PathBuf};

use numpy::{PyArray1, PyArrayMethods};
use pyo3::prelude::*;
use pyo3::types::{PyBytes, PyDict, PyList};
use serde_json::Value;
use splinekit::subdivision::{ChaikinOptions, FourPointOptions, chaikin, four_point, lane_riesenfeld};
use splinekit_mesh::export::by_extension::{mesh_bytes, polyline_bytes, polyline_svg};
use splinekit_mesh::export::{Format, GltfGeometry, GltfObject, GltfScene, Subject};
use splinekit_scene::budget::Cost;
use splinekit_scene::points::{from_points, to_points};
use splinekit_scene::scenes::SceneDocument;
use splinekit_scene::{Curves, DimensionVisitor, SceneOrShape, ShapeDocument, with_dimension};
use splinekit_step::documents::{Form, export_document, import_items};
use splinekit_step::part21::StepFile;
use splinekit_step::part21::writer::HeaderInfo;

use crate::arrays::Numbers;
use crate::budget;
use crate::documents::any_document;
use crate::errors::{Failure, OrValueError, file_error, value_error};
use crate::json_value::to_python;
use crate::mesh::{CurvePoints, MAX_ADAPTIVE_CELLS, MAX_CURVE_POINTS, MAX_DENSITY, PyMesh, SurfaceTriangles};

fn stem(path: &Path) -> String {
    path.file_stem().and_then(|s| s.to_str()).unwrap_or("splinekit").to_string()
}

fn write(path: &Path, bytes: &[u8]) -> PyResult<()> {
    splinekit_scene::write_file(path, bytes)
        .map_err(|e| file_error(format!("path: cannot write '{}': {e}", path.display())))
}

/// What `_read_step` returns: the items as (name, document) and the entity types not
/// converted with their counts.
type ReadStep<'py> = (Vec<(String, Bound<'py, PyAny>)>, Vec<(String, usize)>, Bound<'py, PyAny>);

/// `splinekit convert FILE.step -o OUT.json`: the documents of the file's curves, surfaces
/// and faces, as (name, document) pairs, and the entity types not converted with their
/// counts.
#[pyfunction]
pub fn _read_step(py: Python<'_>, path: PathBuf) -> PyResult<ReadStep<'_>> {
    let imported = py
        .detach(|| -> Result<_, Failure> {
            // A file that cannot be opened is a file error, one that cannot be read as STEP
            // a document error (the same message either way: `StepFile::open`'s).
            let file = StepFile::open(&path).map_err(|e| {
                let failure = Failure::from(e).about("path");
                match std::fs::File::open(&path) {
                    Err(_) => Failure { kind: splinekit_scene::ErrorKind::File, ..failure },
                    Ok(_) => failure,
                }
            })?;
            import_items(&file).map_err(|e| Failure::from(e).about("path"))
        })
        .map_err(Failure::into_py)?;
    if imported.items.is_empty() {
        return Err(value_error("path: the file holds no curve or surface that splinekit reads"));
    }
    let items = imported
        .items
        .iter()
        .map(|i| {
            let value = match &i.document {
                ShapeDocument::Curve(c) => c.to_value(),
                ShapeDocument::Surface(s) => s.to_value(),
            };
            Ok((i.name.clone(), to_python(py, &value)?))
        })
        .collect::<PyResult<_>>()?;
    // The whole file as one document: parts placed by the product structure, repeats as
    // instances (what `convert` writes).
    let document = to_python(py, &imported.to_value())?;
    Ok((items, imported.not_understood.clone(), document))
}

/// `splinekit convert IN.json -o OUT.step`: writes the document (a shape or a scene) as
/// STEP AP214 and returns, per object, a dict of its name, form (`exact`,
/// `exact_polynomial`, `approximated`), measured deviation and tolerance.
#[pyfunction]
#[pyo3(signature = (doc, path, tolerance = 1e-6))]
pub fn _write_step<'py>(doc: &Bound<'py, PyAny>, path: PathBuf, tolerance: f64) -> PyResult<Bound<'py, PyList>> {
    let py = doc.py();
    if !(tolerance.is_finite() && tolerance > 0.0) {
        return Err(value_error(format!("tolerance: must be a positive number, got {tolerance}")));
    }
    if Format::of_path(&path) != Some(Format::Step) {
        return Err(value_error(format!("path: STEP files end in .step or .stp, not '{}'", path.display())));
    }
    let doc = SceneOrShape::from_value(any_document(doc)?).or_value_error()?;
    let name = stem(&path);
    let header = HeaderInfo::now(&name);
    let (step, exported) = py.detach(|| export_document(&doc, &name, tolerance, &header)).or_value_error()?;
    write(&path, step.as_bytes())?;
    let list = PyList::empty(py);
    for e in &exported {
        let d = PyDict::new(py);
        d.set_item("name", &e.item.name)?;
        let form = match e.form {
            Form::Exact => "exact",
            Form::ExactPolynomial { .. } => "exact_polynomial",
            Form::Approximated => "approximated",
        };
        d.set_item("form", form)?;
        d.set_item("max_deviation", e.max_deviation)?;
        d.set_item("tolerance", e.tolerance)?;
        list.append(d)?;
    }
    Ok(list)
}

/// The scene of a document value, with its frames and their rate for glTF (one frame
/// when it is not animated).
fn scene_of(value: Value) -> PyResult<(SceneDocument, usize, f64)> {
    let scene = SceneOrShape::from_value(value).or_value_error()?.into_scene();
    let (frames, fps) = if scene.is_animated() { (scene.clock().frames(), scene.clock().fps) } else { (1, 1.0) };
    for o in &scene.objects {
        budget::current()?.check_shape(&o.shape.cost()).or_value_error()?;
    }
    Ok((scene, frames, fps))
}

/// glTF of a scene or shape document and of meshes beside it: `binary` gives .glb bytes,
/// else .gltf text as bytes; also the animation's period in seconds (None when still).
/// An animated scene carries its frames as morph targets (as `splinekit tessellate
/// SCENE -o FILE.glb`).
#[pyfunction]
#[pyo3(signature = (doc, meshes = Vec::new(), binary = true))]
pub fn _gltf<'py>(
    py: Python<'py>,
    doc: Option<&Bound<'py, PyAny>>,
    meshes: Vec<PyRef<'py, PyMesh>>,
    binary: bool,
) -> PyResult<(Bound<'py, PyBytes>, Option<f64>)> {
    let mut out = GltfScene::default();
    let mut period = None;
    if let Some(doc) = doc {
        let (scene, frames, fps) = scene_of(any_document(doc)?)?;
        if frames > 1 {
            period = Some(frames as f64 / fps);
        }
        out = py.detach(|| splinekit_render::scene_to_gltf(&scene, frames, fps)).or_value_error()?;
    }
    // The renderer's blue for meshes (linear RGB of sRGB (0.3, 0.55, 0.85)).
    for (i, m) in meshes.iter().enumerate() {
        out.objects.push(GltfObject {
            name: format!("mesh {i}"),
            geometry: GltfGeometry::Mesh(m.mesh.clone()),
            color: [0.073, 0.263, 0.694, 1.0],
            frames: Vec::new(),
        });
    }
    let bytes = out.to_format_bytes(if binary { Format::Glb } else { Format::Gltf }).or_value_error()?;
    Ok((PyBytes::new(py, &bytes), period))
}

/// `splinekit tessellate SHAPE -o FILE [--density N | --tolerance E] [--time T]`: the
/// shape's polyline or mesh, or a scene in any mesh format, written by extension.
#[pyfunction]
#[pyo3(signature = (doc, path, density = None, tolerance = None, time = None))]
pub fn _save(
    doc: &Bound<'_, PyAny>,
    path: PathBuf,
    density: Option<usize>,
    tolerance: Option<f64>,
    time: Option<f64>,
) -> PyResult<()> {
    save_any(doc, &path, density, tolerance, time)
}

/// [`_save`]'s work, for `Scene.save` and the shapes' `save` too, by the path's
/// [`Format`]: `.json` writes the document itself, `.step`/`.stp` its exact geometry
/// ([`_write_step`]), the others its tessellation.
pub fn save_any(
    doc: &Bound<'_, PyAny>,
    path: &Path,
    density: Option<usize>,
    tolerance: Option<f64>,
    time: Option<f64>,
) -> PyResult<()> {
    let py = doc.py();
    let format = Format::of_path(path);
    match format {
        Some(Format::Json) => {
            let text = serde_json::to_string(&any_document(doc)?).map_err(value_error)?;
            return write(path, text.as_bytes());
        }
        Some(Format::Step) => return _write_step(doc, path.to_path_buf(), 1e-6).map(drop),
        _ => {}
    }
    let shown = path.display().to_string();
    let format_for = |subject: Subject| subject.check(format, &shown).map_err(|e| value_error(format!("path: {e}")));
    if density.is_some() && tolerance.is_some() {
        return Err(value_error("density: give density or tolerance, not both"));
    }
    if let Some(t) = time.filter(|t| !t.is_finite()) {
        return Err(value_error(format!("time: must be finite, got {t}")));
    }
    let mut doc = match SceneOrShape::from_value(any_document(doc)?).or_value_error()? {
        SceneOrShape::Scene(scene) => {
            let format = format_for(Subject::Scene)?;
            let (scene, _, _) = scene_of(scene.to_value())?;
            let bytes =
                py.detach(|| splinekit_render::scene_file(&scene, format, &stem(path), time)).or_value_error()?;
            return write(path, &bytes);
        }
        SceneOrShape::Shape(doc) => doc,
    };
    if let Some(t) = time {
        doc.set_time(t);
    }
    let cost = doc.cost();
    budget::current()?.check_shape(&cost).or_value_error()?;
    let name = stem(path);
    let bytes = match &doc {
        ShapeDocument::Curve(c) => {
            let format = format_for(Subject::Curve)?;
            let points = density.map_or(MAX_CURVE_POINTS, |n| n.min(MAX_CURVE_POINTS)) as f64 + 1.0;
            let field = if density.is_some() { "density" } else { "tolerance" };
            let what = format!("a polyline of up to {points} points");
            budget::check_request(field, &what, &cost, splinekit_scene::budget::polyline(points, cost.eval))?;
            let curve = c.build().or_value_error()?;
            let closed = curve.visit(Closed);
            let (flat, d) = py.detach(|| curve.visit(CurvePoints(density, tolerance))).or_value_error()?;
            let points: Vec<[f64; 3]> =
                flat.chunks_exact(d).map(|p| std::array::from_fn(|k| p.get(k).copied().unwrap_or(0.0))).collect();
            if format == Format::Svg {
                polyline_svg(&points, closed, d).or_value_error()?.into_bytes()
            } else {
                polyline_bytes(&points, closed, &name, format).or_value_error()?
            }
        }
        ShapeDocument::Surface(s) => {
            let format = format_for(Subject::Surface)?;
            let mut cells = MAX_ADAPTIVE_CELLS;
            if tolerance.is_none() {
                let n = density.unwrap_or(64).min(MAX_DENSITY);
                let what = format!("a mesh of {n}×{n} cells");
                let request = splinekit_scene::budget::regular_mesh(n, cost.eval);
                budget::check_request("density", &what, &cost, request)?;
            } else {
                cells = cells.min(budget::current()?.adaptive_cells(&cost));
            }
            let surface = s.build().or_value_error()?;
            let mesh = py.detach(|| surface.visit(SurfaceTriangles(density, tolerance, cells))).or_value_error()?;
            mesh_bytes(std::borrow::Cow::Owned(mesh), &name, format).or_value_error()?
        }
    };
    write(path, &bytes)
}

/// Whether a curve is closed (its polyline then closes, as the command line's).
struct Closed;

impl DimensionVisitor<Curves> for Closed {
    type Output = bool;
    fn visit<const D: usize>(self, c: &dyn splinekit::curve::Curve<D>) -> bool {
        c.is_closed()
    }
}

/// The SVG drawing of a curve (as `splinekit tessellate CURVE -o FILE.svg`).
#[pyfunction]
pub fn _svg(doc: &Bound<'_, PyAny>) -> PyResult<String> {
    let py = doc.py();
    let ShapeDocument::Curve(c) = ShapeDocument::from_value(any_document(doc)?).or_value_error()? else {
        return Err(value_error("shape: SVG drawings are of curves"));
    };
    let curve = c.build().or_value_error()?;
    let closed = curve.visit(Closed);
    let (flat, d) = py.detach(|| curve.visit(CurvePoints(None, None))).or_value_error()?;
    let points: Vec<[f64; 3]> =
        flat.chunks_exact(d).map(|p| std::array::from_fn(|k| p.get(k).copied().unwrap_or(0.0))).collect();
    polyline_svg(&points, closed, d).or_value_error()
}

/// `splinekit subdivide POINTS --scheme S [--degree D] --steps M [--closed] [--keep-ends]
/// [--tension W]`: the refined polygon, shape (N, D).
#[pyfunction]
#[pyo3(signature = (points, scheme, steps, degree = None, closed = false, keep_ends = false, tension = 0.0625))]
#[allow(clippy::too_many_arguments)]
pub fn subdivide<'py>(
    points: &Bound<'py, PyAny>,
    scheme: &str,
    steps: usize,
    degree: Option<usize>,
    closed: bool,
    keep_ends: bool,
    tension: f64,
) -> PyResult<Bound<'py, PyAny>> {
    let py = points.py();
    let numbers = Numbers::new(points)?;
    let (n, dim) = numbers.rows("points")?;
    crate::arrays::check_finite("points", numbers.values())?;
    let pts: Vec<Vec<f64>> = numbers.values().chunks_exact(dim.max(1)).map(<[f64]>::to_vec).collect();
    if pts.is_empty() {
        return Err(value_error("points: expected at least one point"));
    }
    let passes = if scheme.replace('-', "_") == "lane_riesenfeld" { degree.unwrap_or(3) as f64 + 1.0 } else { 1.0 };
    let out_points = n as f64 * 2f64.powi(steps.min(1100) as i32) + 4.0;
    let numbers_out = out_points * dim as f64;
    budget::current()?
        .check(
            "steps",
            &format!("{steps} steps on {n} points"),
            Cost::new(numbers_out * 8.0 * 3.0, numbers_out * 4.0 * passes),
        )
        .or_value_error()?;
    let flat: Vec<f64> = with_dimension!(dim, "points", D => {
        let p = to_points::<D>(&pts);
        let r = match scheme.replace('-', "_").as_str() {
            "chaikin" => {
                if let Some(d) = degree.filter(|&d| d != 2) {
                    return Err(value_error(format!("degree: Chaikin's scheme is of degree 2, got {d} (use scheme=\"lane_riesenfeld\")")));
                }
                chaikin(&p, steps, ChaikinOptions { closed, keep_ends })
            }
            "lane_riesenfeld" => {
                let d = degree.unwrap_or(3);
                if d == 0 || d > 64 {
                    return Err(value_error(format!("degree: must be between 1 and 64, got {d}")));
                }
                lane_riesenfeld(&p, d, steps, closed)
            }
            "four_point" => four_point(&p, steps, FourPointOptions { closed, tension }),
            other => return Err(value_error(format!(
                "scheme: expected \"chaikin\", \"lane_riesenfeld\" or \"four_point\", got \"{other}\""
            ))),
        }
        .or_value_error()?;
        Ok::<Vec<f64>, PyErr>(from_points(&r).into_iter().flatten().collect())
    }, or value_error)?;
    let rows = flat.len() / dim;
    Ok(PyArray1::from_vec(py, flat).reshape([rows, dim])?.into_any())
}
