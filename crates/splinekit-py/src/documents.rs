//! Shape and scene documents: ``splinekit.load`` (a dict, a JSON string or a path) and
//! ``to_dict`` / ``to_json`` on scenes (curves and surfaces: `shape_methods.rs`), through the
//! parser the command line uses.

use pyo3::prelude::*;
use pyo3::types::{PyDict, PyList};
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

/// A scene object's entry: a shape (its document), a dict of a shape and its style
/// (`{"shape": …, "color": …}`), or a pair (shape, style dict).
fn object_entry(item: &Bound<'_, PyAny>, k: usize) -> PyResult<Value> {
    let name = format!("objects[{k}]");
    if let Ok((shape, style)) = item.extract::<(Bound<'_, PyAny>, Bound<'_, PyDict>)>() {
        let mut entry = to_value(&style, &name)?;
        let shape = to_value(&shape, &format!("{name}.shape"))?;
        match entry.as_object_mut() {
            Some(m) => {
                m.insert("shape".into(), shape);
            }
            None => return Err(value_error(format!("{name}: the style must be a dict"))),
        }
        return Ok(entry);
    }
    let value = to_value(item, &name)?;
    if value.get("shape").is_some() { Ok(value) } else { Ok(serde_json::json!({ "shape": value })) }
}

impl PyScene {
    /// The scene of a document value (checked by the parser the command line uses).
    fn of_value(value: Value) -> PyResult<Self> {
        let doc = SceneDocument::from_value(value.clone()).or_value_error()?;
        Ok(PyScene { value, doc })
    }
}

#[pymethods]
impl PyScene {
    /// A scene of ``objects`` — shapes, ``(shape, style)`` pairs or dicts ``{"shape": …,
    /// "color": …}`` (style fields of docs/format.md, "Scenes": ``color``, ``line_width``,
    /// ``wireframe``, ``control_net``, ``local_pieces``, ``color_map``, ``density``,
    /// ``hidden``, ``color_cycle``, ``points``) — with the scene's ``camera``, ``lights``,
    /// ``background``, ``size``, ``axes`` and ``animation`` clock when given.
    #[new]
    #[pyo3(signature = (objects = None, *, camera = None, lights = None, background = None, size = None, axes = None, animation = None))]
    #[allow(clippy::too_many_arguments)]
    fn new(
        objects: Option<&Bound<'_, PyAny>>,
        camera: Option<&Bound<'_, PyAny>>,
        lights: Option<&Bound<'_, PyAny>>,
        background: Option<&Bound<'_, PyAny>>,
        size: Option<&Bound<'_, PyAny>>,
        axes: Option<bool>,
        animation: Option<&Bound<'_, PyAny>>,
    ) -> PyResult<Self> {
        let mut entries = Vec::new();
        if let Some(objects) = objects {
            for (k, item) in objects.try_iter()?.enumerate() {
                entries.push(object_entry(&item?, k)?);
            }
        }
        let mut m = serde_json::Map::new();
        m.insert("type".into(), "scene".into());
        m.insert("objects".into(), Value::Array(entries));
        for (key, v) in [
            ("camera", camera),
            ("lights", lights),
            ("background", background),
            ("size", size),
            ("animation", animation),
        ] {
            if let Some(v) = v {
                m.insert(key.into(), to_value(v, key)?);
            }
        }
        if let Some(a) = axes {
            m.insert("axes".into(), a.into());
        }
        Self::of_value(Value::Object(m))
    }

    /// A new scene with ``shape`` added as its last object, styled by ``style``
    /// (``color=(r, g, b)``, ``wireframe=True``, …; docs/format.md, "Scenes").
    #[pyo3(signature = (shape, **style))]
    fn add(&self, shape: &Bound<'_, PyAny>, style: Option<&Bound<'_, PyDict>>) -> PyResult<Self> {
        let mut value = self.value.clone();
        let objects = value["objects"].as_array().map_or(0, Vec::len);
        let mut entry = match style {
            Some(style) => to_value(style, &format!("objects[{objects}]"))?,
            None => Value::Object(Default::default()),
        };
        entry["shape"] = to_value(shape, &format!("objects[{objects}].shape"))?;
        match value.get_mut("objects").and_then(Value::as_array_mut) {
            Some(list) => list.push(entry),
            None => value["objects"] = Value::Array(vec![entry]),
        }
        Self::of_value(value)
    }

    /// A new scene with the scene fields given replaced (``camera``, ``lights``,
    /// ``background``, ``size``, ``axes``, ``animation``; None removes a field).
    #[pyo3(signature = (**fields))]
    fn replace(&self, fields: Option<&Bound<'_, PyDict>>) -> PyResult<Self> {
        let mut value = self.value.clone();
        if let Some(fields) = fields {
            for (k, v) in fields.iter() {
                let key: String = k.extract()?;
                if !["camera", "lights", "background", "size", "axes", "animation", "objects"].contains(&key.as_str()) {
                    return Err(value_error(format!(
                        "{key}: not a scene field (camera, lights, background, size, axes, animation, objects)"
                    )));
                }
                let Some(m) = value.as_object_mut() else { break };
                if v.is_none() {
                    m.remove(&key);
                } else if key == "objects" {
                    let entries = v
                        .try_iter()?
                        .enumerate()
                        .map(|(k, item)| object_entry(&item?, k))
                        .collect::<PyResult<Vec<_>>>()?;
                    m.insert(key, Value::Array(entries));
                } else {
                    m.insert(key.clone(), to_value(&v, &key)?);
                }
            }
        }
        Self::of_value(value)
    }

    /// The animation clock ``(duration, fps)`` in seconds and frames a second (the
    /// scene's, else 1 s at 20 fps).
    #[getter]
    fn clock(&self) -> (f64, f64) {
        let c = self.doc.clock();
        (c.duration, c.fps)
    }

    /// The image size (width, height) in pixels that ``render`` uses by default.
    #[getter]
    fn size(&self) -> (u32, u32) {
        (self.doc.size[0], self.doc.size[1])
    }

    /// Writes the scene: ``.json`` (the document), ``.gltf`` or ``.glb`` (every drawn
    /// object as a node, an animation as morph targets: ``splinekit tessellate``).
    fn save(slf: &Bound<'_, Self>, path: std::path::PathBuf) -> PyResult<()> {
        crate::exchange::save_any(slf.as_any(), &path, None, None, None)
    }

    fn __len__(&self) -> usize {
        self.doc.objects.len()
    }
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
            .map_err(|e| crate::errors::file_error(format!("document: cannot read '{}': {e}", path.display())))
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
