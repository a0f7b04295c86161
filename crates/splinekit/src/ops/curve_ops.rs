//! Knot operations as methods of [`BSplineCurve`] and [`NurbsCurve`]. Periodic curves stay
//! periodic (the operation is applied to every periodic image of a knot); clamping,
//! splitting and Bézier decomposition open them.

use crate::Interval;
use crate::Point;
use crate::curve::{BSplineCurve, BezierCurve, NurbsCurve, RationalBezierCurve};
use crate::error::{Error, Result};
use crate::ops::decomposition::{self, BezierSegment};
use crate::ops::degree_elevation::elevate_degree;
use crate::ops::homogeneous::{CoefficientNorm, Homogeneous};
use crate::ops::knot_insertion::{insert_knot, refine};
use crate::ops::knot_removal::remove_knot;
use crate::ops::spline_data::{SplineData, to_bspline, to_nurbs};

/// All images u + jT of `u` strictly inside the open interval of `data`'s domain, plus
/// the domain ends when they are images.
fn images<T: crate::Coefficient>(data: &SplineData<T>, u: f64, period: f64) -> Vec<f64> {
    let Interval { start: a, end: b } = data.domain();
    let base = u - ((u - a) / period).floor() * period;
    let mut out = Vec::new();
    let mut v = base;
    while v <= b {
        if v >= a {
            out.push(v);
        }
        v += period;
    }
    out
}

fn insert_generic<T: CoefficientNorm>(
    data: &SplineData<T>,
    periodic: bool,
    u: f64,
    times: usize,
) -> Result<SplineData<T>> {
    if !periodic {
        return insert_knot(data, u, times);
    }
    let Interval { start: a, end: b } = data.domain();
    if !(u >= a && u <= b) {
        return Err(Error::invalid("insert", format!("knot {u} is outside the domain [{a}, {b}]")));
    }
    data.map_periodic(|mut d, period| {
        for v in images(&d, u, period) {
            d = insert_knot(&d, v, times)?;
        }
        Ok(d)
    })
}

fn refine_generic<T: CoefficientNorm>(data: &SplineData<T>, periodic: bool, knots: &[f64]) -> Result<SplineData<T>> {
    if !periodic {
        return refine(data, knots);
    }
    let mut d = data.clone();
    for &u in knots {
        d = insert_generic(&d, true, u, 1)?;
    }
    Ok(d)
}

fn remove_generic<T: CoefficientNorm>(
    data: &SplineData<T>,
    periodic: bool,
    u: f64,
    times: usize,
    tol: f64,
) -> Result<(SplineData<T>, usize)> {
    if !periodic {
        return remove_knot(data, u, times, tol);
    }
    let mut removed = usize::MAX;
    let out = data.map_periodic(|mut d, period| {
        for v in images(&d, u, period) {
            let Interval { start: a, end: b } = d.domain();
            if v > a && v < b {
                let (next, r) = remove_knot(&d, v, times, tol)?;
                removed = removed.min(r);
                d = next;
            }
        }
        Ok(d)
    })?;
    let removed = if removed == usize::MAX { 0 } else { removed };
    Ok((out, removed))
}

fn elevate_generic<T: CoefficientNorm>(data: &SplineData<T>, periodic: bool, t: usize) -> Result<SplineData<T>> {
    if periodic { data.map_periodic(|d, _| elevate_degree(&d, t)) } else { elevate_degree(data, t) }
}

/// Cuts a periodic spline open at `u`: the clamped spline on [u, u + T].
fn open_at<T: CoefficientNorm>(data: &SplineData<T>, u: f64) -> Result<SplineData<T>> {
    let n = data.coefficients.len();
    let p = data.degree;
    let period = data.knots[n + p] - data.knots[p];
    let u0 = u - ((u - data.knots[p]) / period).floor() * period;
    let (unrolled, _) = data.unroll_periodic(2);
    let (_, right) = decomposition::split(&unrolled, u0)?;
    let (piece, _) = decomposition::split(&right, u0 + period)?;
    Ok(piece)
}

/// The clamped form on the domain: a periodic spline cut open at the start of its domain
/// (knot t_p), an open one with its end knots raised to full multiplicity.
fn clamp_generic<T: CoefficientNorm>(data: &SplineData<T>, periodic: bool) -> Result<SplineData<T>> {
    if periodic { open_at(data, data.knots[data.degree]) } else { decomposition::clamp(data) }
}

/// An open spline split at `u` into the splines on [start, u] and [u, end]; a periodic one
/// cut open at `u` instead (one spline on [u, u + T], no second piece).
fn split_generic<T: CoefficientNorm>(
    data: &SplineData<T>,
    periodic: bool,
    u: f64,
) -> Result<(SplineData<T>, Option<SplineData<T>>)> {
    if periodic {
        return Ok((open_at(data, u)?, None));
    }
    let (l, r) = decomposition::split(data, u)?;
    Ok((l, Some(r)))
}

/// The Bézier segments with their parameter intervals (a periodic spline cut open at the
/// start of its domain first).
fn segments_generic<T: CoefficientNorm>(data: &SplineData<T>, periodic: bool) -> Result<Vec<BezierSegment<T>>> {
    if periodic {
        decomposition::bezier_segments(&open_at(data, data.knots[data.degree])?)
    } else {
        decomposition::bezier_segments(data)
    }
}

fn check_removal_tolerance(tolerance: f64) -> Result<()> {
    if !(tolerance >= 0.0 && tolerance.is_finite()) {
        return Err(Error::invalid("tolerance", format!("must be finite and ≥ 0, got {tolerance}")));
    }
    Ok(())
}

impl<const D: usize> BSplineCurve<D> {
    fn data(&self) -> SplineData<Point<D>> {
        SplineData::from(self)
    }
    /// Inserts knot `u` `times` times (Boehm); the curve is unchanged.
    ///
    /// # Examples
    ///
    /// ```
    /// use splinekit::Point;
    /// use splinekit::curve::{BSplineCurve, Curve};
    /// let p = |x, y| Point::<2>::new(x, y);
    /// let c = BSplineCurve::clamped_uniform(3, vec![p(0.0, 0.0), p(1.0, 2.0), p(2.0, -1.0), p(4.0, 1.0), p(5.0, 0.0)]).unwrap();
    /// let same = |a: &BSplineCurve<2>, b: &BSplineCurve<2>| (0..=20).all(|i| (a.point(i as f64 / 20.0) - b.point(i as f64 / 20.0)).norm() < 1e-14);
    /// let k = c.insert_knot(0.3, 2).unwrap();
    /// assert_eq!(k.control_points().len(), 7);
    /// assert!(same(&c, &k));
    /// ```
    pub fn insert_knot(&self, u: f64, times: usize) -> Result<Self> {
        to_bspline(insert_generic(&self.data(), self.is_periodic(), u, times)?, self.is_periodic())
    }
    /// Inserts all of `knots` (knot refinement); the curve is unchanged.
    pub fn refine(&self, knots: &[f64]) -> Result<Self> {
        to_bspline(refine_generic(&self.data(), self.is_periodic(), knots)?, self.is_periodic())
    }
    /// Removes the interior knot `u` up to `times` times while the curve moves by at most
    /// `tolerance`; returns the curve and the number of removals.
    ///
    /// # Examples
    ///
    /// ```
    /// use splinekit::Point;
    /// use splinekit::curve::{BSplineCurve, Curve};
    /// let p = |x, y| Point::<2>::new(x, y);
    /// let c = BSplineCurve::clamped_uniform(3, vec![p(0.0, 0.0), p(1.0, 2.0), p(2.0, -1.0), p(4.0, 1.0), p(5.0, 0.0)]).unwrap();
    /// let same = |a: &BSplineCurve<2>, b: &BSplineCurve<2>| (0..=20).all(|i| (a.point(i as f64 / 20.0) - b.point(i as f64 / 20.0)).norm() < 1e-14);
    /// // A knot just inserted comes out again, as often as it went in.
    /// let (back, removed) = c.insert_knot(0.3, 2).unwrap().remove_knot(0.3, 2, 1e-12).unwrap();
    /// assert_eq!((removed, back.control_points().len()), (2, 5));
    /// assert!(same(&c, &back));
    /// ```
    pub fn remove_knot(&self, u: f64, times: usize, tolerance: f64) -> Result<(Self, usize)> {
        check_removal_tolerance(tolerance)?;
        let (d, r) = remove_generic(&self.data(), self.is_periodic(), u, times, tolerance)?;
        Ok((to_bspline(d, self.is_periodic())?, r))
    }
    /// Raises the degree by `t`; the curve is unchanged.
    ///
    /// # Examples
    ///
    /// ```
    /// use splinekit::Point;
    /// use splinekit::curve::{BSplineCurve, Curve};
    /// let p = |x, y| Point::<2>::new(x, y);
    /// let c = BSplineCurve::clamped_uniform(3, vec![p(0.0, 0.0), p(1.0, 2.0), p(2.0, -1.0), p(4.0, 1.0), p(5.0, 0.0)]).unwrap();
    /// let same = |a: &BSplineCurve<2>, b: &BSplineCurve<2>| (0..=20).all(|i| (a.point(i as f64 / 20.0) - b.point(i as f64 / 20.0)).norm() < 1e-14);
    /// let e = c.elevate_degree(2).unwrap();
    /// assert_eq!(e.degree(), 5);
    /// assert!(same(&c, &e));
    /// ```
    pub fn elevate_degree(&self, t: usize) -> Result<Self> {
        to_bspline(elevate_generic(&self.data(), self.is_periodic(), t)?, self.is_periodic())
    }
    /// The same curve with clamped knots on its domain (a periodic curve is cut open at
    /// the start of its domain).
    pub fn clamped(&self) -> Result<Self> {
        to_bspline(clamp_generic(&self.data(), self.is_periodic())?, false)
    }
    /// Splits at `u` into the curves on [start, u] and [u, end]. A periodic curve is cut
    /// open at `u` instead: the result is one open curve on [u, u + T] (returned twice is
    /// not useful, so the second element is `None`).
    ///
    /// # Examples
    ///
    /// ```
    /// use splinekit::Point;
    /// use splinekit::curve::{BSplineCurve, Curve};
    /// let p = |x, y| Point::<2>::new(x, y);
    /// let c = BSplineCurve::clamped_uniform(3, vec![p(0.0, 0.0), p(1.0, 2.0), p(2.0, -1.0), p(4.0, 1.0), p(5.0, 0.0)]).unwrap();
    /// let same = |a: &BSplineCurve<2>, b: &BSplineCurve<2>| (0..=20).all(|i| (a.point(i as f64 / 20.0) - b.point(i as f64 / 20.0)).norm() < 1e-14);
    /// let (left, right) = c.split(0.4).unwrap();
    /// let right = right.unwrap();
    /// assert_eq!((left.domain().end, right.domain().start), (0.4, 0.4));
    /// assert!((left.point(0.25) - c.point(0.25)).norm() < 1e-14 && (right.point(0.7) - c.point(0.7)).norm() < 1e-14);
    /// ```
    pub fn split(&self, u: f64) -> Result<(Self, Option<Self>)> {
        let (l, r) = split_generic(&self.data(), self.is_periodic(), u)?;
        Ok((to_bspline(l, false)?, r.map(|r| to_bspline(r, false)).transpose()?))
    }
    /// The Bézier segments of the curve, each with its parameter interval.
    pub fn bezier_segments(&self) -> Result<Vec<(Interval, BezierCurve<D>)>> {
        segments_generic(&self.data(), self.is_periodic())?
            .into_iter()
            .map(|BezierSegment { interval, control_points }| Ok((interval, BezierCurve::new(control_points)?)))
            .collect()
    }
}

impl<const D: usize> NurbsCurve<D> {
    fn data(&self) -> SplineData<Homogeneous<D>> {
        SplineData::from(self)
    }
    /// Inserts knot `u` `times` times; the curve is unchanged.
    pub fn insert_knot(&self, u: f64, times: usize) -> Result<Self> {
        to_nurbs(insert_generic(&self.data(), self.is_periodic(), u, times)?, self.is_periodic())
    }
    /// Inserts all of `knots`; the curve is unchanged.
    pub fn refine(&self, knots: &[f64]) -> Result<Self> {
        to_nurbs(refine_generic(&self.data(), self.is_periodic(), knots)?, self.is_periodic())
    }
    /// Removes `u` up to `times` times within `tolerance` (NURBS Book: the homogeneous
    /// test uses tolerance · w_min / (1 + max |P|), which bounds the curve's deviation).
    pub fn remove_knot(&self, u: f64, times: usize, tolerance: f64) -> Result<(Self, usize)> {
        check_removal_tolerance(tolerance)?;
        let wmin = self.weights().iter().copied().fold(f64::INFINITY, f64::min);
        let pmax = self.control_points().iter().map(|p| p.norm()).fold(0.0, f64::max);
        let tol = tolerance * wmin / (1.0 + pmax);
        let (d, r) = remove_generic(&self.data(), self.is_periodic(), u, times, tol)?;
        Ok((to_nurbs(d, self.is_periodic())?, r))
    }
    /// Raises the degree by `t`; the curve is unchanged.
    pub fn elevate_degree(&self, t: usize) -> Result<Self> {
        to_nurbs(elevate_generic(&self.data(), self.is_periodic(), t)?, self.is_periodic())
    }
    /// Clamped form on the domain (periodic curves are cut open at the domain start).
    pub fn clamped(&self) -> Result<Self> {
        to_nurbs(clamp_generic(&self.data(), self.is_periodic())?, false)
    }
    /// Splits at `u`; see [`BSplineCurve::split`].
    pub fn split(&self, u: f64) -> Result<(Self, Option<Self>)> {
        let (l, r) = split_generic(&self.data(), self.is_periodic(), u)?;
        Ok((to_nurbs(l, false)?, r.map(|r| to_nurbs(r, false)).transpose()?))
    }
    /// The rational Bézier segments with their parameter intervals.
    pub fn bezier_segments(&self) -> Result<Vec<(Interval, RationalBezierCurve<D>)>> {
        segments_generic(&self.data(), self.is_periodic())?
            .into_iter()
            .map(|BezierSegment { interval, control_points }| {
                let pts = control_points.iter().map(|h| h.project()).collect();
                let ws = control_points.iter().map(|h| h.weight).collect();
                Ok((interval, RationalBezierCurve::new(pts, ws)?))
            })
            .collect()
    }
}
