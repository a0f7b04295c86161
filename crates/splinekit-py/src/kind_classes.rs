//! The Python class of every kind, made from the registry's lists
//! (`splinekit_scene::curve_kinds!`, `surface_kinds!`): each line's `python(…)` says whether
//! a kind's objects are of the plain base class (`base`), of a hand-written class named
//! after the variant (`own`, in the family's `own` module), or of a class made here from
//! the kind's document fields (`fields "Name"`: its constructor takes the fields as
//! keyword arguments and parses them as the command line does). A kind that names a
//! missing hand-written class does not compile.
//!
//! `python_classes!` expands in a family's module, which provides `Base` (the base class),
//! `base` (the base object of a document given as JSON) and `own` (the hand-written
//! classes, each an [`OwnClass`]); it makes `maker` (how an object of each kind is made),
//! `wrap` (the object of a built shape), the module `fields_classes` and `add_classes`.

use pyo3::PyClass;
use pyo3::prelude::*;
use pyo3::types::PyDict;
use serde_json::{Map, Value};

use crate::fit_report::FitReport;
use crate::json_value::to_value;

/// A hand-written class of a kind (`python(own)`), made for a built curve or surface of its
/// family's base class (`add_subclass` checks the base): a `BSpline` keeps the fit report.
pub trait OwnClass: PyClass {
    /// The class's part of the object.
    fn made(report: Option<Py<FitReport>>) -> Self;
}

/// [`OwnClass`] for hand-written classes with no state of their own (unit structs).
macro_rules! stateless_own_classes {
    ($($class:ident),+) => {
        $( impl $crate::kind_classes::OwnClass for $class {
            fn made(_report: Option<Py<$crate::fit_report::FitReport>>) -> Self {
                $class
            }
        } )+
    };
}
pub(crate) use stateless_own_classes;

/// How an object of a kind is made from its base object of class `B` (and the fit report,
/// which only a fitted `BSpline` has).
pub type Maker<B> =
    for<'py> fn(Python<'py>, PyClassInitializer<B>, Option<Py<FitReport>>) -> PyResult<Bound<'py, PyAny>>;

/// The document `{"type": ty, …keyword arguments…}`.
#[allow(dead_code)] // used by the classes of kinds declared `python(fields "…")`
pub fn kwargs_document(ty: &str, fields: Option<&Bound<'_, PyDict>>) -> PyResult<Value> {
    let mut map = Map::new();
    map.insert("type".into(), Value::String(ty.into()));
    for (name, value) in fields.into_iter().flat_map(|f| f.iter()) {
        let name: String = name.extract()?;
        let value = to_value(&value, &name)?;
        map.insert(name, value);
    }
    Ok(Value::Object(map))
}

macro_rules! python_classes {
    (
        $(#[$meta:meta])*
        pub enum $Enum:ident of $Family:ty {
            $( $(#[$variant_meta:meta])* $Variant:ident($Doc:ty) = $name:literal, python($($python:tt)*), )+
        }
    ) => {
        /// How an object of the document's kind is made (the registry's `python(…)`).
        fn maker(doc: &splinekit_scene::$Enum) -> $crate::kind_classes::Maker<Base> {
            match doc {
                $( splinekit_scene::$Enum::$Variant(_) => $crate::kind_classes::python_classes!(@maker $Variant $($python)*), )+
            }
        }

        /// The Python object of a built shape: the class of its kind (a fitted `BSpline`
        /// keeps the fit `report`).
        pub fn wrap(
            py: Python<'_>,
            shape: Base,
            report: Option<Py<$crate::fit_report::FitReport>>,
        ) -> PyResult<Bound<'_, PyAny>> {
            let make = maker(&shape.doc);
            make(py, PyClassInitializer::from(shape), report)
        }

        /// The classes made from their kinds' document fields.
        pub mod fields_classes {
            #[allow(unused_imports)]
            use super::*;
            $( $crate::kind_classes::python_classes!(@class [$(#[$variant_meta])*] $Variant $name $($python)*); )+
        }

        /// Adds the classes made from their kinds' fields to the module; their names.
        pub fn add_classes(m: &Bound<'_, PyModule>) -> PyResult<Vec<&'static str>> {
            #[allow(unused_mut)]
            let mut names = Vec::new();
            $( $crate::kind_classes::python_classes!(@add m names $Variant $($python)*); )+
            let _ = m;
            Ok(names)
        }
    };
    (@maker $V:ident base) => {
        |py, init, _report| Ok(Bound::new(py, init)?.into_any())
    };
    (@maker $V:ident own) => {
        |py, init, report| Ok(Bound::new(py, init.add_subclass(<own::$V as $crate::kind_classes::OwnClass>::made(report)))?.into_any())
    };
    (@maker $V:ident fields $class:literal) => {
        |py, init, _report| Ok(Bound::new(py, init.add_subclass(fields_classes::$V))?.into_any())
    };
    (@class [$($m:tt)*] $V:ident $name:literal base) => {};
    (@class [$($m:tt)*] $V:ident $name:literal own) => {};
    (@class [$(#[$m:meta])*] $V:ident $name:literal fields $class:literal) => {
        $(#[$m])*
        ///
        /// Made from the document's fields, given as keyword arguments (docs/format.md).
        #[pyclass(extends = Base, module = "splinekit", name = $class)]
        pub struct $V;

        #[pymethods]
        impl $V {
            #[new]
            #[pyo3(signature = (**fields))]
            fn new(fields: Option<&Bound<'_, pyo3::types::PyDict>>) -> PyResult<PyClassInitializer<Self>> {
                Ok(base($crate::kind_classes::kwargs_document($name, fields)?)?.add_subclass($V))
            }
        }
    };
    (@add $m:ident $names:ident $V:ident base) => {};
    (@add $m:ident $names:ident $V:ident own) => {};
    (@add $m:ident $names:ident $V:ident fields $class:literal) => {
        $m.add_class::<fields_classes::$V>()?;
        $names.push($class);
    };
}
pub(crate) use python_classes;
