//! The regular Loop patch as a tensor-product Bézier patch of degree (4, 4) with one
//! collapsed edge (for STEP export).
//!
//! On a regular triangle (see [`super::regular_patch::loop_control_points`]: smooth
//! corners of valence 6, or regular crease corners with phantom points) the limit is the
//! quartic box-spline patch L(u, v) = Σₖ Pₖ Bₖ(u, v) on u, v ≥ 0, u + v ≤ 1
//! ([`super::box_spline::loop_basis`]). The atlas ([`super::atlas`]) charts the triangle by
//! the unit square collapsed onto it, (u, v) = (s(1 − t), t): barycentric coordinates
//! ((1 − s)(1 − t), s(1 − t), t), so t = 1 is the corner c₂. Every monomial uᵃvᵇ with
//! a + b ≤ 4 becomes sᵃ(1 − t)ᵃtᵇ, of degree ≤ 4 in s and ≤ 4 in t: T(s, t) = L(s(1 − t), t)
//! is a polynomial of degree (4, 4), exactly a tensor Bézier patch of that degree.
//!
//! Its control net is found by interpolation: a polynomial of degree (4, 4) is fixed by
//! its values on the 5 × 5 grid (i/4, j/4), and with M the 5 × 5 Bernstein collocation
//! matrix Mₚᵢ = Bᵢ⁴(p/4) (condition number about 11) the net of values V is
//! D = M⁻¹ V M⁻ᵀ. This is done once per basis function Bₖ, giving 12 weight nets; a patch's
//! net is Σₖ Pₖ Wₖ. The row t = 1 is the single point L(0, 1) (Σᵢ dᵢ₄ Bᵢ⁴(s) is constant
//! in s, so every dᵢ₄ equals it), and is set to it exactly: the edge collapses to c₂'s
//! limit point without rounding.

use std::sync::OnceLock;

use super::box_spline::{loop_basis, solve};
use super::cage::Cage;
use super::regular_patch::loop_control_points;
use super::topology::Topology;
use crate::Point;

/// A (4, 4) tensor Bézier net, `[i][j]` with i along s and j along t.
pub type QuarticNet = [[Point<3>; 5]; 5];

/// The weight nets `[k][i][j]` of the 12 box-spline basis functions.
fn weights() -> &'static [[[f64; 5]; 5]; 12] {
    static W: OnceLock<[[[f64; 5]; 5]; 12]> = OnceLock::new();
    W.get_or_init(derive)
}

/// The binomial-weighted Bernstein polynomial Bᵢ⁴(x).
fn bernstein4(i: usize, x: f64) -> f64 {
    const C: [f64; 5] = [1.0, 4.0, 6.0, 4.0, 1.0];
    C[i] * x.powi(i as i32) * (1.0 - x).powi(4 - i as i32)
}

fn derive() -> [[[f64; 5]; 5]; 12] {
    let m: [[f64; 5]; 5] = std::array::from_fn(|p| std::array::from_fn(|i| bernstein4(i, p as f64 / 4.0)));
    // Columns of M⁻¹.
    let cols: [[f64; 5]; 5] = std::array::from_fn(|c| solve(m, std::array::from_fn(|r| f64::from(u8::from(r == c)))));
    let inv = |i: usize, p: usize| cols[p][i];
    let values: [[[f64; 12]; 5]; 5] = std::array::from_fn(|p| {
        std::array::from_fn(|q| {
            let (s, t) = (p as f64 / 4.0, q as f64 / 4.0);
            loop_basis(s * (1.0 - t), t)[0]
        })
    });
    let apex = loop_basis(0.0, 1.0)[0];
    std::array::from_fn(|k| {
        std::array::from_fn(|i| {
            std::array::from_fn(|j| {
                if j == 4 {
                    return apex[k];
                }
                let mut w = 0.0;
                for p in 0..5 {
                    for q in 0..5 {
                        w += inv(i, p) * inv(j, q) * values[p][q][k];
                    }
                }
                w
            })
        })
    })
}

/// The (4, 4) Bézier net of triangle f's limit in the atlas chart (s, t) ↦ (s(1 − t), t),
/// if f is regular; its edge t = 1 is collapsed onto the limit point of the corner c₂.
pub fn loop_bezier_patch(cage: &Cage, topo: &Topology, f: u32) -> Option<QuarticNet> {
    let pts = loop_control_points(cage, topo, f)?;
    let w = weights();
    let mut net = [[Point::<3>::zeros(); 5]; 5];
    for (k, &x) in pts.iter().enumerate() {
        for (i, row) in net.iter_mut().enumerate() {
            for (j, d) in row.iter_mut().enumerate() {
                *d += x * w[k][i][j];
            }
        }
    }
    Some(net)
}

/// The tensor Bézier patch of degree (4, 4) of `net` at (s, t).
pub fn quartic_at(net: &QuarticNet, s: f64, t: f64) -> Point<3> {
    let mut p = Point::<3>::zeros();
    for (i, row) in net.iter().enumerate() {
        for (j, d) in row.iter().enumerate() {
            p += d * (bernstein4(i, s) * bernstein4(j, t));
        }
    }
    p
}
