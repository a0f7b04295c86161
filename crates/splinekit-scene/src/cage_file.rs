//! Cage files of `subdivision_surface` documents: a document may name an OBJ file
//! (`"obj": "cage.obj"`, relative to the document's folder) instead of giving `vertices`
//! and `faces`; [`read_cage_files`] reads every such file of a document or scene into the
//! document (its `v` and `f` lines as `vertices` and `faces`, its `t crease` tags before
//! the document's own `creases`), so the loaded document holds the cage inline.

use std::path::Path;

use serde_json::{Value, json};
use splinekit::subdivision::surface::read_obj_cage;

use crate::error::{DocumentError, Result};

/// The largest cage file read (bytes).
pub const MAX_CAGE_FILE_BYTES: u64 = 1 << 30;

/// Reads the cage file of every `subdivision_surface` in `value` (nested ones too), paths
/// relative to `folder`; errors name the field (`objects[1].shape.obj: …`).
pub fn read_cage_files(value: &mut Value, folder: &Path) -> Result<()> {
    walk(value, folder, "")
}

fn walk(value: &mut Value, folder: &Path, path: &str) -> Result<()> {
    let join = |key: &str| if path.is_empty() { key.to_string() } else { format!("{path}.{key}") };
    match value {
        Value::Array(items) => {
            items.iter_mut().enumerate().try_for_each(|(i, v)| walk(v, folder, &format!("{path}[{i}]")))
        }
        Value::Object(map) => {
            if map.get("type").and_then(Value::as_str) == Some("subdivision_surface")
                && let Some(file) = map.get("obj")
            {
                let field = join("obj");
                let Some(file) = file.as_str() else {
                    return Err(DocumentError::new(field, format!("expected a file name, got {file}")));
                };
                if map.contains_key("vertices") || map.contains_key("faces") {
                    return Err(DocumentError::new(
                        field,
                        "give the cage either as a file (\"obj\") or as \"vertices\" and \"faces\", not both",
                    ));
                }
                let full = folder.join(file);
                let cannot = |e: &dyn std::fmt::Display| {
                    DocumentError::new(field.clone(), format!("cannot read the cage file '{}': {e}", full.display()))
                };
                let size = std::fs::metadata(&full).map_err(|e| cannot(&e))?.len();
                if size > MAX_CAGE_FILE_BYTES {
                    return Err(cannot(&format!("{size} bytes, more than {MAX_CAGE_FILE_BYTES}")));
                }
                let text = std::fs::read_to_string(&full).map_err(|e| cannot(&e))?;
                let cage = read_obj_cage(&text).map_err(|e| cannot(&e))?;
                let mut creases: Vec<Value> =
                    cage.creases.iter().map(|c| json!({"edge": [c.a, c.b], "sharpness": c.sharpness})).collect();
                if let Some(Value::Array(own)) = map.get("creases") {
                    creases.extend(own.iter().cloned());
                }
                map.remove("obj");
                map.insert("vertices".into(), json!(cage.vertices));
                map.insert("faces".into(), json!(cage.faces));
                if !creases.is_empty() {
                    map.insert("creases".into(), Value::Array(creases));
                }
                return Ok(());
            }
            map.iter_mut().try_for_each(|(k, v)| walk(v, folder, &join(k)))
        }
        _ => Ok(()),
    }
}
