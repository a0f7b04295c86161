//! Lane–Riesenfeld subdivision of any degree d: each step doubles every point and then
//! averages neighbours d times. Its limit is the uniform B-spline of degree d on the
//! initial control polygon (periodic for closed polygons, unclamped for open ones): one
//! step is exactly midpoint knot insertion.

use crate::Point;
use crate::curve::BSplineCurve;
use crate::error::{Error, Result, check_degree, check_points_finite};

/// Upper bound on the number of output points a call may produce.
pub const MAX_POINTS: usize = 50_000_000;

/// Validates a control polygon: finite points, at least `min` of them, and an output of
/// `factor`^`steps` times the input that stays below [`MAX_POINTS`].
pub(crate) fn check_polygon<const D: usize>(
    points: &[Point<D>],
    min: usize,
    what: &str,
    steps: usize,
    factor: usize,
) -> Result<()> {
    check_points_finite("points", points)?;
    if points.len() < min {
        return Err(Error::count("points", format!("at least {min} points{what}"), points.len()));
    }
    check_output_size(points.len(), steps, factor, "steps")
}

fn check_output_size(n: usize, steps: usize, factor: usize, field: &str) -> Result<()> {
    let mut total = n;
    for _ in 0..steps {
        total = total.saturating_mul(factor);
        if total > MAX_POINTS {
            return Err(Error::invalid(
                field,
                format!("{steps} steps on {n} points would produce more than {MAX_POINTS} points"),
            ));
        }
    }
    Ok(())
}

/// One or more Lane–Riesenfeld steps of degree `degree` ≥ 1.
///
/// Closed polygons (cyclic; the first point is not repeated at the end) of n points give
/// 2^k n points. Open polygons of n points give n_{k+1} = 2 n_k − d points after each step,
/// the control polygon of the same unclamped uniform B-spline on half-spaced knots.
///
/// # Examples
///
/// ```
/// use splinekit::Point;
/// use splinekit::subdivision::{ChaikinOptions, chaikin, lane_riesenfeld};
/// // Degree 2 is Chaikin's corner cutting.
/// let p: Vec<Point<2>> = [[0.0, 0.0], [2.0, 0.0], [2.0, 1.0], [0.0, 3.0]].iter().map(|&[x, y]| Point::<2>::new(x, y)).collect();
/// let lr = lane_riesenfeld(&p, 2, 2, true).unwrap();
/// let ch = chaikin(&p, 2, ChaikinOptions { closed: true, keep_ends: false }).unwrap();
/// assert_eq!(lr.len(), 16);
/// assert!(lr.iter().all(|q| ch.iter().any(|c| (c - q).norm() < 1e-15)));
/// ```
pub fn lane_riesenfeld<const D: usize>(
    points: &[Point<D>],
    degree: usize,
    steps: usize,
    closed: bool,
) -> Result<Vec<Point<D>>> {
    check_degree(degree)?;
    let min = if closed { 2 } else { degree + 1 };
    check_polygon(points, min, &format!(" for degree {degree}"), steps, 2)?;
    let mut p = points.to_vec();
    for _ in 0..steps {
        let mut q = Vec::with_capacity(2 * p.len());
        for v in &p {
            q.push(*v);
            q.push(*v);
        }
        for _ in 0..degree {
            if closed {
                let first = q[0];
                let len = q.len();
                for i in 0..len - 1 {
                    q[i] = (q[i] + q[i + 1]) * 0.5;
                }
                q[len - 1] = (q[len - 1] + first) * 0.5;
            } else {
                for i in 0..q.len() - 1 {
                    q[i] = (q[i] + q[i + 1]) * 0.5;
                }
                q.pop();
            }
        }
        p = q;
    }
    Ok(p)
}

/// The limit curve of [`lane_riesenfeld`]: the uniform B-spline of degree d on the
/// polygon, with knot spacing 1 (periodic for closed polygons, unclamped on [d, n] for
/// open ones).
pub fn lane_riesenfeld_limit<const D: usize>(
    points: &[Point<D>],
    degree: usize,
    closed: bool,
) -> Result<BSplineCurve<D>> {
    let n = points.len();
    let knots: Vec<f64> = (0..n + degree + 1).map(|i| i as f64).collect();
    if closed {
        BSplineCurve::new_periodic(degree, knots, points.to_vec())
    } else {
        BSplineCurve::new(degree, knots, points.to_vec())
    }
}
