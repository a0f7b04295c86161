//! Clamping, Bézier decomposition and splitting, all by knot insertion.

use crate::Coefficient;
use crate::Interval;
use crate::error::{Error, Result};
use crate::ops::knot_insertion::{insert_knot, refine};
use crate::ops::spline_data::SplineData;

fn count(knots: &[f64], u: f64) -> usize {
    knots.iter().filter(|&&k| k == u).count()
}

/// Raises the multiplicity of `u` to at least `target` (≤ p).
fn raise_to<T: Coefficient>(data: SplineData<T>, u: f64, target: usize) -> Result<SplineData<T>> {
    let s = count(&data.knots, u);
    if s >= target { Ok(data) } else { insert_knot(&data, u, target - s) }
}

/// The same curve on its domain [t_p, t_n] with clamped knots (p + 1 copies of each end).
pub fn clamp<T: Coefficient>(data: &SplineData<T>) -> Result<SplineData<T>> {
    let p = data.degree;
    let Interval { start: a, end: b } = data.domain();
    if p == 0 {
        let i = data.knots.iter().rposition(|&k| k == a).unwrap();
        let j = data.knots.iter().position(|&k| k == b).unwrap();
        let mut knots = data.knots[i..=j].to_vec();
        knots[0] = a;
        return Ok(SplineData { degree: 0, knots, coefficients: data.coefficients[i..j].to_vec() });
    }
    let d = raise_to(data.clone(), a, p)?;
    let d = raise_to(d, b, p)?;
    // The last p copies of a start at i; the curve passes through Q[i−1] there.
    let i = d.knots.iter().rposition(|&k| k == a).unwrap() + 1 - p;
    let j = d.knots.iter().position(|&k| k == b).unwrap();
    let mut knots = vec![a];
    knots.extend_from_slice(&d.knots[i..j + p]);
    knots.push(b);
    Ok(SplineData { degree: p, knots, coefficients: d.coefficients[i - 1..j].to_vec() })
}

/// A Bézier segment of a decomposed spline: its parameter interval and p + 1 control points.
#[derive(Debug, Clone, PartialEq)]
pub struct BezierSegment<T> {
    /// Parameter interval [start, end] of the segment in the spline's parameter.
    pub interval: Interval,
    /// Control points of the segment, as a Bézier curve on [0, 1].
    pub control_points: Vec<T>,
}

/// Decomposes the spline into its Bézier segments (one per non-empty knot span of the
/// domain) by raising every interior knot to multiplicity p.
pub fn bezier_segments<T: Coefficient>(data: &SplineData<T>) -> Result<Vec<BezierSegment<T>>> {
    let p = data.degree;
    let mut d = clamp(data)?;
    let Interval { start: a, end: b } = d.domain();
    let mut interior: Vec<f64> = d.knots.iter().copied().filter(|&k| k > a && k < b).collect();
    // One refinement raises every interior knot to multiplicity p (linear in the knots).
    let mut missing = Vec::new();
    for run in interior.chunk_by(|x, y| x == y) {
        missing.extend(std::iter::repeat_n(run[0], p.saturating_sub(run.len())));
    }
    d = refine(&d, &missing)?;
    interior.dedup();
    let mut bounds = vec![a];
    bounds.extend(&interior);
    bounds.push(b);
    Ok(bounds
        .windows(2)
        .enumerate()
        .map(|(s, w)| BezierSegment {
            interval: Interval::new(w[0], w[1]),
            control_points: d.coefficients[s * p..=s * p + p].to_vec(),
        })
        .collect())
}

/// Splits an open spline at `u` (strictly inside the domain) into the clamped splines on
/// [t_p, u] and [u, t_n]. At a knot of multiplicity p + 1 (a jump) the left piece ends at
/// the left limit and the right piece starts at the right limit.
pub fn split<T: Coefficient>(data: &SplineData<T>, u: f64) -> Result<(SplineData<T>, SplineData<T>)> {
    let p = data.degree;
    let Interval { start: a, end: b } = data.domain();
    if !(u > a && u < b) {
        return Err(Error::invalid("split", format!("parameter {u} is not inside the domain ({a}, {b})")));
    }
    let mut d = clamp(data)?;
    if p == 0 && count(&d.knots, u) == 0 {
        // A degree-0 spline takes a new knot by duplicating the coefficient of its span.
        let f = d.knots.partition_point(|&k| k <= u) - 1;
        d.knots.insert(f + 1, u);
        let c = d.coefficients[f];
        d.coefficients.insert(f, c);
    } else if p > 0 {
        d = raise_to(d, u, p)?;
    }
    // Copies of u occupy [first, first + count): the left limit is Q[first − 1] and the
    // right limit Q[first + count − p − 1].
    let first = d.knots.iter().position(|&k| k == u).unwrap();
    let c = count(&d.knots, u);
    let mut lk = d.knots[..first].to_vec();
    lk.extend(std::iter::repeat_n(u, p + 1));
    let left = SplineData { degree: p, knots: lk, coefficients: d.coefficients[..first].to_vec() };
    let r0 = first + c - p - 1;
    let mut rk = vec![u; p + 1];
    rk.extend_from_slice(&d.knots[first + c..]);
    let right = SplineData { degree: p, knots: rk, coefficients: d.coefficients[r0..].to_vec() };
    Ok((left, right))
}
