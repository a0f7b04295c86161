//! Placed objects and instances in scenes: `"placement"` is a rigid frame checked when the
//! scene is read; `"instance_of": k` gives an object object k's shape, is written back as
//! the link alone, and refuses links that cannot be followed, naming the field.

use serde_json::json;
use splinekit_scene::scenes::SceneDocument;

fn error(value: serde_json::Value) -> String {
    SceneDocument::from_value(value).err().map(|e| e.to_string()).unwrap_or_else(|| "read".into())
}

#[test]
fn an_instance_takes_its_parts_shape_and_is_written_as_the_link() {
    let doc = json!({"type": "scene", "objects": [
        {"shape": {"type": "torus", "major_radius": 2}, "name": "ring"},
        {"instance_of": 0, "name": "ring again", "placement": {"origin": [0, 0, 5], "axis": [1, 0, 0], "ref_direction": [0, 1, 0]}}]});
    let scene = SceneDocument::from_value(doc).unwrap();
    assert_eq!(scene.objects[1].shape, scene.objects[0].shape);
    assert_eq!(scene.objects[1].name.as_deref(), Some("ring again"));
    let t = scene.objects[1].placement.as_ref().unwrap().transform().unwrap();
    // x ↦ the reference (0, 1, 0), z ↦ the axis (1, 0, 0), y = z × x = (0, 0, 1).
    assert_eq!(t.apply([1.0, 0.0, 0.0]), [0.0, 1.0, 5.0]);
    assert_eq!(t.apply([0.0, 1.0, 0.0]), [0.0, 0.0, 6.0]);
    assert_eq!(t.apply([0.0, 0.0, 1.0]), [1.0, 0.0, 5.0]);
    let written = scene.objects[1].to_value();
    assert_eq!(written["instance_of"], 0);
    assert!(written.get("shape").is_none(), "{written}");
    assert_eq!(written["placement"]["origin"], json!([0.0, 0.0, 5.0]));
    // Read back, the same scene.
    let again =
        SceneDocument::from_value(json!({"type": "scene", "objects": [scene.objects[0].to_value(), written]})).unwrap();
    assert_eq!(again.objects, scene.objects);
}

#[test]
fn links_and_frames_that_cannot_be_followed_are_refused_by_field() {
    let torus = json!({"shape": {"type": "torus"}});
    let cases = [
        (json!([torus, {"instance_of": 5}]), "objects[1].instance_of: 5: the scene has 2 objects"),
        (json!([torus, {"instance_of": 1}]), "objects[1].instance_of: 1: an object cannot be an instance of itself"),
        (
            json!([torus, {"instance_of": 0}, {"instance_of": 1}]),
            "objects[2].instance_of: 1: object 1 is itself an instance (of object 0)",
        ),
        (json!([torus, {"instance_of": 0, "shape": {"type": "torus"}}]), "give `shape` or `instance_of`, not both"),
        (json!([torus, {"instance_of": -1}]), "instance_of: expected the index of an object of the scene, got -1"),
        (
            json!([{"shape": {"type": "torus"}, "placement": {"axis": [0, 0, 0]}}]),
            "placement: axis: must be a non-zero vector",
        ),
        (
            json!([{"shape": {"type": "torus"}, "placement": {"axis": [0, 0, 1], "ref_direction": [0, 0, 2]}}]),
            "ref_direction: must not be parallel",
        ),
        (
            json!([{"shape": {"type": "torus"}, "placement": {"origin": [1, 2]}}]),
            "origin: expected 3 finite coordinates",
        ),
        (json!([{"shape": {"type": "torus"}, "placement": {"turn": 1}}]), "unknown field `turn`"),
        (json!([{"shape": {"type": "torus"}, "name": 3}]), "name: expected a string"),
    ];
    for (objects, expected) in cases {
        let e = error(json!({"type": "scene", "objects": objects}));
        assert!(e.contains(expected), "{objects}: {e:?} lacks {expected:?}");
    }
}
