//! Python objects ↔ JSON values, so that documents given as dicts (or built from
//! arguments) go through the same parser, with the same messages, as the command line's
//! JSON files.
//!
//! Both directions walk the objects directly (no JSON text in between): pickling and
//! unpickling a shape costs a walk over its numbers, not a print and a parse of them. A
//! value's path (`control_points[2][1]`) is kept as a chain of borrowed segments on the
//! stack and written out only when an error names it.

use pyo3::prelude::*;
use pyo3::types::{PyBool, PyDict, PyFloat, PyInt, PyList, PyString, PyTuple};
use serde_json::{Map, Number, Value};

use crate::errors::value_error;

/// Deepest nesting accepted (documents nest a few levels; this guards the recursion).
const MAX_DEPTH: usize = 64;

/// Where a value sits in the document: the root's name, a dict key below a parent or a
/// list index below a parent.
#[derive(Clone, Copy)]
enum Path<'a> {
    Root(&'a str),
    Key(&'a Path<'a>, &'a str),
    Index(&'a Path<'a>, usize),
}

impl Path<'_> {
    /// The path as the errors write it: `a.b[2][1]`, or the root's name alone.
    fn render(&self) -> String {
        match self {
            Path::Root(name) => (*name).to_string(),
            Path::Key(parent, key) => {
                let head = parent.render();
                if head.is_empty() { (*key).to_string() } else { format!("{head}.{key}") }
            }
            Path::Index(parent, i) => format!("{}[{i}]", parent.render()),
        }
    }
}

/// A Python value (dict, list, tuple, str, int, float, bool, None, numpy array or
/// scalar) as JSON; `path` names it in errors (`control_points[2][1]`).
pub fn to_value(ob: &Bound<'_, PyAny>, path: &str) -> PyResult<Value> {
    to_value_at(ob, Path::Root(path), 0)
}

fn to_value_at(ob: &Bound<'_, PyAny>, path: Path<'_>, depth: usize) -> PyResult<Value> {
    if depth > MAX_DEPTH {
        return Err(value_error(format!("{}: nested more than {MAX_DEPTH} levels deep", path.render())));
    }
    if let Ok(f) = ob.cast::<PyFloat>() {
        return number(f.value(), || path.render());
    }
    if ob.is_none() {
        return Ok(Value::Null);
    }
    if let Ok(b) = ob.cast::<PyBool>() {
        return Ok(Value::Bool(b.is_true()));
    }
    if ob.is_instance_of::<PyInt>() {
        return integer(ob, path);
    }
    if let Ok(s) = ob.cast::<PyString>() {
        return Ok(Value::String(s.to_cow()?.into_owned()));
    }
    if let Ok(d) = ob.cast::<PyDict>() {
        let mut map = Map::new();
        for (k, v) in d.iter() {
            let key: String =
                k.extract().map_err(|_| value_error(format!("{}: keys must be strings", path.render())))?;
            let inner = Path::Key(&path, &key);
            let item = to_value_at(&v, inner, depth + 1)?;
            map.insert(key, item);
        }
        return Ok(Value::Object(map));
    }
    if let Ok(list) = ob.cast::<PyList>() {
        return sequence(list.iter(), list.len(), path, depth);
    }
    if let Ok(tuple) = ob.cast::<PyTuple>() {
        return sequence(tuple.iter(), tuple.len(), path, depth);
    }
    // splinekit's objects (curves, surfaces, scenes, subdivision surfaces, B-functions)
    // stand for their documents.
    if ob.hasattr("to_dict")? && ob.getattr("__module__").is_ok_and(|m| m.to_string().starts_with("splinekit")) {
        return to_value_at(&ob.call_method0("to_dict")?, path, depth + 1);
    }
    if ob.hasattr("tolist")? {
        return to_value_at(&ob.call_method0("tolist")?, path, depth + 1);
    }
    Err(value_error(format!("{}: cannot be written as JSON ({})", path.render(), ob.get_type().name()?)))
}

/// The items of a list or tuple as a JSON array, each named by its index in errors.
fn sequence<'py>(
    items: impl Iterator<Item = Bound<'py, PyAny>>,
    len: usize,
    path: Path<'_>,
    depth: usize,
) -> PyResult<Value> {
    let mut values = Vec::with_capacity(len);
    for (i, item) in items.enumerate() {
        values.push(to_value_at(&item, Path::Index(&path, i), depth + 1)?);
    }
    Ok(Value::Array(values))
}

fn integer(ob: &Bound<'_, PyAny>, path: Path<'_>) -> PyResult<Value> {
    if let Ok(i) = ob.extract::<i64>() {
        return Ok(Value::from(i));
    }
    if let Ok(u) = ob.extract::<u64>() {
        return Ok(Value::from(u));
    }
    number(ob.extract::<f64>()?, || path.render())
}

/// A finite number; JSON has no NaN or infinity. `path` is written only for the error.
fn number(v: f64, path: impl FnOnce() -> String) -> PyResult<Value> {
    Number::from_f64(v).map(Value::Number).ok_or_else(|| value_error(format!("{}: value is not finite ({v})", path())))
}

/// A JSON value as a Python object, as the standard `json` module would read its text:
/// objects as dicts (in their order), arrays as lists, integers as `int`, other numbers
/// as `float` (the same double), strings, booleans and null as `str`, `bool` and `None`.
pub fn to_python<'py>(py: Python<'py>, value: &Value) -> PyResult<Bound<'py, PyAny>> {
    Ok(match value {
        Value::Null => py.None().into_bound(py),
        Value::Bool(b) => PyBool::new(py, *b).to_owned().into_any(),
        Value::Number(n) => {
            if let Some(i) = n.as_i64() {
                i.into_pyobject(py)?.into_any()
            } else if let Some(u) = n.as_u64() {
                u.into_pyobject(py)?.into_any()
            } else {
                PyFloat::new(py, n.as_f64().unwrap_or(f64::NAN)).into_any()
            }
        }
        Value::String(s) => PyString::new(py, s).into_any(),
        Value::Array(items) => {
            let list = PyList::empty(py);
            for item in items {
                list.append(to_python(py, item)?)?;
            }
            list.into_any()
        }
        Value::Object(map) => {
            let dict = PyDict::new(py);
            for (key, item) in map {
                dict.set_item(key, to_python(py, item)?)?;
            }
            dict.into_any()
        }
    })
}
