//! Closest point on a curve: coarse sampling, then safeguarded Newton iteration.
//!
//! Minimises f(t) = |c(t) − q|²/2 with f' = (c − q)·c', f'' = c'·c' + (c − q)·c''.
//! Each of the best few samples (on a grid refined between breakpoints) seeds Newton
//! iterations that are clamped to the domain, or wrapped on closed curves; the best
//! converged candidate wins, so a poor seed cannot return a worse point than sampling.

use crate::Point;
use crate::curve::Curve;

/// The parameter t* and the point c(t*) nearest to `query`.
pub fn closest_point<const D: usize, C: Curve<D> + ?Sized>(curve: &C, query: &Point<D>) -> (f64, Point<D>) {
    let dom = curve.domain();
    let bps = curve.breakpoints();
    let mut samples: Vec<f64> = Vec::new();
    let per_piece = (256 / bps.len().max(2)).clamp(8, 64);
    for w in bps.windows(2) {
        for i in 0..per_piece {
            samples.push(w[0] + (w[1] - w[0]) * i as f64 / per_piece as f64);
        }
    }
    samples.push(dom.end);
    let dist = |t: f64| (curve.point(t) - query).norm_squared();
    let mut scored: Vec<(f64, f64)> = samples.iter().map(|&t| (dist(t), t)).collect();
    scored.sort_by(|a, b| a.0.total_cmp(&b.0));
    let mut best = scored[0];
    for &(_, t0) in scored.iter().take(4) {
        let mut t = t0;
        let mut out = [Point::<D>::zeros(); 3];
        for _ in 0..50 {
            curve.eval(t, &mut out);
            let r = out[0] - query;
            let g = r.dot(&out[1]);
            let h = out[1].norm_squared() + r.dot(&out[2]);
            if h <= 0.0 || !h.is_finite() {
                break;
            }
            let mut next = t - g / h;
            next = if curve.is_closed() { dom.wrap(next) } else { dom.clamp(next) };
            let step = (next - t).abs();
            t = next;
            if step <= 1e-15 * dom.length().max(1.0) {
                break;
            }
        }
        let d = dist(t);
        if d < best.0 {
            best = (d, t);
        }
    }
    (best.1, curve.point(best.1))
}
