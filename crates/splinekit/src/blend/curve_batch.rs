//! Batch evaluation of a blending-spline curve whose locals are Bézier curves of one degree
//! d ≤ 7 (the shape documents' default: cubic Bézier locals): the fast path behind
//! [`crate::curve::Curve::eval_many`] of [`super::BlendingSplineCurve`].
//!
//! On the interval [c_k, c_{k+1}) of width Δ the curve is f = a + B(w)·e with the two
//! active locals a = ℓ_k, b = ℓ_{k+1}, e = b − a and w = (t − c_k)/Δ; by Leibniz
//! ([`super::leibniz`]) f^{(r)} = a^{(r)} + Σ_j C(r, j) B^{(j)}(w) Δ^{−j} e^{(r−j)}. Both
//! locals are polynomials of degree d there, so when the batch enters an interval it
//! restricts each local to it — the Bézier points of the piece over [c_k, c_{k+1}] are the
//! blossom values Q_i = ℓ(u₀^{⟨d−i⟩}, u₁^{⟨i⟩}) at the ends u₀, u₁ of the interval in the
//! local's own parameter (de Casteljau with those arguments) — and keeps, for j up to the
//! order asked, the scaled differences d!/(d−j)! Δ^{−j} Δ^j Q of a and of e. A point then
//! costs the powers of w and 1 − w (shared by a, e and the Bernstein weights of every
//! level), two Bernstein sums per order, the B-function at the same w and the blend — no
//! de Casteljau triangle per point, no copy of the control points. All Bernstein weights
//! are positive and sum to one, so the values stay within a few ulps of the general
//! evaluation (de Casteljau on each local, [`super::BlendingSplineCurve::eval_side`]).
//!
//! A sorted batch restricts each interval once; any other order restricts the interval of
//! each parameter that leaves the current one. An interval whose locals are not both Bézier
//! curves of degree d, or that reaches past a local's support (where the general path
//! clamps the local's parameter), is evaluated by the general path.

use super::knots::BlendKnots;
use crate::basis::{BFunction, Side};
use crate::curve::bezier_spans::{BINOMIAL, by_width, powers};
use crate::{Interval, Point};

/// Highest derivative order the batch path serves (higher orders take the general path).
pub(crate) const MAX_ORDER: usize = 4;

/// Highest Bézier degree of the locals the batch path serves.
pub(crate) const MAX_DEGREE: usize = 7;

/// A Bézier local as the batch sees it: its world control points and its support.
pub(crate) struct BezierLocal<'a, const D: usize> {
    pub points: &'a [Point<D>],
    pub support: Interval,
}

/// The Bézier points of `local` restricted to [t0, t1] (parameters of the global curve),
/// or `None` when that reaches past the local's support by more than rounding.
fn restrict<const W: usize, const D: usize>(local: &BezierLocal<'_, D>, t0: f64, t1: f64) -> Option<[Point<D>; W]> {
    let (start, length) = (local.support.start, local.support.length());
    // The local's own parameter as `Reparametrized` computes it.
    let (u0, u1) = ((t0 - start) / length, (t1 - start) / length);
    let slack = 1e-12;
    if !(u0 >= -slack && u1 <= 1.0 + slack && u0 <= u1) {
        return None;
    }
    let (u0, u1) = (u0.clamp(0.0, 1.0), u1.clamp(0.0, 1.0));
    let d = W - 1;
    let mut q = [Point::<D>::zeros(); W];
    for (i, qi) in q.iter_mut().enumerate() {
        // The blossom at (u0 repeated d − i times, u1 repeated i times).
        let mut b: [Point<D>; W] = local.points.try_into().ok()?;
        for r in 0..d {
            let x = if r < d - i { u0 } else { u1 };
            for j in 0..d - r {
                b[j] = b[j] * (1.0 - x) + b[j + 1] * x;
            }
        }
        *qi = b[0];
    }
    Some(q)
}

/// Scaled difference tables of a polynomial piece with Bézier points `q` on an interval of
/// width Δ: `table[j]` = d!/(d−j)! Δ^{−j} Δ^j q (its j-th derivative in t in Bernstein
/// form of degree d − j), j ≤ `top`.
fn tables<const W: usize, const D: usize>(
    q: [Point<D>; W],
    inv_width: f64,
    top: usize,
) -> [[Point<D>; W]; MAX_ORDER + 1] {
    let d = W - 1;
    let mut t = [[Point::<D>::zeros(); W]; MAX_ORDER + 1];
    t[0] = q;
    for j in 1..=top {
        let factor = (d - j + 1) as f64 * inv_width;
        for i in 0..W - j {
            t[j][i] = (t[j - 1][i + 1] - t[j - 1][i]) * factor;
        }
    }
    t
}

/// The interval of the batch's current run of parameters: its index and ends, 1/Δ and its
/// powers, and the tables of a and e (`None`: the general path serves this interval).
struct Current<const W: usize, const D: usize> {
    index: usize,
    start: f64,
    end: f64,
    inv_width: f64,
    /// Δ^{−j}, j ≤ [`MAX_ORDER`]: the chain rule of w = (t − c_k)/Δ.
    inv_width_powers: [f64; MAX_ORDER + 1],
    pieces: Option<Box<Pieces<W, D>>>,
}

/// The difference tables of a = ℓ_k and e = ℓ_{k+1} − ℓ_k on the current interval.
struct Pieces<const W: usize, const D: usize> {
    a: [[Point<D>; W]; MAX_ORDER + 1],
    e: [[Point<D>; W]; MAX_ORDER + 1],
}

/// Writes `out[i·(order+1) + j]` = f^{(j)}(`params[i]`) for a spline whose locals
/// `local(k)` are mostly Bézier curves of the degree d of local 0; parameters on an
/// interval whose locals are not (`local` gives `None` or another degree) go to `general`.
/// Needs 1 ≤ d ≤ [`MAX_DEGREE`] and order ≤ [`MAX_ORDER`].
pub(crate) fn eval_many<'a, const D: usize>(
    knots: &BlendKnots,
    bfunction: &BFunction,
    local: impl Fn(usize) -> Option<BezierLocal<'a, D>>,
    general: impl Fn(f64, &mut [Point<D>]),
    params: &[f64],
    order: usize,
    out: &mut [Point<D>],
) {
    let degree = local(0).map_or(0, |l| l.points.len().saturating_sub(1));
    debug_assert!((1..=MAX_DEGREE).contains(&degree) && order <= MAX_ORDER);
    // Monomorphised on the degree and on the number of outputs, so that every sum unrolls.
    by_width!(degree, W => match order {
        0 => eval_many_fixed::<W, 1, D>(knots, bfunction, local, general, params, out),
        1 => eval_many_fixed::<W, 2, D>(knots, bfunction, local, general, params, out),
        2 => eval_many_fixed::<W, 3, D>(knots, bfunction, local, general, params, out),
        3 => eval_many_fixed::<W, 4, D>(knots, bfunction, local, general, params, out),
        _ => eval_many_fixed::<W, 5, D>(knots, bfunction, local, general, params, out),
    })
}

/// [`eval_many`] for W = d + 1 Bézier points per local and K = order + 1 outputs.
fn eval_many_fixed<'a, const W: usize, const K: usize, const D: usize>(
    knots: &BlendKnots,
    bfunction: &BFunction,
    local: impl Fn(usize) -> Option<BezierLocal<'a, D>>,
    general: impl Fn(f64, &mut [Point<D>]),
    params: &[f64],
    out: &mut [Point<D>],
) {
    let top = (K - 1).min(W - 1);
    let domain = knots.domain();
    let closed = knots.is_closed();
    let values = knots.values();
    let last = values.len() - 2;
    let piece = |k: usize, t0: f64, t1: f64| {
        local(k).filter(|l| l.points.len() == W).and_then(|l| restrict::<W, D>(&l, t0, t1))
    };
    let mut at: Option<Current<W, D>> = None;
    let mut bf = [0.0; K];
    for (&t, o) in params.iter().zip(out.chunks_exact_mut(K)) {
        // The parameter as `BlendKnots::locate` brings it into the domain.
        let tm = if closed { domain.wrap_periodic(t, Side::Right) } else { domain.clamp(t) };
        let inside = at.as_ref().is_some_and(|s| tm >= s.start && (tm < s.end || s.index == last));
        if !inside {
            let span = knots.locate(t, Side::Right);
            let (start, end) = (values[span.first], values[span.first + 1]);
            let inv_width = 1.0 / span.width;
            let shift = span.second_shift;
            let pieces = match (piece(span.first, start, end), piece(span.second, start + shift, end + shift)) {
                (Some(a), Some(b)) => {
                    let mut e = a;
                    for (x, y) in e.iter_mut().zip(b) {
                        *x = y - *x;
                    }
                    Some(Box::new(Pieces { a: tables(a, inv_width, top), e: tables(e, inv_width, top) }))
                }
                _ => None,
            };
            let mut inv_width_powers = [1.0; MAX_ORDER + 1];
            for j in 1..=MAX_ORDER {
                inv_width_powers[j] = inv_width_powers[j - 1] * inv_width;
            }
            at = Some(Current { index: span.first, start, end, inv_width, inv_width_powers, pieces });
        }
        let s = at.as_ref().expect("an interval");
        let Some(pieces) = &s.pieces else {
            general(t, o);
            continue;
        };
        let x = (tm - s.start) * s.inv_width;
        bfunction.eval_array(x, &mut bf);
        let x = x.clamp(0.0, 1.0);
        // Bernstein weights of every level q = d − j from one set of powers of x and 1 − x.
        let (up, sp) = powers::<W>(x);
        let mut a = [Point::<D>::zeros(); K];
        let mut e = [Point::<D>::zeros(); K];
        for j in 0..K.min(W) {
            let q = W - 1 - j;
            let weight = |i: usize| BINOMIAL[q][i] * up[i] * sp[q - i];
            let (ta, te) = (&pieces.a[j], &pieces.e[j]);
            let w0 = weight(0);
            let (mut va, mut ve) = (ta[0] * w0, te[0] * w0);
            for i in 1..=q {
                let wi = weight(i);
                va += ta[i] * wi;
                ve += te[i] * wi;
            }
            a[j] = va;
            e[j] = ve;
        }
        // f^{(r)} = a^{(r)} + Σ_j C(r, j) B^{(j)} Δ^{−j} e^{(r−j)}.
        let mut g = [0.0; K];
        for j in 0..K {
            g[j] = bf[j] * s.inv_width_powers[j];
        }
        let o: &mut [Point<D>; K] = o.try_into().expect("K outputs");
        for (r, f) in o.iter_mut().enumerate() {
            let mut v = a[r];
            for j in 0..=r {
                v += e[r - j] * (BINOMIAL[r][j] * g[j]);
            }
            *f = v;
        }
    }
}
