//! The regular Loop patch: the quartic three-direction box spline (Stam 1998, "Evaluation
//! of Loop subdivision surfaces"), as 12 quartic polynomials in (u, v) on the triangle
//! P(u, v) = c₀ + u(c₁ − c₀) + v(c₂ − c₀), one per control point of
//! [`super::regular_patch::loop_control_points`].
//!
//! The polynomials are derived, once, from the subdivision rules themselves rather than
//! typed in: a quartic on the triangle is fixed by its values at the 15 points
//! (i/4, j/4), i + j ≤ 4, and those are limit points of vertices after two Loop steps of
//! the regular 1-ring (limit mask (6v + Σeᵢ)/12 at valence 6), computed exactly in binary
//! fractions; a 15 × 15 solve gives the coefficients. The tests check the result against
//! independent properties of the box spline: partition of unity, C² joins between
//! neighbouring patches, and agreement with three-step subdivision at other points.

use std::sync::OnceLock;

use super::cage::Cage;
use super::limit_eval::{EvalScheme, evaluate_local};
use super::regular_patch::loop_control_points;
use super::topology::Topology;
use crate::Point;

/// Exponents (a, b) of the monomials uᵃvᵇ, a + b ≤ 4.
const MONOMIALS: [(i32, i32); 15] = [
    (0, 0),
    (1, 0),
    (0, 1),
    (2, 0),
    (1, 1),
    (0, 2),
    (3, 0),
    (2, 1),
    (1, 2),
    (0, 3),
    (4, 0),
    (3, 1),
    (2, 2),
    (1, 3),
    (0, 4),
];

/// Coefficients of the 12 basis polynomials in [`MONOMIALS`].
fn coefficients() -> &'static [[f64; 15]; 12] {
    static C: OnceLock<[[f64; 15]; 12]> = OnceLock::new();
    C.get_or_init(derive)
}

fn derive() -> [[f64; 15]; 12] {
    // A triangular lattice, axial coordinates −2..=3, central triangle (0,0), (1,0), (0,1).
    let idx = |i: i32, j: i32| ((i + 2) * 6 + (j + 2)) as u32;
    let mut vertices = Vec::new();
    for i in -2..=3 {
        for j in -2..=3 {
            vertices.push(Point::<3>::new(i as f64 + j as f64 / 2.0, j as f64 * 3f64.sqrt() / 2.0, 0.0));
        }
    }
    let mut faces = vec![vec![idx(0, 0), idx(1, 0), idx(0, 1)]];
    for i in -2..3 {
        for j in -2..3 {
            if (i, j) != (0, 0) {
                faces.push(vec![idx(i, j), idx(i + 1, j), idx(i, j + 1)]);
            }
            faces.push(vec![idx(i + 1, j), idx(i + 1, j + 1), idx(i, j + 1)]);
        }
    }
    let lattice = Cage::new(vertices, &faces);
    let topo = Topology::new(&lattice).expect("the lattice is a manifold");
    // Which lattice vertex is each control point: read off a copy whose vertices carry
    // their own index (the central triangle is interior, so no phantom point is formed).
    let mut labelled = lattice.clone();
    for (q, x) in labelled.vertices.iter_mut().enumerate() {
        *x = Point::<3>::new(q as f64, 0.0, 0.0);
    }
    let points = loop_control_points(&labelled, &topo, 0).expect("the central triangle is regular").map(|p| p.x as u32);
    let samples: Vec<(f64, f64)> =
        (0..=4).flat_map(|i| (0..=4 - i).map(move |j| (i as f64 / 4.0, j as f64 / 4.0))).collect();
    let mut m = [[0.0; 15]; 15];
    for (r, &(u, v)) in samples.iter().enumerate() {
        for (c, &(a, b)) in MONOMIALS.iter().enumerate() {
            m[r][c] = u.powi(a) * v.powi(b);
        }
    }
    let mut out = [[0.0; 15]; 12];
    for (k, &p) in points.iter().enumerate() {
        let mut cage = lattice.clone();
        for (q, x) in cage.vertices.iter_mut().enumerate() {
            *x = Point::<3>::new(if q as u32 == p { 1.0 } else { 0.0 }, 0.0, 0.0);
        }
        let mut rhs = [0.0; 15];
        for (r, &(u, v)) in samples.iter().enumerate() {
            rhs[r] = evaluate_local(cage.clone(), 0, u, v, EvalScheme::Loop, None).expect("a lattice point").position.x;
        }
        out[k] = solve(m, rhs);
    }
    out
}

/// Gaussian elimination with partial pivoting.
pub(crate) fn solve<const N: usize>(mut a: [[f64; N]; N], mut b: [f64; N]) -> [f64; N] {
    for c in 0..N {
        let p = (c..N).max_by(|&i, &j| a[i][c].abs().total_cmp(&a[j][c].abs())).unwrap_or(c);
        a.swap(c, p);
        b.swap(c, p);
        for r in c + 1..N {
            let f = a[r][c] / a[c][c];
            for k in c..N {
                a[r][k] -= f * a[c][k];
            }
            b[r] -= f * b[c];
        }
    }
    let mut x = [0.0; N];
    for r in (0..N).rev() {
        let s: f64 = (r + 1..N).map(|k| a[r][k] * x[k]).sum();
        x[r] = (b[r] - s) / a[r][r];
    }
    x
}

/// Values of the 12 basis functions and of their partials ∂u, ∂v, ∂uu, ∂uv, ∂vv at (u, v):
/// `out[d][k]` for derivative d in that order (d = 0 the values).
pub fn loop_basis(u: f64, v: f64) -> [[f64; 12]; 6] {
    let c = coefficients();
    let pw = |x: f64, n: i32| if n < 0 { 0.0 } else { x.powi(n) };
    let mut out = [[0.0; 12]; 6];
    for (k, row) in c.iter().enumerate() {
        for (m, &(a, b)) in MONOMIALS.iter().enumerate() {
            let (af, bf) = (a as f64, b as f64);
            let w = row[m];
            out[0][k] += w * pw(u, a) * pw(v, b);
            out[1][k] += w * af * pw(u, a - 1) * pw(v, b);
            out[2][k] += w * bf * pw(u, a) * pw(v, b - 1);
            out[3][k] += w * af * (af - 1.0) * pw(u, a - 2) * pw(v, b);
            out[4][k] += w * af * bf * pw(u, a - 1) * pw(v, b - 1);
            out[5][k] += w * bf * (bf - 1.0) * pw(u, a) * pw(v, b - 2);
        }
    }
    out
}
