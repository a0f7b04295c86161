//! Knot removal within a tolerance (*The NURBS Book* A5.8, Tiller's algorithm).
//!
//! Removing u once solves for the p − s + 1 … control points that the last insertion
//! of u would have produced, from both ends of the affected range; if the two solutions
//! meet within `tolerance` the knot is removable. The deviation of the curve is bounded by
//! the tolerance (convex-hull property).

use crate::Interval;
use crate::error::{Error, Result};
use crate::ops::homogeneous::CoefficientNorm;
use crate::ops::spline_data::SplineData;

/// Removes `u` up to `times` times while the coefficient check stays within `tolerance`.
/// Returns the new spline and how many times the knot was actually removed.
///
/// A textbook algorithm kept whole on purpose (about 85 lines): it follows *The NURBS
/// Book*'s A5.8 (RemoveCurveKnot) step by step, index names included, so it can be
/// checked against the book line by line.
pub fn remove_knot<T: CoefficientNorm>(
    data: &SplineData<T>,
    u: f64,
    times: usize,
    tolerance: f64,
) -> Result<(SplineData<T>, usize)> {
    let p = data.degree;
    let mut knots = data.knots.clone();
    let mut pw = data.coefficients.clone();
    let n = pw.len() - 1; // last index
    let m = n + p + 1;
    let Interval { start: a, end: b } = data.domain();
    if !(u > a && u < b) {
        return Err(Error::invalid("remove", format!("knot {u} is not inside the domain ({a}, {b})")));
    }
    let s = knots.iter().filter(|&&k| k == u).count();
    if s == 0 {
        return Err(Error::invalid("remove", format!("{u} is not a knot")));
    }
    let r = knots.iter().rposition(|&k| k == u).unwrap();
    let num = times.min(s);
    let ord = p + 1;
    let fout = (2 * r - s - p) / 2;
    let mut last = r - s;
    let mut first = r - p;
    let mut temp = vec![T::zero(); 2 * p + 1];
    let mut t = 0;
    while t < num {
        let off = first - 1;
        temp[0] = pw[off];
        temp[last + 1 - off] = pw[last + 1];
        let (mut i, mut j) = (first, last);
        let (mut ii, mut jj) = (1usize, last - off);
        while j as isize - i as isize > t as isize {
            let alfi = (u - knots[i]) / (knots[i + ord + t] - knots[i]);
            let alfj = (u - knots[j - t]) / (knots[j + ord] - knots[j - t]);
            temp[ii] = (pw[i] - temp[ii - 1] * (1.0 - alfi)) * (1.0 / alfi);
            temp[jj] = (pw[j] - temp[jj + 1] * alfj) * (1.0 / (1.0 - alfj));
            i += 1;
            ii += 1;
            j -= 1;
            jj -= 1;
        }
        let removable = if (j as isize - i as isize) < t as isize {
            (temp[ii - 1] - temp[jj + 1]).norm() <= tolerance
        } else {
            let alfi = (u - knots[i]) / (knots[i + ord + t] - knots[i]);
            (pw[i] - (temp[ii + t + 1] * alfi + temp[ii - 1] * (1.0 - alfi))).norm() <= tolerance
        };
        if !removable {
            break;
        }
        let (mut i, mut j) = (first, last);
        while j as isize - i as isize > t as isize {
            pw[i] = temp[i - off];
            pw[j] = temp[j - off];
            i += 1;
            j -= 1;
        }
        first -= 1;
        last += 1;
        t += 1;
    }
    if t == 0 {
        return Ok((data.clone(), 0));
    }
    for k in r + 1..=m {
        knots[k - t] = knots[k];
    }
    knots.truncate(m + 1 - t);
    let mut j = fout;
    let mut i = j;
    for k in 1..t {
        if k % 2 == 1 {
            i += 1;
        } else {
            j -= 1;
        }
    }
    for k in i + 1..=n {
        pw[j] = pw[k];
        j += 1;
    }
    pw.truncate(n + 1 - t);
    Ok((SplineData { degree: p, knots, coefficients: pw }, t))
}
