//! B-spline curves fitted to intersection branches.
//!
//! Method: least squares ([`crate::fit::fit`], chord-length parameters, averaged knots) of a
//! cubic to the branch's points (a closed branch: a periodic cubic to its points without the
//! repeated last one), with 8 control points, doubled until the largest distance from a
//! point to its fitted image is within the tolerance or the control points would reach half
//! the points (then the fit with most control points is returned, its error stated).
//! Consecutive points closer than 10⁻¹² of the coordinates' size count once.

use crate::Point;
use crate::error::{Error, Result};
use crate::fit::{Fit, FitOptions, fit};
use crate::query::branch::IntersectionBranch;

impl IntersectionBranch {
    /// A cubic B-spline within `tolerance` (> 0) of every point of the branch where the
    /// branch has enough points for it (see the module documentation); `max_error` of the
    /// answer says how close it came.
    pub fn fit_bspline(&self, tolerance: f64) -> Result<Fit<3>> {
        if !(tolerance > 0.0 && tolerance.is_finite()) {
            return Err(Error::invalid("tolerance", format!("must be finite and > 0, got {tolerance}")));
        }
        let all: &[Point<3>] =
            if self.closed && self.points.len() > 1 { &self.points[..self.points.len() - 1] } else { &self.points };
        // Consecutive points that coincide (a step ending on a boundary it started on) would
        // get equal chord-length parameters: keep one of them.
        let scale = all.iter().fold(0.0f64, |m, p| m.max(p.amax())).max(f64::MIN_POSITIVE);
        let mut pts: Vec<Point<3>> = Vec::with_capacity(all.len());
        for p in all {
            if pts.last().is_none_or(|q: &Point<3>| (p - q).norm() > 1e-12 * scale) {
                pts.push(*p);
            }
        }
        let pts = &pts[..];
        if pts.len() < 2 {
            return Err(Error::invalid("points", format!("a branch needs 2 points to fit, has {}", pts.len())));
        }
        let degree = 3.min(pts.len() - 1);
        let most = (pts.len() / 2).max(degree + 1);
        let mut n = 8.min(most).max(degree + 1);
        loop {
            let options =
                FitOptions { closed: self.closed, interpolate_ends: !self.closed, ..FitOptions::new(degree, n) };
            let f = fit(pts, &options)?;
            if f.max_error <= tolerance || n >= most {
                return Ok(f);
            }
            n = (2 * n).min(most);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::curve::Curve;

    #[test]
    fn a_polyline_on_a_circle_fits_a_closed_cubic_within_the_tolerance() {
        let m = 400;
        let points: Vec<Point<3>> = (0..=m)
            .map(|k| {
                let a = std::f64::consts::TAU * (k % m) as f64 / m as f64;
                Point::<3>::new(2.0 * a.cos(), 2.0 * a.sin(), 0.5)
            })
            .collect();
        let branch = IntersectionBranch { points, closed: true, ..Default::default() };
        let f = branch.fit_bspline(1e-6).unwrap();
        assert!(f.max_error <= 1e-6 && f.curve.is_closed(), "error {}", f.max_error);
        for k in 0..100 {
            let p = f.curve.point(f.curve.domain().lerp(k as f64 / 100.0));
            assert!(((p.x * p.x + p.y * p.y).sqrt() - 2.0).abs() < 1e-6 && (p.z - 0.5).abs() < 1e-9);
        }
    }
}
