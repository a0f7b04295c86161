//! Blending surfaces over triangulations, triangle atlases and height-field interpolants
//! against independent truth: the affine transition between neighbouring triangles of the
//! equilateral flat structure (edge continuity of values and derivatives), finite
//! differences, the locals' own evaluation at the vertices, bit-identical evaluation outside
//! a moved local's star, the degenerate tensor patch, and polynomial reproduction.

use splinekit::Point;
use splinekit::basis::BFunction;
use splinekit::frame::Affine;
use splinekit::surface::Surface;
use splinekit::triangle::{
    BezierTriangle, Triangle, TriangleAtlas, TriangulatedSurface, TriangulationBlend, degenerate_patch_parameters,
};
use splinekit::triangulation::{Delaunay, HeightInterpolant, height_pieces};

fn sphere_blend() -> (TriangulatedSurface, TriangulationBlend) {
    let m = TriangulatedSurface::icosphere(1.0, 1).unwrap();
    let b = TriangulationBlend::new(&m, 2, BFunction::erbs_default()).unwrap();
    (m, b)
}

/// Every interior edge as (τ, m, τ', m'): τ[m] → τ[m+1] is τ'[m'+1] → τ'[m'].
fn shared_edges(tris: &[[u32; 3]]) -> Vec<(usize, usize, usize, usize)> {
    let mut map = std::collections::HashMap::new();
    for (t, tri) in tris.iter().enumerate() {
        for m in 0..3 {
            map.insert((tri[m], tri[(m + 1) % 3]), (t, m));
        }
    }
    let mut out = Vec::new();
    for (t, tri) in tris.iter().enumerate() {
        for m in 0..3 {
            let (a, b) = (tri[m], tri[(m + 1) % 3]);
            if a < b
                && let Some(&(t2, m2)) = map.get(&(b, a))
            {
                out.push((t, m, t2, m2));
            }
        }
    }
    out
}

/// The map λ' ↦ λ from τ' to τ across their common edge in the flat structure (both
/// equilateral, d = a + b − c): λ_a = λ'_a + λ'_d, λ_b = λ'_b + λ'_d, λ_c = −λ'_d.
fn transition(m: usize, m2: usize, lam2: [f64; 3]) -> [f64; 3] {
    let (b2, a2, d2) = (lam2[m2], lam2[(m2 + 1) % 3], lam2[(m2 + 2) % 3]);
    let mut lam = [0.0; 3];
    lam[m] = a2 + d2;
    lam[(m + 1) % 3] = b2 + d2;
    lam[(m + 2) % 3] = -d2;
    lam
}

/// Values and first and second partials of S_τ' and of S_τ ∘ A at edge points agree.
fn check_edges(b: &TriangulationBlend, value_tol: f64, first_tol: f64, second_tol: f64) {
    let tris = b.triangles().to_vec();
    let edges = shared_edges(&tris);
    assert!(!edges.is_empty());
    let (mut e0, mut e1, mut e2) = (0.0f64, 0.0f64, 0.0f64);
    for &(t, m, t2, m2) in &edges {
        for s in [0.15, 0.4, 0.5, 0.77] {
            // The point at fraction s from τ[m] = τ'[m'+1] towards τ[m+1] = τ'[m'].
            let mut lam2 = [0.0; 3];
            lam2[(m2 + 1) % 3] = 1.0 - s;
            lam2[m2] = s;
            let lam = transition(m, m2, lam2);
            let (tri, tri2) = (b.triangle(t), b.triangle(t2));
            let mut p = [Point::<3>::zeros(); 9];
            let mut q = [Point::<3>::zeros(); 9];
            tri.eval_partials(lam[0], lam[1], 2, 2, &mut p);
            tri2.eval_partials(lam2[0], lam2[1], 2, 2, &mut q);
            // ∂λ/∂u' and ∂λ/∂v' through the (linear part of the) transition.
            let du = {
                let a = transition(m, m2, [1.0, 0.0, -1.0]);
                [a[0], a[1]]
            };
            let dv = {
                let a = transition(m, m2, [0.0, 1.0, -1.0]);
                [a[0], a[1]]
            };
            // p[i*3+j] = ∂^{i+j}/∂u^i∂v^j.
            let grad = |x: [f64; 2]| p[3] * x[0] + p[1] * x[1];
            let hess = |x: [f64; 2], y: [f64; 2]| {
                p[6] * (x[0] * y[0]) + p[4] * (x[0] * y[1] + x[1] * y[0]) + p[2] * (x[1] * y[1])
            };
            e0 = e0.max((p[0] - q[0]).norm());
            e1 = e1.max((grad(du) - q[3]).norm()).max((grad(dv) - q[1]).norm());
            e2 = e2
                .max((hess(du, du) - q[6]).norm())
                .max((hess(du, dv) - q[4]).norm())
                .max((hess(dv, dv) - q[2]).norm());
        }
    }
    assert!(e0 < value_tol, "values differ by {e0:e} across edges");
    assert!(e1 < first_tol, "first partials differ by {e1:e} across edges");
    assert!(e2 < second_tol, "second partials differ by {e2:e} across edges");
    eprintln!("edges: values {e0:.1e}, first {e1:.1e}, second {e2:.1e}");
}

#[test]
fn sphere_blend_is_smooth_across_edges() {
    let (_, b) = sphere_blend();
    check_edges(&b, 1e-14, 1e-10, 1e-8);
}

#[test]
fn torus_blend_is_smooth_across_edges_and_close_to_the_torus() {
    let m = TriangulatedSurface::torus(3.0, 1.0, 16, 8).unwrap();
    let b = TriangulationBlend::new(&m, 2, BFunction::erbs_default()).unwrap();
    check_edges(&b, 1e-13, 1e-10, 1e-8);
    // Distance to the torus: |(√(x² + y²) − 3, z)| = 1.
    let mut worst = 0.0f64;
    for t in 0..b.triangles().len() {
        let p = b.triangle(t).point(0.2, 0.3, 0.5);
        worst = worst.max((((p.x * p.x + p.y * p.y).sqrt() - 3.0).hypot(p.z) - 1.0).abs());
    }
    assert!(worst < 0.03, "{worst}");
}

#[test]
fn polynomial_bfunction_is_c1_across_edges_but_not_c2() {
    let m = TriangulatedSurface::icosphere(1.0, 1).unwrap();
    let b = TriangulationBlend::new(&m, 2, BFunction::polynomial(1).unwrap()).unwrap();
    check_edges(&b, 1e-14, 1e-10, 1e9);
}

#[test]
fn partials_match_finite_differences() {
    let (_, b) = sphere_blend();
    let t = b.triangle(11);
    let (u, v, h) = (0.31, 0.27, 1e-5);
    let mut p = [Point::<3>::zeros(); 9];
    t.eval_partials(u, v, 2, 2, &mut p);
    let f = |u: f64, v: f64| t.point(u, v, 1.0 - u - v);
    let su = (f(u + h, v) - f(u - h, v)) / (2.0 * h);
    let sv = (f(u, v + h) - f(u, v - h)) / (2.0 * h);
    let suv = (f(u + h, v + h) - f(u + h, v - h) - f(u - h, v + h) + f(u - h, v - h)) / (4.0 * h * h);
    assert!((su - p[3]).norm() < 1e-8, "{}", (su - p[3]).norm());
    assert!((sv - p[1]).norm() < 1e-8);
    assert!((suv - p[4]).norm() < 1e-5, "{}", (suv - p[4]).norm());
}

#[test]
fn interpolates_each_local_at_its_vertex() {
    let (m, b) = sphere_blend();
    for (t, tri) in m.triangles.iter().enumerate() {
        let s = b.triangle(t);
        for (corner, &i) in tri.iter().enumerate() {
            let mut c = [0.0; 3];
            c[corner] = 1.0;
            let i = i as usize;
            // The vertex itself, exactly, with the local's normal (the sphere's).
            assert_eq!(s.point(c[0], c[1], c[2]), b.origin(i).unwrap());
            assert!((b.origin(i).unwrap() - m.positions[i]).norm() < 1e-15);
            let n = s.normal(c[0], c[1], c[2]).unwrap();
            assert!((n - m.normals[i]).norm() < 1e-14, "{}", (n - m.normals[i]).norm());
            // Near it (within 1 − ρ) the surface is the local in its chart, every partial.
            let mut lam = [0.04; 3];
            lam[corner] = 0.92;
            let mut got = [Point::<3>::zeros(); 16];
            s.eval_partials(lam[0], lam[1], 3, 3, &mut got);
            // The local at ζ(λ), composed by finite differences of ζ would lose digits: use
            // the value and the first partials by the chain rule with ζ's difference quotient.
            let zeta = |u: f64, v: f64| b.chart_point(t, corner, u, v);
            let mut lp = [Point::<3>::zeros(); 4];
            b.local_partials(i, zeta(lam[0], lam[1]), 1, 1, &mut lp).unwrap();
            assert!((got[0] - lp[0]).norm() < 1e-14);
            let h = 1e-6;
            let dz_du = (zeta(lam[0] + h, lam[1]) - zeta(lam[0] - h, lam[1])) / (2.0 * h);
            let via_chart = lp[2] * dz_du.x + lp[1] * dz_du.y;
            assert!((via_chart - got[4]).norm() < 1e-8, "{}", (via_chart - got[4]).norm());
        }
    }
}

#[test]
fn valence_six_corners_have_every_partial_of_the_local() {
    // On the torus every vertex has valence 6: ζ = z, an affine map of (u, v), so the
    // surface's partials at the corner are the local's, pulled back exactly.
    let m = TriangulatedSurface::torus(3.0, 1.0, 12, 6).unwrap();
    let b = TriangulationBlend::new(&m, 2, BFunction::erbs_default()).unwrap();
    let s = b.triangle(5);
    let i = m.triangles[5][0] as usize;
    let mut got = [Point::<3>::zeros(); 16];
    s.eval_partials(1.0, 0.0, 3, 3, &mut got);
    // z = λ_v + λ_w e^{iπ/3} turned by kπ/3, with λ_v = v, λ_w = 1 − u − v.
    let z0 = b.chart_point(5, 0, 1.0, 0.0);
    assert!(z0.norm() == 0.0);
    let zu = b.chart_point(5, 0, 0.0, 0.0) - b.chart_point(5, 0, 1.0, 0.0); // ∂z/∂u = −e^{iπ/3}·turn
    let zv = b.chart_point(5, 0, 0.0, 1.0) - b.chart_point(5, 0, 0.0, 0.0); // ∂z/∂v
    let zu = -zu;
    let mut l = [Point::<3>::zeros(); 16];
    b.local_partials(i, z0, 3, 3, &mut l).unwrap();
    // L(X, Y) quadratic: ∂²S/∂u∂v = L_XX zu.x zv.x + L_XY (zu.x zv.y + zu.y zv.x) + L_YY zu.y zv.y.
    let second = l[8] * (zu.x * zv.x) + l[5] * (zu.x * zv.y + zu.y * zv.x) + l[2] * (zu.y * zv.y);
    assert!((got[5] - second).norm() < 1e-12, "{}", (got[5] - second).norm());
    let first = l[4] * zu.x + l[1] * zu.y;
    assert!((got[4] - first).norm() < 1e-12);
    // Third partials of a quadratic pulled back affinely vanish.
    assert!(got[12].norm() < 1e-12 && got[15].norm() < 1e-12);
}

#[test]
fn weights_are_a_partition_of_unity() {
    let (_, b) = sphere_blend();
    for i in 0..=20 {
        for j in 0..=20 - i {
            let (u, v) = (i as f64 / 20.0, j as f64 / 20.0);
            let w = b.weights(u, v);
            assert!((w[0] + w[1] + w[2] - 1.0).abs() < 1e-15, "{w:?}: {:e}", w[0] + w[1] + w[2] - 1.0);
            assert!(w.iter().all(|x| (0.0..=1.0).contains(x)));
        }
    }
    assert_eq!(b.weights(1.0, 0.0), [1.0, 0.0, 0.0]);
    // Within 1 − ρ of a corner only its weight is non-zero.
    assert_eq!(b.weights(0.9, 0.05), [1.0, 0.0, 0.0]);
}

#[test]
fn moving_a_local_changes_the_surface_only_in_its_star() {
    let (m, b) = sphere_blend();
    let mut moved = b.clone();
    let i = 3;
    moved.set_frame(i, Affine::translation(Point::<3>::new(0.0, 0.0, 0.4))).unwrap();
    let mut inside_changed = false;
    for (t, tri) in m.triangles.iter().enumerate() {
        for (u, v) in [(0.2, 0.3), (0.5, 0.5), (0.05, 0.9), (1.0 / 3.0, 1.0 / 3.0)] {
            let (a, c) = (b.triangle(t).point(u, v, 1.0 - u - v), moved.triangle(t).point(u, v, 1.0 - u - v));
            if tri.contains(&(i as u32)) {
                inside_changed |= a != c;
            } else {
                assert_eq!(a, c, "triangle {t} is outside the star of {i}");
            }
        }
    }
    assert!(inside_changed);
    // The vertex moves with its local.
    let t = m.triangles.iter().position(|t| t[0] == i as u32).unwrap();
    assert_eq!(moved.triangle(t).point(1.0, 0.0, 0.0), b.origin(i).unwrap() + Point::<3>::new(0.0, 0.0, 0.4));
}

#[test]
fn affine_map_of_every_local_maps_the_surface() {
    let (m, b) = sphere_blend();
    let mut moved = b.clone();
    let g = Affine::rotation(Point::<3>::new(1.0, 2.0, 0.5), 0.7).unwrap().after(&Affine::uniform_scale(1.5));
    for i in 0..m.positions.len() {
        // Frames act about each local's origin: o + A(x − o) + b equals G x when b = G o − o.
        let o = b.origin(i).unwrap();
        let f = Affine { linear: g.linear, translation: g.apply_point(&o) - o };
        moved.set_frame(i, f).unwrap();
    }
    for t in [0, 17, 40, 79] {
        let p = b.triangle(t).point(0.3, 0.25, 0.45);
        let q = moved.triangle(t).point(0.3, 0.25, 0.45);
        assert!((g.apply_point(&p) - q).norm() < 1e-14, "{}", (g.apply_point(&p) - q).norm());
    }
}

#[test]
fn scattered_points_with_and_without_normals() {
    // Heights of a paraboloid on a jittered grid, triangulated in the plane.
    let mut pts = Vec::new();
    for i in 0..7 {
        for j in 0..7 {
            let (x, y) =
                (i as f64 / 6.0 + 0.013 * ((i * 7 + j) % 5) as f64, j as f64 / 6.0 + 0.011 * ((i + 3 * j) % 4) as f64);
            pts.push(Point::<2>::new(x, y));
        }
    }
    let d = Delaunay::new(&pts).unwrap();
    let f = |p: &Point<2>| 0.5 * (p.x * p.x + p.y * p.y);
    let positions: Vec<Point<3>> = pts.iter().map(|p| Point::<3>::new(p.x, p.y, f(p))).collect();
    let normals: Vec<Point<3>> = pts.iter().map(|p| Point::<3>::new(-p.x, -p.y, 1.0).normalize()).collect();
    let triangles: Vec<[u32; 3]> = d.triangles().iter().map(|t| t.map(|i| i as u32)).collect();
    for normals in [normals, Vec::new()] {
        let m = TriangulatedSurface { positions: positions.clone(), normals, triangles: triangles.clone() };
        let b = TriangulationBlend::new(&m, 2, BFunction::erbs_default()).unwrap();
        check_edges(&b, 1e-14, 1e-10, 1e-7);
        let (mut worst, mut inner) = (0.0f64, 0.0f64);
        for t in 0..triangles.len() {
            let p = b.triangle(t).point(0.3, 0.3, 0.4);
            let e = (p.z - 0.5 * (p.x * p.x + p.y * p.y)).abs();
            worst = worst.max(e);
            if triangles[t].iter().all(|&i| !b.valence(i as usize).1) {
                inner = inner.max(e);
            }
        }
        eprintln!("worst {worst:e}, away from the boundary {inner:e}");
        // On this irregular grid (spacing 1/6, curvature 1) the locals disagree tangentially
        // (see the module documentation): the blend stays within 0.02 of the paraboloid away
        // from the boundary, 0.05 at it where estimated normals are one-sided.
        assert!(inner < 0.02 && worst < 0.05, "{worst}, {inner} (normals given: {})", !m.normals.is_empty());
    }
}

#[test]
fn bad_meshes_are_refused_naming_the_field() {
    let mut m = TriangulatedSurface::icosphere(1.0, 0).unwrap();
    m.triangles[3] = [m.triangles[3][1], m.triangles[3][0], m.triangles[3][2]];
    let e = TriangulationBlend::new(&m, 2, BFunction::erbs_default()).unwrap_err().to_string();
    assert!(e.contains("triangles["), "{e}");
    let mut m = TriangulatedSurface::icosphere(1.0, 0).unwrap();
    m.triangles[0][1] = 99;
    assert!(
        TriangulationBlend::new(&m, 2, BFunction::erbs_default()).unwrap_err().to_string().contains("triangles[0]")
    );
    let m = TriangulatedSurface::icosphere(1.0, 0).unwrap();
    assert!(TriangulationBlend::new(&m, 3, BFunction::erbs_default()).is_err());
}

#[test]
fn atlas_chart_is_the_degenerate_tensor_patch_with_its_partials() {
    let t = BezierTriangle::from_fn(3, |(i, j, k)| {
        Point::<3>::new(i as f64 + 0.3 * (j * k) as f64, (j * j) as f64 * 0.5, (k + i * j) as f64 * 0.25)
    })
    .unwrap();
    let patch = t.to_tensor_patch();
    let atlas = TriangleAtlas::new(vec![std::sync::Arc::new(t.clone()), std::sync::Arc::new(t.clone())]).unwrap();
    for (s, q) in [(0.3, 0.8), (0.0, 0.4), (1.0, 0.5), (0.77, 0.1)] {
        let mut a = [Point::<3>::zeros(); 16];
        let mut p = [Point::<3>::zeros(); 16];
        atlas.eval_partials(1.0 + s, q, 3, 3, &mut a);
        patch.eval_partials(s, q, 3, 3, &mut p);
        for k in 0..16 {
            assert!((a[k] - p[k]).norm() < 1e-12 * (1.0 + p[k].norm()), "{k}: {:?} {:?}", a[k], p[k]);
        }
        let [u, v, w] = degenerate_patch_parameters(s, q);
        if s > 0.0 {
            let n = atlas.normal(1.0 + s, q).unwrap();
            assert!((n - t.normal(u, v, w).unwrap()).norm() < 1e-15);
        }
    }
    // The collapsed corner still has the triangle's normal.
    assert_eq!(atlas.normal(0.0, 0.3), t.normal(0.0, 0.0, 1.0));
}

#[test]
fn clough_tocher_is_c1_and_reproduces_quadratics() {
    let pts: Vec<Point<2>> = (0..40)
        .map(|k| {
            let a = k as f64 * 2.399_963;
            let r = (k as f64 / 40.0).sqrt();
            Point::<2>::new(r * a.cos(), r * a.sin())
        })
        .collect();
    let d = Delaunay::new(&pts).unwrap();
    let quad = |p: &Point<2>| 1.0 + 0.5 * p.x - p.y + 0.7 * p.x * p.x - 0.3 * p.x * p.y + 0.2 * p.y * p.y;
    let grad = |p: &Point<2>| [0.5 + 1.4 * p.x - 0.3 * p.y, -1.0 - 0.3 * p.x + 0.4 * p.y];
    let z: Vec<f64> = pts.iter().map(quad).collect();
    let g: Vec<[f64; 2]> = pts.iter().map(grad).collect();
    let pieces = height_pieces(&d, &z, Some(&g), HeightInterpolant::CloughTocher).unwrap();
    for t in &pieces.triangles {
        for (u, v) in [(0.2, 0.3), (0.6, 0.1), (0.0, 0.5)] {
            let p = t.point(u, v, 1.0 - u - v);
            assert!((p.z - quad(&Point::<2>::new(p.x, p.y))).abs() < 1e-13);
        }
    }
    // A non-polynomial function with estimated gradients: C¹ across every edge, checked by
    // the gradient of z over (x, y) from both sides at edge points.
    let z: Vec<f64> = pts.iter().map(|p| (2.0 * p.x).sin() * p.y.exp()).collect();
    let pieces = height_pieces(&d, &z, None, HeightInterpolant::CloughTocher).unwrap();
    let grad_xy = |t: &BezierTriangle<3>, u: f64, v: f64| {
        let mut o = [Point::<3>::zeros(); 4];
        t.eval_partials(u, v, 1, 1, &mut o);
        // [x_u x_v; y_u y_v]^{-T} [z_u; z_v].
        let (xu, xv, yu, yv) = (o[2].x, o[1].x, o[2].y, o[1].y);
        let det = xu * yv - xv * yu;
        [(yv * o[2].z - yu * o[1].z) / det, (-xv * o[2].z + xu * o[1].z) / det]
    };
    let edges = shared_edges(&pieces.corners);
    assert!(edges.len() > 100);
    let mut worst = 0.0f64;
    for (t, m, t2, m2) in edges {
        for s in [0.25, 0.6] {
            let mut l = [0.0; 3];
            l[m] = 1.0 - s;
            l[(m + 1) % 3] = s;
            let mut l2 = [0.0; 3];
            l2[(m2 + 1) % 3] = 1.0 - s;
            l2[m2] = s;
            let (a, b) = (grad_xy(&pieces.triangles[t], l[0], l[1]), grad_xy(&pieces.triangles[t2], l2[0], l2[1]));
            let pa = pieces.triangles[t].point(l[0], l[1], l[2]);
            let pb = pieces.triangles[t2].point(l2[0], l2[1], l2[2]);
            assert!((pa - pb).norm() < 1e-14);
            worst = worst.max((a[0] - b[0]).abs()).max((a[1] - b[1]).abs());
        }
    }
    assert!(worst < 1e-10, "{worst}");
}
