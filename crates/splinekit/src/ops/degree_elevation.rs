//! Degree elevation: decompose into Bézier segments, elevate each
//! (Q_i = Σ_j C(p,j) C(t,i−j)/C(p+t,i) P_j), reassemble and remove the surplus knots.
//! Each interior knot of multiplicity m ends with multiplicity m + t, so the elevated
//! curve has the same continuity and the same shape.

use crate::Interval;
use crate::basis::binomial;
use crate::error::{Error, Result};
use crate::ops::decomposition::bezier_segments;
use crate::ops::homogeneous::CoefficientNorm;
use crate::ops::knot_removal::remove_knot;
use crate::ops::spline_data::SplineData;

/// Elevating Bézier pieces doubles the interior knots; removing the copies again must not
/// move the curve by more than this fraction of max(1, |coefficients|) (the pieces join
/// exactly, so only rounding is left).
const RESTORE_KNOT_RELATIVE: f64 = 1e-9;

/// Elevates a Bézier control polygon of degree p by `t`.
pub fn elevate_bezier<T: CoefficientNorm>(points: &[T], t: usize) -> Vec<T> {
    let p = points.len() - 1;
    (0..=p + t)
        .map(|i| {
            let lo = i.saturating_sub(t);
            let hi = i.min(p);
            let mut acc = T::zero();
            for (j, pj) in points.iter().enumerate().take(hi + 1).skip(lo) {
                acc += *pj * (binomial(p, j) * binomial(t, i - j) / binomial(p + t, i));
            }
            acc
        })
        .collect()
}

/// The same spline with degree raised by `t` (clamped on its domain).
pub fn elevate_degree<T: CoefficientNorm>(data: &SplineData<T>, t: usize) -> Result<SplineData<T>> {
    if t == 0 {
        return Ok(data.clone());
    }
    let p = data.degree;
    let q = p + t;
    let segments = bezier_segments(data)?;
    let Interval { start: a, end: b } = data.domain();
    // Assemble with every interior knot of multiplicity q (C⁰ joins of the Bézier pieces).
    let mut knots = vec![a; q + 1];
    let mut coefficients = Vec::new();
    for (s, seg) in segments.iter().enumerate() {
        let e = elevate_bezier(&seg.control_points, t);
        if s == 0 {
            coefficients.extend_from_slice(&e);
        } else {
            coefficients.extend_from_slice(&e[1..]);
        }
        if s + 1 < segments.len() {
            knots.extend(std::iter::repeat_n(seg.interval.end, q));
        }
    }
    knots.extend(std::iter::repeat_n(b, q + 1));
    let mut out = SplineData { degree: q, knots, coefficients };
    let scale = out.coefficients.iter().map(|c| c.norm()).fold(1.0, f64::max);
    let tol = RESTORE_KNOT_RELATIVE * scale;
    for seg in segments.iter().take(segments.len().saturating_sub(1)) {
        let u = seg.interval.end;
        let m = data.knots.iter().filter(|&&k| k == u).count();
        let surplus = p - m.min(p);
        if surplus > 0 {
            let (next, removed) = remove_knot(&out, u, surplus, tol)?;
            if removed != surplus {
                return Err(Error::numerical(
                    "elevate",
                    format!("could only restore knot {u} to multiplicity {} (wanted {})", q - removed, m + t),
                ));
            }
            out = next;
        }
    }
    Ok(out)
}
