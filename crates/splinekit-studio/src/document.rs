//! The document open in the studio: read from a file (a scene, or a bare shape that becomes
//! a one-object scene), written back as an ordinary scene document; [`Document`] holds it
//! with the file it came from and its undo history, and every change of it goes through
//! that history.

use std::path::{Path, PathBuf};

use splinekit_scene::scenes::{CameraDoc, SceneDocument};
use splinekit_scene::{DocumentError, SceneOrShape};

use crate::edit::{BuildCheck, Edit, EditError};
use crate::error::StudioError;
use crate::history::History;

/// The scene being edited, the file it came from, and undo and redo. The scene is read
/// through [`Document::scene`] and changed only by [`Document::edit`], [`Document::undo`]
/// and [`Document::redo`], so every change can be undone.
#[derive(Debug, Clone)]
pub struct Document {
    scene: SceneDocument,
    path: Option<PathBuf>,
    history: History,
}

impl Document {
    /// The document `scene`, read from `path` (`None`: the starter scene or text).
    pub fn new(scene: SceneDocument, path: Option<PathBuf>) -> Self {
        Document { scene, path, history: History::default() }
    }

    /// The scene.
    pub fn scene(&self) -> &SceneDocument {
        &self.scene
    }

    /// The file it came from (or was last saved to).
    pub fn path(&self) -> Option<&Path> {
        self.path.as_deref()
    }

    /// Applies `edit` through the history (with `merge`, joining the last step during a
    /// drag, [`History::apply`]), the edited shape built by `check`.
    ///
    /// Live links are followed afterwards ([`SceneDocument::resolve_models`]): a blending
    /// spline whose `model_of` is the edited object takes its new shape as its model (and
    /// the view re-fits it, as it re-fits any changed object). An edit after which a link
    /// cannot be followed (the model turned from a curve into a surface) is undone and
    /// refused.
    pub fn edit(&mut self, edit: Edit, merge: bool, check: &mut BuildCheck<'_>) -> Result<(), EditError> {
        self.history.apply_with(&mut self.scene, edit, merge, check)?;
        if let Err(e) = self.scene.resolve_models() {
            self.history.undo(&mut self.scene)?;
            self.scene.resolve_models().map_err(EditError::Invalid)?;
            return Err(EditError::Invalid(e));
        }
        Ok(())
    }

    /// Ends a run of merged edits (the drag ended): the next edit is a new step.
    pub fn close_step(&mut self) {
        self.history.close();
    }

    /// Undoes the last step; `false` when there is none.
    pub fn undo(&mut self) -> Result<bool, EditError> {
        let done = self.history.undo(&mut self.scene)?;
        self.scene.resolve_models().map_err(EditError::Invalid)?;
        Ok(done)
    }

    /// Redoes the last undone step; `false` when there is none.
    pub fn redo(&mut self) -> Result<bool, EditError> {
        let done = self.history.redo(&mut self.scene)?;
        self.scene.resolve_models().map_err(EditError::Invalid)?;
        Ok(done)
    }

    /// Saves to the file opened (or `studio.json`, [`save_path`]) with `camera` as the
    /// scene's camera; the file saved to is the document's from then on. The message for
    /// the status line: the file saved, or why not.
    pub fn save(&mut self, camera: Option<CameraDoc>) -> String {
        let path = save_path(self.path.as_deref());
        let mut scene = self.scene.clone();
        if let Some(c) = camera {
            scene.camera = Some(c);
        }
        let message = match write(&scene, &path) {
            Ok(()) => format!("saved {}", path.display()),
            Err(e) => e.to_string(),
        };
        self.path = Some(path);
        message
    }
}

/// The starter scene shown without a file: the heart as a blending spline of ten
/// quadratic Bézier locals, local curves shown.
pub const STARTER: &str = r#"{"type": "scene", "objects": [{"shape": {"type": "blending_spline",
  "model": {"type": "heart"}, "local_curves": 10, "local": {"type": "bezier", "degree": 2}},
  "local_pieces": true, "color": [0.9, 0.25, 0.55], "line_width": 3}], "size": [600, 600]}"#;

/// Reads a scene or shape document (cage files of subdivision surfaces relative to its
/// folder); the message names the file and the field.
pub fn read(path: &Path) -> Result<SceneDocument, StudioError> {
    let text = std::fs::read_to_string(path).map_err(|e| StudioError::file(path, format!("cannot read: {e}")))?;
    let folder = path.parent().filter(|p| !p.as_os_str().is_empty()).unwrap_or(Path::new("."));
    Ok(SceneOrShape::from_json_in(&text, folder)
        .map(SceneOrShape::into_scene)
        .map_err(|e| e.about(&path.display().to_string()))?)
}

/// Parses a scene or shape document from JSON text (cage files relative to the current
/// folder).
pub fn parse(text: &str) -> Result<SceneDocument, StudioError> {
    Ok(SceneOrShape::from_json_in(text, Path::new(".")).map(SceneOrShape::into_scene)?)
}

/// Writes the scene as pretty JSON.
pub fn write(scene: &SceneDocument, path: &Path) -> Result<(), StudioError> {
    let text = serde_json::to_string_pretty(&scene.to_value()).map_err(|e| DocumentError::new("", e.to_string()))?;
    splinekit_scene::write_file(path, (text + "\n").as_bytes())
        .map_err(|e| StudioError::file(path, format!("cannot write: {e}")))
}

/// Where Ctrl+S writes: the file opened, or `studio.json` for the starter scene.
pub fn save_path(opened: Option<&Path>) -> PathBuf {
    opened.map_or_else(|| PathBuf::from("studio.json"), Path::to_path_buf)
}

#[cfg(test)]
mod tests {
    use super::*;
    use serde_json::{Value, json};

    /// A document with numbers that f32 cannot hold (0.9, 0.1, 0.95), saved and read back:
    /// the saved file holds the same numbers, no `animation` block, and saving again
    /// writes the same bytes.
    #[test]
    fn saving_keeps_the_numbers_given_and_adds_no_animation() {
        let text = r#"{"type": "scene", "objects": [{"shape": {"type": "bspline", "degree": 2,
            "knots": [0, 0, 0, 0.1, 1, 1, 1], "control_points": [[0, 0], [0.3, 0.7], [1.1, 0.9], [2, 0]]},
            "color": [0.9, 0.25, 0.55, 0.7], "line_width": 2.1, "control_net": true}],
            "background": [0.95, 0.9, 0.85], "size": [640, 480]}"#;
        let dir = std::env::temp_dir().join(format!("splinekit-studio-save-{}", std::process::id()));
        std::fs::create_dir_all(&dir).expect("a temporary directory");
        let (first, second) = (dir.join("first.json"), dir.join("second.json"));
        write(&parse(text).expect("valid"), &first).expect("saved");
        let saved: Value = serde_json::from_str(&std::fs::read_to_string(&first).expect("read")).expect("JSON");
        let object = &saved["objects"][0];
        assert_eq!(object["color"], json!([0.9, 0.25, 0.55, 0.7]));
        assert_eq!(object["line_width"], json!(2.1));
        assert_eq!(object["shape"]["knots"][3], json!(0.1));
        assert_eq!(object["shape"]["control_points"][1], json!([0.3, 0.7]));
        assert_eq!(saved["background"], json!([0.95, 0.9, 0.85]));
        assert!(saved.get("animation").is_none(), "{saved}");
        write(&read(&first).expect("reads back"), &second).expect("saved again");
        let bytes = |p: &Path| std::fs::read(p).expect("read");
        assert_eq!(bytes(&first), bytes(&second));
        // A document that has a clock keeps it.
        let clocked = text.replacen(r#""size""#, r#""animation": {"duration": 2.5, "fps": 24}, "size""#, 1);
        write(&parse(&clocked).expect("valid"), &first).expect("saved");
        let saved: Value = serde_json::from_str(&std::fs::read_to_string(&first).expect("read")).expect("JSON");
        assert_eq!(saved["animation"], json!({"duration": 2.5, "fps": 24.0}));
        std::fs::remove_dir_all(&dir).ok();
    }

    /// A blending spline of object 0 follows object 0's edits, their undo and redo; an
    /// edit that breaks the link is refused and leaves the scene as it was.
    #[test]
    fn a_linked_blending_spline_follows_its_models_edits() {
        use splinekit_scene::ShapeDocument;
        use splinekit_scene::curves::CurveDocument;
        let text = r#"{"type": "scene", "objects": [{"shape": {"type": "heart", "scale": 1}},
            {"shape": {"type": "blending_spline", "local_curves": 8}, "model_of": 0}]}"#;
        let mut doc = Document::new(parse(text).expect("valid"), None);
        let model_scale = |doc: &Document| match &doc.scene().objects[1].shape {
            ShapeDocument::Curve(CurveDocument::BlendingSpline(d)) => {
                d.model.as_ref().map(|m| m.to_value()["scale"].clone())
            }
            _ => None,
        };
        assert_eq!(model_scale(&doc), Some(json!(1.0)));
        let mut check = |_: usize, shape: &ShapeDocument| crate::edit::check_builds(shape);
        let scale = Edit::Set { object: 0, pointer: "/shape/scale".into(), value: Some(json!(2.5)) };
        doc.edit(scale, false, &mut check).expect("edited");
        assert_eq!(model_scale(&doc), Some(json!(2.5)), "the spline follows its model");
        doc.undo().expect("undone");
        assert_eq!(model_scale(&doc), Some(json!(1.0)));
        doc.redo().expect("redone");
        assert_eq!(model_scale(&doc), Some(json!(2.5)));
        let before = doc.scene().clone();
        let to_surface = Edit::Set { object: 0, pointer: "/shape".into(), value: Some(json!({"type": "torus"})) };
        let e = doc.edit(to_surface, false, &mut check).expect_err("a blending_spline takes a curve");
        assert!(e.to_string().contains("objects[1].model_of: object 0 is a surface"), "{e}");
        assert_eq!(doc.scene(), &before);
    }
}
