//! Triangle meshes of surfaces (welded seams, poles, adaptive quad-trees without cracks) and
//! every export read back.

mod common;

use std::collections::HashMap;
use std::f64::consts::PI;

use splinekit::Point;
use splinekit::surface::model::{Plane, Sphere, Torus};
use splinekit_mesh::export::{ExportError, GltfGeometry, GltfObject, GltfScene, obj, ply, stl};
use splinekit_mesh::surface_mesh::{adaptive, regular};
use splinekit_mesh::{AdaptiveTolerance, MeshOptions, TriangleMesh};

fn torus() -> Torus {
    Torus::new(3.0, 1.0).unwrap()
}

/// Boundary edges after merging vertices with bitwise-equal positions: what a crack shows as.
fn cracks(mesh: &TriangleMesh) -> usize {
    let mut id = HashMap::new();
    let canon: Vec<u32> =
        mesh.positions.iter().enumerate().map(|(i, p)| *id.entry(p.map(f64::to_bits)).or_insert(i as u32)).collect();
    let welded = TriangleMesh {
        positions: mesh.positions.clone(),
        triangles: mesh.triangles.iter().map(|t| t.map(|i| canon[i as usize])).collect(),
        ..Default::default()
    };
    welded.boundary_edges().len()
}

#[test]
fn regular_torus_is_closed_welded_and_converges_in_area() {
    let t = torus();
    let exact = 4.0 * PI * PI * 3.0;
    let mut last = f64::INFINITY;
    for n in [8, 16, 32, 64] {
        let m = regular(&t, 2 * n, n, MeshOptions { uv: false }).unwrap();
        assert_eq!(m.vertex_count(), 2 * n * n, "seams are welded: one vertex per grid point");
        assert!(m.boundary_edges().is_empty(), "a closed surface has no boundary");
        let err = (m.area() - exact).abs();
        assert!(err < last / 3.5, "area error {err} after {last}");
        last = err;
        for (p, nrm) in m.positions.iter().zip(&m.normals) {
            let len = (nrm[0] * nrm[0] + nrm[1] * nrm[1] + nrm[2] * nrm[2]).sqrt();
            assert!((len - 1.0).abs() < 1e-12);
            // The torus normal points away from the tube's centre circle.
            let r = (p[0] * p[0] + p[1] * p[1]).sqrt();
            let c = [3.0 * p[0] / r, 3.0 * p[1] / r, 0.0];
            let d = (p[0] - c[0]) * nrm[0] + (p[1] - c[1]) * nrm[1] + p[2] * nrm[2];
            assert!(d > 0.99, "outward normal");
        }
    }
    // With (u, v) the seam vertices are duplicated, bitwise equal: no cracks.
    let m = regular(&t, 24, 12, MeshOptions { uv: true }).unwrap();
    assert_eq!(m.vertex_count(), 25 * 13);
    assert!(!m.boundary_edges().is_empty());
    assert_eq!(cracks(&m), 0);
}

#[test]
fn sphere_poles_lose_their_degenerate_triangles_and_get_normals() {
    let s = Sphere::new(2.0).unwrap();
    let m = regular(&s, 16, 8, MeshOptions { uv: false }).unwrap();
    for t in 0..m.triangles.len() {
        assert!(m.double_area(t) > 0.0);
    }
    for (p, n) in m.positions.iter().zip(&m.normals) {
        let dot = (p[0] * n[0] + p[1] * n[1] + p[2] * n[2]) / 2.0;
        assert!(dot > 0.999, "normal at {p:?} is {n:?}");
    }
}

#[test]
fn adaptive_meshes_refine_where_curved_and_stitch_levels_without_cracks() {
    let t = torus();
    let tol = |h: f64| AdaptiveTolerance { chord_height: h, normal_angle: 0.5, max_depth: 8 };
    let coarse = adaptive(&t, (4, 4), tol(0.05), MeshOptions { uv: false }).unwrap();
    let fine = adaptive(&t, (4, 4), tol(0.001), MeshOptions { uv: false }).unwrap();
    assert!(fine.triangles.len() > 4 * coarse.triangles.len());
    for m in [&coarse, &fine] {
        assert!(m.boundary_edges().is_empty(), "closed and crack-free");
    }
    let exact = 4.0 * PI * PI * 3.0;
    assert!((fine.area() - exact).abs() < 0.01 * exact);
    // Every vertex lies on the torus.
    for p in &fine.positions {
        let r = (p[0] * p[0] + p[1] * p[1]).sqrt();
        assert!(((r - 3.0).powi(2) + p[2] * p[2] - 1.0).abs() < 1e-12);
    }
    // A plane needs no refinement; a mixed-level mesh of a bumpy surface has no cracks.
    let plane =
        Plane::new(Point::<3>::zeros(), Point::<3>::new(1.0, 0.0, 0.0), Point::<3>::new(0.0, 1.0, 0.0)).unwrap();
    let flat = adaptive(&plane, (3, 2), tol(1e-3), MeshOptions::default()).unwrap();
    assert_eq!(flat.triangles.len(), 12);
    let bumpy = splinekit::surface::BezierSurface::new(vec![
        vec![Point::<3>::new(0.0, 0.0, 0.0), Point::<3>::new(0.0, 1.0, 0.0), Point::<3>::new(0.0, 2.0, 0.0)],
        vec![Point::<3>::new(1.0, 0.0, 0.0), Point::<3>::new(1.0, 1.0, 3.0), Point::<3>::new(1.0, 2.0, 0.0)],
        vec![Point::<3>::new(2.0, 0.0, 0.0), Point::<3>::new(2.0, 1.0, 0.0), Point::<3>::new(2.0, 2.0, 0.0)],
    ])
    .unwrap();
    let m = adaptive(&bumpy, (2, 2), tol(0.002), MeshOptions { uv: false }).unwrap();
    // The only boundary is the square's outline, made of the outline's own vertices.
    for [a, b] in m.boundary_edges() {
        let (p, q) = (m.positions[a as usize], m.positions[b as usize]);
        let on_outline = |p: [f64; 3]| p[0] == 0.0 || p[0] == 2.0 || p[1] == 0.0 || p[1] == 2.0;
        assert!(on_outline(p) && on_outline(q), "interior crack between {p:?} and {q:?}");
    }
}

fn sample_mesh() -> TriangleMesh {
    regular(&torus(), 12, 6, MeshOptions { uv: true }).unwrap()
}

#[test]
fn obj_ply_and_stl_read_back() {
    let m = sample_mesh();
    let back = obj::read_obj(&common::text(|out| obj::write_obj(&m, "torus", out))).unwrap();
    assert_eq!(
        (back.positions.clone(), back.normals.clone(), back.uvs.clone()),
        (m.positions.clone(), m.normals.clone(), m.uvs.clone())
    );
    assert_eq!(back.triangles, m.triangles);
    let back = ply::read_ply(&common::text(|out| ply::write_ply(&m, out))).unwrap();
    assert_eq!(
        (back.positions, back.normals, back.uvs, back.triangles),
        (m.positions.clone(), m.normals.clone(), m.uvs.clone(), m.triangles.clone())
    );
    for bytes in [
        common::bytes(|out| stl::write_stl_binary(&m, out)),
        common::bytes(|out| stl::write_stl_ascii(&m, "torus", out)),
    ] {
        let tris = stl::read_stl(&bytes).unwrap();
        assert_eq!(tris.len(), m.triangles.len());
        for (t, (n, c)) in tris.iter().enumerate() {
            for k in 0..3 {
                let p = m.positions[m.triangles[t][k] as usize];
                assert!((0..3).all(|j| (c[k][j] - p[j] as f32).abs() <= 1e-6 * (p[j].abs() as f32).max(1.0)));
            }
            let fnorm = m.face_normal(t);
            assert!((0..3).all(|j| (n[j] - fnorm[j] as f32).abs() < 1e-6));
        }
    }
    assert!(obj::read_obj("v 1 2\n").unwrap_err().contains("line 1"));
    assert!(stl::read_stl(b"short").is_err());
}

#[test]
fn gltf_and_glb_read_back_with_the_gltf_crate() {
    let m = sample_mesh();
    let mut moved = m.positions.clone();
    for p in &mut moved {
        p[2] += 0.5;
    }
    let scene = GltfScene {
        objects: vec![
            GltfObject {
                name: "torus".into(),
                geometry: GltfGeometry::Mesh(m.clone()),
                color: [0.2, 0.4, 0.8, 1.0],
                frames: vec![(0.0, m.positions.clone(), m.normals.clone()), (0.5, moved, m.normals.clone())],
            },
            GltfObject {
                name: "curve".into(),
                geometry: GltfGeometry::LineStrip(vec![[0.0, 0.0, 0.0], [1.0, 1.0, 0.0], [2.0, 0.0, 1.0]]),
                color: [1.0, 0.0, 0.0, 1.0],
                frames: vec![],
            },
        ],
    };
    let glb = scene.to_glb().unwrap();
    let text = scene.to_gltf().unwrap();
    let from_glb = gltf::Gltf::from_slice(&glb).unwrap();
    let glb_blob = from_glb.blob.clone().unwrap();
    let from_text = gltf::Gltf::from_slice(text.as_bytes()).unwrap();
    let uri = from_text.buffers().next().unwrap();
    let gltf::buffer::Source::Uri(uri) = uri.source() else { panic!("embedded buffer") };
    let text_blob = common::base64_decode(uri.split_once(',').unwrap().1);
    for (doc, blob) in [(&from_glb, &glb_blob), (&from_text, &text_blob)] {
        assert_eq!(doc.nodes().count(), 2);
        let mesh = doc.meshes().next().unwrap();
        let prim = mesh.primitives().next().unwrap();
        assert_eq!(prim.mode(), gltf::mesh::Mode::Triangles);
        let reader = prim.reader(|_| Some(&blob[..]));
        let positions: Vec<[f32; 3]> = reader.read_positions().unwrap().collect();
        assert_eq!(positions.len(), m.positions.len());
        for (a, b) in positions.iter().zip(&m.positions) {
            assert!((0..3).all(|k| a[k] == b[k] as f32));
        }
        let normals: Vec<[f32; 3]> = reader.read_normals().unwrap().collect();
        assert_eq!(normals.len(), m.normals.len());
        let idx: Vec<u32> = reader.read_indices().unwrap().into_u32().collect();
        assert_eq!(idx.len(), 3 * m.triangles.len());
        assert_eq!(prim.morph_targets().count(), 2);
        let anim = doc.animations().next().unwrap();
        assert_eq!(anim.channels().next().unwrap().target().property(), gltf::animation::Property::MorphTargetWeights);
        let line = doc.meshes().nth(1).unwrap().primitives().next().unwrap();
        assert_eq!(line.mode(), gltf::mesh::Mode::LineStrip);
    }
}

#[test]
fn trimmed_surfaces_follow_their_loops_by_constrained_delaunay() {
    use splinekit::curve::{CircleFrame, NurbsCurve};
    use splinekit::surface::TrimmedSurface;
    let plane = || {
        Box::new(
            Plane::new(Point::<3>::zeros(), Point::<3>::new(1.0, 0.0, 0.0), Point::<3>::new(0.0, 1.0, 0.0)).unwrap(),
        )
    };
    let hole = NurbsCurve::<2>::circle(&CircleFrame::in_xy_plane(Point::<2>::new(0.5, 0.5), 0.25)).unwrap();
    let s = TrimmedSurface::new(plane(), None, &[&hole]).unwrap();
    let m = regular(&s, 32, 32, MeshOptions::default()).unwrap();
    let exact = 1.0 - PI * 0.25 * 0.25;
    assert!((m.area() - exact).abs() < 2e-3, "area {} vs {exact}", m.area());
    // The boundary is the square's outline and vertices on the circle — no staircase.
    for [a, b] in m.boundary_edges() {
        for p in [m.positions[a as usize], m.positions[b as usize]] {
            let on_square = p[0] == 0.0 || p[0] == 1.0 || p[1] == 0.0 || p[1] == 1.0;
            let r = ((p[0] - 0.5).powi(2) + (p[1] - 0.5).powi(2)).sqrt();
            assert!(on_square || (r - 0.25).abs() < 1e-9, "boundary vertex {p:?} at radius {r}");
        }
    }
    assert!(m.triangles.len() > 1000);
    // A hole crossing the outer loop is refused.
    let outer = NurbsCurve::<2>::circle(&CircleFrame::in_xy_plane(Point::<2>::new(0.5, 0.5), 0.4)).unwrap();
    let crossing = NurbsCurve::<2>::circle(&CircleFrame::in_xy_plane(Point::<2>::new(0.85, 0.5), 0.2)).unwrap();
    let s = TrimmedSurface::new(plane(), Some(&outer), &[&crossing]).unwrap();
    let e = regular(&s, 16, 16, MeshOptions::default()).unwrap_err();
    assert!(e.to_string().contains("holes[0]"), "{e}");
}

/// A sink whose writes fail, like a full disk.
struct Full;
impl std::io::Write for Full {
    fn write(&mut self, _: &[u8]) -> std::io::Result<usize> {
        Err(std::io::Error::new(std::io::ErrorKind::StorageFull, "no space left on device"))
    }
    fn flush(&mut self) -> std::io::Result<()> {
        Ok(())
    }
}

#[test]
fn huge_and_tiny_spheres_keep_welded_poles_and_unit_normals() {
    for r in [1e300, 1e-300, 1e30] {
        let s = Sphere::new(r).unwrap();
        let m = regular(&s, 16, 8, MeshOptions { uv: false }).unwrap();
        assert!(m.boundary_edges().is_empty(), "radius {r}: closed by its indices");
        assert_eq!(m.vertex_count(), 16 * 7 + 2, "radius {r}: one vertex per pole");
        for (p, n) in m.positions.iter().zip(&m.normals) {
            let len = (n[0] * n[0] + n[1] * n[1] + n[2] * n[2]).sqrt();
            let outward = (p[0] / r) * n[0] + (p[1] / r) * n[1] + (p[2] / r) * n[2];
            assert!((len - 1.0).abs() < 1e-12 && outward > 0.99, "radius {r}: normal {n:?} at {p:?}");
        }
    }
}

#[test]
fn writers_refuse_numbers_the_format_cannot_hold_and_report_write_errors() {
    // 1e39 is finite in f64 but beyond f32: OBJ and PLY hold it, STL and glTF refuse.
    let m = regular(&Sphere::new(1e39).unwrap(), 8, 4, MeshOptions::default()).unwrap();
    assert!(obj::write_obj(&m, "big", Vec::new()).is_ok());
    assert!(ply::write_ply(&m, Vec::new()).is_ok());
    for e in [
        stl::write_stl_binary(&m, Vec::new()).unwrap_err(),
        stl::write_stl_ascii(&m, "big", Vec::new()).unwrap_err(),
        GltfScene::single("big", GltfGeometry::Mesh(m.clone()), [1.0; 4]).to_glb().unwrap_err(),
    ] {
        let e = e.to_string();
        assert!(e.contains("positions[0][2]: -1e39 is beyond the largest 32-bit float"), "{e}");
    }
    let e = GltfScene::single("big", GltfGeometry::Mesh(m), [1.0; 4]).to_gltf().unwrap_err().to_string();
    assert!(e.starts_with(r#"objects[0] ("big") mesh positions[0][2]"#), "{e}");
    // A sphere too small for f32: its corners collapse, so single-precision files refuse it.
    let tiny = regular(&Sphere::new(1e-300).unwrap(), 8, 4, MeshOptions::default()).unwrap();
    assert!(obj::write_obj(&tiny, "tiny", Vec::new()).is_ok());
    let e = stl::write_stl_binary(&tiny, Vec::new()).unwrap_err().to_string();
    assert!(e.starts_with("triangles[0]: vertices") && e.contains("32-bit floats that STL stores"), "{e}");
    // NaN anywhere is refused by every writer, naming where.
    let mut bad = sample_mesh();
    bad.normals[5][1] = f64::NAN;
    let e = obj::write_obj(&bad, "bad", Vec::new()).unwrap_err().to_string();
    assert_eq!(e, "normals[5][1]: NaN is not a finite number, which OBJ needs");
    assert!(ply::write_ply(&bad, Vec::new()).unwrap_err().to_string().starts_with("normals[5][1]"));
    let e = obj::write_obj_polyline(&[[0.0, f64::INFINITY, 0.0]], false, "l", Vec::new()).unwrap_err();
    assert!(e.to_string().starts_with("points[0][1]: inf"), "{e}");
    // A morph target whose offset overflows f32 though both frames fit: x stretched to
    // ±2.8e38 and mirrored in the second frame.
    let mut far = sample_mesh();
    for p in far.positions.iter_mut() {
        p[0] *= 7e37;
    }
    let mirrored: Vec<[f64; 3]> = far.positions.iter().map(|p| [-p[0], p[1], p[2]]).collect();
    let frames = vec![(0.0, far.positions.clone(), far.normals.clone()), (1.0, mirrored, far.normals.clone())];
    let object = GltfObject { name: "far".into(), geometry: GltfGeometry::Mesh(far), color: [1.0; 4], frames };
    let e = GltfScene { objects: vec![object] }.to_glb().unwrap_err().to_string();
    assert!(e.starts_with(r#"objects[0] ("far") frames[1] POSITION offset["#), "{e}");
    assert!(e.contains("is beyond the largest 32-bit float"), "{e}");
    // Write errors come back instead of being dropped.
    let m = sample_mesh();
    for e in [
        obj::write_obj(&m, "t", Full).unwrap_err(),
        ply::write_ply(&m, Full).unwrap_err(),
        stl::write_stl_binary(&m, Full).unwrap_err(),
        stl::write_stl_ascii(&m, "t", Full).unwrap_err(),
    ] {
        assert!(matches!(e, ExportError::Io(_)), "{e}");
        assert!(e.to_string().contains("no space left on device"), "{e}");
    }
}

#[test]
fn adaptive_meshes_estimate_their_size_before_refining() {
    let sphere = Sphere::new(2.0).unwrap();
    let tol = AdaptiveTolerance { chord_height: 1e-3, normal_angle: 0.2, max_depth: 10 };
    let mesh = adaptive(&sphere, (8, 8), tol, MeshOptions::default()).unwrap();
    let cells = mesh.triangles.len() / 2;
    // The estimate is within a small factor of the cells made: a budget well above them
    // passes, one far below is refused at once by the estimate (not by the running count).
    let roomy =
        splinekit_mesh::adaptive_mesh::adaptive_with_limit(&sphere, (8, 8), tol, MeshOptions::default(), 3 * cells);
    assert!(roomy.is_ok(), "{:?}", roomy.err());
    let tight =
        splinekit_mesh::adaptive_mesh::adaptive_with_limit(&sphere, (8, 8), tol, MeshOptions::default(), cells / 4);
    let message = tight.unwrap_err().to_string();
    assert!(message.starts_with("tolerance:") && message.contains("estimated"), "{message}");
    // A tolerance far below the sphere's size is refused before any refinement.
    let tiny = AdaptiveTolerance { chord_height: 1e-12, ..tol };
    let started = std::time::Instant::now();
    let refused =
        splinekit_mesh::adaptive_mesh::adaptive_with_limit(&sphere, (8, 8), tiny, MeshOptions::default(), 1 << 24);
    assert!(refused.unwrap_err().to_string().contains("estimated"));
    assert!(started.elapsed().as_secs_f64() < 5.0, "refusal is immediate (probe only)");
}

/// Issue 20: a horn torus (major radius = minor radius) meets itself at the centre, where
/// the tube's innermost vertices are one point in 32-bit floats (−0 and +0 among them).
/// STL and glTF used to refuse its mesh; now the mesher merges them (−0 and +0 are one
/// point) and the writers leave out any triangle whose corners still meet in f32 (a mesh
/// made elsewhere), writing the rest.
#[test]
fn a_horn_torus_is_written_without_collapsed_triangles() {
    let torus = Torus::new(1.0, 1.0).unwrap();
    let mut m = regular(&torus, 48, 24, MeshOptions::default()).unwrap();
    let check = |m: &TriangleMesh, expected: usize| {
        for bytes in [
            common::bytes(|out| stl::write_stl_binary(m, out)),
            common::bytes(|out| stl::write_stl_ascii(m, "horn", out)),
        ] {
            let tris = stl::read_stl(&bytes).unwrap();
            assert_eq!(tris.len(), expected);
            for (_, c) in &tris {
                assert!(c[0] != c[1] && c[1] != c[2] && c[2] != c[0], "{c:?}");
                for p in c {
                    // (√(x² + y²) − R)² + z² = r² with R = r = 1.
                    let (x, y, z) = (p[0] as f64, p[1] as f64, p[2] as f64);
                    let q = (x.hypot(y) - 1.0).powi(2) + z * z;
                    assert!((q - 1.0).abs() < 1e-6, "{p:?} is off the torus");
                }
            }
        }
        let glb = GltfScene::single("horn", GltfGeometry::Mesh(m.clone()), [1.0; 4]).to_glb().unwrap();
        assert!(glb.len() > 1000);
    };
    let whole = m.triangles.len();
    check(&m, whole);
    // A sliver at the pinch whose two corners differ only below f32's resolution: left out.
    let n = m.positions.len() as u32;
    m.positions.extend([[0.0, 0.0, 0.0], [1e-50, 0.0, 0.0], [0.0, 0.0, 2.0]]);
    m.normals.extend([[0.0, 0.0, 1.0]; 3]);
    if !m.uvs.is_empty() {
        m.uvs.extend([[0.0, 0.0]; 3]);
    }
    if !m.colors.is_empty() {
        m.colors.extend([[1.0; 4]; 3]);
    }
    m.triangles.push([n, n + 1, n + 2]);
    check(&m, whole);
    // The formats of f64 (OBJ) keep it.
    let back = obj::read_obj(&common::text(|out| obj::write_obj(&m, "horn", out))).unwrap();
    assert_eq!(back.triangles.len(), whole + 1);
}

/// An adaptive mesh of a trimmed surface depends on the surface only: the leaf corners go
/// into the triangulation in lattice order, not in the order of a freshly seeded hash map
/// (two calls in one process seed theirs differently).
#[test]
fn trimmed_adaptive_meshes_are_the_same_on_every_call() {
    use splinekit::curve::{CircleFrame, NurbsCurve};
    use splinekit::surface::TrimmedSurface;
    let hole = NurbsCurve::<2>::circle(&CircleFrame::in_xy_plane(Point::<2>::new(0.4, 0.6), 0.2)).unwrap();
    let s = TrimmedSurface::new(Box::new(torus()), None, &[&hole]).unwrap();
    let tol = AdaptiveTolerance { chord_height: 0.02, normal_angle: 0.4, max_depth: 6 };
    let bits = |m: &TriangleMesh| {
        let p: Vec<[u64; 3]> = m.positions.iter().map(|p| p.map(f64::to_bits)).collect();
        (p, m.triangles.clone())
    };
    let first = bits(&adaptive(&s, (4, 4), tol, MeshOptions::default()).unwrap());
    assert!(first.1.len() > 100);
    for _ in 0..4 {
        let again = bits(&adaptive(&s, (4, 4), tol, MeshOptions::default()).unwrap());
        assert!(again == first, "the mesh changed between calls");
    }
}
