//! The document open in the studio: read from a file (a scene, or a bare shape that becomes
//! a one-object scene), written back as an ordinary scene document.

use std::path::{Path, PathBuf};

use splinekit_scene::SceneOrShape;
use splinekit_scene::scenes::SceneDocument;

/// The starter scene shown without a file: the heart as a blending spline of ten
/// quadratic Bézier locals, local curves shown.
pub const STARTER: &str = r#"{"type": "scene", "objects": [{"shape": {"type": "blending_spline",
  "model": {"type": "heart"}, "local_curves": 10, "local": {"type": "bezier", "degree": 2}},
  "local_pieces": true, "color": [0.9, 0.25, 0.55], "line_width": 3}], "size": [600, 600]}"#;

/// Reads a scene or shape document; the message names the file and the field.
pub fn read(path: &Path) -> Result<SceneDocument, String> {
    let text = std::fs::read_to_string(path).map_err(|e| format!("{}: cannot read: {e}", path.display()))?;
    parse(&text).map_err(|e| format!("{}: {e}", path.display()))
}

/// Parses a scene or shape document from JSON text.
pub fn parse(text: &str) -> Result<SceneDocument, String> {
    SceneOrShape::from_json(text).map(SceneOrShape::into_scene).map_err(|e| e.to_string())
}

/// Writes the scene as pretty JSON.
pub fn write(scene: &SceneDocument, path: &Path) -> Result<(), String> {
    let text = serde_json::to_string_pretty(&scene.to_value()).map_err(|e| e.to_string())?;
    splinekit_scene::write_file(path, (text + "\n").as_bytes())
        .map_err(|e| format!("{}: cannot write: {e}", path.display()))
}

/// Where Ctrl+S writes: the file opened, or `studio.json` for the starter scene.
pub fn save_path(opened: Option<&Path>) -> PathBuf {
    opened.map_or_else(|| PathBuf::from("studio.json"), Path::to_path_buf)
}
