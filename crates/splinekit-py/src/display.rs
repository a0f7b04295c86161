//! Notebook display: `_repr_mimebundle_` of curves, surfaces, meshes, subdivision surfaces
//! and scenes, answered by `splinekit/_display.py` (an interactive three.js view of the
//! object's glTF, SVG for plane curves, a PNG picture for front ends without JavaScript),
//! and the pinned three.js bundle those views embed. Also `save` on curves and surfaces
//! (`splinekit tessellate`).

use pyo3::prelude::*;
use pyo3::types::PyDict;

use crate::curve::PyCurve;
use crate::documents::PyScene;
use crate::mesh::PyMesh;
use crate::subdivision::PySubdivisionSurface;
use crate::surface::PySurface;

/// What `_repr_mimebundle_` returns: `splinekit._display.mimebundle(obj, include, exclude)`.
fn bundle<'py>(
    obj: &Bound<'py, PyAny>,
    include: Option<&Bound<'py, PyAny>>,
    exclude: Option<&Bound<'py, PyAny>>,
) -> PyResult<Bound<'py, PyAny>> {
    obj.py().import("splinekit._display")?.getattr("mimebundle")?.call1((obj, include, exclude))
}

macro_rules! displayed {
    ($($Class:ty),*) => {$(
        #[pymethods]
        impl $Class {
            /// The object in a notebook (IPython's display protocol): an interactive 3-D
            /// view (text/html), SVG for plane curves, a PNG picture, and text.
            #[pyo3(signature = (include = None, exclude = None, **_kwargs))]
            fn _repr_mimebundle_<'py>(
                slf: &Bound<'py, Self>,
                include: Option<&Bound<'py, PyAny>>,
                exclude: Option<&Bound<'py, PyAny>>,
                _kwargs: Option<&Bound<'py, PyDict>>,
            ) -> PyResult<Bound<'py, PyAny>> {
                bundle(slf.as_any(), include, exclude)
            }
        }
    )*};
}

displayed!(PyCurve, PySurface, PyMesh, PySubdivisionSurface, PyScene);

macro_rules! saved {
    ($($Class:ty),*) => {$(
        #[pymethods]
        impl $Class {
            /// Writes the shape as ``splinekit tessellate`` does, the extension picking the
            /// format (curves: .svg, .obj, .gltf, .glb; surfaces: .obj, .stl, .stla, .ply,
            /// .gltf, .glb; both: .json, the document): ``density`` segments or cells, or
            /// adaptive to ``tolerance``, posed at ``time`` seconds.
            #[pyo3(signature = (path, density = None, tolerance = None, time = None))]
            fn save(
                slf: &Bound<'_, Self>,
                path: std::path::PathBuf,
                density: Option<usize>,
                tolerance: Option<f64>,
                time: Option<f64>,
            ) -> PyResult<()> {
                crate::exchange::save_any(slf.as_any(), &path, density, tolerance, time)
            }
        }
    )*};
}

saved!(PyCurve, PySurface);

/// The pinned three.js bundle (defines the global `SplinekitThree`) and its licence.
#[pyfunction]
pub fn _three_bundle() -> (&'static str, &'static str) {
    (splinekit_render::web_viewer::THREE_BUNDLE, splinekit_render::web_viewer::THREE_LICENSE)
}

#[pymethods]
impl PyMesh {
    /// The mesh as glTF bytes (.glb, or .gltf text with ``binary=False``), as a notebook
    /// view shows it.
    #[pyo3(signature = (binary = true))]
    fn to_gltf<'py>(slf: &Bound<'py, Self>, binary: bool) -> PyResult<Bound<'py, pyo3::types::PyBytes>> {
        let py = slf.py();
        let (bytes, _) = crate::exchange::_gltf(py, None, vec![slf.borrow()], binary)?;
        Ok(bytes)
    }
}
