//! The Python methods that `Curve` and `Surface` have alike, written once for both
//! classes: `dimension`, `kind`, the document out (`to_dict`, `to_json`), `==` (equal
//! documents), and a blending spline's frames, clock and local pieces (`set_transform`,
//! `at_time`, `local_pieces`; the pieces, frames and checks are `blending.rs`'s).
//!
//! A macro, because the two classes differ in their Rust types only: the document enum
//! and its blending-spline variant, the function that makes the Python object of a
//! document, the index of a local piece (k, or (i, j) for patches) and the function that
//! samples the local pieces. The docstrings that differ by more than the noun ("curve",
//! "surface") are given with each class's invocation.

use pyo3::prelude::*;

use crate::curve::PyCurve;
use crate::surface::PySurface;

/// The shared `#[pymethods]` of a shape class; see the module's documentation.
macro_rules! shape_methods {
    (
        impl $Class:ident ($noun:literal) for $Doc:ident::$Blending:ident ($kinds:literal, piece: $Piece:ty), $object:path, $pieces:ident (samples = $samples:tt);
        $(#[doc = $kind:tt])* kind;
        $(#[doc = $set_transform:tt])* set_transform;
        $(#[doc = $at_time:tt])* at_time;
        $(#[doc = $local_pieces:tt])* local_pieces;
    ) => {
        #[pymethods]
        impl $Class {
            #[doc = concat!("The dimension D of the ", $noun, "'s points.")]
            #[getter(dimension)]
            fn dimension_getter(&self) -> usize {
                self.dimension()
            }

            $(#[doc = $kind])*
            #[getter]
            fn kind(&self) -> &'static str {
                self.doc.type_name()
            }

            #[doc = concat!("The ", $noun, "'s shape document as a dict (``splinekit.load`` reads it back).")]
            fn to_dict<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
                $crate::json_value::to_python(py, &self.doc.to_value())
            }

            #[doc = concat!("The ", $noun, "'s shape document as JSON text (what the command line reads).")]
            fn to_json(&self) -> PyResult<String> {
                serde_json::to_string(&self.doc.to_value()).map_err($crate::errors::value_error)
            }

            #[doc = concat!("Equal documents: the same kind, the same numbers (so the same ", $noun, ").")]
            fn __eq__(&self, other: PyRef<'_, $Class>) -> bool {
                self.doc.to_value() == other.doc.to_value()
            }

            $(#[doc = $set_transform])*
            #[pyo3(signature = (k, translate = None, rotate = None, scale = None))]
            fn set_transform(
                &mut self,
                k: $Piece,
                translate: Option<&Bound<'_, PyAny>>,
                rotate: Option<&Bound<'_, PyAny>>,
                scale: Option<&Bound<'_, PyAny>>,
            ) -> PyResult<()> {
                let splinekit_scene::$Doc::$Blending(d) = &self.doc else {
                    return Err($crate::blending::only_on("set_transform", $kinds, self.doc.type_name()));
                };
                let mut d = d.clone();
                $crate::blending::put(&mut d.transforms, k, $crate::blending::transform(translate, rotate, scale)?);
                *self = $Class::new(splinekit_scene::$Doc::$Blending(d))?;
                Ok(())
            }

            $(#[doc = $at_time])*
            fn at_time<'py>(&self, py: Python<'py>, t: f64) -> PyResult<Bound<'py, PyAny>> {
                $crate::blending::check_time(t)?;
                let mut doc = self.doc.clone();
                doc.set_time(t);
                $object(py, doc)
            }

            $(#[doc = $local_pieces])*
            #[pyo3(signature = (samples = $samples))]
            fn local_pieces<'py>(&self, py: Python<'py>, samples: usize) -> PyResult<Bound<'py, pyo3::types::PyList>> {
                $crate::blending::check_samples(samples)?;
                let splinekit_scene::$Doc::$Blending(d) = &self.doc else {
                    return Err($crate::blending::only_on("local_pieces", $kinds, self.doc.type_name()));
                };
                splinekit_scene::with_dimension!(
                    self.dimension(),
                    "control_points",
                    D => $crate::blending::PieceSampling { py, cost: &self.doc.cost(), samples }.$pieces::<D>(d),
                    or $crate::errors::value_error
                )
            }
        }
    };
}

shape_methods! {
    impl PyCurve ("curve") for CurveDocument::BlendingSpline ("blending_spline curves", piece: usize), crate::curve_kinds::curve_object, local_curves (samples = 97);
    /// The document's ``type`` (``"bspline"``, ``"circle"``, …).
    kind;
    /// Sets the affine frame of local curve `k`, in place: ``translate`` (D numbers),
    /// ``rotate`` (``{"axis": [..], "angle": radians, "pivot": [..]}``), ``scale`` (a
    /// number), applied in the local curve's own frame about its interpolation point and
    /// replacing the frame it had. On an error the curve is left as it was.
    set_transform;
    /// A copy posed at time `t` (seconds) by the document's animation tracks, as
    /// ``splinekit eval --time``; shapes without animation are unchanged.
    at_time;
    /// The local curves ℓₖ of a blending spline: a list of dicts with ``index`` k,
    /// ``support`` (tₖ₋₁, tₖ₊₁), ``origin`` ℓₖ's interpolation point, and ``points``
    /// (samples, D) of ℓₖ over its support (at the global parameter, frame applied).
    local_pieces;
}

shape_methods! {
    impl PySurface ("surface") for SurfaceDocument::BlendingSplineSurface ("blending_spline_surface surfaces", piece: (usize, usize)), crate::surface_kinds::surface_object, local_patches (samples = 17);
    /// The document's ``type``.
    kind;
    /// Sets the affine frame of local patch ``k = (i, j)``, in place (see
    /// ``Curve.set_transform``).
    set_transform;
    /// A copy posed at time `t` (seconds) by the document's animation tracks.
    at_time;
    /// The local patches of a blending-spline surface: dicts with ``index`` (i, j),
    /// ``support`` ((u0, u1), (v0, v1)), ``origin``, and ``points`` (samples, samples, D).
    local_pieces;
}
