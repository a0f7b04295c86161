//! The window's live path (issue 11): during a drag the composed scene is brought up to date
//! in place and only the changed items are written into the kept vertex buffers
//! ([`splinekit_studio::gpu::keep_geometry`]); the buffers then hold, float for float, what
//! uploading a fresh composition of the edited document holds (read back from the device),
//! and the composed items are the fresh composition's.

use splinekit::Point;
use splinekit::blend::BlendingSplineCurve;
use splinekit_mesh::Polyline;
use splinekit_mesh::polyline::distance_to_segment;
use splinekit_render::compose::{CURVE_POINTS, curve_tolerance};
use splinekit_render::{Geometry, RenderScene, Renderer, compose};
use splinekit_scene::{Decoration, ShapeDocument};
use splinekit_studio::gesture::GestureKind;
use splinekit_studio::gpu::keep_geometry;
use splinekit_studio::handles::HandleKind;
use splinekit_studio::live_view::Changes;
use splinekit_studio::studio::Studio;
use splinekit_studio::view_camera::Projector;

mod common;
use common::studio;

const SIZE: (u32, u32) = (500, 400);

/// The items of `a` and `b` and their drawing order are the same.
fn assert_same_items(a: &RenderScene, b: &RenderScene, what: &str) {
    common::assert_same_items(a, b, what);
    assert_eq!(a.painter_order, b.painter_order, "{what}: painter's order");
}

/// Draws one frame's changes into the kept geometry and checks it and the composed scene
/// against a fresh composition; returns the changes and whether they were written in place.
fn frame(studio: &mut Studio, renderer: &Renderer, kept: &mut Option<Geometry>, what: &str) -> (Changes, bool) {
    let view = studio.view_scene(SIZE, false).expect("composes");
    let in_place = keep_geometry(renderer, kept, view.composed, &view.changes);
    let changes = view.changes.clone();
    let composed = view.composed.clone();
    let fresh = compose(studio.document.scene(), studio.time(), SIZE.0 as f32 / SIZE.1 as f32).expect("composes");
    assert_same_items(&composed, &fresh, what);
    let want = renderer.read_geometry(&renderer.upload(&fresh)).expect("reads back");
    let got = renderer.read_geometry(kept.as_ref().expect("kept")).expect("reads back");
    assert!(got == want, "{what}: the buffers written in place are not those of a fresh upload");
    (changes, in_place)
}

fn projector(studio: &mut Studio) -> Projector {
    let view = studio.view_scene(SIZE, true).expect("composes");
    let p = Projector::with_bounds(&view.overlay, view.bounds, SIZE);
    // The overlays' changes were taken by this view; nothing in the composition changed.
    assert_eq!(view.changes, Changes::none());
    p
}

/// Starts a drag on the shown handle of `kind` and returns its pixel position.
fn grab(studio: &mut Studio, projector: &Projector, kind: HandleKind) -> [f64; 2] {
    let h = studio.shown_handles().find(|h| h.kind == kind).cloned().unwrap_or_else(|| panic!("{kind:?} shown"));
    let (p, _) = projector.project(h.position).expect("in front");
    assert!(studio.begin_drag(projector, p, GestureKind::Move(None)), "{kind:?} grabbed");
    p
}

fn mesh_rows(changes: &Changes) -> usize {
    match changes {
        Changes::Items { meshes, .. } => meshes.iter().map(|(_, r)| r.len()).sum(),
        Changes::All => usize::MAX,
    }
}

#[test]
fn dragging_a_patch_or_its_control_point_writes_the_refreshed_rows_only() {
    let renderer = Renderer::new().expect("a headless adapter (Mesa llvmpipe)");
    let mut s = studio(
        r#"{"type": "scene", "objects": [{"shape": {"type": "blending_spline_surface",
            "model": {"type": "torus"}, "local_surfaces": [8, 6]}, "local_pieces": true, "density": 64},
            {"shape": {"type": "blending_spline", "model": {"type": "circle"}, "local_curves": 5},
            "local_pieces": true, "density": 300}]}"#,
    );
    let mut kept = None;
    let (changes, in_place) = frame(&mut s, &renderer, &mut kept, "first frame");
    assert!(changes == Changes::All && !in_place);
    let projector = projector(&mut s);
    let p = grab(&mut s, &projector, HandleKind::LocalPatch(3, 2));
    let vertices = 65 * 65;
    for k in 1..=3 {
        s.drag_to(&projector, [p[0] + 9.0 * k as f64, p[1] - 6.0 * k as f64]);
        let (changes, in_place) = frame(&mut s, &renderer, &mut kept, &format!("patch drag step {k}"));
        let rows = mesh_rows(&changes);
        assert!(in_place && rows > 0 && rows < vertices / 2, "step {k}: {rows} of {vertices} vertices written");
        let Changes::Items { lines, .. } = &changes else { unreachable!() };
        assert_eq!(lines.len(), 6, "the moved patch's outline and middle lines");
    }
    s.end_drag();
    let (changes, _) = frame(&mut s, &renderer, &mut kept, "after the drag");
    assert_eq!(changes, Changes::All, "the still scene is composed afresh");

    // A control point of the selected patch's Bézier net.
    let projector = self::projector(&mut s);
    let p = grab(&mut s, &projector, HandleKind::LocalPatchPoint(3, 2, 1, 2));
    let grabbed = s.gesture.as_ref().map(|g| g.handle.kind);
    assert!(matches!(grabbed, Some(HandleKind::LocalPatchPoint(3, 2, _, _))), "{grabbed:?}");
    for k in 1..=2 {
        s.drag_to(&projector, [p[0] - 7.0 * k as f64, p[1] + 5.0 * k as f64]);
        let (changes, in_place) = frame(&mut s, &renderer, &mut kept, &format!("net drag step {k}"));
        let rows = mesh_rows(&changes);
        assert!(in_place && rows > 0 && rows < vertices / 2, "step {k}: {rows} of {vertices} vertices written");
    }
    s.end_drag();
    frame(&mut s, &renderer, &mut kept, "after the second drag");

    // The circle's local curve: the curve composed again on its own, its lines and points
    // written in place (a given density keeps the number of points).
    let projector = self::projector(&mut s);
    let p = grab(&mut s, &projector, HandleKind::LocalCurve(1));
    s.drag_to(&projector, [p[0] + 12.0, p[1] + 4.0]);
    let (changes, in_place) = frame(&mut s, &renderer, &mut kept, "local curve drag");
    assert!(in_place && mesh_rows(&changes) == 0, "{changes:?}");
}

/// A style drawn from the whole surface (a curvature colour map) takes the full path for
/// that object: it is meshed again whole, still written in place, still the fresh scene.
#[test]
fn a_colour_mapped_surface_is_meshed_whole_during_a_drag() {
    let renderer = Renderer::new().expect("a headless adapter (Mesa llvmpipe)");
    let mut s = studio(
        r#"{"type": "scene", "objects": [{"shape": {"type": "blending_spline_surface",
            "model": {"type": "torus"}, "local_surfaces": [6, 6]}, "local_pieces": true, "density": 40,
            "color_map": "gaussian"}]}"#,
    );
    let mut kept = None;
    frame(&mut s, &renderer, &mut kept, "first frame");
    let projector = projector(&mut s);
    let p = grab(&mut s, &projector, HandleKind::LocalPatch(2, 2));
    s.drag_to(&projector, [p[0] + 10.0, p[1] + 10.0]);
    let (changes, in_place) = frame(&mut s, &renderer, &mut kept, "colour-mapped drag");
    assert!(in_place && mesh_rows(&changes) == 41 * 41, "the whole mesh: {changes:?}");
}

/// The heart's blending spline (3-D) as the studio's document now builds it.
fn heart_curve(s: &Studio) -> BlendingSplineCurve<3> {
    let ShapeDocument::Curve(c) = &s.document.scene().objects[0].shape else { panic!("a curve") };
    let Decoration::LocalCurves(d) = c.decoration() else { panic!("a blending spline") };
    d.curve::<3>().expect("builds")
}

/// Checks a drag step of the heart: the buffers are the upload of the scene as the live
/// path brought it up to date; every item but the curve's line is the fresh composition's;
/// the line is, point for point, the edited curve flattened whole to `tolerance` (the
/// drag's), and the curve stays within `tolerance` of it (dense samples of the curve, each
/// near some segment).
fn heart_step(s: &mut Studio, renderer: &Renderer, kept: &mut Option<Geometry>, tolerance: f64, what: &str) {
    let view = s.view_scene(SIZE, false).expect("composes");
    let in_place = keep_geometry(renderer, kept, view.composed, &view.changes);
    assert!(in_place && view.changes != Changes::All, "{what}: written in place: {:?}", view.changes);
    let Changes::Items { runs, .. } = &view.changes else { unreachable!() };
    assert!(!runs.is_empty(), "{what}: the curve's polyline spliced");
    let composed = view.composed.clone();
    let want = renderer.read_geometry(&renderer.upload(&composed)).expect("reads back");
    let got = renderer.read_geometry(kept.as_ref().expect("kept")).expect("reads back");
    assert!(got == want, "{what}: the buffers written in place are not those of uploading the scene");
    let mut fresh = compose(s.document.scene(), s.time(), SIZE.0 as f32 / SIZE.1 as f32).expect("composes");
    let line = composed.lines.len() - 1;
    let curve = heart_curve(s);
    let whole = Polyline::adaptive_with_limit(&curve, tolerance, CURVE_POINTS).expect("flattens");
    assert!(whole.closed, "the heart is closed");
    let points: Vec<[f32; 3]> = whole.points.iter().map(|p| [p.x as f32, p.y as f32, p.z as f32]).collect();
    assert!(composed.lines[line].points == points, "{what}: the spliced polyline is not the whole flatten");
    fresh.lines[line].points = points.clone();
    assert_same_items(&composed, &fresh, what);
    let samples = Polyline::regular(&curve, 3000).expect("samples");
    let mut segments: Vec<([f32; 3], [f32; 3])> = points.windows(2).map(|w| (w[0], w[1])).collect();
    segments.push((points[points.len() - 1], points[0]));
    let near = |q: &Point<3>| {
        let d = |(a, b): &([f32; 3], [f32; 3])| {
            let (a, b) = (
                Point::<3>::new(a[0].into(), a[1].into(), a[2].into()),
                Point::<3>::new(b[0].into(), b[1].into(), b[2].into()),
            );
            distance_to_segment(q, &a, &b)
        };
        segments.iter().map(d).fold(f64::INFINITY, f64::min)
    };
    // Single-precision vertices add up to about 10⁻⁷ of the curve's size.
    let worst = samples.points.iter().map(near).fold(0.0, f64::max);
    assert!(worst <= 1.01 * tolerance, "{what}: the curve strays {worst} from its polyline (tolerance {tolerance})");
}

/// The heart drawn adaptively: a drag step flattens again only the spans of the moved
/// local and splices them into the kept polyline, writing only the changed run of segments
/// (the buffer has room for a few more); after the drag the still scene is composed afresh.
#[test]
fn dragging_a_local_curve_of_the_heart_splices_its_polyline() {
    let renderer = Renderer::new().expect("a headless adapter (Mesa llvmpipe)");
    let text =
        std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/../../examples/scenes/heart_local_curves.json"))
            .expect("the example");
    let mut s = studio(&text);
    let mut kept = None;
    frame(&mut s, &renderer, &mut kept, "first frame");
    // Local 2 inside the domain, local 0 across the closed curve's seam.
    for local in [2, 0] {
        let projector = projector(&mut s);
        let p = grab(&mut s, &projector, HandleKind::LocalCurve(local));
        s.drag_to(&projector, [p[0] + 15.0, p[1] - 10.0]);
        let tolerance = curve_tolerance::<3>(&heart_curve(&s)).expect("a tolerance");
        heart_step(&mut s, &renderer, &mut kept, tolerance, &format!("local {local}, first step"));
        for k in 2..=4 {
            s.drag_to(&projector, [p[0] + 15.0 * k as f64, p[1] - 25.0 * k as f64]);
            heart_step(&mut s, &renderer, &mut kept, tolerance, &format!("local {local}, step {k}"));
        }
        s.end_drag();
        let (changes, _) = frame(&mut s, &renderer, &mut kept, &format!("local {local}, after the drag"));
        assert_eq!(changes, Changes::All, "the still scene is composed afresh");
    }
}
