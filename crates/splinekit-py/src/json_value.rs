//! Python objects ↔ JSON values, so that documents given as dicts (or built from
//! arguments) go through the same parser, with the same messages, as the command line's
//! JSON files.

use pyo3::prelude::*;
use pyo3::types::{PyBool, PyDict, PyFloat, PyInt, PyList, PyString, PyTuple};
use serde_json::{Map, Number, Value};

use crate::errors::value_error;

/// Deepest nesting accepted (documents nest a few levels; this guards the recursion).
const MAX_DEPTH: usize = 64;

/// A Python value (dict, list, tuple, str, int, float, bool, None, numpy array or
/// scalar) as JSON; `path` names it in errors (`control_points[2][1]`).
pub fn to_value(ob: &Bound<'_, PyAny>, path: &str) -> PyResult<Value> {
    to_value_at(ob, path, 0)
}

fn to_value_at(ob: &Bound<'_, PyAny>, path: &str, depth: usize) -> PyResult<Value> {
    if depth > MAX_DEPTH {
        return Err(value_error(format!("{path}: nested more than {MAX_DEPTH} levels deep")));
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
    if let Ok(f) = ob.cast::<PyFloat>() {
        return number(f.value(), path);
    }
    if let Ok(s) = ob.cast::<PyString>() {
        return Ok(Value::String(s.to_cow()?.into_owned()));
    }
    if let Ok(d) = ob.cast::<PyDict>() {
        let mut map = Map::new();
        for (k, v) in d.iter() {
            let key: String = k.extract().map_err(|_| value_error(format!("{path}: keys must be strings")))?;
            let inner = if path.is_empty() { key.clone() } else { format!("{path}.{key}") };
            map.insert(key, to_value_at(&v, &inner, depth + 1)?);
        }
        return Ok(Value::Object(map));
    }
    if ob.is_instance_of::<PyList>() || ob.is_instance_of::<PyTuple>() {
        let items: Vec<Value> = ob
            .try_iter()?
            .enumerate()
            .map(|(i, item)| to_value_at(&item?, &format!("{path}[{i}]"), depth + 1))
            .collect::<PyResult<_>>()?;
        return Ok(Value::Array(items));
    }
    if ob.hasattr("tolist")? {
        return to_value_at(&ob.call_method0("tolist")?, path, depth + 1);
    }
    Err(value_error(format!("{path}: cannot be written as JSON ({})", ob.get_type().name()?)))
}

fn integer(ob: &Bound<'_, PyAny>, path: &str) -> PyResult<Value> {
    if let Ok(i) = ob.extract::<i64>() {
        return Ok(Value::from(i));
    }
    if let Ok(u) = ob.extract::<u64>() {
        return Ok(Value::from(u));
    }
    number(ob.extract::<f64>()?, path)
}

/// A finite number; JSON has no NaN or infinity.
pub fn number(v: f64, path: &str) -> PyResult<Value> {
    Number::from_f64(v).map(Value::Number).ok_or_else(|| value_error(format!("{path}: value is not finite ({v})")))
}

/// A JSON value as a Python object (through the standard `json` module).
pub fn to_python<'py>(py: Python<'py>, value: &Value) -> PyResult<Bound<'py, PyAny>> {
    let text = serde_json::to_string(value).map_err(value_error)?;
    py.import("json")?.call_method1("loads", (text,))
}
