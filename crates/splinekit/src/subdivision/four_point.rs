//! The interpolatory 4-point scheme of Dyn, Levin and Gregory: old points stay, and each
//! edge gets P_{2i+1} = (½ + w)(P_i + P_{i+1}) − w(P_{i−1} + P_{i+2}); w = 1/16 gives the
//! classic C¹ scheme, reproducing cubics.

use crate::Point;
use crate::error::{Error, Result, check_points_finite};
use crate::subdivision::lane_riesenfeld::check_polygon;

/// Options of [`four_point`]; the default is an open polygon and the classic tension 1/16.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FourPointOptions {
    /// The polygon is cyclic (its first point is not repeated at the end).
    pub closed: bool,
    /// The tension w, 0 < w < 1/4 (below 1/8 for a C¹ limit).
    pub tension: f64,
}

impl Default for FourPointOptions {
    fn default() -> Self {
        FourPointOptions { closed: false, tension: 1.0 / 16.0 }
    }
}

/// `steps` rounds of the 4-point scheme. Closed polygons are cyclic (n → 2n points); open
/// ones (n → 2n − 1) use the reflected neighbours P_{−1} = 2P_0 − P_1 and
/// P_n = 2P_{n−1} − P_{n−2} at the ends.
///
/// # Examples
///
/// ```
/// use splinekit::Point;
/// use splinekit::subdivision::{FourPointOptions, four_point};
/// // Points on a cubic stay on it (w = 1/16 reproduces cubics): y = x³ at x = 0 … 3.
/// let p: Vec<Point<2>> = (0..4).map(|i| Point::<2>::new(i as f64, (i * i * i) as f64)).collect();
/// let q = four_point(&p, 1, FourPointOptions::default()).unwrap();
/// assert_eq!(q[0], p[0]);
/// assert!((q[3] - Point::<2>::new(1.5, 3.375)).norm() < 1e-14);
/// ```
pub fn four_point<const D: usize>(
    points: &[Point<D>],
    steps: usize,
    options: FourPointOptions,
) -> Result<Vec<Point<D>>> {
    let FourPointOptions { closed, tension: w } = options;
    check_points_finite("points", points)?;
    if !(w.is_finite() && w > 0.0 && w < 0.25) {
        return Err(Error::invalid("tension", format!("must be in (0, 1/4), got {w}")));
    }
    check_polygon(points, if closed { 3 } else { 2 }, "", steps, 2)?;
    let mut p = points.to_vec();
    for _ in 0..steps {
        let n = p.len();
        let at = |i: isize| -> Point<D> {
            if closed {
                p[i.rem_euclid(n as isize) as usize]
            } else if i < 0 {
                p[0] * 2.0 - p[1]
            } else if i >= n as isize {
                p[n - 1] * 2.0 - p[n - 2]
            } else {
                p[i as usize]
            }
        };
        let edges = if closed { n } else { n - 1 };
        let mut q = Vec::with_capacity(2 * n);
        for i in 0..edges as isize {
            q.push(at(i));
            q.push((at(i) + at(i + 1)) * (0.5 + w) - (at(i - 1) + at(i + 2)) * w);
        }
        if !closed {
            q.push(p[n - 1]);
        }
        p = q;
    }
    Ok(p)
}
