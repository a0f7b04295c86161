//! ``splinekit.render`` and ``splinekit.animate``: pictures of a scene or shape, drawn
//! offscreen by wgpu as ``splinekit render`` and ``splinekit animate`` draw them, written
//! to a PNG or GIF file or returned as numpy arrays of RGBA bytes. Behind the cargo feature
//! ``render`` (it adds wgpu to the build); without it the functions raise an error that
//! says how to get it.

use std::path::PathBuf;

use pyo3::prelude::*;

use crate::documents::any_document;
use crate::errors::value_error;

/// Checks the extension of an output path.
fn check_extension(path: Option<&PathBuf>, ext: &str, function: &str) -> PyResult<()> {
    match path {
        Some(p) if p.extension().and_then(|e| e.to_str()).map(str::to_ascii_lowercase).as_deref() != Some(ext) => {
            Err(value_error(format!("path: {function} writes .{ext} files, not '{}'", p.display())))
        }
        _ => Ok(()),
    }
}

/// Draws ``obj`` (a ``Scene``, ``Curve`` or ``Surface``, or any document ``load`` takes):
/// ``size`` (width, height) in pixels (default: the scene's, else 800 × 600), the animation
/// posed at ``time`` seconds. With ``path`` writes a PNG there and returns None; without,
/// returns the picture as an array (height, width, 4) of uint8 RGBA (sRGB, rows top to
/// bottom). Raises ``RuntimeError`` when no graphics adapter exists (install a GPU driver
/// or Mesa) or when the package was built without the ``render`` feature.
#[pyfunction]
#[pyo3(signature = (obj, path = None, size = None, time = None), text_signature = "(obj, path=None, size=None, time=None)")]
pub fn render<'py>(
    py: Python<'py>,
    obj: &Bound<'py, PyAny>,
    path: Option<PathBuf>,
    size: Option<(u32, u32)>,
    time: Option<f64>,
) -> PyResult<Option<Bound<'py, PyAny>>> {
    check_extension(path.as_ref(), "png", "render")?;
    if let Some(t) = time.filter(|t| !t.is_finite()) {
        return Err(value_error(format!("time: must be finite, got {t}")));
    }
    let value = any_document(obj)?;
    gpu::draw(py, value, path.as_deref(), size, time)
}

/// Draws a scene's animation (``splinekit animate``): ``frames`` pictures (default: the
/// scene's duration × fps) at ``fps`` frames a second (default: the scene's, else 20), of
/// ``size`` (default: the scene's), one camera for all. With ``path`` writes an animated
/// GIF there and returns None; without, returns the frames as an array (frames, height,
/// width, 4) of uint8 RGBA.
#[pyfunction]
#[pyo3(signature = (obj, path = None, frames = None, fps = None, size = None), text_signature = "(obj, path=None, frames=None, fps=None, size=None)")]
pub fn animate<'py>(
    py: Python<'py>,
    obj: &Bound<'py, PyAny>,
    path: Option<PathBuf>,
    frames: Option<usize>,
    fps: Option<f64>,
    size: Option<(u32, u32)>,
) -> PyResult<Option<Bound<'py, PyAny>>> {
    check_extension(path.as_ref(), "gif", "animate")?;
    if let Some(v) = fps.filter(|v| !(*v > 0.0 && *v <= 100.0)) {
        return Err(value_error(format!("fps: must be in (0, 100], got {v}")));
    }
    if let Some(n) = frames.filter(|&n| n > 2000) {
        return Err(value_error(format!("frames: {n} is more than the limit of 2000")));
    }
    let value = any_document(obj)?;
    gpu::animate(py, value, path.as_deref(), frames, fps, size)
}

#[cfg(feature = "render")]
mod gpu {
    use std::path::Path;

    use numpy::{PyArray1, PyArrayMethods};
    use pyo3::prelude::*;
    use splinekit_render::{Image, Renderer, compose, renderer::MAX_SIDE, write_gif};
    use splinekit_scene::SceneOrShape;
    use splinekit_scene::scenes::SceneDocument;

    use crate::errors::{OrValueError, file_error, render_error, value_error};

    fn scene_and_size(value: serde_json::Value, size: Option<(u32, u32)>) -> PyResult<(SceneDocument, (u32, u32))> {
        let scene = SceneOrShape::from_value(value).or_value_error()?.into_scene();
        let size = size.unwrap_or((scene.size[0], scene.size[1]));
        if !(1..=MAX_SIDE).contains(&size.0) || !(1..=MAX_SIDE).contains(&size.1) {
            return Err(value_error(format!(
                "size: each side must be between 1 and {MAX_SIDE} pixels, got {}x{}",
                size.0, size.1
            )));
        }
        Ok((scene, size))
    }

    fn renderer() -> PyResult<Renderer> {
        Renderer::new().map_err(|e| render_error(format!("render: {e}")))
    }

    fn frame(
        renderer: &Renderer,
        scene: &SceneDocument,
        time: Option<f64>,
        size: (u32, u32),
        camera: Option<splinekit_render::Camera>,
    ) -> PyResult<Image> {
        let mut rs = compose(scene, time, size.0 as f32 / size.1 as f32).or_value_error()?;
        if camera.is_some() {
            rs.camera = camera;
        }
        renderer.render(&rs, size.0, size.1).map_err(|e| render_error(format!("render: {e}")))
    }

    /// Images as an array (count, height, width, 4), or without the first axis for one.
    fn array<'py>(py: Python<'py>, images: Vec<Image>, single: bool) -> PyResult<Bound<'py, PyAny>> {
        let (w, h, n) = (images[0].width as usize, images[0].height as usize, images.len());
        let bytes: Vec<u8> = images.into_iter().flat_map(|i| i.rgba).collect();
        let a = PyArray1::from_vec(py, bytes);
        Ok(if single { a.reshape([h, w, 4])?.into_any() } else { a.reshape([n, h, w, 4])?.into_any() })
    }

    fn write(path: &Path, bytes: &[u8]) -> PyResult<()> {
        splinekit_scene::write_file(path, bytes)
            .map_err(|e| file_error(format!("path: cannot write '{}': {e}", path.display())))
    }

    pub fn draw<'py>(
        py: Python<'py>,
        value: serde_json::Value,
        path: Option<&Path>,
        size: Option<(u32, u32)>,
        time: Option<f64>,
    ) -> PyResult<Option<Bound<'py, PyAny>>> {
        let (scene, size) = scene_and_size(value, size)?;
        let fields = splinekit_scene::budget::RenderFields { size: "size", frames: "size" };
        crate::budget::current()?.check_render(&scene, size, 1, fields).or_value_error()?;
        let image = py.detach(|| frame(&renderer()?, &scene, time, size, None))?;
        match path {
            Some(p) => write(p, &image.to_png()).map(|()| None),
            None => array(py, vec![image], true).map(Some),
        }
    }

    pub fn animate<'py>(
        py: Python<'py>,
        value: serde_json::Value,
        path: Option<&Path>,
        frames: Option<usize>,
        fps: Option<f64>,
        size: Option<(u32, u32)>,
    ) -> PyResult<Option<Bound<'py, PyAny>>> {
        let (scene, size) = scene_and_size(value, size)?;
        let fps = fps.unwrap_or(scene.clock().fps);
        let frames = frames.unwrap_or_else(|| scene.clock().frames_at(fps));
        if frames == 0 {
            return Err(value_error("frames: need at least one frame"));
        }
        if frames as u64 * size.0 as u64 * size.1 as u64 > 2_000_000_000 {
            return Err(value_error(format!(
                "frames: {frames} frames of {}x{} are more than 2·10⁹ pixels",
                size.0, size.1
            )));
        }
        let fields = splinekit_scene::budget::RenderFields { size: "size", frames: "frames" };
        crate::budget::current()?.check_render(&scene, size, frames, fields).or_value_error()?;
        let images = py.detach(|| -> PyResult<Vec<Image>> {
            let renderer = renderer()?;
            // One camera for every frame: the scene's at time 0, moved back by 12 % to
            // leave room for the motion (as `splinekit animate`).
            let rs = compose(&scene, Some(0.0), size.0 as f32 / size.1 as f32).or_value_error()?;
            let camera = rs.camera.map(|c| c.zoomed(1.12));
            (0..frames).map(|k| frame(&renderer, &scene, Some(k as f64 / fps), size, camera)).collect()
        })?;
        match path {
            Some(p) => {
                let mut gif = Vec::new();
                write_gif(&mut gif, &images, fps as f32).map_err(|e| value_error(format!("path: {e}")))?;
                write(p, &gif).map(|()| None)
            }
            None => array(py, images, false).map(Some),
        }
    }
}

/// Without the `render` feature: the error that says how to get it.
#[cfg(not(feature = "render"))]
mod gpu {
    use pyo3::prelude::*;

    pub(super) fn missing<T>() -> PyResult<T> {
        Err(crate::errors::render_error(
            "render: this build of splinekit has no renderer; reinstall with MATURIN_PEP517_ARGS=\"--features render\" \
             pip install ./crates/splinekit-py, or write obj.to_json() to a file and run `splinekit render FILE -o out.png`",
        ))
    }

    pub fn draw<'py>(
        _: Python<'py>,
        _: serde_json::Value,
        _: Option<&std::path::Path>,
        _: Option<(u32, u32)>,
        _: Option<f64>,
    ) -> PyResult<Option<Bound<'py, PyAny>>> {
        missing()
    }

    pub fn animate<'py>(
        _: Python<'py>,
        _: serde_json::Value,
        _: Option<&std::path::Path>,
        _: Option<usize>,
        _: Option<f64>,
        _: Option<(u32, u32)>,
    ) -> PyResult<Option<Bound<'py, PyAny>>> {
        missing()
    }
}
