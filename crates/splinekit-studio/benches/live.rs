//! Live re-evaluation after moving one local piece (issue 11's aims, one core): one patch
//! of the 8×8 bicubic blending-spline torus sampled 256×256 with normals (< 2 ms incl.
//! upload), one local curve of the heart (< 0.2 ms). "Upload" is `Queue::write_buffer` of
//! the changed rows plus a submit; the GPU copy itself runs asynchronously. And the
//! window's work after a drag step on the torus at density 256: the edit and the scene's
//! composition with the live refresh ([`splinekit_studio::live_surfaces`]) against the
//! composition afresh it replaced.

use criterion::{Criterion, criterion_group, criterion_main};
use serde_json::json;
use splinekit::Point;
use splinekit::curve::CurveSamples;
use splinekit::frame::Affine;
use splinekit::surface::SurfaceGridSamples;
use splinekit_scene::{Decoration, ShapeDocument};
use splinekit_studio::edit::Edit;
use splinekit_studio::live::{LiveCurve, LiveSurface};
use splinekit_studio::studio::Studio;

fn shape(text: &str) -> ShapeDocument {
    ShapeDocument::from_json(text).expect("a valid shape")
}

fn bench(c: &mut Criterion) {
    let renderer = splinekit_render::Renderer::new().expect("a graphics adapter (Mesa llvmpipe headless)");
    let (device, queue) = (renderer.device(), renderer.queue());
    let torus = shape(r#"{"type":"blending_spline_surface","model":{"type":"torus"},"local_surfaces":[8,8]}"#);
    let ShapeDocument::Surface(s) = &torus else { panic!("a surface") };
    let Decoration::LocalPatches(d) = s.decoration() else { panic!("a blending-spline surface") };
    let mut surface =
        LiveSurface::new(device, queue, d.surface::<3>().expect("builds"), (256, 256), [0.5; 4]).expect("live");
    let mut lift = 0.0;
    c.bench_function("torus 8x8 bicubic, 256x256 with normals: move one patch + upload", |b| {
        b.iter(|| {
            lift = if lift == 0.0 { 0.3 } else { 0.0 };
            surface.set_transform(queue, (3, 4), Affine::translation(Point::<3>::new(0.0, 0.0, lift)));
            queue.submit([]);
        })
    });
    let heart = shape(
        r#"{"type":"blending_spline","model":{"type":"heart"},"local_curves":10,"local":{"type":"bezier","degree":2}}"#,
    );
    let ShapeDocument::Curve(cd) = &heart else { panic!("a curve") };
    let Decoration::LocalCurves(d) = cd.decoration() else { panic!("a blending spline") };
    let mut curve = LiveCurve::new(device, queue, d.curve::<3>().expect("builds"), 2000, [0.9, 0.25, 0.55, 1.0], 3.0)
        .expect("live");
    c.bench_function("heart, 10 quadratic locals, 2000 samples: move one local + upload", |b| {
        b.iter(|| {
            lift = if lift == 0.0 { 0.5 } else { 0.0 };
            curve.set_transform(queue, 2, Affine::translation(Point::<3>::new(lift, 0.0, 0.0)));
            queue.submit([]);
        })
    });
    let points = curve.curve.local_bezier_points(2).expect("Bézier locals").to_vec();
    c.bench_function("heart, 10 quadratic locals, 2000 samples: move one local's control point + upload", |b| {
        b.iter(|| {
            lift = if lift == 0.0 { 0.5 } else { 0.0 };
            let mut p = points.clone();
            p[1].x += lift;
            curve.set_local_bezier_points(queue, 2, p).expect("an edit");
            queue.submit([]);
        })
    });
    let net = surface.surface.bezier_rest_net(3, 4).expect("Bézier patches").0.to_vec();
    c.bench_function("torus 8x8 bicubic, 256x256 with normals: move one patch's control point + upload", |b| {
        b.iter(|| {
            lift = if lift == 0.0 { 0.3 } else { 0.0 };
            let mut n = net.clone();
            n[5].z += lift;
            surface.set_bezier_net(queue, (3, 4), n).expect("an edit");
            queue.submit([]);
        })
    });
}

/// The kernel's part alone: set the frame and refresh the samples, no packing or upload.
fn kernel_only(c: &mut Criterion) {
    let torus = shape(r#"{"type":"blending_spline_surface","model":{"type":"torus"},"local_surfaces":[8,8]}"#);
    let ShapeDocument::Surface(s) = &torus else { panic!("a surface") };
    let Decoration::LocalPatches(d) = s.decoration() else { panic!("a blending-spline surface") };
    let mut surface = d.surface::<3>().expect("builds");
    let mut samples = SurfaceGridSamples::uniform(&surface, 256, 256).expect("samples");
    let mut lift = 0.0;
    c.bench_function("torus 8x8 bicubic, 256x256 with normals: move one patch, refresh only", |b| {
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
    c.bench_function("heart, 10 quadratic locals, 2000 samples: move one local, refresh only", |b| {
        b.iter(|| {
            lift = if lift == 0.0 { 0.5 } else { 0.0 };
            let ranges = curve.set_transform(2, Affine::translation(Point::<3>::new(lift, 0.0, 0.0)));
            samples.refresh(&curve, &ranges)
        })
    });
}

/// The window's composition after one drag step (the edit applied through the history):
/// live refresh against composing afresh.
fn window(c: &mut Criterion) {
    let text = r#"{"type": "scene", "objects": [{"shape": {"type": "blending_spline_surface",
        "model": {"type": "torus"}, "local_surfaces": [8, 8]}, "density": 256}]}"#;
    let mut studio = Studio::new(splinekit_studio::document::parse(text).expect("valid"), None);
    let size = (1000, 700);
    studio.render_scene(size, false).expect("composes");
    let mut lift = 0.0;
    let mut step = |studio: &mut Studio| {
        lift = if lift == 0.0 { 0.3 } else { 0.0 };
        let value = json!({"translate": [0.0, 0.0, lift]});
        studio.edit(Edit::Set { object: 0, pointer: "/shape/transforms/3,4".into(), value: Some(value) }, false);
    };
    let mut group = c.benchmark_group("window");
    group.sample_size(20);
    group.bench_function("torus 8x8 bicubic, density 256: drag step + compose, live refresh", |b| {
        b.iter(|| {
            step(&mut studio);
            studio.render_scene(size, false).expect("composes")
        })
    });
    group.bench_function("torus 8x8 bicubic, density 256: drag step + compose afresh", |b| {
        b.iter(|| {
            step(&mut studio);
            splinekit_render::compose(&studio.scene, None, 1000.0 / 700.0).expect("composes")
        })
    });
    group.finish();
}

criterion_group!(benches, bench, kernel_only, window);
criterion_main!(benches);
