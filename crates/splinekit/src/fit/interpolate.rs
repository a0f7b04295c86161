//! Global B-spline interpolation (*The NURBS Book* §9.2): the curve passes through every
//! data point at its parameter; knots by averaging so the collocation matrix is
//! non-singular (Schoenberg–Whitney).

use crate::Point;
use crate::basis::{Side, basis_derivatives, find_span};
use crate::curve::{BSplineCurve, Curve};
use crate::error::{Error, Result, check_degree, check_points_finite};
use crate::fit::banded_qr::BandedLeastSquares;
use crate::fit::parametrize::{Parametrization, parametrize};

/// Options of [`interpolate`].
#[derive(Debug, Clone, PartialEq)]
pub struct InterpolationOptions<const D: usize> {
    /// Degree p ≥ 1.
    pub degree: usize,
    /// Data parameters.
    pub params: Parametrization,
    /// Interpolate a closed (periodic) curve.
    pub closed: bool,
    /// Prescribed first derivatives c'(0), c'(1) at the ends (open curves).
    pub end_derivatives: Option<(Point<D>, Point<D>)>,
}

impl<const D: usize> InterpolationOptions<D> {
    /// Degree with chord-length parameters, open, free ends.
    pub fn new(degree: usize) -> Self {
        InterpolationOptions { degree, params: Parametrization::ChordLength, closed: false, end_derivatives: None }
    }
}

/// An interpolating curve and the parameters of the data points.
#[derive(Debug, Clone)]
pub struct Interpolation<const D: usize> {
    /// The interpolating B-spline.
    pub curve: BSplineCurve<D>,
    /// c(`params[i]`) = `points[i]`.
    pub params: Vec<f64>,
}

/// Interpolates `points` by a B-spline of the given degree.
///
/// * Open: n = m control points, clamped knots on [0, 1] with interior knots
///   u_{j+p} = (1/p) Σ_{i=j}^{j+p−1} t_i; with end derivatives n = m + 2 and
///   u_{j+p} = (1/p) Σ_{i=j−1}^{j+p−2} t_i.
/// * Closed: n = m control points on a periodic knot vector of period 1 with knots at the
///   parameters (odd p) or midway between them (even p).
///
/// # Examples
///
/// ```
/// use splinekit::Point;
/// use splinekit::curve::Curve;
/// use splinekit::fit::{InterpolationOptions, interpolate};
/// let points: Vec<Point<2>> = [[0.0, 0.0], [1.0, 2.0], [2.0, 1.0], [3.0, 3.0], [4.0, 0.0]]
///     .iter()
///     .map(|&[x, y]| Point::<2>::new(x, y))
///     .collect();
/// let i = interpolate(&points, &InterpolationOptions::new(3)).unwrap();
/// for (t, q) in i.params.iter().zip(&points) {
///     assert!((i.curve.point(*t) - q).norm() < 1e-14);
/// }
/// ```
pub fn interpolate<const D: usize>(points: &[Point<D>], options: &InterpolationOptions<D>) -> Result<Interpolation<D>> {
    check_points_finite("points", points)?;
    let p = options.degree;
    let m = points.len();
    check_degree(p)?;
    if m < p + 1 {
        return Err(Error::invalid(
            "points",
            format!("degree {p} interpolation needs at least {} points, got {m}", p + 1),
        ));
    }
    if options.closed && options.end_derivatives.is_some() {
        return Err(Error::invalid("end_derivatives", "a closed curve has no ends"));
    }
    if let Some((a, b)) = &options.end_derivatives {
        check_points_finite("end_derivatives", &[*a, *b])?;
    }
    let t = parametrize(points, options.params, options.closed)?;
    if options.closed {
        let s: Vec<f64> = (0..m)
            .map(|j| {
                let next = if j + 1 < m { t[j + 1] } else { 1.0 + t[0] };
                if p % 2 == 1 { t[j] } else { (t[j] + next) / 2.0 }
            })
            .collect();
        let knots: Vec<f64> = (0..m + p + 1)
            .map(|i| {
                let j = i as isize - p as isize;
                s[j.rem_euclid(m as isize) as usize] + j.div_euclid(m as isize) as f64
            })
            .collect();
        let template = BSplineCurve::new_periodic(p, knots, vec![Point::<D>::zeros(); m])?;
        let rows: Vec<(f64, usize, Point<D>)> = t.iter().zip(points).map(|(&ti, q)| (ti, 0, *q)).collect();
        let curve = solve(&template, &rows, true)?;
        return Ok(Interpolation { curve, params: t });
    }
    let with_derivs = options.end_derivatives.is_some();
    let n = if with_derivs { m + 2 } else { m };
    let mut knots = vec![0.0; p + 1];
    for j in 1..n - p {
        let range = if with_derivs { (j - 1)..(j + p - 1) } else { j..(j + p) };
        knots.push(t[range].iter().sum::<f64>() / p as f64);
    }
    knots.extend(vec![1.0; p + 1]);
    let template = BSplineCurve::new(p, knots, vec![Point::<D>::zeros(); n])?;
    let mut rows: Vec<(f64, usize, Point<D>)> = Vec::with_capacity(n);
    if let Some((d0, d1)) = options.end_derivatives {
        rows.push((0.0, 1, d0));
        rows.extend(t.iter().zip(points).map(|(&ti, q)| (ti, 0, *q)));
        rows.push((1.0, 1, d1));
    } else {
        rows.extend(t.iter().zip(points).map(|(&ti, q)| (ti, 0, *q)));
    }
    let curve = solve(&template, &rows, false)?;
    Ok(Interpolation { curve, params: t })
}

/// Solves the square collocation system: row (t, k, v) asks c^{(k)}(t) = v.
fn solve<const D: usize>(
    template: &BSplineCurve<D>,
    rows: &[(f64, usize, Point<D>)],
    periodic: bool,
) -> Result<BSplineCurve<D>> {
    let p = template.degree();
    let n = template.control_points().len();
    let dom = template.domain();
    let (knots, eval_pts) = template.evaluation_data();
    let mut ls = BandedLeastSquares::<D>::new(n, p + 1, if periodic { p } else { 0 });
    let mut ders = vec![0.0; 2 * (p + 1)];
    for &(t, k, v) in rows {
        let t = if periodic { dom.wrap(t) } else { t };
        let span = find_span(knots, p, eval_pts.len(), t, Side::Right);
        basis_derivatives(knots, p, span, t, k, &mut ders);
        ls.add_row((span - p) % n, &ders[k * (p + 1)..(k + 1) * (p + 1)], v);
    }
    let sol = ls.solve().map_err(|_| {
        Error::numerical("interpolate", "the collocation matrix is singular (repeated or badly spread points)")
    })?;
    let knots = template.knots().to_vec();
    if periodic { BSplineCurve::new_periodic(p, knots, sol.x) } else { BSplineCurve::new(p, knots, sol.x) }
}
