//! `splinekit.fit` and `splinekit.interpolate`: B-splines from sampled points, by the
//! kernel functions `splinekit fit` and `splinekit interpolate` call.

use pyo3::prelude::*;
use splinekit::Point;
use splinekit::fit::{
    self as kfit, Fit, FitOptions, FitWithKnotsOptions, InterpolationOptions, KnotPlacement, Parametrization,
};
use splinekit_scene::refine::bspline_doc;
use splinekit_scene::{CurveDocument, with_dimension};

use crate::arrays::{Numbers, as_points, check_finite};
use crate::curve::PyCurve;
use crate::curve_kinds::wrap;
use crate::errors::{Failure, OrValueError, value_error};
use crate::fit_report::FitReport;

/// Largest degree accepted for fitting and interpolation (as the command line).
const MAX_DEGREE: usize = 64;

/// A method name or an array: `params` and `knots` take either.
#[derive(FromPyObject)]
pub enum Choice<'py> {
    /// `"chord"`, `"averaged"`, …
    Name(String),
    /// Explicit numbers.
    Values(Bound<'py, PyAny>),
}

impl Choice<'_> {
    /// The method named, read by `by_name` (which refuses an unknown name), or the array
    /// given, as the finite numbers of the argument `field`.
    pub fn read<T>(self, field: &str, by_name: fn(&str) -> PyResult<T>) -> PyResult<Result<T, Vec<f64>>> {
        Ok(match self {
            Choice::Name(n) => Ok(by_name(&n)?),
            Choice::Values(v) => Err(numbers_of(field, &v)?),
        })
    }
}

/// The parametrization named by `params` (a message naming the choices otherwise).
pub fn parametrization(name: &str) -> PyResult<Parametrization> {
    Ok(match name {
        "uniform" => Parametrization::Uniform,
        "chord" => Parametrization::ChordLength,
        "centripetal" => Parametrization::Centripetal,
        other => {
            return Err(value_error(format!(
                "params: expected \"uniform\", \"chord\", \"centripetal\" or an array of parameters, got \"{other}\""
            )));
        }
    })
}

/// The knot placement named by `knots` (a message naming the choices otherwise).
pub fn placement(name: &str) -> PyResult<KnotPlacement> {
    Ok(match name {
        "uniform" => KnotPlacement::Uniform,
        "averaged" => KnotPlacement::Averaged,
        other => {
            return Err(value_error(format!(
                "knots: expected \"uniform\", \"averaged\" or an array of knots, got \"{other}\""
            )));
        }
    })
}

/// Refuses a degree outside 1 ..= [`MAX_DEGREE`].
pub fn check_degree(p: usize) -> PyResult<()> {
    if p == 0 || p > MAX_DEGREE {
        return Err(value_error(format!("degree: must be between 1 and {MAX_DEGREE}, got {p}")));
    }
    Ok(())
}

/// A fit's error, its field named as the Python argument: the kernel's `control_points`
/// is `n_control_points` here (as the command line names it `--control-points`), the
/// rest of the line unchanged.
fn fit_error(e: splinekit::Error) -> Failure {
    let failure = Failure::from(e);
    match failure.message.strip_prefix("control_points:") {
        Some(rest) => Failure { message: format!("n_control_points:{rest}"), ..failure },
        None => failure,
    }
}

/// Declares the `#[pyfunction]` `$name` whose arguments are `$first`, then `fit`'s
/// keyword arguments with `fit`'s defaults (`degree`, `n_control_points=None`,
/// `params='chord'`, `knots='averaged'`, `closed=False`, `weights=None`, `fix_ends=False`),
/// then its own `$extra` ones with theirs. It reads and checks the keywords into a
/// [`FitRequest`] (the degree, then `params`, `knots` and `weights`) and returns
/// `$run(py, $first, request, $extra…)`. The one declaration of the keywords, so that `fit`
/// and `fit_many` take them alike; the text signature (a literal, for pyo3) is each
/// function's own.
macro_rules! fit_function {
    (
        $(#[$doc:meta])*
        fn $name:ident($first:ident $(, $extra:ident: $extra_ty:ty = $default:tt)*) -> $ret:ty = $run:path;
        text_signature = $text:tt;
    ) => {
        $(#[$doc])*
        #[pyo3::pyfunction]
        #[pyo3(
            signature = ($first, degree, n_control_points = None, params = $crate::fitting::Choice::Name("chord".into()), knots = $crate::fitting::Choice::Name("averaged".into()), closed = false, weights = None, fix_ends = false $(, $extra = $default)*),
            text_signature = $text
        )]
        #[allow(clippy::too_many_arguments)]
        pub fn $name<'py>(
            py: pyo3::Python<'py>,
            $first: &pyo3::Bound<'py, pyo3::PyAny>,
            degree: usize,
            n_control_points: Option<usize>,
            params: $crate::fitting::Choice<'py>,
            knots: $crate::fitting::Choice<'py>,
            closed: bool,
            weights: Option<&pyo3::Bound<'py, pyo3::PyAny>>,
            fix_ends: bool,
            $($extra: $extra_ty,)*
        ) -> pyo3::PyResult<$ret> {
            use $crate::fitting::{check_degree, numbers_of, parametrization, placement};
            check_degree(degree)?;
            let request = $crate::fitting::FitRequest {
                degree,
                control_points: n_control_points,
                params: params.read("params", parametrization)?,
                knots: knots.read("knots", placement)?,
                closed,
                weights: weights.map(|w| numbers_of("weights", w)).transpose()?,
                fix_ends,
            };
            $run(py, $first, request $(, $extra)*)
        }
    };
}
pub(crate) use fit_function;

impl FitRequest {
    /// Refuses a fit of `m` points of dimension `d` whose least-squares solve would not
    /// fit the budget (see [`splinekit_scene::budget::least_squares_fit`]). More control
    /// points than points are left to the fit, which refuses them before allocating.
    pub fn check_budget(&self, m: usize, d: usize) -> PyResult<()> {
        let n = match (&self.control_points, &self.knots) {
            (Some(n), _) => *n,
            (None, Err(knots)) => knots.len().saturating_sub(self.degree + 1),
            (None, Ok(_)) => return Ok(()),
        };
        if n > m {
            return Ok(());
        }
        let p = self.degree;
        let cost = splinekit_scene::budget::least_squares_fit(m as f64, n as f64, p, d);
        let what = format!("a degree-{p} fit of {m} points with {n} control points");
        crate::budget::current()?.check("points", &what, cost).or_value_error()
    }

    /// The argument `ob` read as an array of points of shape (m, d), with d, refused when
    /// the fit of m points would not fit the budget ([`FitRequest::check_budget`]).
    pub fn points<'py>(&self, ob: &Bound<'py, PyAny>) -> PyResult<(Numbers<'py>, usize)> {
        let data = Numbers::new(ob)?;
        let (m, d) = data.rows("points")?;
        self.check_budget(m, d)?;
        Ok((data, d))
    }
}

/// The fit of the C-ordered coordinates `values` of points of dimension `d` (any thread,
/// no GIL): the B-spline's document and the report, or the error.
pub fn fitted(request: FitRequest, values: &[f64], d: usize) -> Result<(CurveDocument, FitReport), Failure> {
    with_dimension!(d, "points", D => {
        let f = request.run(as_points::<D>(values)).map_err(fit_error)?;
        let report = FitReport { rms_error: f.rms_error, max_error: f.max_error, condition_estimate: f.condition_estimate, params: f.params };
        Ok((bspline_doc(&f.curve), report))
    }, or dimension_error)
}

fn dimension_error(e: splinekit_scene::DocumentError) -> Failure {
    Failure::from(e)
}

/// Owned numbers of a 1-D argument, checked finite.
pub fn numbers_of(field: &str, ob: &Bound<'_, PyAny>) -> PyResult<Vec<f64>> {
    let n = Numbers::new(ob)?;
    let v = n.list(field)?.to_vec();
    check_finite(field, &v)?;
    Ok(v)
}

/// Everything `fit` was asked for, read from Python and checked (by [`fit_function!`]).
#[derive(Clone)]
pub struct FitRequest {
    pub(crate) degree: usize,
    pub(crate) control_points: Option<usize>,
    pub(crate) params: Result<Parametrization, Vec<f64>>,
    pub(crate) knots: Result<KnotPlacement, Vec<f64>>,
    pub(crate) closed: bool,
    pub(crate) weights: Option<Vec<f64>>,
    pub(crate) fix_ends: bool,
}

impl FitRequest {
    /// The fit of `points` (the kernel's `fit`, or `fit_with_knots` when parameters or
    /// knots are given as numbers).
    fn run<const D: usize>(self, points: &[Point<D>]) -> splinekit::Result<Fit<D>> {
        let p = self.degree;
        let count_from_knots = |k: &Vec<f64>| k.len().saturating_sub(p + 1);
        let n = match (&self.knots, self.control_points) {
            (_, Some(n)) => n,
            (Err(k), None) => count_from_knots(k),
            (Ok(_), None) => {
                return Err(splinekit::Error::invalid(
                    "n_control_points",
                    "give a number of control points or an array of knots",
                ));
            }
        };
        if let (Ok(params), Ok(knots)) = (&self.params, &self.knots) {
            let o = FitOptions {
                params: *params,
                knots: *knots,
                closed: self.closed,
                interpolate_ends: self.fix_ends,
                weights: self.weights,
                ..FitOptions::new(p, n)
            };
            return kfit::fit(points, &o);
        }
        let params = match self.params {
            Ok(method) => kfit::parametrize(points, method, self.closed)?,
            Err(values) => values,
        };
        kfit::check_data(points, &params, self.weights.as_deref())?;
        let knots = match self.knots {
            Ok(placement) if self.closed => kfit::periodic_knots(&params, p, n, placement)?,
            Ok(placement) => kfit::fit_knots(&params, p, n, placement)?,
            Err(k) if self.control_points.is_some_and(|n| n != count_from_knots(&k)) => {
                return Err(splinekit::Error::invalid(
                    "n_control_points",
                    format!(
                        "{n} does not match the {} knots of degree {p}, which give {} control points",
                        k.len(),
                        count_from_knots(&k)
                    ),
                ));
            }
            Err(k) => k,
        };
        let o = FitWithKnotsOptions {
            closed: self.closed,
            interpolate_ends: self.fix_ends,
            weights: self.weights,
            ..FitWithKnotsOptions::new(p, knots)
        };
        kfit::fit_with_knots(points, &params, &o)
    }
}

fit_function! {
    /// Least-squares B-spline c minimising Σᵢ (wᵢ |c(tᵢ) − Qᵢ|)² over its control points, by
    /// banded Givens QR (the problem of scipy's ``make_lsq_spline``).
    ///
    /// ``points`` (m, D); ``degree`` p; ``n_control_points`` n (p + 1 ≤ n ≤ m). ``params``:
    /// ``"uniform"`` (tᵢ = i/(m − 1)), ``"chord"`` (accumulated chord length) or
    /// ``"centripetal"`` on [0, 1], or an array of m parameters. ``knots``: ``"averaged"``
    /// (every knot span holds data), ``"uniform"``, or an array of n + p + 1 knots (then n may
    /// be omitted). ``closed`` fits a periodic curve; ``weights`` (m,) ≥ 0 multiply the
    /// residuals; ``fix_ends`` makes the curve start and end at the first and last points.
    /// Returns a ``BSpline`` whose ``fit_report`` holds the errors.
    fn fit(points) -> Bound<'py, PyAny> = fit_points;
    text_signature = "(points, degree, n_control_points=None, params='chord', knots='averaged', closed=False, weights=None, fix_ends=False)";
}

/// `fit`'s work once its keywords are read: the points, the fit with the GIL released, and
/// the `BSpline` that keeps its report.
fn fit_points<'py>(py: Python<'py>, points: &Bound<'py, PyAny>, request: FitRequest) -> PyResult<Bound<'py, PyAny>> {
    let (data, d) = request.points(points)?;
    let values = data.values();
    let (doc, report) = py.detach(|| fitted(request, values, d)).map_err(Failure::into_py)?;
    wrap(py, PyCurve::new(doc)?, Some(Py::new(py, report)?))
}

/// The B-spline of degree p through every point Qᵢ at its parameter tᵢ (global
/// interpolation, *The NURBS Book* §9.2; knots by averaging the parameters so the
/// collocation matrix is non-singular). ``params`` as in ``fit``; ``closed`` interpolates
/// a periodic curve; ``end_derivatives=(d0, d1)`` prescribes c'(0) and c'(1).
#[pyfunction]
#[pyo3(signature = (points, degree, params = "chord", closed = false, end_derivatives = None))]
pub fn interpolate<'py>(
    py: Python<'py>,
    points: &Bound<'py, PyAny>,
    degree: usize,
    params: &str,
    closed: bool,
    end_derivatives: Option<(Bound<'py, PyAny>, Bound<'py, PyAny>)>,
) -> PyResult<Bound<'py, PyAny>> {
    check_degree(degree)?;
    let method = parametrization(params)?;
    let ends = end_derivatives
        .map(|(a, b)| Ok::<_, PyErr>((numbers_of("end_derivatives[0]", &a)?, numbers_of("end_derivatives[1]", &b)?)))
        .transpose()?;
    let data = Numbers::new(points)?;
    let (_, d) = data.rows("points")?;
    let values = data.values();
    let doc = with_dimension!(d, "points", D => {
        let mut o = InterpolationOptions::<D>::new(degree);
        o.params = method;
        o.closed = closed;
        if let Some((a, b)) = &ends {
            if a.len() != D || b.len() != D {
                return Err(value_error(format!("end_derivatives: expected {D} coordinates like the points, got {} and {}", a.len(), b.len())));
            }
            o.end_derivatives = Some((Point::<D>::from_column_slice(a), Point::<D>::from_column_slice(b)));
        }
        let r = py.detach(|| kfit::interpolate(as_points::<D>(values), &o)).or_value_error()?;
        Ok::<_, PyErr>(bspline_doc(&r.curve))
    }, or value_error)?;
    wrap(py, PyCurve::new(doc)?, None)
}
