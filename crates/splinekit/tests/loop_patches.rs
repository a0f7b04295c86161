//! The Loop limit as Bézier patches (`bezier_patches` with `loop_bezier`): regular
//! triangles as exact (4, 4) patches with a collapsed edge, checked against exact
//! evaluation through the atlas chart; irregular ones refined locally, with the deviation
//! falling by Loop's subdominant eigenvalue per level; borders exact through phantom points.

mod common;

use splinekit::Point;
use splinekit::subdivision::surface::atlas::LimitAtlas;
use splinekit::subdivision::surface::bezier_patches::{limit_patches, limit_patches_within};
use splinekit::subdivision::surface::loop_bezier::{loop_bezier_patch, quartic_at};
use splinekit::subdivision::surface::{Cage, Scheme, SubdivisionSurface};

fn p(x: f64, y: f64, z: f64) -> Point<3> {
    Point::<3>::new(x, y, z)
}

/// A bumpy triangulated n × n grid (interior vertices of valence 6, a boundary whose
/// vertices other than the corners have three triangles).
fn bumpy_grid(n: u32) -> SubdivisionSurface {
    let vs: Vec<Point<3>> = (0..n * n)
        .map(|k| {
            let (i, j) = (k % n, k / n);
            p(i as f64 + 0.1 * j as f64, j as f64, ((i * 7 + j * 3) % 5) as f64 * 0.3)
        })
        .collect();
    let mut faces = Vec::new();
    for j in 0..n - 1 {
        for i in 0..n - 1 {
            let (a, b, c, d) = (j * n + i, j * n + i + 1, (j + 1) * n + i + 1, (j + 1) * n + i);
            faces.push(vec![a, b, c]);
            faces.push(vec![a, c, d]);
        }
    }
    SubdivisionSurface::new(Cage::new(vs, &faces), Scheme::Loop, false).unwrap()
}

/// The icosahedron on the unit sphere (twelve vertices of valence 5).
fn icosahedron() -> SubdivisionSurface {
    SubdivisionSurface::new(common::cages::icosahedron(), Scheme::Loop, false).unwrap()
}

/// A small deterministic generator of samples in [0, 1).
fn lcg(state: &mut u64) -> f64 {
    *state = state.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
    (*state >> 11) as f64 / (1u64 << 53) as f64
}

/// Every regular triangle's (4, 4) patch is its limit in the atlas chart, at random
/// (s, t), on the edges and within 10⁻⁹ of the collapsed edge t = 1, to 10⁻¹²; the
/// collapsed edge is one point, the limit point of the corner c₂.
#[test]
fn regular_triangles_are_exact_quartic_patches() {
    let s = bumpy_grid(7);
    let atlas = LimitAtlas::new(s.clone());
    let (cage, topo) = (s.cage(), s.topology());
    let mut rng = 7u64;
    let mut regular = 0;
    for f in 0..cage.face_count() as u32 {
        let Some(net) = loop_bezier_patch(cage, topo, f) else { continue };
        regular += 1;
        let mut params: Vec<(f64, f64)> = (0..20).map(|_| (lcg(&mut rng), lcg(&mut rng))).collect();
        params.extend([(0.0, 0.0), (1.0, 0.0), (0.5, 0.0), (0.0, 0.5), (1.0, 0.5), (0.3, 1.0 - 1e-9), (0.7, 1.0)]);
        for (a, b) in params {
            // The atlas chart (its u = f + 1 is the next chart's start: evaluate directly).
            let exact = if a < 1.0 {
                atlas.sample(f as f64 + a, b).unwrap().position
            } else {
                s.evaluate(f as usize, a * (1.0 - b), b).unwrap().position
            };
            let d = (quartic_at(&net, a, b) - exact).norm();
            assert!(d < 1e-12, "face {f} at ({a}, {b}): {d:e}");
        }
        let apex = s.limit_frame(cage.face(f as usize)[2]).unwrap().position;
        assert!(net.iter().all(|row| (row[4] - apex).norm() < 1e-13), "face {f}: edge t = 1 not collapsed");
        assert!(net.iter().all(|row| row[4] == net[0][4]));
    }
    // Every vertex but the grid's four corners is regular: the 5 × 5 interior ones of
    // valence 6 and the border ones with three triangles (phantom points beyond the
    // border). Of the 72 triangles, 6 touch a corner: 2 at (0, 0) and at (6, 6), 1 at the
    // two others.
    assert_eq!(regular, 2 * 6 * 6 - 6);
}

/// Loop's subdominant eigenvalue at a smooth vertex of valence n.
fn lambda(n: usize) -> f64 {
    0.375 + 0.25 * (2.0 * std::f64::consts::PI / n as f64).cos()
}

/// The icosahedron: every triangle has three valence-5 corners, so at each level every
/// irregular triangle keeps its 3 corner children irregular and its middle one regular at
/// level 1, and then 3 regular children and 1 irregular (the one at the vertex): depth d
/// gives 20 + 180(d − 1) quartic patches and 60 stand-ins, whose deviation falls by about
/// λ(5) ≈ 0.45 a level. Within 10⁻⁴ and 10⁻⁶ every stand-in is within the tolerance,
/// at the fewest levels that reach it.
#[test]
fn icosahedron_within_tolerance() {
    let s = icosahedron();
    let mut deviations = Vec::new();
    for d in 1..=6 {
        let p = limit_patches(&s, d).unwrap();
        assert_eq!((p.quartic.len(), p.bilinear.len(), p.bicubic.len(), p.depth()), (20 + 180 * (d - 1), 60, 0, d));
        deviations.push(p.max_deviation);
    }
    eprintln!("icosahedron deviation by depth: {deviations:?}");
    let ratio = deviations[5] / deviations[4];
    assert!((ratio / lambda(5) - 1.0).abs() < 0.1, "ratio {ratio} vs λ = {}", lambda(5));
    for tolerance in [1e-4, 1e-6] {
        let p = limit_patches_within(&s, tolerance).unwrap();
        let depth = p.depth();
        assert!(p.max_deviation <= tolerance && p.max_deviation > 0.0);
        assert!(
            depth >= 2 && limit_patches(&s, depth - 1).unwrap().max_deviation > tolerance,
            "{tolerance}: depth {depth} is not the fewest"
        );
        assert_eq!((p.quartic.len(), p.bilinear.len()), (20 + 180 * (depth - 1), 60));
        eprintln!("icosahedron within {tolerance:e}: depth {depth}, {} quartic + 60 stand-ins", p.quartic.len());
    }
}

/// Along a border the triangles are exact box-spline patches (phantom points beyond the
/// border); only the triangles at the grid's four corners, whose vertices are not regular
/// crease vertices, stay stand-ins: each keeps one child at its corner, 6 at every depth,
/// with the deviation falling level by level, and the tolerance met.
#[test]
fn borders_are_exact_and_only_corners_need_stand_ins() {
    let s = bumpy_grid(4);
    let mut deviations = Vec::new();
    for d in 1..=4 {
        let p = limit_patches(&s, d).unwrap();
        assert_eq!(p.bilinear.len(), 6, "depth {d}");
        deviations.push(p.max_deviation);
    }
    assert!(deviations.windows(2).all(|w| w[1] < 0.8 * w[0]), "{deviations:?}");
    let p = limit_patches_within(&s, 1e-3).unwrap();
    assert!(p.max_deviation <= 1e-3 && p.bilinear.len() == 6);
    eprintln!(
        "open grid within 1e-3: depth {}, {} quartic + {} stand-ins; deviations by depth {deviations:?}",
        p.depth(),
        p.quartic.len(),
        p.bilinear.len()
    );
}
