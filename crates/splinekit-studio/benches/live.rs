//! Live re-evaluation after moving one local piece (issue 11's aims, one core): one patch
//! of the 8×8 bicubic blending-spline torus sampled 256×256 with normals (< 2 ms incl.
//! upload), one local curve of the heart (< 0.2 ms).
//!
//! - `kernel/…`: the kernel's part alone, the frame set and the samples refreshed.
//! - `window/…`: what the window does for one drag step ([`splinekit_studio::live_view`]):
//!   the edit (its check builds the shape once), the refresh of the kept samples, the
//!   changed rows copied into the composed mesh (or the curve composed again), the handles,
//!   and the changed vertices written into the kept buffers (`Queue::write_buffer` and a
//!   submit; the GPU copy itself runs asynchronously); against composing and uploading
//!   the edited scene afresh, what the window did before.

use criterion::{Criterion, criterion_group, criterion_main};
use splinekit::Point;
use splinekit::curve::CurveSamples;
use splinekit::frame::Affine;
use splinekit::surface::SurfaceGridSamples;
use splinekit_render::{Geometry, Renderer};
use splinekit_scene::{Decoration, ShapeDocument};
use splinekit_studio::gesture::GestureKind;
use splinekit_studio::gpu::keep_geometry;
use splinekit_studio::handles::HandleKind;
use splinekit_studio::studio::Studio;
use splinekit_studio::view_camera::Projector;

/// The torus's patch count and a density of 255 cells: 256 × 256 samples with normals.
const TORUS: &str = r#"{"type": "scene", "objects": [{"shape": {"type": "blending_spline_surface",
    "model": {"type": "torus"}, "local_surfaces": [8, 8]}, "local_pieces": true, "density": 255}]}"#;
const HEART: &str = r#"{"type": "scene", "objects": [{"shape": {"type": "blending_spline",
    "model": {"type": "heart"}, "local_curves": 10, "local": {"type": "bezier", "degree": 2}},
    "local_pieces": true, "line_width": 3}]}"#;
const SIZE: (u32, u32) = (1000, 700);

fn shape(text: &str) -> ShapeDocument {
    ShapeDocument::from_json(text).expect("a valid shape")
}

/// The kernel's part alone: set the frame and refresh the samples, no packing or upload.
fn kernel_only(c: &mut Criterion) {
    let torus = shape(r#"{"type":"blending_spline_surface","model":{"type":"torus"},"local_surfaces":[8,8]}"#);
    let ShapeDocument::Surface(s) = &torus else { panic!("a surface") };
    let Decoration::LocalPatches(d) = s.decoration() else { panic!("a blending-spline surface") };
    let mut surface = d.surface::<3>().expect("builds");
    let mut samples = SurfaceGridSamples::uniform(&surface, 256, 256).expect("samples");
    let mut lift = 0.0;
    c.bench_function("kernel/torus 8x8 bicubic, 256x256 with normals: move one patch, refresh", |b| {
        b.iter(|| {
            lift = if lift == 0.0 { 0.3 } else { 0.0 };
            let rects = surface.set_transform(3, 4, Affine::translation(Point::<3>::new(0.0, 0.0, lift)));
            samples.refresh(&surface, &rects)
        })
    });
    let heart = shape(
        r#"{"type":"blending_spline","model":{"type":"heart"},"local_curves":10,"local":{"type":"bezier","degree":2}}"#,
    );
    let ShapeDocument::Curve(cd) = &heart else { panic!("a curve") };
    let Decoration::LocalCurves(d) = cd.decoration() else { panic!("a blending spline") };
    let mut curve = d.curve::<3>().expect("builds");
    let mut samples = CurveSamples::uniform(&curve, 2000, 0).expect("samples");
    c.bench_function("kernel/heart, 10 quadratic locals, 2000 samples: move one local, refresh", |b| {
        b.iter(|| {
            lift = if lift == 0.0 { 0.5 } else { 0.0 };
            let ranges = curve.set_transform(2, Affine::translation(Point::<3>::new(lift, 0.0, 0.0)));
            samples.refresh(&curve, &ranges)
        })
    });
}

/// A studio on `text` drawn once into kept buffers, dragging the handle `kind` (after
/// selecting `select`, whose local Bézier's control points are then shown).
fn dragging(
    text: &str,
    renderer: &Renderer,
    select: HandleKind,
    kind: HandleKind,
) -> (Studio, Option<Geometry>, Projector, [f64; 2]) {
    let mut studio = Studio::new(splinekit_studio::document::parse(text).expect("valid"), None);
    let mut kept = None;
    let view = studio.view_scene(SIZE, false).expect("composes");
    keep_geometry(renderer, &mut kept, view.composed, &view.changes);
    studio.selection.handle = studio.view.handles.iter().find(|h| h.kind == select).cloned();
    let view = studio.view_scene(SIZE, true).expect("composes");
    let projector = Projector::with_bounds(&view.overlay, view.bounds, SIZE);
    let h = studio.shown_handles().find(|h| h.kind == kind).cloned().expect("the handle is shown");
    let (p, _) = projector.project(h.position).expect("in front");
    assert!(studio.begin_drag(&projector, p, GestureKind::Move(None)), "grabbed");
    (studio, kept, projector, p)
}

fn window(c: &mut Criterion) {
    let renderer = Renderer::new().expect("a graphics adapter (Mesa llvmpipe headless)");
    let cases = [
        (
            "torus 8x8 bicubic, 256x256 with normals: drag one patch",
            TORUS,
            HandleKind::LocalPatch(3, 4),
            HandleKind::LocalPatch(3, 4),
        ),
        (
            "torus 8x8 bicubic, 256x256 with normals: drag one patch's control point",
            TORUS,
            HandleKind::LocalPatch(3, 4),
            HandleKind::LocalPatchPoint(3, 4, 1, 2),
        ),
        (
            "heart, 10 quadratic locals, adaptive: drag one local",
            HEART,
            HandleKind::LocalCurve(2),
            HandleKind::LocalCurve(2),
        ),
        (
            "heart, 10 quadratic locals, adaptive: drag one local's control point",
            HEART,
            HandleKind::LocalCurve(2),
            HandleKind::LocalCurvePoint(2, 1),
        ),
    ];
    let mut group = c.benchmark_group("window");
    group.sample_size(30);
    for (name, text, select, kind) in cases {
        let (mut studio, mut kept, projector, p) = dragging(text, &renderer, select, kind);
        let mut away = false;
        group.bench_function(format!("{name}, live path"), |b| {
            b.iter(|| {
                away = !away;
                studio.drag_to(&projector, if away { [p[0] + 12.0, p[1] - 8.0] } else { p });
                let view = studio.view_scene(SIZE, false).expect("composes");
                keep_geometry(&renderer, &mut kept, view.composed, &view.changes);
                renderer.queue().submit([]);
            })
        });
        if kind.is_local() {
            group.bench_function(format!("{name}, composed and uploaded afresh"), |b| {
                b.iter(|| {
                    away = !away;
                    studio.drag_to(&projector, if away { [p[0] + 12.0, p[1] - 8.0] } else { p });
                    let aspect = SIZE.0 as f32 / SIZE.1 as f32;
                    let fresh = splinekit_render::compose(studio.document.scene(), None, aspect).expect("composes");
                    let geometry = renderer.upload(&fresh);
                    renderer.queue().submit([]);
                    geometry
                })
            });
        }
    }
    group.finish();
}

criterion_group!(benches, kernel_only, window);
criterion_main!(benches);
