//! Shape and scene documents: ``splinekit.load`` (a dict, a JSON string or a path) and
//! ``to_dict`` / ``to_json`` on scenes (curves and surfaces: `shape_methods.rs`), through the
//! parser the command line uses.

use pyo3::prelude::*;
use pyo3::types::PyList;
use serde_json::Value;
use splinekit_scene::{SceneDocument, ShapeDocument};

use crate::curve::PyCurve;
use crate::curve_kinds::curve_object;
use crate::errors::{OrValueError, value_error};
use crate::json_value::{to_python, to_value};
use crate::surface::PySurface;
use crate::surface_kinds::surface_object;

/// A scene document: objects with styles, camera, lights, animation clock.
#[pyclass(frozen, module = "splinekit", name = "Scene")]
pub struct PyScene {
    /// The document as given (scenes are read, not rewritten, so this is what round-trips).
    pub(crate) value: Value,
    pub(crate) doc: SceneDocument,
}

#[pymethods]
impl PyScene {
    /// The shapes of the scene's objects, in order.
    #[getter]
    fn objects<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyList>> {
        let shapes =
            self.doc.objects.iter().map(|o| shape_object(py, o.shape.clone())).collect::<PyResult<Vec<_>>>()?;
        PyList::new(py, shapes)
    }
    /// Whether any object is animated.
    #[getter]
    fn animated(&self) -> bool {
        self.doc.is_animated()
    }
    /// The document as a dict.
    fn to_dict<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        to_python(py, &self.value)
    }
    /// The document as JSON text.
    fn to_json(&self) -> PyResult<String> {
        serde_json::to_string(&self.value).map_err(value_error)
    }
    fn __repr__(&self) -> String {
        format!("<splinekit scene of {} objects>", self.doc.objects.len())
    }
}

/// The Python object of a shape document.
pub fn shape_object(py: Python<'_>, doc: ShapeDocument) -> PyResult<Bound<'_, PyAny>> {
    match doc {
        ShapeDocument::Curve(c) => curve_object(py, c),
        ShapeDocument::Surface(s) => surface_object(py, s),
    }
}

/// The document of an object (`Scene`, `Curve`, `Surface`) or of a ``load`` argument.
pub fn any_document(ob: &Bound<'_, PyAny>) -> PyResult<Value> {
    if let Ok(scene) = ob.cast::<PyScene>() {
        return Ok(scene.get().value.clone());
    }
    if let Ok(curve) = ob.cast::<PyCurve>() {
        return Ok(curve.borrow().doc.to_value());
    }
    if let Ok(surface) = ob.cast::<PySurface>() {
        return Ok(surface.borrow().doc.to_value());
    }
    document_value(ob)
}

/// The JSON value of a ``load`` argument: a dict (or any JSON-like Python value), JSON
/// text, or a path (``str`` or ``os.PathLike``) of a JSON file. The cage files of
/// subdivision surfaces (``"obj"``) are read relative to the file's folder, or to the
/// current folder for a dict or JSON text.
fn document_value(doc: &Bound<'_, PyAny>) -> PyResult<Value> {
    let read = |path: &std::path::Path| {
        std::fs::read_to_string(path)
            .map_err(|e| value_error(format!("document: cannot read '{}': {e}", path.display())))
    };
    let (text, path): (Option<String>, Option<std::path::PathBuf>) = if let Ok(s) = doc.extract::<String>() {
        if s.trim_start().starts_with('{') {
            (Some(s), None)
        } else {
            let path = std::path::PathBuf::from(&s);
            (Some(read(&path)?), Some(path))
        }
    } else if doc.hasattr("__fspath__")? {
        let path: std::path::PathBuf = doc.extract()?;
        (Some(read(&path)?), Some(path))
    } else {
        (None, None)
    };
    let mut value = match text {
        Some(t) => parse_json(doc.py(), &t)?,
        None => to_value(doc, "")?,
    };
    let folder = match path.as_deref().and_then(std::path::Path::parent) {
        Some(p) if !p.as_os_str().is_empty() => p.to_path_buf(),
        _ => std::path::PathBuf::from("."),
    };
    splinekit_scene::cage_file::read_cage_files(&mut value, &folder).or_value_error()?;
    Ok(value)
}

/// JSON text as a value, its numbers read by Python's correctly rounded parser (every
/// number keeps its exact double); text that is not JSON gets serde_json's message, the
/// command line's.
fn parse_json(py: Python<'_>, text: &str) -> PyResult<Value> {
    match py.import("json")?.call_method1("loads", (text,)) {
        Ok(parsed) => to_value(&parsed, ""),
        Err(_) => match serde_json::from_str::<Value>(text) {
            Err(e) => Err(value_error(format!("document: invalid JSON: {e}"))),
            Ok(_) => Err(value_error("document: invalid JSON")),
        },
    }
}

/// Loads a shape or scene document (docs/format.md): ``doc`` is a dict, JSON text, or the
/// path of a JSON file. Returns the curve (``BSpline``, ``NURBS``, … or ``Curve``), the
/// surface (``BSplineSurface``, … or ``Surface``) or the ``Scene``. Errors are the
/// ``ValueError`` of the command line's message (``knots: expected 12 values …``).
#[pyfunction]
pub fn load<'py>(py: Python<'py>, doc: &Bound<'py, PyAny>) -> PyResult<Bound<'py, PyAny>> {
    let value = document_value(doc)?;
    if value.get("type").and_then(Value::as_str) == Some("scene") {
        let scene = SceneDocument::from_value(value.clone()).or_value_error()?;
        return Ok(Bound::new(py, PyScene { value, doc: scene })?.into_any());
    }
    shape_object(py, ShapeDocument::from_value(value).or_value_error()?)
}
