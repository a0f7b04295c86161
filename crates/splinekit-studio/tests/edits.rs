//! Edits as commands on the scene document, without a window (issue 11): each edit changes
//! exactly what a document would say, undo restores the document exactly, and a value the
//! library refuses leaves the document as it was, with the library's message.

use serde_json::json;
use splinekit::Point;
use splinekit::curve::Curve;
use splinekit_render::{Camera, RenderScene};
use splinekit_scene::scenes::SceneDocument;
use splinekit_scene::{Decoration, ShapeDocument};
use splinekit_studio::edit::Edit;
use splinekit_studio::gesture::{Gesture, GestureKind};
use splinekit_studio::handles::{HandleKind, handles};
use splinekit_studio::history::History;
use splinekit_studio::studio::Studio;
use splinekit_studio::view_camera::Projector;

fn scene(text: &str) -> SceneDocument {
    splinekit_studio::document::parse(text).expect("a valid scene")
}

fn heart() -> SceneDocument {
    scene(
        &std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/../../examples/scenes/heart_local_curves.json"))
            .expect("the example"),
    )
}

fn curve(s: &SceneDocument) -> splinekit::blend::BlendingSplineCurve<3> {
    let ShapeDocument::Curve(c) = &s.objects[0].shape else { panic!("a curve") };
    let Decoration::LocalCurves(b) = c.decoration() else { panic!("a blending spline") };
    b.curve::<3>().expect("builds")
}

fn set(pointer: &str, value: serde_json::Value) -> Edit {
    Edit::Set { object: 0, pointer: pointer.into(), value: Some(value) }
}

#[test]
fn moving_a_local_curve_edits_its_transform_as_a_document_would_and_undo_restores_it() {
    let original = heart();
    let mut doc = original.clone();
    let mut history = History::default();
    history.apply(&mut doc, set("/shape/transforms/3", json!({"translate": [0.5, -1.0, 0.0]})), false).expect("valid");
    // The same as the document written by hand.
    let mut by_hand = original.to_value();
    by_hand["objects"][0]["shape"]["transforms"] = json!({"3": {"translate": [0.5, -1.0, 0.0]}});
    assert_eq!(doc, SceneDocument::from_value(by_hand).expect("valid"));
    // The curve moved on local 3's support only.
    let (before, after) = (curve(&original), curve(&doc));
    let support = after.local_support(3);
    assert!(
        (after.point(after.centre(3)) - before.point(after.centre(3)) - Point::<3>::new(0.5, -1.0, 0.0)).norm() < 1e-12
    );
    for i in 0..=400 {
        let t = after.domain().lerp(i as f64 / 400.0);
        if !(support.start < t && t < support.end) {
            assert_eq!(after.point(t), before.point(t), "t = {t}");
        }
    }
    assert!(history.undo(&mut doc).expect("undoable"));
    assert_eq!(doc, original);
    assert!(history.redo(&mut doc).expect("redoable"));
    assert_eq!(curve(&doc).point(after.centre(3)), after.point(after.centre(3)));
}

#[test]
fn a_refused_value_leaves_the_document_and_names_the_field() {
    let original = scene(
        r#"{"type":"scene","objects":[{"shape":{"type":"bspline","degree":2,"knots":[0,0,0,1,1,1],
        "control_points":[[0,0],[1,1],[2,0]]}}]}"#,
    );
    let mut doc = original.clone();
    let mut history = History::default();
    let e = history.apply(&mut doc, set("/shape/degree", json!(5)), false).expect_err("degree above the points");
    assert!(e.to_string().contains("degree"), "{e}");
    assert_eq!(doc, original);
    let e = history.apply(&mut doc, set("/density", json!(0)), false).expect_err("no samples");
    assert!(e.to_string().contains("density"), "{e}");
    let mut heart = heart();
    let e = history.apply(&mut heart, set("/shape/local_curves", json!(1)), false).expect_err("one local");
    assert!(e.to_string().contains("local_curves"), "{e}");
    let e =
        history.apply(&mut heart, set("/shape/bfunction", json!({"type": "erbs", "alpha": -1})), false).expect_err("α");
    assert!(e.to_string().contains("bfunction"), "{e}");
    assert_eq!(heart, self::heart());
    assert!(!history.can_undo(), "refused edits are not steps");
}

#[test]
fn properties_change_at_once_and_undo_one_by_one() {
    let original = heart();
    let mut doc = original.clone();
    let mut h = History::default();
    for (pointer, value) in [
        ("/shape/bfunction", json!({"type": "trigonometric"})),
        ("/shape/local_curves", json!(12)),
        ("/shape/local", json!({"type": "bezier", "degree": 3})),
        ("/density", json!(300)),
        ("/control_net", json!(true)),
    ] {
        h.apply(&mut doc, set(pointer, value.clone()), false).expect(pointer);
        assert_eq!(doc.objects[0].to_value().pointer(pointer), Some(&value));
    }
    assert_eq!(curve(&doc).local_count(), 12);
    for _ in 0..5 {
        assert!(h.undo(&mut doc).expect("undo"));
    }
    assert_eq!(doc, original);
    assert!(!h.undo(&mut doc).expect("nothing left"));
}

#[test]
fn a_control_point_moves_and_objects_are_added_duplicated_and_deleted() {
    let mut doc =
        scene(r#"{"type":"scene","objects":[{"shape":{"type":"bezier","control_points":[[0,0],[1,2],[3,0]]}}]}"#);
    let mut h = History::default();
    h.apply(&mut doc, set("/shape/control_points/1", json!([1.5, 2.5])), false).expect("valid");
    let hs = handles(&doc, None).expect("handles");
    assert_eq!(hs[1].kind, HandleKind::ControlPoint(1, "control_points"));
    assert_eq!(hs[1].position, [1.5, 2.5, 0.0]);
    let copy = Box::new(doc.objects[0].clone());
    h.apply(&mut doc, Edit::Insert { index: 1, object: copy }, false).expect("duplicate");
    assert_eq!(doc.objects.len(), 2);
    h.apply(&mut doc, Edit::Remove { index: 0 }, false).expect("delete");
    let e = h.apply(&mut doc, Edit::Remove { index: 0 }, false).expect_err("the last object");
    assert!(e.to_string().contains("objects"), "{e}");
    h.undo(&mut doc).expect("undo delete");
    h.undo(&mut doc).expect("undo duplicate");
    assert_eq!(doc.objects.len(), 1);
}

/// A top view of the heart at 600×600 pixels, as the studio draws it.
fn studio_on_heart() -> (Studio, Projector) {
    let mut studio = Studio::new(heart(), None);
    let rs: RenderScene = studio.render_scene((600, 600), false).expect("composes");
    assert!(matches!(rs.camera, Some(Camera::Orthographic { .. })), "the heart is seen from the top");
    (studio, Projector::new(&rs, (600, 600)))
}

#[test]
fn a_drag_on_a_handle_follows_the_mouse_and_is_one_undo_step() {
    let (mut studio, projector) = studio_on_heart();
    let h = studio.view.handles.iter().find(|h| h.kind == HandleKind::LocalCurve(4)).expect("local 4").clone();
    let (p, _) = projector.project(h.position).expect("in view");
    assert!(
        studio.begin_drag(&projector, [p[0] + 3.0, p[1] - 2.0], GestureKind::Move(None)),
        "picked within the radius"
    );
    for k in 1..=10 {
        studio.drag_to(&projector, [p[0] + 3.0 + 4.0 * k as f64, p[1] - 2.0 + 2.0 * k as f64]);
    }
    studio.end_drag();
    let moved = studio.selection.handle.clone().expect("still selected");
    let (q, _) = projector.project(moved.position).expect("in view");
    assert!((q[0] - (p[0] + 40.0)).abs() < 1e-6 && (q[1] - (p[1] + 20.0)).abs() < 1e-6, "{q:?} from {p:?}");
    studio.undo();
    assert_eq!(*studio.document.scene(), heart(), "the whole drag is one step");
    // The next frame shows the selection where the undo put it, not where the drag left it.
    studio.render_scene((600, 600), true).expect("composes");
    let back = studio.selection.handle.clone().expect("still selected");
    assert_eq!(back.position, h.position, "the selected handle follows the undo");
}

#[test]
fn rotating_and_scaling_by_hand_compose_with_the_transform() {
    let (studio, projector) = studio_on_heart();
    let h = studio.view.handles.iter().find(|h| h.kind == HandleKind::LocalCurve(1)).expect("local 1").clone();
    let (p, _) = projector.project(h.position).expect("in view");
    let rotate = Gesture::start(studio.document.scene(), &projector, &h, GestureKind::Rotate, [p[0] + 50.0, p[1]])
        .expect("starts");
    // A quarter turn counter-clockwise on screen (y down: from +x to −y).
    let Edit::Set { value: Some(v), .. } = rotate.edit_at(&projector, [p[0], p[1] - 50.0]).expect("an edit") else {
        panic!("a set")
    };
    let angle = v["rotate"]["angle"].as_f64().expect("an angle");
    let axis = &v["rotate"]["axis"];
    assert!(
        (angle - std::f64::consts::FRAC_PI_2).abs() < 1e-9 && (axis[2].as_f64().expect("z") - 1.0).abs() < 1e-9,
        "{v}"
    );
    let scale = Gesture::start(studio.document.scene(), &projector, &h, GestureKind::Scale, [p[0] + 20.0, p[1]])
        .expect("starts");
    let Edit::Set { value: Some(v), .. } = scale.edit_at(&projector, [p[0] + 50.0, p[1]]).expect("an edit") else {
        panic!("a set")
    };
    assert!((v["scale"].as_f64().expect("a factor") - 2.5).abs() < 1e-12, "{v}");
}

/// The world position of a shown handle of `kind`.
fn shown(studio: &Studio, kind: HandleKind) -> Option<splinekit_studio::handles::Handle> {
    studio.shown_handles().find(|h| h.kind == kind).cloned()
}

/// Drags the handle of `kind` by `by` pixels in ten steps; returns its pixel position
/// before and after.
fn drag(studio: &mut Studio, projector: &Projector, kind: HandleKind, by: [f64; 2]) -> ([f64; 2], [f64; 2]) {
    let h = shown(studio, kind).unwrap_or_else(|| panic!("{kind:?} shown"));
    let (p, _) = projector.project(h.position).expect("in view");
    assert!(studio.begin_drag(projector, p, GestureKind::Move(None)), "{kind:?} picked");
    for k in 1..=10 {
        studio.drag_to(projector, [p[0] + by[0] * k as f64 / 10.0, p[1] + by[1] * k as f64 / 10.0]);
    }
    studio.end_drag();
    let moved = studio.selection.handle.clone().expect("still selected");
    assert_eq!(moved.kind, kind);
    (p, projector.project(moved.position).expect("in view").0)
}

/// A control point of a local Bézier (GMlib's updateCoeffs): shown once its local is
/// selected, dragged so that its world position follows the mouse, saved as the local's
/// `local_control_points` entry with the other points as fitted; the curve changes inside
/// the local's support only; the drag is one undo step.
#[test]
fn a_control_point_of_a_local_bezier_follows_the_mouse_and_edits_that_local_only() {
    let (mut studio, projector) = studio_on_heart();
    let before = curve(studio.document.scene());
    let fitted = before.local_bezier_points(4).expect("Bézier locals").to_vec();
    assert_eq!(fitted.len(), 3, "quadratic locals");
    // Not shown (nor picked) until local 4 is selected; then only local 4's points are.
    let point = handles(studio.document.scene(), None).expect("handles");
    let point = point.iter().find(|h| h.kind == HandleKind::LocalCurvePoint(4, 1)).expect("a handle").clone();
    assert!(shown(&studio, HandleKind::LocalCurvePoint(4, 1)).is_none());
    let (px, _) = projector.project(point.position).expect("in view");
    assert!(studio.pick(&projector, px).is_none_or(|h| h.kind.point_path().is_none()));
    studio.selection.handle = shown(&studio, HandleKind::LocalCurve(4));
    let points: Vec<HandleKind> =
        studio.shown_handles().filter(|h| h.kind.point_path().is_some()).map(|h| h.kind).collect();
    assert_eq!(points, (0..3).map(|i| HandleKind::LocalCurvePoint(4, i)).collect::<Vec<_>>());
    assert_eq!(studio.pick(&projector, px).map(|h| h.kind), Some(HandleKind::LocalCurvePoint(4, 1)));
    // Drawn with the overlays: the control polygon through the local's world points.
    let drawn = studio.render_scene((600, 600), true).expect("composes");
    let polygon: Vec<[f32; 3]> = fitted.iter().map(|p| [p.x as f32, p.y as f32, p.z as f32]).collect();
    assert!(drawn.lines.iter().any(|l| l.points == polygon), "the control polygon of local 4");
    assert!(!studio.render_scene((600, 600), false).expect("composes").lines.iter().any(|l| l.points == polygon));

    let (from, to) = drag(&mut studio, &projector, HandleKind::LocalCurvePoint(4, 1), [30.0, -20.0]);
    assert!((to[0] - from[0] - 30.0).abs() < 1e-6 && (to[1] - from[1] + 20.0).abs() < 1e-6, "{to:?} from {from:?}");
    let doc = studio.document.scene().objects[0].to_value();
    let entry: Vec<Vec<f64>> =
        serde_json::from_value(doc["shape"]["local_control_points"]["4"].clone()).expect("the local's entry");
    assert_eq!(entry.len(), 3);
    assert_eq!(entry[0], fitted[0].as_slice(), "the other points stay as fitted");
    assert_eq!(entry[2], fitted[2].as_slice());
    assert!(doc["shape"].get("transforms").is_none(), "the frame did not change");
    let after = curve(studio.document.scene());
    let support = before.local_support(4);
    let mut changed = 0;
    for i in 0..=1000 {
        let t = std::f64::consts::TAU * i as f64 / 1000.0;
        if t <= support.start || t >= support.end {
            assert_eq!(before.point(t), after.point(t), "t = {t} is outside local 4's support");
        } else if before.point(t) != after.point(t) {
            changed += 1;
        }
    }
    assert!(changed > 50, "{changed}");
    studio.undo();
    assert_eq!(*studio.document.scene(), heart(), "the whole drag is one step");
    studio.redo();
    assert_eq!(curve(studio.document.scene()).point(support.lerp(0.5)), after.point(support.lerp(0.5)));
}

/// With the local turned and scaled by its transform, the point is moved in the local's
/// rest frame by the inverse of the frame, so that its world position still follows the
/// mouse; moving it along X only keeps its world y and z.
#[test]
fn a_local_bezier_point_of_a_turned_and_scaled_local_follows_the_mouse() {
    let (mut studio, projector) = studio_on_heart();
    let frame = json!({"rotate": {"axis": [0.0, 0.0, 1.0], "angle": 0.7}, "scale": 1.8, "translate": [0.5, -0.3, 0.0]});
    assert!(studio.edit(set("/shape/transforms/6", frame.clone()), false));
    studio.render_scene((600, 600), false).expect("composes");
    studio.selection.handle = shown(&studio, HandleKind::LocalCurve(6));
    let (from, to) = drag(&mut studio, &projector, HandleKind::LocalCurvePoint(6, 2), [-25.0, 35.0]);
    assert!((to[0] - from[0] + 25.0).abs() < 1e-6 && (to[1] - from[1] - 35.0).abs() < 1e-6, "{to:?} from {from:?}");
    assert_eq!(studio.document.scene().objects[0].to_value()["shape"]["transforms"]["6"], frame, "the frame is kept");
    let before = shown(&studio, HandleKind::LocalCurvePoint(6, 0)).expect("shown").position;
    let h = shown(&studio, HandleKind::LocalCurvePoint(6, 0)).expect("shown");
    let (p, _) = projector.project(h.position).expect("in view");
    assert!(studio.begin_drag(&projector, p, GestureKind::Move(Some(0))));
    studio.drag_to(&projector, [p[0] + 40.0, p[1] + 40.0]);
    studio.end_drag();
    let after = studio.selection.handle.clone().expect("selected").position;
    assert!((after[0] - before[0]).abs() > 0.1, "{after:?} {before:?}");
    assert!((after[1] - before[1]).abs() < 1e-9 && (after[2] - before[2]).abs() < 1e-9, "{after:?} {before:?}");
}

/// A beat is one undoable edit of the object's animation; the posed heart then moves, each
/// local away from the centre and back, and undo takes the animation away.
#[test]
fn a_beat_animates_the_locals_and_undo_takes_it_away() {
    let (mut studio, _) = studio_on_heart();
    assert!(!studio.document.scene().is_animated());
    studio.selection.object = Some(0);
    assert!(studio.add_beat(0), "{:?}", studio.status.message);
    assert!(studio.document.scene().is_animated() && studio.clock.playing);
    let rest = curve(&heart());
    let posed = |t: f64| {
        let mut s = studio.document.scene().clone();
        s.objects[0].shape.set_time(t);
        curve(&s)
    };
    let (quarter, half) = (posed(0.25), posed(0.5));
    let origin = |c: &splinekit::blend::BlendingSplineCurve<3>, k: usize| {
        c.transform(k).apply_point_about(&c.origin(k), &c.origin(k))
    };
    for k in 0..rest.local_count() {
        // Out by the amplitude a quarter beat in, back at half a beat.
        let (o, q, h) = (origin(&rest, k), origin(&quarter, k), origin(&half, k));
        assert!((q - o).norm() > 1e-3 && (h - o).norm() < 1e-9, "local {k}: {o} {q} {h}");
    }
    studio.undo();
    assert!(!studio.document.scene().is_animated());
}
