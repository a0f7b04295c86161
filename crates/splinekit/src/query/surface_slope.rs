//! What a patch's Bernstein nets say about the squared distance f = |S − q|²/2 on it.
//!
//! With H the patch's bicubic Hermite net (see [`crate::query::surface_cover`]), the
//! gradient of f in the patch parameters is approximated by G_s = (H − q)·H_s (degrees
//! 5 × 6) and G_t = (H − q)·H_t (6 × 5), and its Hessian by
//! A = H_s·H_s + (H − q)·H_ss (4 × 6), B = H_s·H_t + (H − q)·H_st (5 × 5),
//! C = H_t·H_t + (H − q)·H_tt (6 × 4), all exact Bernstein products
//! ([`product_2d`]); the patch's radii bound the difference to the true functions. Over the
//! patch each function lies between its extreme coefficients, so:
//! * if every coefficient of G_s (or of G_t) has one sign beyond the margin, f has no
//!   stationary point inside the patch;
//! * if min A > 0, min C > 0 and min A · min C > max B², f is strictly convex on the patch
//!   and has at most one stationary point there, a minimum.

use crate::Point;
use crate::query::bernstein_product::product_2d;
use crate::query::slope::{ZERO_SLOPE, is_rounding_sized};
use crate::query::surface_cover::SurfacePatch;

/// What the nets tell about one patch.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum PatchShape {
    /// One gradient component keeps its sign: no stationary point inside.
    NoStationaryPoint,
    /// f is constant to rounding (a query at the centre of a sphere).
    Flat,
    /// f is strictly convex: at most one stationary point, a minimum.
    Convex,
    /// One gradient component vanishes on the whole patch, to rounding (a query on the axis
    /// of a surface of revolution, where the stationary points form circles).
    HalfFlat,
    /// The nets cannot tell: split the patch.
    Unresolved,
}

/// The Bézier net of ∂^{a+b}H/∂s^a∂t^b (a + b ≤ 2) of a bicubic net `net[i·4 + j]`:
/// forward differences of order a in i and b in j, times 3!/(3 − a)! · 3!/(3 − b)!,
/// row-major with 4 − b columns.
fn derivative_net<const D: usize>(net: &[Point<D>; 16], a: usize, b: usize) -> Vec<Point<D>> {
    const FACTOR: [f64; 3] = [1.0, 3.0, 6.0];
    let (rows, cols) = (4 - a, 4 - b);
    let scale = FACTOR[a] * FACTOR[b];
    let at = |i: usize, j: usize| net[i * 4 + j];
    let mut out = Vec::with_capacity(rows * cols);
    for i in 0..rows {
        for j in 0..cols {
            let d = match (a, b) {
                (0, 0) => at(i, j),
                (1, 0) => at(i + 1, j) - at(i, j),
                (0, 1) => at(i, j + 1) - at(i, j),
                (2, 0) => at(i + 2, j) - at(i + 1, j) * 2.0 + at(i, j),
                (0, 2) => at(i, j + 2) - at(i, j + 1) * 2.0 + at(i, j),
                (1, 1) => at(i + 1, j + 1) - at(i + 1, j) - at(i, j + 1) + at(i, j),
                _ => unreachable!("derivative_net is called with a + b ≤ 2"),
            };
            out.push(d * scale);
        }
    }
    out
}

fn max_norm<const D: usize>(v: &[Point<D>]) -> f64 {
    v.iter().fold(0.0f64, |m, p| m.max(p.norm()))
}

/// The range [min, max] of a list of coefficients.
fn range(c: &[f64]) -> (f64, f64) {
    c.iter().fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), &x| (lo.min(x), hi.max(x)))
}

/// The sum of two Bernstein products of the same degree.
fn product_sum<const D: usize>(
    (a, da): (&[Point<D>], (usize, usize)),
    (b, db): (&[Point<D>], (usize, usize)),
    (c, dc): (&[Point<D>], (usize, usize)),
    (e, de): (&[Point<D>], (usize, usize)),
) -> Vec<f64> {
    let len = (da.0 + db.0 + 1) * (da.1 + db.1 + 1);
    let (mut x, mut y) = (vec![0.0; len], vec![0.0; len]);
    product_2d(a, da, b, db, |p, q| p.dot(q), &mut x);
    product_2d(c, dc, e, de, |p, q| p.dot(q), &mut y);
    x.iter().zip(&y).map(|(p, q)| p + q).collect()
}

/// Which sides of a patch lie on the boundary of an open direction of the domain:
/// (low u, high u, low v, high v).
pub type BoundarySides = [bool; 4];

/// Classifies `patch` for the query point `q`; a patch whose box is at rounding level is
/// flat. On sides that lie on the domain boundary (`boundary`) a gradient coefficient may
/// vanish to rounding without spoiling the sign test: the minima there are the boundary
/// edge's, which the projection searches as a curve (this is what keeps the patches around
/// a sphere's pole or a cone's apex, where a gradient component vanishes along the
/// degenerate edge, from being split without end).
pub fn classify_patch<const D: usize>(patch: &SurfacePatch<D>, q: &Point<D>, boundary: BoundarySides) -> PatchShape {
    if is_rounding_sized(&patch.bounds, q) {
        return PatchShape::Flat;
    }
    let rel: Vec<Point<D>> = patch.control.iter().map(|b| b - q).collect();
    let (hs, ht) = (derivative_net(&patch.control, 1, 0), derivative_net(&patch.control, 0, 1));
    let big_a = max_norm(&rel) + patch.radius;
    let (es, et) = (max_norm(&hs) + patch.slope_radius, max_norm(&ht) + patch.slope_radius);
    let mut gs = vec![0.0; 6 * 7];
    let mut gt = vec![0.0; 7 * 6];
    product_2d(&rel, (3, 3), &hs, (2, 3), |p, q| p.dot(q), &mut gs);
    product_2d(&rel, (3, 3), &ht, (3, 2), |p, q| p.dot(q), &mut gt);
    let zero_s = ZERO_SLOPE * big_a * es;
    let zero_t = ZERO_SLOPE * big_a * et;
    let tol_s = zero_s + big_a * patch.slope_radius + patch.radius * es;
    let tol_t = zero_t + big_a * patch.slope_radius + patch.radius * et;
    if definite(&gs, (5, 6), tol_s, zero_s, boundary) || definite(&gt, (6, 5), tol_t, zero_t, boundary) {
        return PatchShape::NoStationaryPoint;
    }
    let (vanish_s, vanish_t) = (gs.iter().all(|x| x.abs() <= tol_s), gt.iter().all(|x| x.abs() <= tol_t));
    if vanish_s && vanish_t && samples_flat(patch, q) {
        return PatchShape::Flat;
    }
    if is_convex(patch, &rel, &hs, &ht, big_a, (es, et)) {
        PatchShape::Convex
    } else if vanish_s || vanish_t {
        PatchShape::HalfFlat
    } else {
        PatchShape::Unresolved
    }
}

/// Whether every coefficient of a (d₁+1)×(d₂+1) net has one sign beyond `tol`, except those
/// on a boundary side, which need only not have the other sign beyond `zero`.
fn definite(g: &[f64], (d1, d2): (usize, usize), tol: f64, zero: f64, boundary: BoundarySides) -> bool {
    let on_boundary = |k: usize| {
        let (i, j) = (k / (d2 + 1), k % (d2 + 1));
        (boundary[0] && i == 0) || (boundary[1] && i == d1) || (boundary[2] && j == 0) || (boundary[3] && j == d2)
    };
    let signed = |s: f64| g.iter().enumerate().all(|(k, &x)| if on_boundary(k) { s * x > -zero } else { s * x > tol });
    signed(1.0) || signed(-1.0)
}

/// The Hessian test of the module documentation, with the radii as margins.
fn is_convex<const D: usize>(
    patch: &SurfacePatch<D>,
    rel: &[Point<D>],
    hs: &[Point<D>],
    ht: &[Point<D>],
    big_a: f64,
    (es, et): (f64, f64),
) -> bool {
    let (hss, hst, htt) = (
        derivative_net(&patch.control, 2, 0),
        derivative_net(&patch.control, 1, 1),
        derivative_net(&patch.control, 0, 2),
    );
    let a = product_sum((hs, (2, 3)), (hs, (2, 3)), (rel, (3, 3)), (&hss, (1, 3)));
    let b = product_sum((hs, (2, 3)), (ht, (3, 2)), (rel, (3, 3)), (&hst, (2, 2)));
    let c = product_sum((ht, (3, 2)), (ht, (3, 2)), (rel, (3, 3)), (&htt, (3, 1)));
    let (sr, cr, r) = (patch.slope_radius, patch.curvature_radius, patch.radius);
    let second = max_norm(&hss).max(max_norm(&hst)).max(max_norm(&htt)) + cr;
    let margin = |e1: f64, e2: f64| (e1 + e2) * sr + sr * sr + big_a * cr + r * second;
    let (a_lo, _) = range(&a);
    let (b_lo, b_hi) = range(&b);
    let (c_lo, _) = range(&c);
    let a_lo = a_lo - margin(es, es);
    let c_lo = c_lo - margin(et, et);
    let b_max = b_lo.abs().max(b_hi.abs()) + margin(es, et);
    a_lo > 0.0 && c_lo > 0.0 && a_lo * c_lo > b_max * b_max
}

/// The sampled gradient vanishes and the sampled distances agree, to rounding, at all nine
/// samples.
fn samples_flat<const D: usize>(patch: &SurfacePatch<D>, q: &Point<D>) -> bool {
    let d: Vec<f64> = patch.grid.iter().map(|s| (s.point - q).norm()).collect();
    let scale = d.iter().fold(0.0f64, |m, x| m.max(*x)) + patch.bounds.diagonal();
    let zero = ZERO_SLOPE * scale;
    let flat_gradient = patch.grid.iter().all(|s| {
        let r = s.point - q;
        r.dot(&s.du).abs() <= zero * s.du.norm() && r.dot(&s.dv).abs() <= zero * s.dv.norm()
    });
    flat_gradient && d.iter().all(|x| (x - d[4]).abs() <= ZERO_SLOPE * scale)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::surface::Surface;
    use crate::surface::model::Sphere;

    #[test]
    fn derivative_nets_reproduce_partials() {
        let s = Sphere::new(2.0).unwrap();
        let patch =
            SurfacePatch::new(&s, crate::curve::Interval::new(0.3, 0.5), crate::curve::Interval::new(-0.2, 0.1));
        let (hu, hv) = (0.2, 0.3);
        // H_s at the corner (0, 0) is h_u S_u there; H_st is h_u h_v S_uv.
        let hs = derivative_net(&patch.control, 1, 0);
        assert!((hs[0] - s.partial(0.3, -0.2, 1, 0) * hu).norm() < 1e-12);
        let hst = derivative_net(&patch.control, 1, 1);
        assert!((hst[0] - s.partial(0.3, -0.2, 1, 1) * (hu * hv)).norm() < 1e-12);
    }
}
