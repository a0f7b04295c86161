//! ``splinekit.render``: a PNG of a scene or shape, drawn offscreen by wgpu as
//! ``splinekit render`` draws it. Behind the cargo feature ``render`` (it adds wgpu to the
//! build); without it the function raises an error that says how to get it.

use std::path::PathBuf;

use pyo3::exceptions::PyRuntimeError;
use pyo3::prelude::*;

use crate::documents::any_document;
use crate::errors::value_error;

/// Writes a PNG of ``obj`` (a ``Scene``, ``Curve`` or ``Surface``, or any document ``load``
/// takes) to ``path``: ``size`` (width, height) in pixels, the animation posed at
/// ``time`` seconds. Raises ``RuntimeError`` when no graphics adapter exists (install a
/// GPU driver or Mesa) or when the package was built without the ``render`` feature.
#[pyfunction]
#[pyo3(signature = (obj, path, size = (800, 600), time = None), text_signature = "(obj, path, size=(800, 600), time=None)")]
pub fn render(
    py: Python<'_>,
    obj: &Bound<'_, PyAny>,
    path: PathBuf,
    size: (u32, u32),
    time: Option<f64>,
) -> PyResult<()> {
    if path.extension().and_then(|e| e.to_str()).map(str::to_ascii_lowercase).as_deref() != Some("png") {
        return Err(value_error(format!("path: render writes .png files, not '{}'", path.display())));
    }
    if let Some(t) = time.filter(|t| !t.is_finite()) {
        return Err(value_error(format!("time: must be finite, got {t}")));
    }
    let value = any_document(obj)?;
    draw(py, value, &path, size, time)
}

#[cfg(feature = "render")]
fn draw(
    py: Python<'_>,
    value: serde_json::Value,
    path: &std::path::Path,
    size: (u32, u32),
    time: Option<f64>,
) -> PyResult<()> {
    use crate::errors::OrValueError;
    use splinekit_render::{Renderer, compose, renderer::MAX_SIDE};
    use splinekit_scene::SceneOrShape;

    if !(1..=MAX_SIDE).contains(&size.0) || !(1..=MAX_SIDE).contains(&size.1) {
        return Err(value_error(format!(
            "size: each side must be between 1 and {MAX_SIDE} pixels, got {}x{}",
            size.0, size.1
        )));
    }
    let text = serde_json::to_string(&value).map_err(value_error)?;
    let scene = SceneOrShape::from_json(&text).or_value_error()?.into_scene();
    let fields = splinekit_scene::budget::RenderFields { size: "size", frames: "size" };
    crate::budget::current()?.check_render(&scene, size, 1, fields).or_value_error()?;
    let png = py.detach(|| -> PyResult<Vec<u8>> {
        let renderer = Renderer::new().map_err(|e| PyRuntimeError::new_err(format!("render: {e}")))?;
        let rs = compose(&scene, time, size.0 as f32 / size.1 as f32).or_value_error()?;
        let image =
            renderer.render(&rs, size.0, size.1).map_err(|e| PyRuntimeError::new_err(format!("render: {e}")))?;
        Ok(image.to_png())
    })?;
    splinekit_scene::write_file(path, &png)
        .map_err(|e| value_error(format!("path: cannot write '{}': {e}", path.display())))
}

/// Without the `render` feature: the error that says how to get it (`draw`'s arguments
/// unused).
#[cfg(not(feature = "render"))]
fn draw(_: Python<'_>, _: serde_json::Value, _: &std::path::Path, _: (u32, u32), _: Option<f64>) -> PyResult<()> {
    Err(PyRuntimeError::new_err(
        "render: this build of splinekit has no renderer; reinstall with MATURIN_PEP517_ARGS=\"--features render\" \
         pip install ./crates/splinekit-py, or write obj.to_json() to a file and run `splinekit render FILE -o out.png`",
    ))
}
