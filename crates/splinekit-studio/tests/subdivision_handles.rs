//! The cage vertices of a `subdivision_surface` as handles: a drag moves the vertex with the
//! mouse, the limit surface follows it (by the valence-3 limit mask, the cube's corner limit
//! moves 9/24 of the vertex's move), and the whole drag is one undo step.

use serde_json::json;
use splinekit::Point;
use splinekit::surface::Surface;
use splinekit_render::RenderScene;
use splinekit_scene::scenes::SceneDocument;
use splinekit_scene::{ShapeDocument, SurfaceDocument};
use splinekit_studio::gesture::GestureKind;
use splinekit_studio::handles::HandleKind;
use splinekit_studio::studio::Studio;
use splinekit_studio::view_camera::Projector;

fn cube_scene() -> SceneDocument {
    splinekit_studio::document::parse(
        &json!({"type": "scene", "objects": [{"shape": {
            "type": "subdivision_surface",
            "vertices": [[-1,-1,-1],[1,-1,-1],[-1,1,-1],[1,1,-1],[-1,-1,1],[1,-1,1],[-1,1,1],[1,1,1]],
            "faces": [[0,2,3,1],[4,5,7,6],[0,1,5,4],[2,6,7,3],[0,4,6,2],[1,3,7,5]]
        }, "control_net": true}]})
        .to_string(),
    )
    .expect("a valid scene")
}

/// The limit point at the corner c₂ of the last face ([1, 3, 7, 5]): vertex 7's limit point.
fn corner_limit(scene: &SceneDocument) -> Point<3> {
    let ShapeDocument::Surface(SurfaceDocument::SubdivisionSurface(d)) = &scene.objects[0].shape else {
        panic!("a subdivision surface")
    };
    d.atlas().expect("builds").point(6.0, 1.0)
}

#[test]
fn dragging_a_cage_vertex_moves_the_limit_and_is_one_undo_step() {
    let original = cube_scene();
    let mut studio = Studio::new(original.clone(), None);
    let rs: RenderScene = studio.render_scene((600, 600), false).expect("composes");
    let projector = Projector::new(&rs, (600, 600));
    let h = studio
        .view
        .handles
        .iter()
        .find(|h| h.kind == HandleKind::ControlPoint(7, "vertices"))
        .expect("vertex 7")
        .clone();
    assert_eq!(h.position, [1.0, 1.0, 1.0]);
    assert_eq!(
        studio.view.handles.iter().filter(|h| matches!(h.kind, HandleKind::ControlPoint(_, "vertices"))).count(),
        8
    );
    let (p, _) = projector.project(h.position).expect("in view");
    assert!(studio.begin_drag(&projector, [p[0], p[1]], GestureKind::Move(None)), "picked");
    for k in 1..=10 {
        studio.drag_to(&projector, [p[0] + 3.0 * k as f64, p[1] - 2.0 * k as f64]);
    }
    studio.end_drag();
    // The vertex follows the mouse…
    let ShapeDocument::Surface(SurfaceDocument::SubdivisionSurface(d)) = &studio.document.scene().objects[0].shape
    else {
        panic!("a subdivision surface")
    };
    let moved = Point::<3>::from_column_slice(&d.vertices[7]);
    let (q, _) = projector.project([moved.x, moved.y, moved.z]).expect("in view");
    assert!((q[0] - (p[0] + 30.0)).abs() < 1e-6 && (q[1] - (p[1] - 20.0)).abs() < 1e-6, "{q:?} from {p:?}");
    let delta = moved - Point::<3>::new(1.0, 1.0, 1.0);
    assert!(delta.norm() > 1e-3);
    // …no other vertex moves, and the limit follows: (9v + 4Σe + Σd)/24 moves 9/24 of Δ.
    let ShapeDocument::Surface(SurfaceDocument::SubdivisionSurface(o)) = &original.objects[0].shape else { panic!() };
    assert_eq!(d.vertices[..7], o.vertices[..7]);
    let before = corner_limit(&original);
    assert!((before - Point::<3>::new(0.5, 0.5, 0.5)).norm() < 1e-15);
    let after = corner_limit(studio.document.scene());
    assert!((after - before - delta * (9.0 / 24.0)).norm() < 1e-14, "{after} vs {before} + 9/24 {delta}");
    // The next frame draws the moved limit (it composes), and one undo restores the scene.
    studio.render_scene((600, 600), true).expect("composes");
    studio.undo();
    assert_eq!(*studio.document.scene(), original, "the whole drag is one step");
}
