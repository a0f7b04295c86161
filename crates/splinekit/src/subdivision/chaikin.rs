//! Chaikin's corner cutting: every edge P_i P_{i+1} is replaced by the points
//! ¾P_i + ¼P_{i+1} and ¼P_i + ¾P_{i+1}. The limit is the uniform quadratic B-spline
//! (Chaikin is Lane–Riesenfeld of degree 2).

use crate::Point;
use crate::error::Result;
use crate::subdivision::lane_riesenfeld::check_polygon;

/// Options of [`chaikin`]; the default is an open polygon whose ends are cut like the
/// rest.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct ChaikinOptions {
    /// The polygon is cyclic (its first point is not repeated at the end).
    pub closed: bool,
    /// Open polygons: keep the two end points, so the limit curve starts and ends there.
    pub keep_ends: bool,
}

/// `steps` rounds of corner cutting. Closed polygons (cyclic) of n points give 2n points
/// per step; open ones of n points give 2(n − 1), or 2(n − 1) + 2 when the ends are kept.
///
/// # Examples
///
/// ```
/// use splinekit::Point;
/// use splinekit::subdivision::{ChaikinOptions, chaikin};
/// let square = [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]].map(|[x, y]| Point::<2>::new(x, y));
/// let cut = chaikin(&square, 1, ChaikinOptions { closed: true, ..Default::default() }).unwrap();
/// assert_eq!(cut.len(), 8);
/// assert_eq!((cut[0], cut[1]), (Point::<2>::new(0.25, 0.0), Point::<2>::new(0.75, 0.0)));
/// ```
pub fn chaikin<const D: usize>(points: &[Point<D>], steps: usize, options: ChaikinOptions) -> Result<Vec<Point<D>>> {
    let ChaikinOptions { closed, keep_ends } = options;
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
