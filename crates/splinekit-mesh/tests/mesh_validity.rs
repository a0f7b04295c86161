//! Every closed model surface and every example scene, meshed and written in every format,
//! judged by code independent of the mesher: files are read back (the `gltf` crate for
//! glTF), vertices welded by their 32-bit positions (what a program reading single
//! precision sees), and then edges counted (a closed 2-manifold uses each edge twice, once in
//! each direction when consistently oriented), boundary loops traced, the enclosed volume
//! taken by the divergence theorem and compared with the analytic volume and area, with the
//! error shrinking like h² as the grid is refined.
//!
//! The files and a manifest of what each should be are left in
//! `target/tmp/mesh-exports/` for the outside judges (`tools/validate/`: the Khronos glTF
//! validator and trimesh), which `.ci/validate-exports.sh` runs.

mod common;

use std::collections::HashMap;
use std::f64::consts::PI;
use std::path::PathBuf;

use serde_json::{Value, json};
use splinekit::Point;
use splinekit::surface::Surface;
use splinekit_mesh::AdaptiveTolerance;
use splinekit_mesh::export::{GltfGeometry, GltfScene, obj, ply, stl};
use splinekit_mesh::surface_mesh::adaptive;
use splinekit_mesh::surface_mesh::regular;
use splinekit_mesh::{MeshOptions, TriangleMesh};
use splinekit_scene::DocumentKind;
use splinekit_scene::curves::NurbsDoc;
use splinekit_scene::scenes::SceneOrShape;
use splinekit_scene::{AnySurface, ShapeDocument};

/// What a file holds: 32-bit positions, per-vertex normals (or none), triangles.
struct Soup {
    positions: Vec<[f32; 3]>,
    normals: Vec<[f32; 3]>,
    triangles: Vec<[u32; 3]>,
}

/// Edge counts and measures of a soup after welding vertices with equal f32 positions.
#[derive(Debug, Default)]
struct Verdict {
    /// Triangles with two corners at the same f32 position.
    degenerate: usize,
    /// Edges used once.
    boundary_edges: usize,
    /// Edges used more than twice.
    overused_edges: usize,
    /// Edges used twice in the same direction (neighbouring triangles oriented apart).
    misoriented_edges: usize,
    /// Connected pieces of the boundary.
    boundary_loops: usize,
    /// Σ (a−o)·((b−o)×(c−o))/6.
    volume: f64,
    area: f64,
}

impl Verdict {
    fn closed(&self) -> bool {
        self.degenerate == 0 && self.boundary_edges == 0 && self.overused_edges == 0
    }
}

fn wide(p: [f32; 3]) -> Point<3> {
    Point::<3>::from(p.map(f64::from))
}

fn root(parent: &mut [usize], mut i: usize) -> usize {
    while parent[i] != i {
        parent[i] = parent[parent[i]];
        i = parent[i];
    }
    i
}

fn judge(soup: &Soup) -> Verdict {
    let mut id: HashMap<[u32; 3], usize> = HashMap::new();
    let canon: Vec<usize> = soup
        .positions
        .iter()
        .map(|p| {
            let n = id.len();
            *id.entry(p.map(f32::to_bits)).or_insert(n)
        })
        .collect();
    let mut v = Verdict::default();
    let mut directed: HashMap<(usize, usize), usize> = HashMap::new();
    let o = wide(soup.positions[0]);
    for t in &soup.triangles {
        let c = t.map(|i| canon[i as usize]);
        if c[0] == c[1] || c[1] == c[2] || c[0] == c[2] {
            v.degenerate += 1;
            continue;
        }
        for k in 0..3 {
            *directed.entry((c[k], c[(k + 1) % 3])).or_insert(0) += 1;
        }
        let [a, b, cc] = t.map(|i| wide(soup.positions[i as usize]) - o);
        v.area += 0.5 * (b - a).cross(&(cc - a)).norm();
        v.volume += a.dot(&b.cross(&cc)) / 6.0;
    }
    let mut parent: Vec<usize> = (0..id.len()).collect();
    let mut on_boundary = vec![false; id.len()];
    for (&(a, b), &n) in &directed {
        let back = directed.get(&(b, a)).copied().unwrap_or(0);
        let uses = n + back;
        if a < b || back == 0 {
            match uses {
                1 => {
                    v.boundary_edges += 1;
                    on_boundary[a] = true;
                    on_boundary[b] = true;
                    let (ra, rb) = (root(&mut parent, a), root(&mut parent, b));
                    parent[ra] = rb;
                }
                2 => {}
                _ => v.overused_edges += 1,
            }
        }
        if n > 1 {
            v.misoriented_edges += 1;
        }
    }
    v.boundary_loops = (0..id.len()).filter(|&i| on_boundary[i] && root(&mut parent, i) == i).count();
    v
}

/// Vertex normals are unit vectors on the side the triangles around them face.
fn check_vertex_normals(soup: &Soup, what: &str) {
    assert_eq!(soup.normals.len(), soup.positions.len(), "{what}: one normal per vertex");
    let mut fan = vec![Point::<3>::zeros(); soup.positions.len()];
    for t in &soup.triangles {
        let [a, b, c] = t.map(|i| wide(soup.positions[i as usize]));
        let n = (b - a).cross(&(c - a));
        for &i in t {
            fan[i as usize] += n;
        }
    }
    for (i, n) in soup.normals.iter().enumerate() {
        let n = wide(*n);
        assert!((n.norm() - 1.0).abs() < 1e-5, "{what}: normal {i} {n:?} is not a unit vector");
        assert!(n.dot(&fan[i]) > 0.0, "{what}: normal {i} {n:?} points away from its triangles {:?}", fan[i]);
    }
}

fn obj_soup(bytes: &[u8]) -> Soup {
    let m = obj::read_obj(std::str::from_utf8(bytes).unwrap()).unwrap();
    mesh_soup(&m)
}
fn ply_soup(bytes: &[u8]) -> Soup {
    mesh_soup(&ply::read_ply(std::str::from_utf8(bytes).unwrap()).unwrap())
}
fn mesh_soup(m: &TriangleMesh) -> Soup {
    let single = |v: &Vec<[f64; 3]>| v.iter().map(|p| p.map(|x| x as f32)).collect();
    Soup { positions: single(&m.positions), normals: single(&m.normals), triangles: m.triangles.clone() }
}
/// STL triangles as a soup; the facet normals must be unit vectors along the winding.
fn stl_soup(bytes: &[u8], what: &str) -> Soup {
    let tris = stl::read_stl(bytes).unwrap();
    let mut soup = Soup { positions: vec![], normals: vec![], triangles: vec![] };
    for (t, (n, c)) in tris.iter().enumerate() {
        let face = (wide(c[1]) - wide(c[0])).cross(&(wide(c[2]) - wide(c[0])));
        let n = wide(*n);
        assert!((n.norm() - 1.0).abs() < 1e-5 && n.dot(&face) > 0.0, "{what}: facet {t} normal {n:?}");
        let base = soup.positions.len() as u32;
        soup.positions.extend_from_slice(c);
        soup.triangles.push([base, base + 1, base + 2]);
    }
    soup
}
fn gltf_soup(bytes: &[u8]) -> Soup {
    let mut meshes = common::gltf_meshes(bytes);
    assert_eq!(meshes.len(), 1);
    let m = meshes.remove(0);
    Soup { positions: m.positions, normals: m.normals, triangles: m.triangles }
}

/// What a surface's mesh must be.
#[derive(Debug, Clone, Copy)]
enum Shape {
    /// Closed and orientable: a closed, consistently oriented 2-manifold of positive volume
    /// in every file, with the analytic (volume, area) when known.
    Closed(Option<(f64, f64)>),
    /// Closed but not orientable (the Klein bottle): closed by its vertex indices, with
    /// edges used twice in the same direction. Its self-intersection circle lies on grid rows,
    /// so files welded by position are only checked for degenerate triangles.
    ClosedNonOrientable,
    /// Open, with this many boundary loops, and the area when known.
    Open { loops: usize, orientable: bool, area: Option<f64> },
}

/// ∫ₐᵇ f by composite Simpson's rule on 20 000 panels.
fn simpson(f: impl Fn(f64) -> f64, a: f64, b: f64) -> f64 {
    let n = 20_000;
    let h = (b - a) / n as f64;
    let inner: f64 = (1..n).map(|k| f(a + k as f64 * h) * if k % 2 == 1 { 4.0 } else { 2.0 }).sum();
    (f(a) + f(b) + inner) * h / 3.0
}

/// The heart surface: the profile h(u) = (16 sin³u, 13 cos u − 5 cos 2u − 2 cos 3u − cos 4u)
/// turned about the z-axis; V = π|∫ h_x² h_y' du| (discs), A = 2π ∫ h_x |h'| du.
fn heart_volume_and_area() -> (f64, f64) {
    let hx = |u: f64| 16.0 * u.sin().powi(3);
    let dhx = |u: f64| 48.0 * u.sin().powi(2) * u.cos();
    let dhy = |u: f64| -13.0 * u.sin() + 10.0 * (2.0 * u).sin() + 6.0 * (3.0 * u).sin() + 4.0 * (4.0 * u).sin();
    let volume = PI * simpson(|u| hx(u).powi(2) * dhy(u), 0.0, PI).abs();
    let area = 2.0 * PI * simpson(|u| hx(u) * dhx(u).hypot(dhy(u)), 0.0, PI);
    (volume, area)
}

/// A tube of radius r about the trefoil (sin t + 2 sin 2t, cos t − 2 cos 2t, −sin 3t) of
/// length L: V = πr²L, A = 2πrL (Pappus for tubes).
fn trefoil_tube_volume_and_area(r: f64) -> (f64, f64) {
    let speed = |t: f64| {
        Point::<3>::new(t.cos() + 4.0 * (2.0 * t).cos(), -t.sin() + 4.0 * (2.0 * t).sin(), -3.0 * (3.0 * t).cos())
            .norm()
    };
    let length = simpson(speed, 0.0, 2.0 * PI);
    (PI * r * r * length, 2.0 * PI * r * length)
}

fn surface_of(doc: &Value) -> Box<dyn Surface<3>> {
    let ShapeDocument::Surface(s) = ShapeDocument::parse(doc).unwrap() else { panic!("{doc} is not a surface") };
    s.build_in::<3>().unwrap()
}

fn example(name: &str) -> String {
    std::fs::read_to_string(format!("{}/../../examples/scenes/{name}.json", env!("CARGO_MANIFEST_DIR"))).unwrap()
}

fn export_dir() -> PathBuf {
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("mesh-exports");
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

/// The closed and open model surfaces (documents as users write them) and what they are.
fn model_cases() -> Vec<(&'static str, Value, Shape)> {
    let r2 = std::f64::consts::FRAC_1_SQRT_2;
    let sphere = |r: f64| Shape::Closed(Some((4.0 / 3.0 * PI * r.powi(3), 4.0 * PI * r * r)));
    let torus = |big: f64, r: f64| Shape::Closed(Some((2.0 * PI * PI * big * r * r, 4.0 * PI * PI * big * r)));
    // The exact unit circle as the scene's NURBS example holds it: nine points of a square,
    // quadratic, weights 1 and 1/√2.
    let unit_circle = NurbsDoc::example();
    let (circle_knots, circle_weights, ring) = (unit_circle.knots, unit_circle.weights, unit_circle.control_points);
    // The rational sphere of radius 1.5: a circle (u) times a half circle from pole to pole (v).
    let meridian = [[0.0, -1.0, 1.0], [1.0, -1.0, r2], [1.0, 0.0, 1.0], [1.0, 1.0, r2], [0.0, 1.0, 1.0]];
    let (mut net, mut weights) = (vec![], vec![]);
    for (k, c) in ring.iter().enumerate() {
        let wu = circle_weights[k];
        net.push(
            meridian.iter().map(|m| json!([1.5 * m[0] * c[0], 1.5 * m[0] * c[1], 1.5 * m[1]])).collect::<Vec<_>>(),
        );
        weights.push(meridian.iter().map(|m| wu * m[2]).collect::<Vec<_>>());
    }
    let nurbs_sphere = json!({"type": "nurbs_surface", "degree_u": 2, "degree_v": 2, "knots_u": circle_knots,
        "knots_v": [0, 0, 0, 0.5, 0.5, 1, 1, 1], "control_points": net, "weights": weights});
    let nurbs_torus = serde_json::from_str::<Value>(&example("nurbs_torus")).unwrap()["objects"][0]["shape"].clone();
    let semicircle = json!({"type": "nurbs", "degree": 2, "knots": [0, 0, 0, 0.5, 0.5, 1, 1, 1],
        "control_points": [[0, 0, -1], [1, 0, -1], [1, 0, 0], [1, 0, 1], [0, 0, 1]], "weights": [1, r2, 1, r2, 1]});
    let tube_circle = json!({"type": "nurbs", "degree": 2, "knots": circle_knots, "weights": circle_weights,
        "control_points": ring.iter().map(|c| json!([3.0 + c[0], 0.0, c[1]])).collect::<Vec<_>>()});
    let square = json!({"type": "bspline", "degree": 1, "knots": [0, 0, 1, 2, 3, 4, 4],
        "control_points": [[1, 0, 0], [2, 0, 0], [2, 0, 1], [1, 0, 1], [1, 0, 0]]});
    let torus_net: Vec<Vec<Value>> = (0..6)
        .map(|i| {
            let a = i as f64 * PI / 3.0;
            (0..5)
                .map(|j| {
                    let b = j as f64 * 2.0 * PI / 5.0;
                    json!([(3.0 + b.cos()) * a.cos(), (3.0 + b.cos()) * a.sin(), b.sin()])
                })
                .collect()
        })
        .collect();
    let hole = json!({"type": "nurbs", "degree": 2, "knots": circle_knots, "weights": circle_weights,
        "control_points": ring.iter().map(|c| json!([0.5 + 0.25 * c[0], 0.5 + 0.25 * c[1]])).collect::<Vec<_>>()});
    let torus_hole = json!({"type": "nurbs", "degree": 2, "knots": circle_knots, "weights": circle_weights,
        "control_points": ring.iter().map(|c| json!([PI + c[0], PI + c[1]])).collect::<Vec<_>>()});
    let heart = heart_volume_and_area();
    let open = |loops, orientable, area| Shape::Open { loops, orientable, area };
    vec![
        ("sphere", json!({"type": "sphere", "radius": 2}), sphere(2.0)),
        ("torus", json!({"type": "torus", "major_radius": 3, "minor_radius": 1}), torus(3.0, 1.0)),
        ("heart_surface", json!({"type": "heart_surface"}), Shape::Closed(Some(heart))),
        ("nurbs_sphere", nurbs_sphere, sphere(1.5)),
        ("nurbs_torus", nurbs_torus, torus(3.0, 1.0)),
        ("revolved_semicircle", json!({"type": "revolution", "curve": semicircle}), sphere(1.0)),
        ("revolved_circle", json!({"type": "revolution", "curve": tube_circle}), torus(3.0, 1.0)),
        ("revolved_square", json!({"type": "revolution", "curve": square}), Shape::Closed(Some((3.0 * PI, 12.0 * PI)))),
        (
            "trefoil_tube",
            json!({"type": "sweep", "profile": {"type": "circle", "radius": 0.3}, "path": {"type": "trefoil"}}),
            Shape::Closed(Some(trefoil_tube_volume_and_area(0.3))),
        ),
        (
            "blending_torus",
            json!({"type": "blending_spline_surface", "model": {"type": "torus"}, "local_surfaces": [6, 4]}),
            Shape::Closed(None),
        ),
        (
            "blending_sphere",
            json!({"type": "blending_spline_surface", "model": {"type": "sphere"}, "local_surfaces": [6, 4]}),
            Shape::Closed(None),
        ),
        (
            "periodic_bspline_torus",
            json!({"type": "bspline_surface", "degree_u": 3, "degree_v": 3, "periodic_u": true,
            "periodic_v": true, "knots_u": (0..10).collect::<Vec<_>>(), "knots_v": (0..9).collect::<Vec<_>>(),
            "control_points": torus_net}),
            Shape::Closed(None),
        ),
        ("klein_bottle", json!({"type": "klein_bottle"}), Shape::ClosedNonOrientable),
        ("cone", json!({"type": "cone"}), open(1, true, Some(PI * 5f64.sqrt()))),
        ("cylinder", json!({"type": "cylinder"}), open(2, true, Some(2.0 * PI))),
        ("seashell", json!({"type": "seashell"}), open(1, true, None)),
        // GMlib's apple is open: its ends are circles of radius 0.2 deep in the dimples.
        ("apple", json!({"type": "apple"}), open(2, true, None)),
        ("mobius", json!({"type": "mobius"}), open(1, false, None)),
        (
            "trimmed_plane",
            json!({"type": "trimmed", "surface": {"type": "plane"}, "holes": [hole]}),
            open(2, true, Some(1.0 - PI / 16.0)),
        ),
        // A torus (R = 3, r = 1) with the unit disc around (π, π) cut from its (u, v) domain,
        // away from the seams, which still glue. The hole's area is ∬ (R + cos v) du dv =
        // 3π − 2π J₁(1) over the disc (J₁(1) = 0.44005058574493355, Bessel).
        (
            "trimmed_torus",
            json!({"type": "trimmed", "surface": {"type": "torus"}, "holes": [torus_hole]}),
            open(1, true, Some(12.0 * PI * PI - (3.0 * PI - 2.0 * PI * 0.44005058574493355))),
        ),
    ]
}

/// The mesh's own vertex indices judged without welding: positions replaced by the index.
fn index_verdict(m: &TriangleMesh) -> Verdict {
    let positions = (0..m.positions.len()).map(|i| [i as f32, 0.0, 0.0]).collect();
    judge(&Soup { positions, normals: vec![], triangles: m.triangles.clone() })
}

/// Relative errors of the volume and area of the n × n mesh against the analytic values.
fn errors(surface: &dyn Surface<3>, n: usize, exact: (f64, f64)) -> (f64, f64) {
    let v = judge(&mesh_soup(&regular(surface, n, n, MeshOptions { uv: false }).unwrap()));
    ((v.volume / exact.0 - 1.0).abs(), (v.area / exact.1 - 1.0).abs())
}

/// The six files the command line writes for a surface (OBJ, PLY and glTF with (u, v)).
fn files(name: &str, surface: &dyn Surface<3>, n: usize) -> Vec<(String, Vec<u8>)> {
    let with_uv = regular(surface, n, n, MeshOptions { uv: true }).unwrap();
    let plain = regular(surface, n, n, MeshOptions { uv: false }).unwrap();
    let gltf = GltfScene::single(name, GltfGeometry::Mesh(with_uv.clone()), [0.2, 0.4, 0.8, 1.0]);
    vec![
        ("obj".into(), common::bytes(|out| obj::write_obj(&with_uv, name, out))),
        ("ply".into(), common::bytes(|out| ply::write_ply(&with_uv, out))),
        ("stl".into(), common::bytes(|out| stl::write_stl_binary(&plain, out))),
        ("stla".into(), common::bytes(|out| stl::write_stl_ascii(&plain, name, out))),
        ("gltf".into(), gltf.to_gltf().unwrap().into_bytes()),
        ("glb".into(), gltf.to_glb().unwrap()),
    ]
}

/// Checks one file against what the surface is; returns its verdict.
fn check_file(what: &str, ext: &str, bytes: &[u8], shape: Shape, tolerance: f64) -> Verdict {
    let soup = match ext {
        "obj" => obj_soup(bytes),
        "ply" => ply_soup(bytes),
        "stl" | "stla" => stl_soup(bytes, what),
        _ => gltf_soup(bytes),
    };
    if !ext.starts_with("stl") {
        check_vertex_normals(&soup, what);
    }
    let v = judge(&soup);
    assert_eq!(v.degenerate, 0, "{what}: triangles degenerate in f32: {v:?}");
    match shape {
        Shape::Closed(known) => {
            assert!(v.closed() && v.misoriented_edges == 0, "{what}: not a closed oriented 2-manifold: {v:?}");
            assert!(v.volume > 0.0, "{what}: faces inward: {v:?}");
            if let Some((volume, area)) = known {
                assert!((v.volume / volume - 1.0).abs() < tolerance, "{what}: volume {} vs {volume}", v.volume);
                assert!((v.area / area - 1.0).abs() < tolerance, "{what}: area {} vs {area}", v.area);
            }
        }
        Shape::ClosedNonOrientable => {}
        Shape::Open { loops, orientable, area } => {
            assert_eq!((v.overused_edges, v.boundary_loops), (0, loops), "{what}: {v:?}");
            assert_eq!(v.misoriented_edges == 0, orientable, "{what}: {v:?}");
            if let Some(area) = area {
                assert!((v.area / area - 1.0).abs() < tolerance, "{what}: area {} vs {area}", v.area);
            }
        }
    }
    v
}

/// Writes the files of a case and its manifest entry for the outside judges.
fn export(name: &str, files: &[(String, Vec<u8>)], shape: Shape, tolerance: f64) -> Value {
    let dir = export_dir();
    let mut names = Vec::new();
    for (ext, bytes) in files {
        let file = format!("{name}.{ext}");
        std::fs::write(dir.join(&file), bytes).unwrap();
        names.push(file);
    }
    let (closed, orientable, loops, known) = match shape {
        Shape::Closed(known) => (Some(true), true, Some(0), known),
        Shape::ClosedNonOrientable => (None, false, None, None),
        Shape::Open { loops, orientable, area } => (Some(false), orientable, Some(loops), area.map(|a| (f64::NAN, a))),
    };
    let finite = |x: f64| x.is_finite().then_some(x);
    json!({"name": name, "files": names, "closed": closed, "orientable": orientable, "boundary_loops": loops,
           "volume": known.and_then(|k| finite(k.0)), "area": known.map(|k| k.1), "tolerance": tolerance})
}

/// Density of the checked meshes, and the relative error allowed at it: the grid's
/// sampling error, second order, a few times (π/48)² ≈ 4·10⁻³ for these shapes (the
/// trefoil tube, whose path is long and curled, reaches 1.8·10⁻²); the halving of the
/// error with the grid spacing is checked separately.
const DENSITY: usize = 48;
const TOLERANCE: f64 = 3e-2;

#[test]
fn every_model_surface_exports_as_a_valid_mesh_in_every_format() {
    let mut manifest = Vec::new();
    for (name, doc, shape) in model_cases() {
        let surface = surface_of(&doc);
        let plain = regular(surface.as_ref(), DENSITY, DENSITY, MeshOptions { uv: false }).unwrap();
        let by_index = index_verdict(&plain);
        match shape {
            Shape::Closed(_) => assert!(by_index.closed() && by_index.misoriented_edges == 0, "{name}: {by_index:?}"),
            Shape::ClosedNonOrientable => {
                assert!(by_index.closed() && by_index.misoriented_edges > 0, "{name}: {by_index:?}")
            }
            Shape::Open { .. } => assert_eq!(by_index.overused_edges, 0, "{name}"),
        }
        let written = files(name, surface.as_ref(), DENSITY);
        let mut line = format!("{name:24}");
        for (ext, bytes) in &written {
            let v = check_file(&format!("{name}.{ext}"), ext, bytes, shape, TOLERANCE);
            line += &format!(" {ext}:{:.6}/{:.6}", v.volume, v.area);
        }
        println!("{line}");
        if let Shape::Closed(Some(exact)) = shape {
            let (coarse, fine) =
                (errors(surface.as_ref(), DENSITY, exact), errors(surface.as_ref(), 2 * DENSITY, exact));
            println!(
                "{name:24} relative errors (volume, area) n={DENSITY}: ({:.2e}, {:.2e})  n={}: ({:.2e}, {:.2e})",
                coarse.0,
                coarse.1,
                2 * DENSITY,
                fine.0,
                fine.1
            );
            assert!(fine.0 < coarse.0 / 3.0 && fine.1 < coarse.1 / 3.0, "{name}: second order: {coarse:?} → {fine:?}");
        }
        manifest.push(export(name, &written, shape, TOLERANCE));
    }
    let path = export_dir().join("manifest-models.json");
    std::fs::write(path, serde_json::to_string_pretty(&json!({"cases": manifest})).unwrap()).unwrap();
}

#[test]
fn adaptive_meshes_are_as_valid_and_follow_trims() {
    for (name, doc, shape) in model_cases() {
        let surface = surface_of(&doc);
        // A chord height of 3/1000 of the surface's size.
        let size = regular(surface.as_ref(), 8, 8, MeshOptions { uv: false }).unwrap().bounds().unwrap().diagonal();
        let tolerance = AdaptiveTolerance { chord_height: 3e-3 * size, normal_angle: 0.3, max_depth: 6 };
        let mesh = |uv| adaptive(surface.as_ref(), (8, 8), tolerance, MeshOptions { uv }).unwrap();
        let (with_uv, plain) = (mesh(true), mesh(false));
        let by_index = index_verdict(&plain);
        if let Shape::Closed(_) = shape {
            assert!(by_index.closed() && by_index.misoriented_edges == 0, "adaptive {name}: {by_index:?}");
        }
        let obj = common::bytes(|out| obj::write_obj(&with_uv, name, out));
        let stl = common::bytes(|out| stl::write_stl_binary(&plain, out));
        let v = check_file(&format!("adaptive {name}.obj"), "obj", &obj, shape, TOLERANCE);
        check_file(&format!("adaptive {name}.stl"), "stl", &stl, shape, TOLERANCE);
        println!("adaptive {name:24} {} triangles, volume {:.6}, area {:.6}", plain.triangles.len(), v.volume, v.area);
    }
}

/// What each example scene's surface is (scenes of curves only have none).
fn scene_shape(scene: &str) -> Option<Shape> {
    let open = |loops, orientable| Shape::Open { loops, orientable, area: None };
    Some(match scene {
        "apple" | "cylinder_after" | "cylinder_animated" | "cylinder_before" | "surface_of_revolution" => open(2, true),
        "bezier_surface" | "coons_patch" | "plane_after" | "plane_animated" | "plane_before" | "seashell" => {
            open(1, true)
        }
        "trimmed_surface" => open(2, true),
        // One triangle: one boundary loop of three edges.
        "bezier_triangle_net" | "gerbs_triangle_locals" => open(1, true),
        "mobius" => open(1, false),
        "klein_bottle" => Shape::ClosedNonOrientable,
        "blending_sphere_animated"
        | "blending_sphere_moved"
        | "blending_torus_local_patches"
        | "nurbs_torus"
        | "sweep_trefoil"
        | "torus_after"
        | "torus_animated"
        | "torus_before"
        | "torus_gaussian_curvature"
        | "subdivision_surfaces" => Shape::Closed(None),
        "beating_heart" | "bspline_polygon" | "heart_local_curves" | "heart_transformed" | "rose_and_blending_copy" => {
            return None;
        }
        other => panic!("examples/scenes/{other}.json is new: say what its surface is in scene_shape"),
    })
}

#[test]
fn every_example_scene_surface_exports_as_a_valid_mesh() {
    let dir = format!("{}/../../examples/scenes", env!("CARGO_MANIFEST_DIR"));
    let mut paths: Vec<_> = std::fs::read_dir(&dir).unwrap().map(|e| e.unwrap().path()).collect();
    paths.sort();
    let mut manifest = Vec::new();
    for path in paths {
        let scene = path.file_stem().unwrap().to_str().unwrap().to_string();
        let doc = SceneOrShape::from_json(&std::fs::read_to_string(&path).unwrap()).unwrap().into_scene();
        let expected = scene_shape(&scene);
        let mut surfaces = 0;
        for (k, object) in doc.objects.iter().enumerate() {
            let ShapeDocument::Surface(s) = &object.shape else { continue };
            let AnySurface::D3(surface) = s.build().unwrap() else { panic!("{scene}: a 3-D surface") };
            let shape = expected.unwrap_or_else(|| panic!("{scene} has a surface: say what it is in scene_shape"));
            let name = format!("scene_{scene}_{k}");
            // The scene's density, at most 32 cells a side to keep the debug-build test quick.
            let written = files(&name, surface.as_ref(), object.style.density.unwrap_or(64).min(32));
            for (ext, bytes) in &written {
                check_file(&format!("{name}.{ext}"), ext, bytes, shape, TOLERANCE);
            }
            manifest.push(export(&name, &written, shape, TOLERANCE));
            surfaces += 1;
        }
        assert_eq!(surfaces > 0, expected.is_some(), "{scene}");
    }
    let path = export_dir().join("manifest-scenes.json");
    std::fs::write(path, serde_json::to_string_pretty(&json!({"cases": manifest})).unwrap()).unwrap();
}
