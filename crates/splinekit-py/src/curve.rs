//! `splinekit.Curve`: any curve of a shape document, evaluated from numpy.
//!
//! A curve object holds its document (the JSON the command line reads, so `to_dict`
//! round-trips and operations reuse the document functions of the CLI) and the kernel
//! curve built from it, of the dimension its points ask for.

use std::mem::MaybeUninit;
use std::sync::atomic::{AtomicBool, Ordering};

use numpy::PyArrayDyn;
use pyo3::prelude::*;
use splinekit::Interval;
use splinekit::curve::Curve;
use splinekit_scene::{AnyCurve, CurveDocument, Curves, DimensionVisitor};

use splinekit_scene::budget::{Cost, F64};

use crate::arrays::{Numbers, as_points_uninit, check_params, params_pass};
use crate::budget;
use crate::errors::{OrValueError, value_error};
use crate::row_writer::filled_rows;

/// Highest derivative order one call may ask for (as `splinekit eval --derivatives`).
pub const MAX_DERIVATIVES: usize = 64;

/// A parametric curve c: [a, b] → ℝᴰ of any kind a shape document describes.
///
/// Call it: ``c(t)`` is the point c(t) for a number t (shape (D,)) or the points at N
/// parameters (shape (N, D)); ``c(t, nu)`` is the derivative c^(nu)(t) with respect to
/// the curve's own parameter. Open curves refuse parameters outside their domain
/// [a, b]; closed (periodic) curves wrap them around.
#[pyclass(subclass, module = "splinekit", name = "Curve")]
pub struct PyCurve {
    pub(crate) doc: CurveDocument,
    pub(crate) curve: AnyCurve,
    pub(crate) domain: Interval,
    pub(crate) closed: bool,
}

/// Domain and closedness of a curve of any dimension.
struct Shape;

impl DimensionVisitor<Curves> for Shape {
    type Output = (Interval, bool);
    fn visit<const D: usize>(self, c: &dyn Curve<D>) -> (Interval, bool) {
        (c.domain(), c.is_closed())
    }
}

/// c(t_i), c'(t_i), …, c^(order)(t_i) for every parameter, written into `out`
/// (`out[(i·(order+1) + k)·D + j]`), every value once.
struct EvalInto<'a> {
    params: &'a [f64],
    order: usize,
    out: &'a mut [MaybeUninit<f64>],
}

impl DimensionVisitor<Curves> for EvalInto<'_> {
    type Output = ();
    fn visit<const D: usize>(self, c: &dyn Curve<D>) {
        c.eval_many_uninit(self.params, self.order, as_points_uninit::<D>(self.out));
    }
}

impl PyCurve {
    /// Builds the kernel curve of `doc`; its errors are the command line's.
    pub fn new(doc: CurveDocument) -> PyResult<Self> {
        let curve = doc.build().or_value_error()?;
        let (domain, closed) = curve.visit(Shape);
        Ok(PyCurve { doc, curve, domain, closed })
    }

    /// The dimension D of the points.
    pub fn dimension(&self) -> usize {
        self.curve.dimension()
    }

    /// Refuses non-finite parameters and, on open curves, parameters outside the domain
    /// (with the slack of `splinekit eval --at`).
    pub fn check_params(&self, field: &str, params: &[f64]) -> PyResult<()> {
        check_params(field, params, self.open_domain(), "curve")
    }

    /// The domain parameters must lie in: that of an open curve, none for a closed one.
    fn open_domain(&self) -> Option<Interval> {
        (!self.closed).then_some(self.domain)
    }

    /// Refuses evaluating derivatives up to `order` at `n` parameters and holding `row`
    /// numbers for each over the budget (`splinekit eval`'s, without the formatting),
    /// naming `field` (the order) when derivatives are asked for, else `t`.
    fn check_budget(&self, n: usize, row: usize, (field, order): (&str, usize)) -> PyResult<()> {
        let cost = self.doc.cost();
        let n = n as f64;
        let request = Cost::new(n * row as f64 * F64, cost.evaluations(n, order));
        let what = format!("{n} parameters with derivatives up to order {order}");
        budget::check_request(if order > 0 { field } else { "t" }, &what, &cost, request)
    }

    /// The derivatives of `order` at the parameters `t` (all orders 0 … `order` when `all`):
    /// shaped (N, D) (`all`: (N, order + 1, D)), without N for a number, written straight
    /// into the new array chunk by chunk with the GIL released. `field` names the order.
    ///
    /// The parameters are checked chunk by chunk, each just before it is evaluated (one
    /// pass over memory instead of two: a separate pass over 10⁶ parameters cost a fifth
    /// as much as a sorted cubic's evaluation). A chunk that fails stops the work: the rest is
    /// zeroed, the array dropped, and the error is [`PyCurve::check_params`]'s over all
    /// the parameters, as if they had been checked first.
    fn evaluate<'py>(
        &self,
        t: &Bound<'py, PyAny>,
        (field, order): (&str, usize),
        all: bool,
    ) -> PyResult<Bound<'py, PyArrayDyn<f64>>> {
        let job = self.unchecked_evaluation(t, (field, order), all)?;
        let (shape, rows, row) = job.layout();
        let (task, params, domain) = (job.task(), job.params(), self.open_domain());
        let refused = AtomicBool::new(false);
        let out = filled_rows(t.py(), &shape, rows, row, |rows, out| {
            if !refused.load(Ordering::Relaxed) && params_pass(&params[rows.clone()], domain) {
                return task.fill(rows, out);
            }
            refused.store(true, Ordering::Relaxed);
            out.fill(MaybeUninit::new(0.0));
        })?;
        if refused.into_inner() {
            self.check_params("t", params)?;
            // Not reached: a chunk that fails `params_pass` fails `check_params` too. Were
            // it reached, the parameters are good, and they are evaluated whole.
            return filled_rows(t.py(), &shape, rows, row, |rows, out| task.fill(rows, out));
        }
        Ok(out)
    }

    /// Checks an evaluation of the derivatives of `order` (all orders up to it when `all`)
    /// at the parameters `t` (order, parameters, budget) and returns it, to be run.
    pub fn evaluation<'a, 'py>(
        &'a self,
        t: &Bound<'py, PyAny>,
        order: (&str, usize),
        all: bool,
    ) -> PyResult<Evaluation<'a, 'py>> {
        let job = self.unchecked_evaluation(t, order, all)?;
        self.check_params("t", job.params())?;
        Ok(job)
    }

    /// [`PyCurve::evaluation`] without the check of the parameters' values (the order,
    /// the shape of `t` and the budget are checked).
    fn unchecked_evaluation<'a, 'py>(
        &'a self,
        t: &Bound<'py, PyAny>,
        (field, order): (&str, usize),
        all: bool,
    ) -> PyResult<Evaluation<'a, 'py>> {
        check_order(field, order)?;
        let numbers = Numbers::new(t)?;
        let n = numbers.list("t")?.len();
        let d = self.dimension();
        self.check_budget(n, if all { (order + 1) * d } else { d }, (field, order))?;
        Ok(Evaluation { curve: &self.curve, numbers, order, all, d })
    }
}

/// A checked evaluation of a curve at parameters (see [`PyCurve::evaluation`]).
pub struct Evaluation<'a, 'py> {
    curve: &'a AnyCurve,
    numbers: Numbers<'py>,
    order: usize,
    all: bool,
    d: usize,
}

impl Evaluation<'_, '_> {
    /// The parameters.
    pub fn params(&self) -> &[f64] {
        self.numbers.values()
    }

    /// The output's shape, its number of rows (parameters) and the values per row.
    pub fn layout(&self) -> (Vec<usize>, usize, usize) {
        let (n, d, order) = (self.params().len(), self.d, self.order);
        let mut shape: Vec<usize> = if self.numbers.is_scalar() { vec![] } else { vec![n] };
        shape.extend(if self.all { vec![order + 1, d] } else { vec![d] });
        let row = if self.all { (order + 1) * d } else { d };
        (shape, n, row)
    }

    /// The part that may cross threads (the curve, the parameters, the orders), without
    /// the Python objects.
    pub fn task(&self) -> EvalTask<'_> {
        EvalTask { curve: self.curve, params: self.params(), order: self.order, all: self.all, d: self.d }
    }
}

/// The thread-safe part of an [`Evaluation`]: the curve, the parameters, what to compute.
#[derive(Clone, Copy)]
pub struct EvalTask<'a> {
    curve: &'a AnyCurve,
    params: &'a [f64],
    order: usize,
    all: bool,
    d: usize,
}

impl EvalTask<'_> {
    /// Writes the rows `rows` of the result into `out`, every value.
    pub fn fill(&self, rows: std::ops::Range<usize>, out: &mut [MaybeUninit<f64>]) {
        let (order, d) = (self.order, self.d);
        let params = &self.params[rows];
        if self.all || order == 0 {
            return self.curve.visit(EvalInto { params, order, out });
        }
        // All orders up to `order`, then the last of each block.
        let mut blocks = vec![MaybeUninit::<f64>::uninit(); params.len() * (order + 1) * d];
        self.curve.visit(EvalInto { params, order, out: &mut blocks });
        for (o, block) in out.chunks_exact_mut(d).zip(blocks.chunks_exact((order + 1) * d)) {
            // `block` was written whole by `EvalInto`: copied as the slots they are.
            o.copy_from_slice(&block[order * d..]);
        }
    }
}

/// Refuses derivative orders above [`MAX_DERIVATIVES`].
pub fn check_order(field: &str, order: usize) -> PyResult<()> {
    if order > MAX_DERIVATIVES {
        return Err(value_error(format!("{field}: {order} is more than the limit of {MAX_DERIVATIVES}")));
    }
    Ok(())
}

#[pymethods]
impl PyCurve {
    /// c^(nu)(t): for a number t an array of shape (D,), for N parameters (N, D).
    ///
    /// nu = 0 gives the points, nu = k the k-th derivative dᵏc/dtᵏ. Splines evaluate a
    /// sorted batch span by span (the knot span is found once per span, then the p + 1
    /// non-zero basis functions or the span's Bézier form are used).
    #[pyo3(signature = (t, nu = 0))]
    fn __call__<'py>(&self, t: &Bound<'py, PyAny>, nu: usize) -> PyResult<Bound<'py, PyArrayDyn<f64>>> {
        self.evaluate(t, ("nu", nu), false)
    }

    /// c(t), c'(t), …, c^(order)(t): shape (N, order + 1, D) for N parameters, (order + 1, D)
    /// for a number; ``derivatives(t, k)[i, j]`` is dʲc/dtʲ at t[i].
    fn derivatives<'py>(&self, t: &Bound<'py, PyAny>, order: usize) -> PyResult<Bound<'py, PyArrayDyn<f64>>> {
        self.evaluate(t, ("order", order), true)
    }

    /// The parameter domain (a, b).
    #[getter]
    fn domain(&self) -> (f64, f64) {
        (self.domain.start, self.domain.end)
    }

    /// Whether the curve is closed (periodic): c(a) = c(b), continuing smoothly.
    #[getter]
    fn closed(&self) -> bool {
        self.closed
    }

    fn __repr__(&self) -> String {
        format!(
            "<splinekit {} curve in {}-D on [{}, {}]{}>",
            self.doc.type_name(),
            self.dimension(),
            self.domain.start,
            self.domain.end,
            if self.closed { ", closed" } else { "" }
        )
    }
}
