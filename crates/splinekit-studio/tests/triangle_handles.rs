//! The triangle family in the studio (issue 36): a Bézier triangle's control points and
//! the frames of a GERBS triangle's locals and of a blending triangulation's vertex locals
//! are handles. A drag follows the mouse and is one undo step, and the surface changes as
//! the formulas say: a control point P_ijk moved by Δ moves T(λ) by B^n_ijk(λ) Δ; a GERBS
//! local moved by Δ moves the corner by Δ, the other corners not at all and the centroid
//! by Δ/3 (the three rational weights are equal there); a local turned about its origin
//! keeps the corner and turns its first partials.

use serde_json::json;
use splinekit::Point;
use splinekit::triangle::Triangle;
use splinekit_render::RenderScene;
use splinekit_scene::scenes::SceneDocument;
use splinekit_scene::{ShapeDocument, SurfaceDocument};
use splinekit_studio::gesture::GestureKind;
use splinekit_studio::handles::{HandleKind, handles};
use splinekit_studio::studio::Studio;
use splinekit_studio::view_camera::Projector;

fn example(name: &str) -> SceneDocument {
    let path = format!("{}/../../examples/scenes/{name}.json", env!("CARGO_MANIFEST_DIR"));
    splinekit_studio::document::parse(&std::fs::read_to_string(path).expect("the example")).expect("a valid scene")
}

/// The studio on `scene` at 600×600 pixels and the projector of its view.
fn studio_on(scene: SceneDocument) -> (Studio, Projector) {
    let mut studio = Studio::new(scene, None);
    let rs: RenderScene = studio.render_scene((600, 600), false).expect("composes");
    (studio, Projector::new(&rs, (600, 600)))
}

/// Drags the handle of `kind` by `by` pixels in ten steps with `gesture`, rendering a frame
/// after each step as the window does (the live view); returns the handle's pixel position
/// before and after.
fn drag(
    studio: &mut Studio,
    projector: &Projector,
    kind: HandleKind,
    by: [f64; 2],
    gesture: GestureKind,
) -> ([f64; 2], [f64; 2]) {
    let h = studio.shown_handles().find(|h| h.kind == kind).unwrap_or_else(|| panic!("{kind:?} shown")).clone();
    let (p, _) = projector.project(h.position).expect("in view");
    let grab = [p[0] + 2.0, p[1] - 1.0];
    assert!(studio.begin_drag(projector, grab, gesture), "{kind:?} picked");
    for k in 1..=10 {
        studio.drag_to(projector, [grab[0] + by[0] * k as f64 / 10.0, grab[1] + by[1] * k as f64 / 10.0]);
        studio.render_scene((600, 600), true).expect("each step composes");
    }
    studio.end_drag();
    let moved = studio.selection.handle.clone().expect("still selected");
    assert_eq!(moved.kind, kind);
    (p, projector.project(moved.position).expect("in view").0)
}

fn surface(scene: &SceneDocument) -> &SurfaceDocument {
    let ShapeDocument::Surface(s) = &scene.objects[0].shape else { panic!("a surface") };
    s
}

fn bezier_triangle(scene: &SceneDocument) -> std::sync::Arc<dyn Triangle<3>> {
    let SurfaceDocument::BezierTriangle(d) = surface(scene) else { panic!("a bezier_triangle") };
    d.triangle::<3>().expect("builds")
}

fn gerbs(scene: &SceneDocument) -> splinekit::triangle::GerbsTriangle<3> {
    let SurfaceDocument::GerbsTriangle(d) = surface(scene) else { panic!("a gerbs_triangle") };
    d.gerbs::<3>().expect("builds")
}

fn p3(a: [f64; 3]) -> Point<3> {
    Point::<3>::new(a[0], a[1], a[2])
}

#[test]
fn a_bezier_triangle_control_point_follows_the_mouse_and_moves_the_surface_by_its_bernstein_weight() {
    let original = example("bezier_triangle_net");
    let (mut studio, projector) = studio_on(original.clone());
    let points: Vec<HandleKind> = studio
        .view
        .handles
        .iter()
        .filter(|h| matches!(h.kind, HandleKind::ControlPoint(_, "control_points")))
        .map(|h| h.kind)
        .collect();
    assert_eq!(points.len(), 10, "a cubic's (3+1)(3+2)/2 points are handles");
    // b_111 sits at (j+k)(j+k+1)/2 + k = 4 in storage order.
    let before = bezier_triangle(&original);
    let b111 = HandleKind::ControlPoint(4, "control_points");
    let (from, to) = drag(&mut studio, &projector, b111, [30.0, -20.0], GestureKind::Move(None));
    assert!((to[0] - from[0] - 30.0).abs() < 1e-6 && (to[1] - from[1] + 20.0).abs() < 1e-6, "{to:?} from {from:?}");
    let SurfaceDocument::BezierTriangle(old) = surface(&original) else { panic!() };
    let SurfaceDocument::BezierTriangle(new) = surface(studio.document.scene()) else { panic!() };
    let delta = p3([0, 1, 2].map(|a| new.control_points[4][a] - old.control_points[4][a]));
    assert!(delta.norm() > 1e-3, "the point moved");
    for i in (0..10).filter(|&i| i != 4) {
        assert_eq!(new.control_points[i], old.control_points[i], "point {i} stays");
    }
    // T changes by B³_111(λ) Δ = 6uvw Δ.
    let after = bezier_triangle(studio.document.scene());
    for (u, v) in [(1.0 / 3.0, 1.0 / 3.0), (0.2, 0.5), (0.7, 0.1), (0.0, 0.4), (1.0, 0.0)] {
        let w = 1.0 - u - v;
        let change = after.point(u, v, w) - before.point(u, v, w);
        let expected = delta * (6.0 * u * v * w);
        assert!((change - expected).norm() < 1e-14, "at ({u}, {v}, {w}): {change} vs {expected}");
    }
    studio.undo();
    assert_eq!(*studio.document.scene(), original, "the whole drag is one step");
}

#[test]
fn a_gerbs_local_frame_is_a_handle_at_its_moved_origin() {
    let scene = example("gerbs_triangle_locals");
    let hs = handles(&scene, None).expect("handles");
    let locals: Vec<_> = hs.iter().filter(|h| matches!(h.kind, HandleKind::LocalTriangle(_))).collect();
    assert_eq!(locals.len(), 3, "one handle per corner's local");
    // The Hermite locals interpolate the model, a sphere of radius 2, at the corners, so the
    // origins lie on it; local 1 is moved by its `transforms` entry (0, 0.4, 0.4).
    for h in &locals {
        assert!((p3(h.origin).norm() - 2.0).abs() < 1e-12, "{:?} on the sphere", h.origin);
        assert_eq!(h.dimension, 3);
        assert_eq!(h.kind.pointer(), format!("/shape/transforms/{}", h.kind.piece().expect("a piece").0));
    }
    let moved = p3(locals[1].position) - p3(locals[1].origin);
    assert!((moved - Point::<3>::new(0.0, 0.4, 0.4)).norm() < 1e-15, "{moved}");
    assert_eq!(locals[0].position, locals[0].origin);
    // The corner of the surface is where the handle is.
    let g = gerbs(&scene);
    for (k, corner) in [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]].iter().enumerate() {
        let at = g.point(corner[0], corner[1], corner[2]);
        assert!((at - p3(locals[k].position)).norm() < 1e-12, "corner {k}: {at} vs {:?}", locals[k].position);
    }
}

#[test]
fn dragging_a_gerbs_local_moves_its_corner_by_the_drag_and_the_centroid_by_a_third() {
    let original = example("gerbs_triangle_locals");
    let (mut studio, projector) = studio_on(original.clone());
    let (from, to) =
        drag(&mut studio, &projector, HandleKind::LocalTriangle(0), [-40.0, 25.0], GestureKind::Move(None));
    assert!((to[0] - from[0] + 40.0).abs() < 1e-6 && (to[1] - from[1] - 25.0).abs() < 1e-6, "{to:?} from {from:?}");
    let saved = studio.document.scene().objects[0].to_value();
    let t = &saved["shape"]["transforms"]["0"]["translate"];
    let delta = p3([0, 1, 2].map(|a| t[a].as_f64().expect("a coordinate")));
    assert!(delta.norm() > 1e-3, "{saved}");
    assert_eq!(saved["shape"]["transforms"]["1"], json!({"translate": [0.0, 0.4, 0.4]}), "local 1 keeps its move");
    let (a, b) = (gerbs(&original), gerbs(studio.document.scene()));
    let change = |l: [f64; 3]| b.point(l[0], l[1], l[2]) - a.point(l[0], l[1], l[2]);
    assert!((change([1.0, 0.0, 0.0]) - delta).norm() < 1e-12, "corner u moves with its local");
    assert!(change([0.0, 1.0, 0.0]).norm() < 1e-12 && change([0.0, 0.0, 1.0]).norm() < 1e-12, "the others stay");
    let third = 1.0 / 3.0;
    assert!((change([third, third, third]) - delta / 3.0).norm() < 1e-12, "β_u = 1/3 at the centroid");
    // Every partial at corner u up to second order is the local's, merely translated.
    let (mut pa, mut pb) = ([Point::<3>::zeros(); 9], [Point::<3>::zeros(); 9]);
    a.eval_partials(1.0, 0.0, 2, 2, &mut pa);
    b.eval_partials(1.0, 0.0, 2, 2, &mut pb);
    for k in 1..9 {
        assert!((pa[k] - pb[k]).norm() < 1e-9, "partial {k}: {} vs {}", pa[k], pb[k]);
    }
    studio.undo();
    assert_eq!(*studio.document.scene(), original, "the whole drag is one step");
}

/// Rodrigues' rotation of `x` about the unit `axis` by `angle`.
fn rotate(x: Point<3>, axis: Point<3>, angle: f64) -> Point<3> {
    x * angle.cos() + axis.cross(&x) * angle.sin() + axis * (axis.dot(&x) * (1.0 - angle.cos()))
}

#[test]
fn turning_a_gerbs_local_by_hand_keeps_its_corner_and_turns_its_partials() {
    let original = example("gerbs_triangle_locals");
    let (mut studio, projector) = studio_on(original.clone());
    drag(&mut studio, &projector, HandleKind::LocalTriangle(2), [0.0, -60.0], GestureKind::Rotate);
    let saved = studio.document.scene().objects[0].to_value();
    let r = &saved["shape"]["transforms"]["2"]["rotate"];
    let angle = r["angle"].as_f64().expect("an angle");
    let axis = p3([0, 1, 2].map(|a| r["axis"][a].as_f64().expect("an axis")));
    assert!(angle.abs() > 0.1, "{saved}");
    let (a, b) = (gerbs(&original), gerbs(studio.document.scene()));
    assert!((b.point(0.0, 0.0, 1.0) - a.point(0.0, 0.0, 1.0)).norm() < 1e-12, "the corner is the pivot");
    let (mut pa, mut pb) = ([Point::<3>::zeros(); 4], [Point::<3>::zeros(); 4]);
    a.eval_partials(0.0, 0.0, 1, 1, &mut pa);
    b.eval_partials(0.0, 0.0, 1, 1, &mut pb);
    for k in [1, 2, 3] {
        let expected = rotate(pa[k], axis.normalize(), angle);
        assert!((pb[k] - expected).norm() < 1e-9 * (1.0 + pa[k].norm()), "partial {k}: {} vs {expected}", pb[k]);
    }
    studio.undo();
    assert_eq!(*studio.document.scene(), original);
}

#[test]
fn dragging_a_vertex_local_of_a_blending_triangulation_changes_its_star_only() {
    let original = splinekit_studio::document::parse(
        &json!({"type": "scene", "objects": [{"shape": {
            "type": "blending_triangulation", "mesh": {"type": "icosphere", "radius": 1, "subdivisions": 1}
        }, "local_pieces": true}]})
        .to_string(),
    )
    .expect("a valid scene");
    let (mut studio, projector) = studio_on(original.clone());
    let locals: Vec<_> =
        studio.view.handles.iter().filter(|h| matches!(h.kind, HandleKind::LocalTriangle(_))).cloned().collect();
    assert_eq!(locals.len(), 42, "one handle per vertex of the icosahedron split once");
    for h in &locals {
        assert!((p3(h.position).norm() - 1.0).abs() < 1e-12, "vertex locals start at the vertices");
    }
    // The vertex nearest the eye: its handle is in front.
    let k = (0..locals.len())
        .min_by(|&a, &b| {
            let depth = |i: usize| projector.project(locals[i].position).expect("in view").1;
            depth(a).total_cmp(&depth(b))
        })
        .expect("handles");
    drag(&mut studio, &projector, HandleKind::LocalTriangle(k), [20.0, 15.0], GestureKind::Move(None));
    let SurfaceDocument::BlendingTriangulation(old) = surface(&original) else { panic!() };
    let SurfaceDocument::BlendingTriangulation(new) = surface(studio.document.scene()) else { panic!() };
    let (a, b) = (old.blend().expect("builds"), new.blend().expect("builds"));
    let moved = b.origin(k).expect("a vertex");
    let delta = b.frame(k).expect("a frame").apply_point_about(&moved, &moved) - moved;
    assert!(delta.norm() > 1e-3);
    let (ca, cb) = (a.atlas(), b.atlas());
    for (t, corners) in a.triangles().iter().enumerate() {
        let (ta, tb) = (&ca.charts()[t], &cb.charts()[t]);
        if let Some(m) = corners.iter().position(|&c| c as usize == k) {
            let mut l = [0.0; 3];
            l[m] = 1.0;
            let change = tb.point(l[0], l[1], l[2]) - ta.point(l[0], l[1], l[2]);
            assert!((change - delta).norm() < 1e-12, "triangle {t}'s corner at vertex {k} moves by the drag");
        } else {
            for (u, v) in [(0.2, 0.3), (0.6, 0.2), (1.0 / 3.0, 1.0 / 3.0)] {
                assert_eq!(ta.point(u, v, 1.0 - u - v), tb.point(u, v, 1.0 - u - v), "triangle {t} is off the star");
            }
        }
    }
    studio.undo();
    assert_eq!(*studio.document.scene(), original);
}
