//! Arc length by adaptive Gauss–Legendre quadrature.
//!
//! L = ∫_a^b |c'(t)| dt. Each piece between breakpoints (knots, segment joins) is
//! integrated with a 10-point Gauss–Legendre rule and compared with the sum over its two
//! halves; pieces whose estimates differ by more than their share of the tolerance are
//! bisected (to depth 50).

use crate::Point;
use crate::curve::Curve;

const NODES: [f64; 5] = [
    0.148_874_338_981_631_2,
    0.433_395_394_129_247_2,
    0.679_409_568_299_024_4,
    0.865_063_366_688_984_5,
    0.973_906_528_517_171_7,
];
const WEIGHTS: [f64; 5] = [
    0.295_524_224_714_752_9,
    0.269_266_719_309_996_4,
    0.219_086_362_515_982_04,
    0.149_451_349_150_580_6,
    0.066_671_344_308_688_14,
];

fn gauss<const D: usize, C: Curve<D> + ?Sized>(curve: &C, a: f64, b: f64) -> f64 {
    let (m, h) = ((a + b) / 2.0, (b - a) / 2.0);
    let mut out = [Point::<D>::zeros(); 2];
    let mut sum = 0.0;
    for (x, w) in NODES.iter().zip(WEIGHTS) {
        curve.eval_side(m - h * x, crate::basis::Side::Right, &mut out);
        sum += w * out[1].norm();
        curve.eval_side(m + h * x, crate::basis::Side::Left, &mut out);
        sum += w * out[1].norm();
    }
    sum * h
}

fn adaptive<const D: usize, C: Curve<D> + ?Sized>(curve: &C, a: f64, b: f64, whole: f64, tol: f64, depth: u32) -> f64 {
    let m = (a + b) / 2.0;
    let (l, r) = (gauss(curve, a, m), gauss(curve, m, b));
    if depth == 0 || (l + r - whole).abs() <= tol {
        return l + r;
    }
    adaptive(curve, a, m, l, tol / 2.0, depth - 1) + adaptive(curve, m, b, r, tol / 2.0, depth - 1)
}

/// Arc length of `curve` between parameters `a ≤ b` to about `tolerance` (absolute).
pub fn arc_length<const D: usize, C: Curve<D> + ?Sized>(curve: &C, a: f64, b: f64, tolerance: f64) -> f64 {
    let tol = tolerance.max(1e-15);
    let mut cuts: Vec<f64> = curve.breakpoints().into_iter().filter(|&k| k > a && k < b).collect();
    cuts.insert(0, a);
    cuts.push(b);
    let pieces = (cuts.len() - 1) as f64;
    cuts.windows(2).map(|w| adaptive(curve, w[0], w[1], gauss(curve, w[0], w[1]), tol / pieces, 50)).sum()
}
