//! Parameters for data points and knot vectors for fitting.

use crate::Point;
use crate::error::{Error, Result};

/// How data points get their parameters on [0, 1].
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Parametrization {
    /// t_i = i/(m − 1) (closed: i/m).
    Uniform,
    /// Proportional to accumulated chord length |Q_i − Q_{i−1}|.
    #[default]
    ChordLength,
    /// Proportional to accumulated √|Q_i − Q_{i−1}| (Lee's centripetal method).
    Centripetal,
}

/// How the knot vector of a fit is placed.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum KnotPlacement {
    /// Uniform knots on [0, 1].
    Uniform,
    /// Knots averaged from the parameters (NURBS Book eq. 9.68–9.69), so every knot
    /// span holds data: the Schoenberg–Whitney condition holds for any n ≤ m.
    #[default]
    Averaged,
}

/// Parameters of the points on [0, 1]. For `closed` data the segment from the last point
/// back to the first counts too, so the parameters lie in [0, 1) and t = 1 is the first
/// point again.
pub fn parametrize<const D: usize>(points: &[Point<D>], method: Parametrization, closed: bool) -> Result<Vec<f64>> {
    let m = points.len();
    if m < 2 {
        return Err(Error::count("points", "at least 2 points", m));
    }
    let segments = if closed { m } else { m - 1 };
    let gap = |i: usize| -> f64 {
        let d = (points[(i + 1) % m] - points[i]).norm();
        match method {
            Parametrization::Uniform => 1.0,
            Parametrization::ChordLength => d,
            Parametrization::Centripetal => d.sqrt(),
        }
    };
    let mut t = vec![0.0; m];
    let mut total = 0.0;
    for i in 0..segments {
        total += gap(i);
        if i + 1 < m {
            t[i + 1] = total;
        }
    }
    if !(total > 0.0 && total.is_finite()) {
        return Err(Error::invalid("points", "all points coincide; chord-length parameters are undefined"));
    }
    for (i, v) in t.iter_mut().enumerate() {
        *v = if method == Parametrization::Uniform { i as f64 / segments as f64 } else { *v / total };
    }
    if !closed {
        t[m - 1] = 1.0;
    }
    for i in 1..m {
        if t[i] <= t[i - 1] {
            return Err(Error::invalid(
                "points",
                format!(
                    "points {} and {i} coincide, so their parameters are equal; remove duplicates or use --params uniform",
                    i - 1
                ),
            ));
        }
    }
    Ok(t)
}

/// Checks the counts a fit's knots are placed for: degree `p` needs at least p + 1 control
/// points, and `n` control points need at least `n` data points (here `m` parameters), so
/// that every knot span can hold data.
pub(crate) fn check_counts(p: usize, n: usize, m: usize) -> Result<()> {
    if n < p + 1 {
        return Err(Error::invalid(
            "control_points",
            format!("degree {p} needs at least {} control points, got {n}", p + 1),
        ));
    }
    if n > m {
        return Err(Error::invalid(
            "control_points",
            format!("{n} control points need at least {n} data points, got {m}"),
        ));
    }
    Ok(())
}

/// Clamped knots on [0, 1] for `n` control points of degree `p` fitted to parameters `t`
/// (p + 1 ≤ n ≤ the number of parameters; an error naming `control_points` otherwise).
pub fn fit_knots(t: &[f64], p: usize, n: usize, placement: KnotPlacement) -> Result<Vec<f64>> {
    check_counts(p, n, t.len())?;
    let mut knots = vec![0.0; p + 1];
    let inner = n - p - 1;
    match placement {
        KnotPlacement::Uniform => {
            for j in 1..=inner {
                knots.push(j as f64 / (inner + 1) as f64);
            }
        }
        KnotPlacement::Averaged => {
            let m = t.len();
            let d = m as f64 / (n - p) as f64;
            for j in 1..=inner {
                let x = j as f64 * d;
                let i = x.floor() as usize;
                let alpha = x - i as f64;
                knots.push((1.0 - alpha) * t[i - 1] + alpha * t[i.min(m - 1)]);
            }
        }
    }
    knots.extend(vec![1.0; p + 1]);
    Ok(knots)
}

/// Periodic knots t_0 … t_{n+p} with period 1 for `n` control points of degree `p`:
/// one period of knots s_0 = 0 < s_1 < … < s_{n−1} < 1 (uniform, or averaged from the
/// cyclic parameters), repeated (p + 1 ≤ n ≤ the number of parameters; an error naming
/// `control_points` otherwise).
pub fn periodic_knots(t: &[f64], p: usize, n: usize, placement: KnotPlacement) -> Result<Vec<f64>> {
    let m = t.len();
    check_counts(p, n, m)?;
    let s: Vec<f64> = match placement {
        KnotPlacement::Uniform => (0..n).map(|j| j as f64 / n as f64).collect(),
        KnotPlacement::Averaged => {
            let d = m as f64 / n as f64;
            (0..n)
                .map(|j| {
                    let x = j as f64 * d;
                    let i = x.floor() as usize;
                    let alpha = x - i as f64;
                    let next = if i + 1 < m { t[i + 1] } else { 1.0 + t[(i + 1) % m] };
                    (1.0 - alpha) * t[i] + alpha * next
                })
                .collect()
        }
    };
    Ok((0..n + p + 1)
        .map(|i| {
            let j = i as isize - p as isize;
            let r = j.rem_euclid(n as isize) as usize;
            s[r] + j.div_euclid(n as isize) as f64
        })
        .collect())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn knots_for_impossible_counts_are_refused_with_the_counts() {
        let t: Vec<f64> = (0..5).map(|i| i as f64 / 4.0).collect();
        for placement in [KnotPlacement::Uniform, KnotPlacement::Averaged] {
            for (p, n, expected) in [
                (3, 2, "control_points: degree 3 needs at least 4 control points, got 2"),
                (2, 0, "control_points: degree 2 needs at least 3 control points, got 0"),
                (3, 6, "control_points: 6 control points need at least 6 data points, got 5"),
            ] {
                for knots in [fit_knots(&t, p, n, placement), periodic_knots(&t, p, n, placement)] {
                    assert_eq!(knots.expect_err("impossible counts").to_string(), expected);
                }
            }
            // The extremes that are possible: n = p + 1 and n = m.
            assert_eq!(fit_knots(&t, 3, 4, placement).unwrap().len(), 8);
            assert_eq!(fit_knots(&t, 1, 5, placement).unwrap().len(), 7);
            assert_eq!(periodic_knots(&t, 3, 5, placement).unwrap().len(), 9);
        }
    }
}
