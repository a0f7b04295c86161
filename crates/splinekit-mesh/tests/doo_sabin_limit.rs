//! The Doo–Sabin limit points and normals (`doo_sabin_limit_mesh`) against independent
//! truth: on a regular closed grid (a torus) the biquadratic B-spline surface built with
//! splinekit's own B-spline surface; at an extraordinary vertex, the mesh of repeated
//! global steps, whose faces around the vertex close in on the limit point and flatten
//! onto the limit tangent plane.

use splinekit::Point;
use splinekit::surface::{BSplineSurface, Surface};
use splinekit_mesh::doo_sabin_limit::doo_sabin_limit_mesh;
use splinekit_mesh::subdivision_surface::{PolygonMesh, SurfaceScheme};

fn pt(p: [f64; 3]) -> Point<3> {
    Point::<3>::from(p)
}

/// A bumpy torus of nu × nv quads, counter-clockwise seen from outside: every vertex of
/// valence 4, every face a quad, no border.
fn torus(nu: usize, nv: usize) -> PolygonMesh {
    let mut vertices = Vec::new();
    for j in 0..nv {
        for i in 0..nu {
            let (t, f) = (std::f64::consts::TAU * i as f64 / nu as f64, std::f64::consts::TAU * j as f64 / nv as f64);
            let r = 1.0 + 0.15 * ((3 * i + 5 * j) as f64).sin();
            let ring = 3.0 + r * f.cos();
            vertices.push([ring * t.cos(), ring * t.sin(), r * f.sin()]);
        }
    }
    let id = |i: usize, j: usize| ((j % nv) * nu + i % nu) as u32;
    let faces = (0..nv)
        .flat_map(|j| (0..nu).map(move |i| vec![id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)]))
        .collect();
    PolygonMesh { vertices, faces }
}

/// On a regular grid the Doo–Sabin limit is the uniform biquadratic B-spline surface, and
/// a vertex's limit point is that surface at the centre of the patch whose middle control
/// point the vertex is (knots −2..3, span [0, 1], centre (½, ½)): position to 1e-14,
/// normal to 1e-13, pointing outwards.
#[test]
fn regular_vertices_are_the_biquadratic_bspline_at_their_patch_centre() {
    let (nu, nv) = (9, 7);
    let mesh = torus(nu, nv);
    let limit = doo_sabin_limit_mesh(&mesh).unwrap();
    let knots: Vec<f64> = (-2..=3).map(f64::from).collect();
    for j in 0..nv {
        for i in 0..nu {
            let net: Vec<Vec<Point<3>>> = (0..3)
                .map(|a| {
                    (0..3).map(|b| pt(mesh.vertices[((j + nv + b - 1) % nv) * nu + (i + nu + a - 1) % nu])).collect()
                })
                .collect();
            let s = BSplineSurface::new((2, 2), knots.clone(), knots.clone(), net, (false, false)).unwrap();
            let v = j * nu + i;
            let (p, n) = (pt(limit.positions[v]), pt(limit.normals[v]));
            assert!((p - s.point(0.5, 0.5)).norm() < 1e-14, "vertex {v}: {p:?} vs {:?}", s.point(0.5, 0.5));
            let expected = s.normal(0.5, 0.5).unwrap();
            assert!((n - expected).norm() < 1e-13, "vertex {v}: normal {n:?} vs {expected:?}");
            let axis = Point::<3>::new(p.x, p.y, 0.0).normalize() * 3.0;
            assert!(n.dot(&(p - axis)) > 0.0, "vertex {v}: the normal points inwards");
        }
    }
    // Faces and order as given.
    assert_eq!(limit.positions.len(), mesh.vertices.len());
    assert!(limit.faces.iter().zip(&mesh.faces).all(|(a, b)| a.iter().map(|c| c.0).eq(b.iter().copied())));
}

/// A pentagonal bipyramid of triangles, its vertices pushed about: the apices have
/// valence 5, their vertex faces are non-planar pentagons.
fn bipyramid() -> PolygonMesh {
    let mut vertices = vec![[0.1, -0.05, 1.3], [0.05, 0.1, -1.1]];
    for k in 0..5 {
        let a = std::f64::consts::TAU * k as f64 / 5.0;
        let r = 1.0 + 0.2 * (k as f64 * 2.3).sin();
        vertices.push([r * a.cos(), r * a.sin(), 0.25 * (k as f64 * 1.7).cos()]);
    }
    let mut faces = Vec::new();
    for k in 0..5u32 {
        let (a, b) = (2 + k, 2 + (k + 1) % 5);
        faces.push(vec![0, a, b]);
        faces.push(vec![1, b, a]);
    }
    PolygonMesh { vertices, faces }
}

/// At an apex (valence 5) the limit point and normal against global subdivision: after
/// one step the apex's vertex face is a face g of the new mesh, and each later step keeps
/// the face descended from it at index g (Doo–Sabin writes the faces' own faces first, in
/// order). Its centroid stays the limit point exactly; every vertex of the faces touching
/// it closes in on the point and onto the tangent plane, its height over the plane falling
/// relative to its distance (like 2⁻ᵏ on a smooth surface) — a wrong normal would leave
/// that ratio at the sine of its error.
#[test]
fn an_extraordinary_vertex_is_where_global_subdivision_converges() {
    let mesh = bipyramid();
    let limit = doo_sabin_limit_mesh(&mesh).unwrap();
    let (c, n) = (pt(limit.positions[0]), pt(limit.normals[0]));
    assert!(n.z > 0.9, "the apex's normal points up: {n:?}");
    let level1 = mesh.subdivide(SurfaceScheme::DooSabin, 1).unwrap();
    // The apex's corner points are the new vertices of its faces' corners 0 (faces 0, 2, …).
    let mut offset = 0u32;
    let mut apex_corners = Vec::new();
    for f in &mesh.faces {
        if let Some(k) = f.iter().position(|&v| v == 0) {
            apex_corners.push(offset + k as u32);
        }
        offset += f.len() as u32;
    }
    apex_corners.sort();
    let g = level1
        .faces
        .iter()
        .position(|f| {
            let mut s = f.clone();
            s.sort();
            s == apex_corners
        })
        .expect("the apex's vertex face");
    let mut m = level1;
    let mut ratios = Vec::new();
    for level in 2..=7 {
        m = m.subdivide(SurfaceScheme::DooSabin, 1).unwrap();
        let face = &m.faces[g];
        let centroid =
            face.iter().fold(Point::<3>::zeros(), |a, &v| a + pt(m.vertices[v as usize])) / face.len() as f64;
        assert!((centroid - c).norm() < 1e-14, "level {level}: centroid {centroid:?} vs {c:?}");
        let touching: Vec<u32> =
            m.faces.iter().filter(|f| f.iter().any(|v| face.contains(v))).flatten().copied().collect();
        let ratio = touching
            .iter()
            .map(|&v| {
                let d = pt(m.vertices[v as usize]) - c;
                d.dot(&n).abs() / d.norm()
            })
            .fold(0.0, f64::max);
        ratios.push(ratio);
    }
    // Halving a level, give or take (0.52, 0.34, 0.19, 0.095, 0.048, 0.024).
    assert!(ratios.windows(2).all(|w| w[1] < 0.7 * w[0]), "{ratios:?}");
    assert!(ratios[5] < ratios[0] / 15.0 && ratios[5] < 0.03, "{ratios:?}");
}

/// An open border has no vertex faces: the limit of a border vertex is refused by name.
#[test]
fn a_border_vertex_is_refused() {
    let mut mesh = torus(6, 5);
    mesh.faces.truncate(12);
    let err = doo_sabin_limit_mesh(&mesh).unwrap_err().to_string();
    assert!(err.contains("vertices[0]") && err.contains("open border"), "{err}");
}
