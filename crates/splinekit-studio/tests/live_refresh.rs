//! The window's live refresh (issue 11): after a patch of a blending-spline surface moves,
//! the studio re-evaluates only the rectangles that patch affects, and the scene it
//! composes equals, bit for bit, the scene composed afresh from the edited document.

use serde_json::json;
use splinekit_render::compose;
use splinekit_studio::edit::Edit;
use splinekit_studio::studio::Studio;

mod common;
use common::{assert_same_items, studio};

const SIZE: (u32, u32) = (400, 300);

/// Asserts that what the studio composed equals a fresh composition of its document.
fn assert_fresh(studio: &mut Studio, what: &str) {
    let live = studio.render_scene(SIZE, false).expect("composes");
    let mut fresh = compose(studio.document.scene(), studio.time(), SIZE.0 as f32 / SIZE.1 as f32).expect("composes");
    fresh.camera = live.camera;
    assert_same_items(&live, &fresh, what);
}

#[test]
fn a_moved_patch_refreshes_its_rectangles_only_and_the_scene_is_the_fresh_one() {
    let mut s = studio(
        r#"{"type": "scene", "objects": [{"shape": {"type": "blending_spline_surface",
            "model": {"type": "torus"}, "local_surfaces": [8, 6]}, "local_pieces": true, "density": 64}]}"#,
    );
    assert_fresh(&mut s, "first frame");
    let moves = [
        ("/shape/transforms/3,2", json!({"translate": [0.0, 0.0, 0.5]})),
        ("/shape/transforms/3,2", json!({"translate": [0.2, -0.1, 0.7]})),
        ("/shape/transforms/0,5", json!({"rotate": {"axis": [0, 0, 1], "angle": 0.4}, "scale": 1.3})),
    ];
    for (pointer, value) in moves {
        assert!(s.edit(Edit::Set { object: 0, pointer: pointer.into(), value: Some(value) }, false));
        assert_fresh(&mut s, pointer);
        let n = s.view.live.last_refreshed;
        assert!(n > 0 && n < 65 * 65 / 4, "{pointer}: refreshed {n} of {} samples", 65 * 65);
    }
    s.undo();
    assert_fresh(&mut s, "undo");
    assert!(s.view.live.last_refreshed > 0);
    // Another change than a frame: the surface is made afresh, still the same scene.
    assert!(s.edit(Edit::Set { object: 0, pointer: "/shape/local_surfaces/1".into(), value: Some(json!(5)) }, false));
    assert_fresh(&mut s, "five patches in v");
    assert_eq!(s.view.live.last_refreshed, 0);
}

#[test]
fn the_animated_torus_is_the_fresh_one_at_every_time() {
    let text =
        std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/../../examples/scenes/torus_animated.json"))
            .expect("the example");
    let mut s = studio(&text);
    let mut refreshed = 0;
    for t in [0.0, 0.4, 0.9, 0.9, 1.7] {
        s.clock.time = t;
        assert_fresh(&mut s, &format!("t = {t}"));
        refreshed += s.view.live.last_refreshed;
    }
    // The animated patches' rectangles were refreshed, not whole surfaces made afresh.
    assert!(refreshed > 0, "nothing refreshed");
}

/// An edited net of a Bézier patch (a dragged control point): only that patch's
/// rectangles are re-evaluated and the scene is the fresh one.
#[test]
fn an_edited_patch_net_refreshes_its_rectangles_only() {
    let mut s = studio(
        r#"{"type": "scene", "objects": [{"shape": {"type": "blending_spline_surface",
            "model": {"type": "torus"}, "local_surfaces": [8, 6], "transforms": {"3,2": {"scale": 1.2}}},
            "local_pieces": true, "density": 64}]}"#,
    );
    assert_fresh(&mut s, "first frame");
    let splinekit_scene::ShapeDocument::Surface(splinekit_scene::SurfaceDocument::BlendingSplineSurface(d)) =
        &s.document.scene().objects[0].shape
    else {
        panic!("a blending-spline surface")
    };
    let built = d.surface::<3>().expect("builds");
    let (net, (_, dv)) = built.bezier_rest_net(3, 2).expect("Bézier patches");
    let mut rows: Vec<Vec<Vec<f64>>> =
        net.chunks(dv + 1).map(|row| row.iter().map(|p| p.as_slice().to_vec()).collect()).collect();
    for lift in [0.4, 0.9] {
        rows[1][2][2] += lift;
        let value = serde_json::to_value(&rows).expect("json");
        assert!(s.edit(
            Edit::Set { object: 0, pointer: "/shape/local_control_points/3,2".into(), value: Some(value) },
            false
        ));
        assert_fresh(&mut s, "lifted");
        let n = s.view.live.last_refreshed;
        assert!(n > 0 && n < 65 * 65 / 4, "refreshed {n} of {} samples", 65 * 65);
    }
    s.undo();
    assert_fresh(&mut s, "undo");
    assert!(s.view.live.last_refreshed > 0);
}
