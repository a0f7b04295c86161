//! Knot insertion (Boehm's algorithm, *The NURBS Book* A5.1) and refinement.
//!
//! Inserting u into [t_k, t_{k+1}) r times replaces p − s control points (s = current
//! multiplicity) by affine combinations Q_i = α_i P_i + (1 − α_i) P_{i−1},
//! α_i = (u − t_i)/(t_{i+p} − t_i); the curve is unchanged.

use smallvec::SmallVec;

use crate::Coefficient;
use crate::Interval;
use crate::error::{Error, Result};
use crate::ops::spline_data::SplineData;

/// Inserts `u` (in the domain [t_p, t_n]) `times` times. The resulting multiplicity may
/// not exceed the degree.
pub fn insert_knot<T: Coefficient>(data: &SplineData<T>, u: f64, times: usize) -> Result<SplineData<T>> {
    let p = data.degree;
    let knots = &data.knots;
    let pts = &data.coefficients;
    let Interval { start: a, end: b } = data.domain();
    if !(u >= a && u <= b) {
        return Err(Error::invalid("insert", format!("knot {u} is outside the domain [{a}, {b}]")));
    }
    let s = knots.iter().filter(|&&k| k == u).count();
    if times == 0 {
        return Ok(data.clone());
    }
    if p == 0 {
        // Piecewise constant: a new knot splits its span, whose coefficient is duplicated.
        if s + times > 1 {
            return Err(Error::invalid("insert", format!("knot {u} can appear only once in a degree-0 spline")));
        }
        let k = knots.partition_point(|&x| x <= u) - 1;
        let mut out = data.clone();
        out.knots.insert(k + 1, u);
        out.coefficients.insert(k, pts[k]);
        return Ok(out);
    }
    if s + times > p {
        let more = if times == 1 { "once more".to_string() } else { format!("{times} more times") };
        return Err(Error::invalid(
            "insert",
            format!("knot {u} has multiplicity {s}; inserting it {more} would exceed the degree {p}"),
        ));
    }
    let r = times;
    let np = pts.len() - 1;
    let mp = np + p + 1;
    // k: last index with U_k ≤ u, kept below the last knot.
    let k = (knots.partition_point(|&x| x <= u) - 1).min(mp - 1);
    let mut uq = Vec::with_capacity(knots.len() + r);
    uq.extend_from_slice(&knots[..=k]);
    uq.extend(std::iter::repeat_n(u, r));
    uq.extend_from_slice(&knots[k + 1..]);
    let mut q = vec![T::zero(); pts.len() + r];
    q[..=k - p].copy_from_slice(&pts[..=k - p]);
    q[k - s + r..=np + r].copy_from_slice(&pts[k - s..=np]);
    let mut rw: SmallVec<[T; 16]> = SmallVec::from_slice(&pts[k - p..=k - s]);
    let mut l = 0;
    for j in 1..=r {
        l = k - p + j;
        for i in 0..=p - j - s {
            let alpha = (u - knots[l + i]) / (knots[i + k + 1] - knots[l + i]);
            rw[i] = rw[i + 1] * alpha + rw[i] * (1.0 - alpha);
        }
        q[l] = rw[0];
        q[k + r - j - s] = rw[p - j - s];
    }
    for i in l + 1..k - s {
        q[i] = rw[i - l];
    }
    Ok(SplineData { degree: p, knots: uq, coefficients: q })
}

/// Inserts every value of `new_knots` once (repeated values repeatedly), in any order.
pub fn refine<T: Coefficient>(data: &SplineData<T>, new_knots: &[f64]) -> Result<SplineData<T>> {
    let mut out = data.clone();
    for &u in new_knots {
        out = insert_knot(&out, u, 1)?;
    }
    Ok(out)
}
