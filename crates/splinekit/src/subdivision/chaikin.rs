//! Chaikin's corner cutting: every edge P_i P_{i+1} is replaced by the points
//! ¾P_i + ¼P_{i+1} and ¼P_i + ¾P_{i+1}. The limit is the uniform quadratic B-spline
//! (Chaikin is Lane–Riesenfeld of degree 2).

use crate::Point;
use crate::error::Result;
use crate::subdivision::lane_riesenfeld::check_polygon;

/// `steps` rounds of corner cutting. Closed polygons (cyclic) of n points give 2n points
/// per step; open ones of n points give 2(n − 1), or 2(n − 1) + 2 with `keep_ends`, which
/// keeps the two end points so the limit curve starts and ends there.
pub fn chaikin<const D: usize>(
    points: &[Point<D>],
    steps: usize,
    closed: bool,
    keep_ends: bool,
) -> Result<Vec<Point<D>>> {
    check_polygon(points, if closed { 3 } else { 2 }, "", steps, 2)?;
    let mut p = points.to_vec();
    for _ in 0..steps {
        let n = p.len();
        let edges = if closed { n } else { n - 1 };
        let mut q = Vec::with_capacity(2 * n + 2);
        if keep_ends && !closed {
            q.push(p[0]);
        }
        for i in 0..edges {
            let (a, b) = (p[i], p[(i + 1) % n]);
            q.push(a * 0.75 + b * 0.25);
            q.push(a * 0.25 + b * 0.75);
        }
        if keep_ends && !closed {
            q.push(p[n - 1]);
        }
        p = q;
    }
    Ok(p)
}
