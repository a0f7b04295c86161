//! Least-squares B-spline approximation of sampled points.
//!
//! Minimises Σ_i (w_i |c(t_i) − Q_i|)² over the control points of a B-spline with given
//! degree and knots (the problem scipy's `make_lsq_spline` solves), by banded QR; see
//! [`super::banded_qr`].

use smallvec::SmallVec;

use crate::Point;
use crate::basis::{advance_span, basis_functions};
use crate::curve::{BSplineCurve, Curve};
use crate::error::{Error, Result, check_degree, check_finite, check_points_finite};
use crate::fit::banded_qr::{BandedLeastSquares, Solution};
use crate::fit::parametrize::{KnotPlacement, Parametrization, check_counts, fit_knots, parametrize, periodic_knots};

/// A fitted curve with its data parameters and quality figures.
#[derive(Debug, Clone)]
pub struct Fit<const D: usize> {
    /// The fitted B-spline.
    pub curve: BSplineCurve<D>,
    /// The parameter of each data point.
    pub params: Vec<f64>,
    /// √(Σ|c(t_i) − Q_i|² / m).
    pub rms_error: f64,
    /// max |c(t_i) − Q_i|.
    pub max_error: f64,
    /// max|R_kk|/min|R_kk| of the QR factor: a lower estimate of the condition number of
    /// the (weighted) collocation matrix.
    pub condition_estimate: f64,
}

/// Options of [`fit`].
#[derive(Debug, Clone, PartialEq)]
pub struct FitOptions {
    /// Degree p ≥ 1.
    pub degree: usize,
    /// Number of control points n (p + 1 ≤ n ≤ number of points).
    pub control_points: usize,
    /// Data parameters.
    pub params: Parametrization,
    /// Knot placement.
    pub knots: KnotPlacement,
    /// Fit a closed (periodic) curve.
    pub closed: bool,
    /// Make the (open) curve start and end exactly at the first and last data points.
    pub interpolate_ends: bool,
    /// Optional weights w_i ≥ 0 multiplying the residuals.
    pub weights: Option<Vec<f64>>,
}

impl FitOptions {
    /// The options of [`fit_with_knots`] with these settings on `knots`.
    fn with_knots(&self, knots: Vec<f64>) -> FitWithKnotsOptions {
        FitWithKnotsOptions {
            degree: self.degree,
            knots,
            closed: self.closed,
            interpolate_ends: self.interpolate_ends,
            weights: self.weights.clone(),
        }
    }

    /// Degree and control-point count, other options at their defaults (chord length,
    /// averaged knots, open, free ends, unweighted).
    pub fn new(degree: usize, control_points: usize) -> Self {
        FitOptions {
            degree,
            control_points,
            params: Parametrization::ChordLength,
            knots: KnotPlacement::Averaged,
            closed: false,
            interpolate_ends: false,
            weights: None,
        }
    }
}

/// Fits a B-spline to `points` as `options` say: parameters, knots, then
/// [`fit_with_knots`].
///
/// # Examples
///
/// ```
/// use splinekit::Point;
/// use splinekit::curve::Curve;
/// use splinekit::fit::{FitOptions, Parametrization, fit};
/// // Samples of the parabola y = x² at equal steps: with uniform parameters a quadratic
/// // reproduces it, whatever its knots.
/// let points: Vec<Point<2>> = (0..11).map(|i| i as f64 / 10.0).map(|x| Point::<2>::new(x, x * x)).collect();
/// let options = FitOptions { params: Parametrization::Uniform, ..FitOptions::new(2, 5) };
/// let f = fit(&points, &options).unwrap();
/// assert!(f.max_error < 1e-14);
/// assert!((f.curve.point(0.45) - Point::<2>::new(0.45, 0.2025)).norm() < 1e-14);
/// ```
pub fn fit<const D: usize>(points: &[Point<D>], options: &FitOptions) -> Result<Fit<D>> {
    check_points_finite("points", points)?;
    let (p, n, m) = (options.degree, options.control_points, points.len());
    check_degree(p)?;
    check_counts(p, n, m)?;
    let params = parametrize(points, options.params, options.closed)?;
    let knots = if options.closed {
        periodic_knots(&params, p, n, options.knots)?
    } else {
        fit_knots(&params, p, n, options.knots)?
    };
    fit_with_knots(points, &params, &options.with_knots(knots))
}

/// Options of [`fit_with_knots`]: the degree and the knot vector are given; the rest
/// defaults to an open, unweighted fit with free ends.
#[derive(Debug, Clone, PartialEq)]
pub struct FitWithKnotsOptions {
    /// Degree p ≥ 1.
    pub degree: usize,
    /// The knots: n + p + 1 values for n control points (a periodic knot vector, see
    /// [`BSplineCurve::new_periodic`], when `closed`).
    pub knots: Vec<f64>,
    /// Fit a closed (periodic) curve; parameters are wrapped into its domain.
    pub closed: bool,
    /// Open curves on clamped knots only: the first and last control points are the first
    /// and last data points; the rest are fitted.
    pub interpolate_ends: bool,
    /// Optional weights w_i ≥ 0 multiplying the residuals.
    pub weights: Option<Vec<f64>>,
}

impl FitWithKnotsOptions {
    /// Degree and knots, other options at their defaults (open, free ends, unweighted).
    pub fn new(degree: usize, knots: Vec<f64>) -> Self {
        FitWithKnotsOptions { degree, knots, closed: false, interpolate_ends: false, weights: None }
    }
}

/// Least-squares B-spline of the given degree on the given knots through `points` at
/// `params` (see [`FitWithKnotsOptions`]).
///
/// # Examples
///
/// ```
/// use splinekit::Point;
/// use splinekit::curve::Curve;
/// use splinekit::fit::{FitWithKnotsOptions, fit_with_knots};
/// // Points on the parabola y = x², fitted by a quadratic: reproduced exactly.
/// let params: Vec<f64> = (0..9).map(|i| i as f64 / 8.0).collect();
/// let points: Vec<Point<2>> = params.iter().map(|&t| Point::<2>::new(t, t * t)).collect();
/// let options = FitWithKnotsOptions::new(2, vec![0.0, 0.0, 0.0, 0.5, 1.0, 1.0, 1.0]);
/// let fit = fit_with_knots(&points, &params, &options).unwrap();
/// assert!(fit.max_error < 1e-14);
/// assert!((fit.curve.point(0.3) - Point::<2>::new(0.3, 0.09)).norm() < 1e-14);
/// ```
pub fn fit_with_knots<const D: usize>(
    points: &[Point<D>],
    params: &[f64],
    options: &FitWithKnotsOptions,
) -> Result<Fit<D>> {
    let weights = options.weights.as_deref();
    check_data(points, params, weights)?;
    let problem = KnotFit::new(options, params)?;
    let unknowns = problem.solve(points, params, weights)?;
    problem.finish(points, params, unknowns)
}

/// Checks the data of [`fit_with_knots`]: finite points, one finite parameter per point,
/// finite non-negative weights (an error naming the field otherwise). Callers that place
/// knots from the parameters ([`crate::fit::fit_knots`]) check the data first, so that a
/// wrong count is reported as such.
pub fn check_data<const D: usize>(points: &[Point<D>], params: &[f64], weights: Option<&[f64]>) -> Result<()> {
    check_points_finite("points", points)?;
    check_finite("params", params)?;
    let m = points.len();
    if params.len() != m {
        return Err(Error::count("params", format!("{m} values, one per point"), params.len()));
    }
    if let Some(w) = weights {
        if w.len() != m {
            return Err(Error::count("weights", format!("{m} values, one per point"), w.len()));
        }
        check_finite("weights", w)?;
        if let Some((i, v)) = w.iter().enumerate().find(|(_, v)| **v < 0.0) {
            return Err(Error::invalid("weights", format!("weight {i} is {v}, but weights must be ≥ 0")));
        }
    }
    Ok(())
}

/// The spline being fitted: its knots (as a template curve) and which control points are
/// unknowns.
struct KnotFit<const D: usize> {
    template: BSplineCurve<D>,
    degree: usize,
    /// Number of control points n.
    count: usize,
    periodic: bool,
    fixed_ends: bool,
}

impl<const D: usize> KnotFit<D> {
    /// Validates the knots against the degree, the parameters against the domain and the
    /// fixed ends against the knots.
    fn new(options: &FitWithKnotsOptions, params: &[f64]) -> Result<Self> {
        let (p, periodic, fixed_ends) = (options.degree, options.closed, options.interpolate_ends);
        let knots = options.knots.clone();
        if knots.len() < p + 2 {
            return Err(Error::count("knots", format!("at least {} values for degree {p}", p + 2), knots.len()));
        }
        let n = knots.len() - p - 1;
        let zeros = vec![Point::<D>::zeros(); n];
        let template =
            if periodic { BSplineCurve::new_periodic(p, knots, zeros)? } else { BSplineCurve::new(p, knots, zeros)? };
        let dom = template.domain();
        if !periodic && let Some((i, t)) = params.iter().enumerate().find(|(_, t)| **t < dom.start || **t > dom.end) {
            return Err(Error::invalid(
                "params",
                format!("parameter {i} ({t}) is outside the domain [{}, {}]", dom.start, dom.end),
            ));
        }
        let k = template.knots();
        if fixed_ends && (periodic || k[0] != k[p] || k[n] != k[n + p]) {
            return Err(Error::invalid("interpolate_ends", "needs an open curve with clamped knots"));
        }
        Ok(KnotFit { template, degree: p, count: n, periodic, fixed_ends })
    }

    /// The unknown control points by banded QR, one row per data point in parameter order
    /// (which keeps the fill of R bounded); fixed end points move to the right-hand side.
    fn solve(&self, points: &[Point<D>], params: &[f64], weights: Option<&[f64]>) -> Result<Solution<D>> {
        let (p, n, m) = (self.degree, self.count, points.len());
        let dom = self.template.domain();
        let (eval_knots, eval_pts) = self.template.evaluation_data();
        let (first_unknown, unknowns) = if self.fixed_ends { (1, n - 2) } else { (0, n) };
        let mut ls = BandedLeastSquares::<D>::new(unknowns, p + 1, if self.periodic { p } else { 0 });
        let mut order: Vec<usize> = (0..m).collect();
        let wrap = |t: f64| if self.periodic { dom.wrap(t) } else { t };
        if params.windows(2).any(|w| wrap(w[1]) < wrap(w[0])) {
            order.sort_by(|&a, &b| wrap(params[a]).total_cmp(&wrap(params[b])));
        }
        let mut basis: SmallVec<[f64; 16]> = SmallVec::from_elem(0.0, p + 1);
        let mut row: SmallVec<[f64; 16]> = SmallVec::new();
        let mut span = p;
        for &i in &order {
            let t = wrap(params[i]);
            // Rows come in parameter order: advance the span instead of searching.
            span = advance_span(eval_knots, p, eval_pts.len(), span, t);
            basis_functions(eval_knots, p, span, t, &mut basis);
            let w = weights.map_or(1.0, |w| w[i]);
            if w == 0.0 {
                continue;
            }
            let mut rhs = points[i] * w;
            let mut first = (span - p) % n;
            row.clear();
            for (r, b) in basis.iter().enumerate() {
                let col = (span - p + r) % n;
                if self.fixed_ends && col == 0 {
                    rhs -= points[0] * (b * w);
                    first = 1;
                } else if self.fixed_ends && col == n - 1 {
                    rhs -= points[m - 1] * (b * w);
                } else {
                    row.push(b * w);
                }
            }
            if !row.is_empty() {
                ls.add_row(first - first_unknown, &row, rhs);
            }
        }
        ls.solve().map_err(|e| match e {
            Error::Numerical { message, .. } => Error::numerical("fit", message.replace("unknown", "control point")),
            other => other,
        })
    }

    /// The fitted curve (fixed ends put back) and its errors at the data.
    fn finish(self, points: &[Point<D>], params: &[f64], sol: Solution<D>) -> Result<Fit<D>> {
        let m = points.len();
        let ctrl = if self.fixed_ends {
            let mut ctrl = Vec::with_capacity(self.count);
            ctrl.push(points[0]);
            ctrl.extend_from_slice(&sol.x);
            ctrl.push(points[m - 1]);
            ctrl
        } else {
            sol.x
        };
        let (p, knots) = (self.degree, self.template.knots().to_vec());
        let curve = if self.periodic {
            BSplineCurve::new_periodic(p, knots, ctrl)?
        } else {
            BSplineCurve::new(p, knots, ctrl)?
        };
        let mut values = vec![Point::<D>::zeros(); m];
        curve.eval_many(params, 0, &mut values);
        let mut sum = 0.0;
        let mut max: f64 = 0.0;
        for (q, v) in points.iter().zip(&values) {
            let e = (v - q).norm();
            sum += e * e;
            max = max.max(e);
        }
        Ok(Fit {
            curve,
            params: params.to_vec(),
            rms_error: (sum / m as f64).sqrt(),
            max_error: max,
            condition_estimate: sol.condition_estimate,
        })
    }
}

/// Samples a curve at `samples` uniform parameters (closed curves: without repeating the
/// first point) and fits it with [`fit`]; the data parameters are the model's own,
/// rescaled to [0, 1], so `params` in the options is ignored.
///
/// # Examples
///
/// ```
/// use splinekit::curve::Curve;
/// use splinekit::curve::model::Circle;
/// use splinekit::fit::{FitOptions, fit_curve};
/// // A closed cubic with 16 control points through 200 samples of the circle of radius 2.
/// let options = FitOptions { closed: true, ..FitOptions::new(3, 16) };
/// let f = fit_curve(&Circle::new(2.0).unwrap(), 200, &options).unwrap();
/// assert!(f.curve.is_closed() && f.max_error < 1e-4);
/// ```
pub fn fit_curve<const D: usize, C: Curve<D> + ?Sized>(
    model: &C,
    samples: usize,
    options: &FitOptions,
) -> Result<Fit<D>> {
    if samples < 2 {
        return Err(Error::invalid("samples", format!("need at least 2, got {samples}")));
    }
    let dom = model.domain();
    let closed = options.closed;
    let denom = if closed { samples } else { samples - 1 } as f64;
    let params: Vec<f64> = (0..samples).map(|i| i as f64 / denom).collect();
    let points: Vec<Point<D>> = params.iter().map(|&s| model.point(dom.lerp(s))).collect();
    let (p, n) = (options.degree, options.control_points);
    if n < p + 1 || n > samples {
        return Err(Error::invalid(
            "control_points",
            format!("need {} ≤ control points ≤ samples = {samples}, got {n}", p + 1),
        ));
    }
    let knots =
        if closed { periodic_knots(&params, p, n, options.knots)? } else { fit_knots(&params, p, n, options.knots)? };
    fit_with_knots(&points, &params, &options.with_knots(knots))
}
