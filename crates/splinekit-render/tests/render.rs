//! Render tests (headless): small scenes compared with stored reference images within a
//! tolerance, and checks that catch blank, black or empty pictures.

use splinekit::surface::model::Torus;
use splinekit_mesh::MeshOptions;
use splinekit_mesh::surface_mesh::regular;
use splinekit_render::{Camera, Image, LineItem, MeshItem, PointItem, RenderScene, Renderer};

fn torus_scene() -> RenderScene {
    let m = regular(&Torus::new(3.0, 1.0).unwrap(), 48, 24, MeshOptions { uv: false }).unwrap();
    let f = |v: &[[f64; 3]]| v.iter().map(|p| p.map(|x| x as f32)).collect::<Vec<_>>();
    let circle: Vec<[f32; 3]> = (0..64)
        .map(|i| {
            let t = i as f32 * std::f32::consts::TAU / 64.0;
            [3.0 * t.cos(), 3.0 * t.sin(), 1.2]
        })
        .collect();
    RenderScene {
        meshes: vec![MeshItem {
            positions: f(&m.positions),
            normals: f(&m.normals),
            color: [0.35, 0.55, 0.85, 1.0],
            triangles: m.triangles.clone(),
            ..Default::default()
        }],
        lines: vec![LineItem {
            points: circle.clone(),
            closed: true,
            color: [0.85, 0.2, 0.1, 1.0],
            width: 3.0,
            colors: Vec::new(),
        }],
        points: circle
            .iter()
            .step_by(8)
            .map(|&p| PointItem { position: p, color: [0.1, 0.1, 0.1, 1.0], size: 9.0 })
            .collect(),
        ..Default::default()
    }
}

fn renderer() -> Renderer {
    Renderer::new().expect("a graphics adapter (Mesa llvmpipe or lavapipe headless)")
}

/// CI runs these tests on each of Mesa's software backends by naming one in `WGPU_BACKEND`
/// (`.ci/run`): the renderer must then use that one, or the run tested the other twice.
#[test]
fn the_backend_named_by_wgpu_backend_is_the_one_used() {
    let name = renderer().adapter_name().to_string();
    match std::env::var("WGPU_BACKEND").as_deref() {
        Ok("gl") => assert!(name.ends_with("(Gl)"), "{name}"),
        Ok("vulkan") => assert!(name.ends_with("(Vulkan)"), "{name}"),
        _ => assert!(name.ends_with("(Gl)") || name.ends_with("(Vulkan)"), "{name}"),
    }
}

/// The stored reference image; `SPLINEKIT_BLESS=1` writes `img` as the new reference (a
/// missing reference is a failure otherwise).
fn reference(name: &str, img: &Image) -> Image {
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data").join(name);
    if std::env::var("SPLINEKIT_BLESS").is_ok() {
        std::fs::create_dir_all(path.parent().unwrap()).unwrap();
        img.save_png(&path).unwrap();
    }
    let bytes = std::fs::read(&path).unwrap_or_else(|e| {
        panic!("reference image {} missing ({e}); run with SPLINEKIT_BLESS=1 to make it", path.display())
    });
    Image::from_png(&bytes).unwrap()
}

#[test]
fn a_shaded_torus_with_a_curve_and_points_matches_its_reference() {
    let r = renderer();
    let img = r.render(&torus_scene(), 320, 240).unwrap();
    let out = std::env::temp_dir().join("splinekit-render-torus.png");
    img.save_png(&out).unwrap();
    // Not blank, not black, background white at the corner, the torus in the middle shaded.
    let cov = img.coverage();
    assert!(cov > 0.2 && cov < 0.9, "coverage {cov}");
    assert_eq!(img.pixel(0, 0), [255, 255, 255, 255]);
    let centre = img.pixel(160, 120);
    assert!(centre[0] > 200 && centre[1] > 200, "the hole of the torus shows the background: {centre:?}");
    let distinct: std::collections::HashSet<[u8; 4]> =
        img.rgba.chunks_exact(4).map(|p| [p[0], p[1], p[2], p[3]]).collect();
    assert!(distinct.len() > 200, "smooth shading makes many colours, got {}", distinct.len());
    let want = reference("torus.png", &img);
    let diff = img.mean_difference(&want).unwrap();
    assert!(diff < 2.0, "mean difference from the reference {diff} (see {})", out.display());
}

#[test]
fn lines_have_their_width_and_a_top_camera_frames_a_plane_figure() {
    let r = renderer();
    let scene = RenderScene {
        lines: vec![LineItem {
            points: vec![[0.0, 0.0, 0.0], [10.0, 0.0, 0.0]],
            closed: false,
            color: [0.0, 0.0, 0.0, 1.0],
            width: 6.0,
            colors: Vec::new(),
        }],
        camera: Some(Camera::top(([0.0, -1.0, 0.0], [10.0, 1.0, 0.0]), 2.0)),
        ..Default::default()
    };
    let img = r.render(&scene, 200, 100).unwrap();
    // A horizontal black bar 6 pixels high through the middle.
    let column: Vec<u8> = (0..100).map(|y| img.pixel(100, y)[0]).collect();
    let dark = column.iter().filter(|&&v| v < 128).count();
    assert!((5..=7).contains(&dark), "{dark} dark pixels: {column:?}");
    assert!(img.pixel(100, 50)[0] < 60);
    let bad = r.render(&scene, 0, 10);
    assert!(bad.unwrap_err().to_string().contains("--size"));
}

/// A single-sampled target draws the same picture as the multisampled one but for the
/// edges, which it does not smooth: the two differ little on average, the single-sampled
/// one has only the mesh's shades and no blends of the background with the torus.
#[test]
fn a_single_sampled_target_draws_the_same_picture_with_hard_edges() {
    let r = renderer();
    let scene = torus_scene();
    let draw = |multisampled: bool| {
        let target = r.target_sampled(320, 240, multisampled).unwrap();
        assert_eq!(target.samples(), if multisampled { splinekit_render::renderer::SAMPLES } else { 1 });
        r.draw(&scene, &target);
        r.read(&target).unwrap()
    };
    let (smooth, hard) = (draw(true), draw(false));
    assert_eq!(smooth.rgba, r.render(&scene, 320, 240).unwrap().rgba, "target() is the multisampled target");
    let diff = hard.mean_difference(&smooth).unwrap();
    assert!(diff > 0.0 && diff < 1.5, "mean difference {diff}");
    assert!((hard.coverage() - smooth.coverage()).abs() < 0.01);
    // Multisampling blends the shapes' edges with what lies behind: more distinct colours.
    let distinct = |img: &Image| {
        img.rgba.chunks_exact(4).map(|p| [p[0], p[1], p[2]]).collect::<std::collections::HashSet<_>>().len()
    };
    assert!(distinct(&hard) < distinct(&smooth), "hard {} smooth {}", distinct(&hard), distinct(&smooth));
}
