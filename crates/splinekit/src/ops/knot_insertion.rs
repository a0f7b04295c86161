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

/// Inserts every value of `new_knots` once (repeated values repeatedly), in any order, in
/// time linear in the number of knots (*The NURBS Book* A5.4, knot refinement; degree 0
/// inserts one knot at a time). Each knot must lie in the domain and no multiplicity may
/// exceed the degree.
pub fn refine<T: Coefficient>(data: &SplineData<T>, new_knots: &[f64]) -> Result<SplineData<T>> {
    let p = data.degree;
    if new_knots.is_empty() {
        return Ok(data.clone());
    }
    if p == 0 {
        let mut out = data.clone();
        for &u in new_knots {
            out = insert_knot(&out, u, 1)?;
        }
        return Ok(out);
    }
    let mut x = new_knots.to_vec();
    x.sort_by(f64::total_cmp);
    let Interval { start: lo, end: hi } = data.domain();
    let u = &data.knots;
    let mut i = 0;
    while i < x.len() {
        let v = x[i];
        if !(v >= lo && v <= hi) {
            return Err(Error::invalid("insert", format!("knot {v} is outside the domain [{lo}, {hi}]")));
        }
        let times = x[i..].iter().take_while(|&&w| w == v).count();
        let s = u.partition_point(|&k| k < v)..u.partition_point(|&k| k <= v);
        if s.len() + times > p {
            let more = if times == 1 { "once more".to_string() } else { format!("{times} more times") };
            return Err(Error::invalid(
                "insert",
                format!("knot {v} has multiplicity {}; inserting it {more} would exceed the degree {p}", s.len()),
            ));
        }
        i += times;
    }
    Ok(refine_sorted(data, &x))
}

/// Knot refinement with sorted, valid new knots `x` (*The NURBS Book* A5.4, kept whole as
/// in the book): the control points outside the affected spans are copied, the others
/// computed from the right by one Boehm step per new knot.
fn refine_sorted<T: Coefficient>(data: &SplineData<T>, x: &[f64]) -> SplineData<T> {
    let p = data.degree;
    let u = &data.knots;
    let pw = &data.coefficients;
    let n = pw.len() - 1;
    let m = n + p + 1;
    let r = x.len() - 1;
    let span = |t: f64| crate::basis::find_span(u, p, n + 1, t, crate::basis::Side::Right);
    let a = span(x[0]);
    let b = span(x[r]) + 1;
    let mut qw = vec![T::zero(); n + r + 2];
    let mut ubar = vec![0.0; m + r + 2];
    qw[..=a - p].copy_from_slice(&pw[..=a - p]);
    for j in b - 1..=n {
        qw[j + r + 1] = pw[j];
    }
    ubar[..=a].copy_from_slice(&u[..=a]);
    for j in b + p..=m {
        ubar[j + r + 1] = u[j];
    }
    let mut i = b + p - 1;
    let mut k = b + p + r;
    for j in (0..=r).rev() {
        while x[j] <= u[i] && i > a {
            qw[k - p - 1] = pw[i - p - 1];
            ubar[k] = u[i];
            k -= 1;
            i -= 1;
        }
        qw[k - p - 1] = qw[k - p];
        for l in 1..=p {
            let ind = k - p + l;
            let alfa = ubar[k + l] - x[j];
            if alfa == 0.0 {
                qw[ind - 1] = qw[ind];
            } else {
                let alfa = alfa / (ubar[k + l] - u[i - p + l]);
                qw[ind - 1] = qw[ind - 1] * alfa + qw[ind] * (1.0 - alfa);
            }
        }
        ubar[k] = x[j];
        k -= 1;
    }
    SplineData { degree: p, knots: ubar, coefficients: qw }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Refinement in one pass gives the knots and coefficients of inserting the knots one
    /// at a time (Boehm), unsorted and repeated knots included.
    #[test]
    fn refinement_equals_repeated_insertion() {
        for p in 1..5 {
            let mut knots = vec![0.0; p + 1];
            knots.extend([1.0, 2.0, 2.0, 3.5, 5.0]);
            knots.extend(vec![6.0; p + 1]);
            let n = knots.len() - p - 1;
            let coefficients: Vec<f64> = (0..n).map(|i| ((i * 37) % 11) as f64 - 4.0).collect();
            let data = SplineData { degree: p, knots, coefficients };
            let mut new = vec![5.5, 0.25, 4.0, 1.5];
            if p >= 2 {
                new.extend([4.0, 0.25, 1.0]);
            }
            if p >= 3 {
                new.extend([2.0, 6.0 - 1e-3, 0.0 + 1e-3]);
            }
            let mut one_by_one = data.clone();
            for &u in &new {
                one_by_one = insert_knot(&one_by_one, u, 1).unwrap();
            }
            let at_once = refine(&data, &new).unwrap();
            assert_eq!(at_once.knots, one_by_one.knots, "p = {p}");
            for (a, b) in at_once.coefficients.iter().zip(&one_by_one.coefficients) {
                assert!((a - b).abs() < 1e-12, "p = {p}: {:?} vs {:?}", at_once.coefficients, one_by_one.coefficients);
            }
        }
    }
}
