//! Subdivision surfaces: counts, closedness and orientation over several steps, the regular
//! rules against the tensor-product B-spline subdivision masks, boundaries, bad meshes.

use splinekit_mesh::subdivision_surface::{PolygonMesh, SurfaceScheme, read_obj_polygons, write_obj_polygons};

/// The kernel's example cube [−1, 1]³ (outward counter-clockwise faces).
fn cube() -> PolygonMesh {
    let cage = splinekit::subdivision::surface::Cage::cube();
    let vertices = cage.vertices.iter().map(|p| [p.x, p.y, p.z]).collect();
    let faces = (0..cage.face_count()).map(|f| cage.face(f).to_vec()).collect();
    PolygonMesh { vertices, faces }
}

fn grid(n: usize, z: impl Fn(usize, usize) -> f64) -> PolygonMesh {
    let vertices = (0..n * n).map(|k| [(k / n) as f64, (k % n) as f64, z(k / n, k % n)]).collect();
    let mut faces = Vec::new();
    for i in 0..n - 1 {
        for j in 0..n - 1 {
            let v = |a: usize, b: usize| (a * n + b) as u32;
            faces.push(vec![v(i, j), v(i + 1, j), v(i + 1, j + 1), v(i, j + 1)]);
        }
    }
    PolygonMesh { vertices, faces }
}

#[test]
fn catmull_clark_on_the_cube_counts_stays_closed_and_rounds_off() {
    let c = cube();
    let one = c.catmull_clark().unwrap();
    assert_eq!((one.vertices.len(), one.faces.len()), (8 + 6 + 12, 24));
    let m = c.subdivide(SurfaceScheme::CatmullClark, 4).unwrap();
    assert_eq!(m.faces.len(), 6 * 4usize.pow(4));
    assert_eq!(m.boundary_edge_count(), 0);
    m.validate().unwrap();
    let radii: Vec<f64> = m.vertices.iter().map(|p| (p[0] * p[0] + p[1] * p[1] + p[2] * p[2]).sqrt()).collect();
    let (lo, hi) = radii.iter().fold((f64::MAX, 0.0f64), |(a, b), &r| (a.min(r), b.max(r)));
    assert!(lo > 0.75 && hi < 1.1 && hi - lo < 0.25, "radii {lo}..{hi}");
    // The triangulated mesh is closed and its normals point outwards.
    let t = m.triangulate();
    assert!(t.boundary_edges().is_empty());
    for (p, n) in t.positions.iter().zip(&t.normals) {
        assert!(p[0] * n[0] + p[1] * n[1] + p[2] * n[2] > 0.0);
    }
}

#[test]
fn catmull_clark_on_a_regular_grid_applies_the_bicubic_b_spline_masks() {
    let z = |i: usize, j: usize| ((i * 7 + j * 3) % 5) as f64 * 0.3 + (i * j) as f64 * 0.01;
    let n = 7;
    let m = grid(n, z).catmull_clark().unwrap();
    // Interior vertex points: [1 6 1]/8 ⊗ [1 6 1]/8; edge points [1 6 1]/8 ⊗ [1 1]/2 (interior edges).
    let w = [1.0 / 8.0, 6.0 / 8.0, 1.0 / 8.0];
    for i in 1..n - 1 {
        for j in 1..n - 1 {
            let mut want = 0.0;
            for a in 0..3 {
                for b in 0..3 {
                    want += w[a] * w[b] * z(i + a - 1, j + b - 1);
                }
            }
            let got = m.vertices[i * n + j][2];
            assert!((got - want).abs() < 1e-14, "vertex ({i}, {j}): {got} vs {want}");
            // The interior edge (i, j)–(i + 1, j) has the point at x = i + ½, y = j.
            if i + 1 < n - 1 {
                let want_e: f64 = (0..3).map(|b| w[b] * 0.5 * (z(i, j + b - 1) + z(i + 1, j + b - 1))).sum();
                let e = m.vertices.iter().find(|p| p[0] == i as f64 + 0.5 && p[1] == j as f64).unwrap();
                assert!((e[2] - want_e).abs() < 1e-14, "edge ({i}, {j})");
            }
        }
    }
    // Boundary vertices follow the cubic curve rule along the border: (1 6 1)/8.
    let b = m.vertices[3];
    assert!((b[2] - (z(0, 2) + 6.0 * z(0, 3) + z(0, 4)) / 8.0).abs() < 1e-14);
}

#[test]
fn doo_sabin_counts_orientation_and_the_biquadratic_masks() {
    let c = cube();
    let one = c.doo_sabin().unwrap();
    assert_eq!((one.vertices.len(), one.faces.len()), (24, 6 + 12 + 8));
    let m = c.subdivide(SurfaceScheme::DooSabin, 4).unwrap();
    m.validate().unwrap();
    assert_eq!(m.boundary_edge_count(), 0);
    // Corners of a regular quad: 9/16, 3/16, 3/16, 1/16 (Chaikin ⊗ Chaikin).
    let z = |i: usize, j: usize| (i * i + 3 * j) as f64 * 0.1;
    let g = grid(4, z).doo_sabin().unwrap();
    let p = g.vertices[0]; // face (0,0), corner (0,0)
    let want = (9.0 * z(0, 0) + 3.0 * z(1, 0) + 3.0 * z(0, 1) + z(1, 1)) / 16.0;
    assert!((p[2] - want).abs() < 1e-14 && (p[0] - 0.25).abs() < 1e-15 && (p[1] - 0.25).abs() < 1e-15);
    // Open grids: faces, interior-edge faces and interior-vertex faces only.
    assert_eq!(g.faces.len(), 9 + 12 + 4);
}

#[test]
fn bad_meshes_are_refused_and_obj_round_trips() {
    let mut c = cube();
    c.faces[1].reverse();
    let e = c.catmull_clark().unwrap_err().to_string();
    assert!(e.contains("faces[") && e.contains("oriented"), "{e}");
    let bad = PolygonMesh { vertices: vec![[0.0; 3]; 3], faces: vec![vec![0, 1]] };
    assert!(bad.doo_sabin().unwrap_err().to_string().contains("faces[0]"));
    let mut text = Vec::new();
    write_obj_polygons(&cube(), "cube", &mut text).unwrap();
    let text = String::from_utf8(text).unwrap();
    assert_eq!(read_obj_polygons(&text).unwrap(), cube());
    assert!(read_obj_polygons("v 0 0 0\nf 1 2 3\n").unwrap_err().contains("line 2"));
}

/// The limit mesh's triangles along sharp creases: every corner of every face keeps its
/// position and its own normal, the cage's vertices come first in order, and a vertex is
/// copied once for each other normal it has (corners on one side of a crease share it):
/// the cube with its four top edges sharp, after one step.
#[test]
fn limit_triangles_split_vertices_once_per_crease_side() {
    use splinekit::Point;
    use splinekit::subdivision::surface::{Cage, Crease, Scheme, SubdivisionSurface};
    use splinekit_mesh::limit_mesh::limit_mesh;

    let c = cube();
    let cage = Cage::new(c.vertices.iter().map(|p| Point::<3>::new(p[0], p[1], p[2])).collect(), &c.faces)
        .with_creases(
            [(4, 5), (5, 7), (7, 6), (6, 4)].map(|(a, b)| Crease { a, b, sharpness: f64::INFINITY }).to_vec(),
        );
    let s = SubdivisionSurface::new(cage, Scheme::CatmullClark, false).unwrap().subdivide(1).unwrap();
    let m = limit_mesh(&s).unwrap();
    let t = m.triangles();
    let vertices = s.cage().vertices.len();
    assert_eq!(&t.positions[..vertices], &m.positions[..]);
    assert!(m.normals.len() > vertices, "the sharp edges give corners normals of their own");
    // Each (position, normal) pair once.
    let mut pairs: Vec<_> =
        t.positions.iter().zip(&t.normals).map(|(p, n)| (p.map(f64::to_bits), n.map(f64::to_bits))).collect();
    let count = pairs.len();
    pairs.sort();
    pairs.dedup();
    assert_eq!(pairs.len(), count, "no vertex copied twice with one normal");
    // Every triangle corner is a face corner: its position and normal.
    let mut fan = t.triangles.iter();
    for face in &m.faces {
        for k in 1..face.len() - 1 {
            let tri = fan.next().expect("one triangle per fan step");
            for (id, &(v, n)) in tri.iter().zip([face[0], face[k], face[k + 1]].iter()) {
                assert_eq!(t.positions[*id as usize], m.positions[v as usize]);
                assert_eq!(t.normals[*id as usize], m.normals[n as usize]);
            }
        }
    }
    assert!(fan.next().is_none());
}

/// An open cage around an extraordinary vertex: vertex 0 (valence 5, four quads and a
/// triangle around it) inside, its ring on the boundary, off the plane by a little.
fn open_fan() -> PolygonMesh {
    let angle = |k: f64| std::f64::consts::TAU * k / 5.0;
    let mut vertices = vec![[0.0, 0.0, 0.1]];
    vertices.extend((0..5).map(|k| {
        let (s, c) = angle(k as f64).sin_cos();
        [c, s, 0.3 * (1.3 * k as f64).sin()]
    }));
    vertices.extend((0..4).map(|k| {
        let (s, c) = angle(k as f64 + 0.5).sin_cos();
        [1.7 * c, 1.7 * s, 0.2 * (0.7 * k as f64).cos()]
    }));
    let mut faces: Vec<Vec<u32>> = (0..4).map(|k| vec![0, k + 1, k + 6, k + 2]).collect();
    faces.push(vec![0, 5, 1]);
    PolygonMesh { vertices, faces }
}

/// The vertices' bits and the faces.
fn bits(m: &PolygonMesh) -> (Vec<[u64; 3]>, Vec<Vec<u32>>) {
    (m.vertices.iter().map(|p| p.map(f64::to_bits)).collect(), m.faces.clone())
}

/// Each step's output depends on the input only, not on the hash maps' seeds (foldhash
/// seeds every map anew, so two calls in one process differ in any order taken from one).
#[test]
fn both_schemes_give_the_same_bits_on_every_call() {
    for scheme in [SurfaceScheme::CatmullClark, SurfaceScheme::DooSabin] {
        let first = bits(&open_fan().subdivide(scheme, 3).unwrap());
        for _ in 0..8 {
            let again = bits(&open_fan().subdivide(scheme, 3).unwrap());
            assert!(again == first, "{scheme:?}: the output changed between calls");
        }
    }
}
