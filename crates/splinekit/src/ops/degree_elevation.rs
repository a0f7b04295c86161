//! Degree elevation: every Bézier segment is elevated
//! (Q_i = Σ_j C(p,j) C(t,i−j)/C(p+t,i) P_j) and the surplus knots between segments are
//! removed again, segment by segment (*The NURBS Book* A5.9, linear in the number of
//! knots). Each interior knot of multiplicity m ends with multiplicity m + t, so the
//! elevated curve has the same continuity and the same shape.

use crate::basis::binomial;
use crate::error::{Error, Result};
use crate::ops::decomposition::clamp;
use crate::ops::homogeneous::CoefficientNorm;
use crate::ops::spline_data::SplineData;

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

/// The same spline with degree raised by `t` (clamped on its domain), in time linear in
/// the number of knots.
///
/// The spline is clamped, cut at its jumps (interior knots of multiplicity p + 1) into
/// pieces that are elevated one by one, and the pieces joined again with the jump knots of
/// multiplicity p + t + 1.
pub fn elevate_degree<T: CoefficientNorm>(data: &SplineData<T>, t: usize) -> Result<SplineData<T>> {
    if t == 0 {
        return Ok(data.clone());
    }
    let clamped = clamp(data)?;
    let p = clamped.degree;
    let q = p.checked_add(t).ok_or_else(|| Error::invalid("elevate", format!("degree {p} + {t} overflows")))?;
    let mut out: Option<SplineData<T>> = None;
    for piece in pieces_between_jumps(&clamped) {
        let e = elevate_clamped(&piece, t);
        out = Some(match out {
            None => e,
            Some(mut acc) => {
                acc.knots.truncate(acc.knots.len() - (q + 1));
                acc.knots.extend_from_slice(&e.knots);
                acc.coefficients.extend_from_slice(&e.coefficients);
                acc
            }
        });
    }
    Ok(out.expect("a spline has at least one piece"))
}

/// The clamped pieces of a clamped spline between its interior knots of multiplicity
/// p + 1 (where it may jump).
fn pieces_between_jumps<T: CoefficientNorm>(data: &SplineData<T>) -> Vec<SplineData<T>> {
    let p = data.degree;
    let n = data.coefficients.len();
    let (mut pieces, mut start) = (Vec::new(), 0);
    let mut i = p + 1;
    while i < n {
        let mut j = i;
        while j + 1 < data.knots.len() && data.knots[j + 1] == data.knots[i] {
            j += 1;
        }
        if j - i + 1 == p + 1 {
            // Knots i ..= j are the jump; the left piece ends with them, the right starts.
            pieces.push(SplineData {
                degree: p,
                knots: data.knots[start..=j].to_vec(),
                coefficients: data.coefficients[start..i].to_vec(),
            });
            start = i;
        }
        i = j + 1;
    }
    pieces.push(SplineData {
        degree: p,
        knots: data.knots[start..].to_vec(),
        coefficients: data.coefficients[start..].to_vec(),
    });
    pieces
}

/// Degree elevation of a clamped spline whose interior knots have multiplicity at most p
/// (*The NURBS Book*, algorithm A5.9, kept whole as in the book): each Bézier segment is
/// extracted by knot insertion, elevated, and the surplus knots at its start are removed
/// again before its points are emitted, so the work is linear in the number of knots.
fn elevate_clamped<T: CoefficientNorm>(data: &SplineData<T>, t: usize) -> SplineData<T> {
    let p = data.degree;
    let u = &data.knots;
    let pw = &data.coefficients;
    if p == 0 {
        // One constant segment (every knot of a degree-0 spline is a jump).
        let mut knots = vec![u[0]; t + 1];
        knots.extend(std::iter::repeat_n(u[1], t + 1));
        return SplineData { degree: t, knots, coefficients: vec![pw[0]; t + 1] };
    }
    let n = pw.len() - 1;
    let m = n + p + 1;
    let ph = p + t;
    let ph2 = ph / 2;
    // Bézier elevation coefficients bezalfs[i][j].
    let mut bezalfs = vec![vec![0.0; p + 1]; ph + 1];
    bezalfs[0][0] = 1.0;
    bezalfs[ph][p] = 1.0;
    for i in 1..=ph2 {
        let inv = 1.0 / binomial(ph, i);
        for j in i.saturating_sub(t)..=p.min(i) {
            bezalfs[i][j] = inv * binomial(p, j) * binomial(t, i - j);
        }
    }
    for i in ph2 + 1..ph {
        for j in i.saturating_sub(t)..=p.min(i) {
            bezalfs[i][j] = bezalfs[ph - i][p - j];
        }
    }
    let segments = u.windows(2).filter(|w| w[0] < w[1]).count();
    let mut uh = Vec::with_capacity(m + 1 + segments * t + t * 2);
    let mut qw = Vec::with_capacity(n + 1 + segments * t + t);
    let mut bpts: Vec<T> = pw[..=p].to_vec();
    let mut next_bpts = vec![T::zero(); p.saturating_sub(1).max(1)];
    let mut ebpts = vec![T::zero(); ph + 1];
    let mut alfs = vec![0.0; p.saturating_sub(1).max(1)];
    let (mut a, mut b) = (p, p + 1);
    let mut r: isize = -1;
    let mut ua = u[0];
    qw.push(pw[0]);
    uh.extend(std::iter::repeat_n(ua, ph + 1));
    while b < m {
        let i0 = b;
        while b < m && u[b] == u[b + 1] {
            b += 1;
        }
        let mul = b - i0 + 1;
        let ub = u[b];
        let oldr = r;
        r = p as isize - mul as isize;
        let lbz = if oldr > 0 { ((oldr + 2) / 2) as usize } else { 1 };
        let rbz = if r > 0 { ph - ((r + 1) / 2) as usize } else { ph };
        if r > 0 {
            // Insert u(b) r times to get the Bézier segment [ua, ub].
            let numer = ub - ua;
            for k in (mul + 1..=p).rev() {
                alfs[k - mul - 1] = numer / (u[a + k] - ua);
            }
            for j in 1..=r as usize {
                let save = r as usize - j;
                let s = mul + j;
                for k in (s..=p).rev() {
                    bpts[k] = bpts[k] * alfs[k - s] + bpts[k - 1] * (1.0 - alfs[k - s]);
                }
                next_bpts[save] = bpts[p];
            }
        }
        // Elevate the segment.
        for i in lbz..=ph {
            ebpts[i] = T::zero();
            for j in i.saturating_sub(t)..=p.min(i) {
                ebpts[i] += bpts[j] * bezalfs[i][j];
            }
        }
        if oldr > 1 {
            // Remove knot ua oldr − 1 times.
            let kind = uh.len();
            let cind = qw.len();
            let (mut first, mut last) = (kind as isize - 2, kind as isize);
            let den = ub - ua;
            let bet = (ub - uh[kind - 1]) / den;
            for tr in 1..oldr {
                let (mut i, mut j) = (first, last);
                let mut kj = j - kind as isize + 1;
                while j - i > tr {
                    if i < cind as isize {
                        let iu = i as usize;
                        let alf = (ub - uh[iu]) / (ua - uh[iu]);
                        qw[iu] = qw[iu] * alf + qw[iu - 1] * (1.0 - alf);
                    }
                    if j >= lbz as isize {
                        let kju = kj as usize;
                        if j - tr <= kind as isize - ph as isize + oldr {
                            let gam = (ub - uh[(j - tr) as usize]) / den;
                            ebpts[kju] = ebpts[kju] * gam + ebpts[kju + 1] * (1.0 - gam);
                        } else {
                            ebpts[kju] = ebpts[kju] * bet + ebpts[kju + 1] * (1.0 - bet);
                        }
                    }
                    i += 1;
                    j -= 1;
                    kj -= 1;
                }
                first -= 1;
                last += 1;
            }
        }
        if a != p {
            // Load the knot ua.
            uh.extend(std::iter::repeat_n(ua, (ph as isize - oldr) as usize));
        }
        qw.extend_from_slice(&ebpts[lbz..=rbz]);
        if b < m {
            // Set up the next segment.
            let kept = r.max(0) as usize;
            bpts[..kept].copy_from_slice(&next_bpts[..kept]);
            for j in kept..=p {
                bpts[j] = pw[b - p + j];
            }
            a = b;
            b += 1;
            ua = ub;
        } else {
            uh.extend(std::iter::repeat_n(ub, ph + 1));
        }
    }
    SplineData { degree: ph, knots: uh, coefficients: qw }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::ops::decomposition::bezier_segments;

    /// Evaluates a spline by de Boor's recurrence (independent of the code under test).
    fn de_boor(d: &SplineData<f64>, x: f64) -> f64 {
        let p = d.degree;
        let n = d.coefficients.len();
        let k = (p..n).rev().find(|&k| d.knots[k] <= x && d.knots[k] < d.knots[k + 1]).unwrap_or(p);
        let mut c: Vec<f64> = (0..=p).map(|j| d.coefficients[j + k - p]).collect();
        for r in 1..=p {
            for j in (r..=p).rev() {
                let i = j + k - p;
                let a = (x - d.knots[i]) / (d.knots[i + p + 1 - r] - d.knots[i]);
                c[j] = (1.0 - a) * c[j - 1] + a * c[j];
            }
        }
        c[p]
    }

    fn spline(p: usize, interior: &[(f64, usize)], seed: u64) -> SplineData<f64> {
        let mut knots = vec![0.0; p + 1];
        for &(u, m) in interior {
            knots.extend(std::iter::repeat_n(u, m));
        }
        knots.extend(vec![10.0; p + 1]);
        let n = knots.len() - p - 1;
        let coefficients = (0..n).map(|i| ((i as u64 * 7919 + seed) % 23) as f64 - 11.0).collect();
        SplineData { degree: p, knots, coefficients }
    }

    #[test]
    fn elevation_keeps_the_curve_and_raises_every_multiplicity_by_t() {
        let cases: Vec<(usize, Vec<(f64, usize)>)> = vec![
            (1, vec![(2.0, 1), (5.0, 1)]),
            (2, vec![(1.0, 1), (3.0, 2), (7.0, 1)]),
            (3, vec![(1.0, 1), (2.0, 3), (4.0, 2), (6.0, 1), (8.0, 4)]),
            (4, vec![(5.0, 5), (6.0, 1)]),
            (3, vec![]),
            (0, vec![(3.0, 1), (4.0, 1)]),
        ];
        for (p, interior) in cases {
            let d = spline(p, &interior, 3);
            for t in 1..4 {
                let e = elevate_degree(&d, t).unwrap();
                assert_eq!(e.degree, p + t);
                for k in 0..=200 {
                    let x = 10.0 * k as f64 / 200.0;
                    let (a, b) = (de_boor(&d, x), de_boor(&e, x));
                    assert!((a - b).abs() < 1e-9, "p = {p}, t = {t}, x = {x}: {a} vs {b}");
                }
                for &(u, m) in &interior {
                    let count = e.knots.iter().filter(|&&k| k == u).count();
                    assert_eq!(count, (m + t).min(p + t + 1), "p = {p}, t = {t}, knot {u}");
                }
                assert_eq!(e.knots.len(), e.coefficients.len() + p + t + 1);
            }
        }
    }

    /// Many knots: the result has as many segments as the input, each still a Bézier
    /// segment of the elevated curve.
    #[test]
    fn long_knot_vectors_elevate_to_the_same_segments() {
        let interior: Vec<(f64, usize)> = (1..2000).map(|i| (i as f64 * 10.0 / 2000.0, 1)).collect();
        let d = spline(3, &interior, 5);
        let e = elevate_degree(&d, 2).unwrap();
        assert_eq!(bezier_segments(&e).unwrap().len(), 2000);
        for k in 0..=1000 {
            let x = 10.0 * k as f64 / 1000.0;
            assert!((de_boor(&d, x) - de_boor(&e, x)).abs() < 1e-9);
        }
    }
}
