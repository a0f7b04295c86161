//! # splinekit for Python
//!
//! The extension module `splinekit._splinekit` (re-exported by the `splinekit` package):
//! curves and surfaces of every kind the shape documents describe, evaluated from and into
//! numpy arrays by the splinekit kernel, fitting and interpolation, documents in and out.
//! Every error is a `ValueError` with the command line's one-line message; batch work runs
//! with the GIL released, and `fit_many` / `evaluate_many` spread many shapes over every
//! core. Every object pickles and copies (its state is its shape document) and compares
//! with `==`.

mod arrays;
mod batch;
mod blending;
mod blending_edits;
mod budget;
mod curve;
mod curve_kinds;
mod curve_queries;
mod display;
mod documents;
mod errors;
mod exchange;
mod fit_report;
mod fitting;
mod json_value;
mod kind_classes;
mod knot_ops;
mod mesh;
mod queries;
mod render;
mod row_writer;
mod shape_methods;
mod subdivision;
mod surface;
mod surface_kinds;
mod travel;

use pyo3::prelude::*;

/// The extension module.
#[pymodule]
fn _splinekit(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_class::<curve::PyCurve>()?;
    m.add_class::<curve_kinds::PyBSpline>()?;
    m.add_class::<curve_kinds::PyNurbs>()?;
    m.add_class::<curve_kinds::PyBezier>()?;
    m.add_class::<curve_kinds::PyRationalBezier>()?;
    m.add_class::<curve_kinds::PyHermite>()?;
    m.add_class::<curve_kinds::PyCatmullRom>()?;
    m.add_class::<surface::PySurface>()?;
    m.add_class::<surface_kinds::PyBSplineSurface>()?;
    m.add_class::<surface_kinds::PyNurbsSurface>()?;
    m.add_class::<surface_kinds::PyBezierSurface>()?;
    let mut fields_classes = curve_kinds::add_classes(m)?;
    fields_classes.extend(surface_kinds::add_classes(m)?);
    m.add("_FIELDS_CLASSES", fields_classes)?;
    m.add_class::<documents::PyScene>()?;
    m.add_class::<fit_report::FitReport>()?;
    m.add_class::<mesh::PyMesh>()?;
    m.add_class::<subdivision::PySubdivisionSurface>()?;
    m.add_function(wrap_pyfunction!(fitting::fit, m)?)?;
    m.add_function(wrap_pyfunction!(fitting::interpolate, m)?)?;
    m.add_function(wrap_pyfunction!(documents::load, m)?)?;
    m.add_function(wrap_pyfunction!(render::render, m)?)?;
    m.add_function(wrap_pyfunction!(render::animate, m)?)?;
    m.add_function(wrap_pyfunction!(queries::_intersect, m)?)?;
    m.add_function(wrap_pyfunction!(queries::_section, m)?)?;
    m.add_function(wrap_pyfunction!(queries::_measure, m)?)?;
    m.add_function(wrap_pyfunction!(queries::_project, m)?)?;
    m.add_function(wrap_pyfunction!(queries::_offset, m)?)?;
    m.add_function(wrap_pyfunction!(exchange::_read_step, m)?)?;
    m.add_function(wrap_pyfunction!(exchange::_write_step, m)?)?;
    m.add_function(wrap_pyfunction!(exchange::_gltf, m)?)?;
    m.add_function(wrap_pyfunction!(exchange::_save, m)?)?;
    m.add_function(wrap_pyfunction!(exchange::_svg, m)?)?;
    m.add_function(wrap_pyfunction!(exchange::subdivide, m)?)?;
    m.add_function(wrap_pyfunction!(display::_three_bundle, m)?)?;
    m.add_function(wrap_pyfunction!(batch::fit_many, m)?)?;
    m.add_function(wrap_pyfunction!(batch::evaluate_many, m)?)?;
    m.add_function(wrap_pyfunction!(travel::_restore, m)?)?;
    m.add("HAS_RENDER", cfg!(feature = "render"))?;
    Ok(())
}
