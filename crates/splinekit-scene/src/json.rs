//! From JSON values to document structs, with errors that name the field by its full path.
//!
//! Documents are deserialised with serde (`#[derive(Deserialize)]` on each document
//! struct); [`fields`] runs it under `serde_path_to_error`, so an error says where it
//! happened (`control_points[2][1]`). A document nested in another (the `first` curve of a
//! `blend`, the `surface` of a `trimmed`) is parsed by its own `type`, which starts a new
//! path; [`nested`] carries that inner error out through serde and [`fields`] joins the
//! two paths again (`first.control_points[2][1]`).

use serde::Deserialize;
use serde::de::{DeserializeOwned, Deserializer, Error as _};
use serde_json::Value;

use crate::error::{DocumentError, Result};

/// Separates the path and message of a nested document's error inside a serde error
/// message (an ASCII control character, never part of a field name or message).
const NESTED: char = '\u{1d}';

/// Deserialises `value` (an object without its `type`) into `T`, locating errors.
pub fn fields<T: DeserializeOwned>(value: Value) -> Result<T> {
    serde_path_to_error::deserialize::<_, T>(value).map_err(|e| {
        let path = e.path().to_string();
        let outer = if path == "." { "" } else { path.as_str() };
        let message = e.into_inner().to_string();
        match message.strip_prefix(NESTED).and_then(|m| m.split_once(NESTED)) {
            Some((inner, message)) => DocumentError::new(inner, message).within(outer),
            None => DocumentError::new(outer, message),
        }
    })
}

/// Deserialises a value with `parse`, reporting its errors relative to the field that
/// holds it: the `Deserialize` of documents nested in other documents.
pub fn nested<'de, D, T>(deserializer: D, parse: impl FnOnce(Value) -> Result<T>) -> std::result::Result<T, D::Error>
where
    D: Deserializer<'de>,
{
    let value = Value::deserialize(deserializer)?;
    parse(value).map_err(|e| D::Error::custom(format_args!("{NESTED}{}{NESTED}{}", e.path, e.message)))
}

/// A list field that may also be absent or `null` (an empty list); anything else than a
/// list is refused with "expected a list, got …".
pub fn list<'de, D, T>(deserializer: D) -> std::result::Result<Vec<T>, D::Error>
where
    D: Deserializer<'de>,
    T: DeserializeOwned,
{
    nested(deserializer, |value| match value {
        Value::Null => Ok(Vec::new()),
        Value::Array(items) => items
            .into_iter()
            .enumerate()
            .map(|(i, item)| fields(item).map_err(|e| e.within(&format!("[{i}]"))))
            .collect(),
        other => Err(DocumentError::new("", format!("expected a list, got {}", kind(&other)))),
    })
}

/// Parses JSON text into a value; invalid text is refused at `document` with serde_json's
/// message ("invalid JSON: …"), the one entry from text of shapes and scenes alike.
pub fn parse_text(text: &str) -> Result<Value> {
    serde_json::from_str(text).map_err(|e| DocumentError::new("document", format!("invalid JSON: {e}")))
}

/// Splits a document object into its `type` and the remaining fields (taking the object,
/// so that a large document is not copied).
pub fn split_type(value: Value) -> Result<(String, Value)> {
    let Value::Object(mut map) = value else {
        return Err(DocumentError::new(
            "",
            format!("expected a JSON object with a \"type\" field, got {}", kind(&value)),
        ));
    };
    let ty = match map.remove("type") {
        Some(Value::String(s)) => s,
        Some(other) => return Err(DocumentError::new("type", format!("expected a string, got {}", kind(&other)))),
        None => return Err(DocumentError::new("type", "missing (every shape document needs a \"type\")")),
    };
    Ok((ty, Value::Object(map)))
}

/// JSON kind of a value, for messages.
pub fn kind(v: &Value) -> &'static str {
    match v {
        Value::Null => "null",
        Value::Bool(_) => "a boolean",
        Value::Number(_) => "a number",
        Value::String(_) => "a string",
        Value::Array(_) => "an array",
        Value::Object(_) => "an object",
    }
}
