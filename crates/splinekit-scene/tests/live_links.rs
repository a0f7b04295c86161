//! Live links in scenes: a blending spline with `"model_of": k` takes object k's shape as
//! its model when the scene is read, follows it when object k changes and the scene is
//! resolved again (what the studio does after every edit), is written back as the link
//! alone, and refuses links that cannot be followed, naming `objects[i].model_of`.

use serde_json::json;
use splinekit::curve::Curve;
use splinekit::surface::Surface;
use splinekit_scene::ShapeDocument;
use splinekit_scene::curves::CurveDocument;
use splinekit_scene::scenes::SceneDocument;
use splinekit_scene::surfaces::SurfaceDocument;

fn scene(value: serde_json::Value) -> SceneDocument {
    SceneDocument::from_value(value).unwrap()
}

fn error(value: serde_json::Value) -> String {
    SceneDocument::from_value(value).err().map(|e| e.to_string()).unwrap_or_else(|| "read".into())
}

fn curve3(shape: &ShapeDocument) -> Box<dyn Curve<3>> {
    match shape {
        ShapeDocument::Curve(c) => c.build_in::<3>().unwrap(),
        other => panic!("{other:?}"),
    }
}

#[test]
fn a_blending_spline_of_another_object_follows_it() {
    let mut s = scene(json!({"type": "scene", "objects": [
        {"shape": {"type": "heart", "scale": 1}},
        {"shape": {"type": "blending_spline", "local_curves": 8}, "model_of": 0, "local_pieces": true}
    ]}));
    let ShapeDocument::Curve(CurveDocument::BlendingSpline(d)) = &s.objects[1].shape else { panic!() };
    assert_eq!(
        d.model.as_deref(),
        Some(match &s.objects[0].shape {
            ShapeDocument::Curve(c) => c,
            _ => panic!(),
        })
    );
    // ERBS reproduces its model at every knot (8 uniform knots over [0, 2π], closed).
    let (heart, spline) = (curve3(&s.objects[0].shape), curve3(&s.objects[1].shape));
    for k in 0..8 {
        let t = std::f64::consts::TAU * k as f64 / 8.0;
        assert!((heart.point(t) - spline.point(t)).norm() < 1e-12, "knot {k}");
    }
    // The model is edited (scaled): resolving again, the spline follows.
    s.objects[0].shape = ShapeDocument::Curve(CurveDocument::from_value(json!({"type": "heart", "scale": 2})).unwrap());
    s.resolve_models().unwrap();
    let (heart, spline) = (curve3(&s.objects[0].shape), curve3(&s.objects[1].shape));
    for k in 0..8 {
        let t = std::f64::consts::TAU * k as f64 / 8.0;
        assert!((heart.point(t) - spline.point(t)).norm() < 1e-12, "knot {k} after the edit");
    }
    // Written back as the link alone, read back equal.
    let v = s.to_value();
    assert_eq!(v["objects"][1]["model_of"], json!(0));
    assert!(v["objects"][1]["shape"].get("model").is_none(), "{v}");
    assert_eq!(SceneDocument::from_value(v).unwrap(), s);
    // An object's own document (what the studio edits) keeps the copy beside the link.
    let o = s.objects[1].to_value();
    assert_eq!(o["model_of"], json!(0));
    assert!(o["shape"].get("model").is_some());
}

#[test]
fn links_follow_chains_and_surfaces() {
    let s = scene(json!({"type": "scene", "objects": [
        {"shape": {"type": "blending_spline_surface", "local_surfaces": [4, 4]}, "model_of": 1},
        {"shape": {"type": "blending_spline_surface", "local_surfaces": [6, 5]}, "model_of": 2},
        {"shape": {"type": "torus", "major_radius": 3, "minor_radius": 1}}
    ]}));
    let ShapeDocument::Surface(SurfaceDocument::BlendingSplineSurface(d)) = &s.objects[0].shape else { panic!() };
    let Some(model) = d.model.as_deref() else { panic!("resolved") };
    assert!(matches!(model, SurfaceDocument::BlendingSplineSurface(_)), "a spline of the spline of the torus");
    let ShapeDocument::Surface(outer) = &s.objects[0].shape else { panic!() };
    let built = outer.build_in::<3>().unwrap();
    assert!(built.point(0.0, 0.0).norm() > 3.9 && built.point(0.0, 0.0).norm() < 4.1);
}

#[test]
fn links_that_cannot_be_followed_are_refused_naming_the_field() {
    let heart = json!({"shape": {"type": "heart"}});
    let link = |k: serde_json::Value| json!({"shape": {"type": "blending_spline", "local_curves": 8}, "model_of": k});
    let e = error(json!({"type": "scene", "objects": [heart, link(json!(5))]}));
    assert_eq!(e, "objects[1].model_of: 5: the scene has 2 objects");
    let e = error(json!({"type": "scene", "objects": [heart, link(json!(1))]}));
    assert_eq!(e, "objects[1].model_of: 1: an object cannot be its own model");
    let e = error(json!({"type": "scene", "objects": [link(json!(1)), link(json!(0))]}));
    assert!(e.contains("model_of: the models run in a circle through objects"), "{e}");
    let e = error(json!({"type": "scene", "objects": [{"shape": {"type": "torus"}}, link(json!(0))]}));
    assert_eq!(e, "objects[1].model_of: object 0 is a surface; a blending_spline takes a curve");
    let e = error(json!({"type": "scene", "objects": [heart, {"shape": {"type": "circle"}, "model_of": 0}]}));
    assert!(e.starts_with("objects[1].model_of: only a blending_spline"), "{e}");
    let e = error(json!({"type": "scene", "objects": [heart, link(json!("first"))]}));
    assert!(e.contains("model_of: expected the index of an object"), "{e}");
}
