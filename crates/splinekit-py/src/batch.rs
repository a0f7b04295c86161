//! Batch calls for many shapes at once: `fit_many` and `evaluate_many`. The arguments are
//! read and checked with the GIL held (every check and message of the single call), then
//! the work runs with the GIL released on rayon's threads (the global pool, or a pool of
//! `threads` threads), each piece by the code of the single call, so the results are bit
//! for bit those of a loop of single calls.

use pyo3::prelude::*;
use pyo3::types::PyList;
use rayon::prelude::*;

use crate::curve::{EvalTask, PyCurve};
use crate::curve_kinds::wrap;
use crate::errors::value_error;
use crate::fitting::{FitRequest, fit_function, fitted};
use crate::row_writer::{RowWriter, unfilled_rows};
use crate::surface::PySurface;

/// Runs `work` on a pool of `threads` threads, or on rayon's global pool (one thread per
/// core, or `RAYON_NUM_THREADS`) when None.
fn on_pool<T: Send>(threads: Option<usize>, work: impl FnOnce() -> T + Send) -> PyResult<T> {
    match threads {
        None => Ok(work()),
        Some(0) => Err(value_error("threads: must be at least 1, got 0")),
        Some(n) => {
            let pool = rayon::ThreadPoolBuilder::new().num_threads(n).build().map_err(value_error)?;
            Ok(pool.install(work))
        }
    }
}

/// A message of item `i` of a batch argument, naming it (`point_sets[3]: …`): the same
/// exception class, the message prefixed.
fn item_error(field: &str, i: usize, e: PyErr, py: Python<'_>) -> PyErr {
    if e.is_instance_of::<pyo3::exceptions::PyValueError>(py) {
        PyErr::from_type(e.get_type(py), format!("{field}[{i}]: {}", e.value(py)))
    } else {
        e
    }
}

fit_function! {
    /// Least-squares fits of many point sets, ``[fit(points, …) for points in point_sets]``
    /// computed in parallel with the GIL released: the same keyword arguments as ``fit``
    /// (applied to every set; an array of ``params``, ``knots`` or ``weights`` is shared by
    /// all), and ``threads`` threads (default: one per core). Each fit is the single call's,
    /// so the curves and reports are bit for bit the loop's. A bad set raises the single
    /// call's ``ValueError`` with its index first (``point_sets[3]: points: …``).
    fn fit_many(point_sets, threads: Option<usize> = None) -> Bound<'py, PyList> = fit_sets;
    text_signature = "(point_sets, degree, n_control_points=None, params='chord', knots='averaged', closed=False, weights=None, fix_ends=False, threads=None)";
}

/// `fit_many`'s work once its keywords are read: every set read and checked with the GIL
/// held, the fits on the pool without it, and the `BSpline`s in order.
fn fit_sets<'py>(
    py: Python<'py>,
    point_sets: &Bound<'py, PyAny>,
    request: FitRequest,
    threads: Option<usize>,
) -> PyResult<Bound<'py, PyList>> {
    let mut sets = Vec::new();
    for (i, ob) in point_sets.try_iter()?.enumerate() {
        sets.push(ob.and_then(|ob| request.points(&ob)).map_err(|e| item_error("point_sets", i, e, py))?);
    }
    let jobs: Vec<(&[f64], usize)> = sets.iter().map(|(data, d)| (data.values(), *d)).collect();
    let results = py.detach(|| {
        on_pool(threads, || jobs.par_iter().map(|&(values, d)| fitted(request.clone(), values, d)).collect::<Vec<_>>())
    })?;
    let curves = PyList::empty(py);
    for (i, r) in results.into_iter().enumerate() {
        let (doc, report) = r.map_err(|e| e.about(&format!("point_sets[{i}]")).into_py())?;
        curves.append(wrap(py, PyCurve::new(doc)?, Some(Py::new(py, report)?))?)?;
    }
    Ok(curves)
}

/// One shape's share of an `evaluate_many` call: its checked evaluation.
enum Job<'a> {
    /// A curve at its parameters; written chunk by chunk.
    Curve(EvalTask<'a>),
    /// A surface on its grid u × v; written at once.
    Surface(&'a PySurface, &'a [f64], &'a [f64]),
}

/// Evaluates many shapes at once, ``[s(*p) if surface else s(p, nu) for s, p in zip(shapes,
/// params)]``, in parallel with the GIL released: a curve's entry of ``params`` is its
/// parameters t (a number or an array; ``nu`` the derivative order), a surface's is the
/// pair ``(u, v)`` of its grid. One large curve is split into the chunks a single call
/// writes, so it too uses every thread. Returns the list of arrays the loop returns, bit
/// for bit; a bad entry raises the single call's ``ValueError`` with its index first
/// (``params[2]: t: parameter 2 is outside …``).
#[pyfunction]
#[pyo3(signature = (shapes, params, nu = 0, threads = None))]
pub fn evaluate_many<'py>(
    py: Python<'py>,
    shapes: &Bound<'py, PyAny>,
    params: &Bound<'py, PyAny>,
    nu: usize,
    threads: Option<usize>,
) -> PyResult<Bound<'py, PyList>> {
    let shapes: Vec<Bound<'py, PyAny>> = shapes.try_iter()?.collect::<PyResult<_>>()?;
    let params: Vec<Bound<'py, PyAny>> = params.try_iter()?.collect::<PyResult<_>>()?;
    if shapes.len() != params.len() {
        return Err(value_error(format!(
            "params: expected one entry per shape ({}), got {}",
            shapes.len(),
            params.len()
        )));
    }
    let curves: Vec<Option<PyRef<'py, PyCurve>>> = shapes.iter().map(|s| s.extract().ok()).collect();
    let surfaces: Vec<Option<PyRef<'py, PySurface>>> = shapes.iter().map(|s| s.extract().ok()).collect();
    // Checked with the GIL: the outputs (not yet written), their writers and their jobs.
    let mut evaluations = Vec::new();
    let mut requests = Vec::new();
    let mut outputs = Vec::new();
    for (i, p) in params.iter().enumerate() {
        let checked = (|| {
            if let Some(c) = &curves[i] {
                let e = c.evaluation(p, ("nu", nu), false)?;
                let (shape, rows, row) = e.layout();
                let (out, writer) = unfilled_rows(py, &shape, rows, row);
                evaluations.push((i, e));
                return Ok((out, writer));
            }
            if let Some(s) = &surfaces[i] {
                let (u, v): (Bound<'py, PyAny>, Bound<'py, PyAny>) = p
                    .extract()
                    .map_err(|_| value_error("expected a pair (u, v) of parameters for a surface".to_string()))?;
                let (r, out, writer) = s.grid_evaluation(py, &u, &v)?;
                requests.push((i, r));
                return Ok((out, writer));
            }
            Err(value_error(format!("expected a splinekit curve or surface, got {}", shapes[i].get_type().name()?)))
        })();
        outputs.push(checked.map_err(|e| {
            let field = if curves[i].is_some() || surfaces[i].is_some() { "params" } else { "shapes" };
            item_error(field, i, e, py)
        })?);
    }
    let mut jobs: Vec<Option<Job<'_>>> = (0..shapes.len()).map(|_| None).collect();
    for (i, e) in &evaluations {
        jobs[*i] = Some(Job::Curve(e.task()));
    }
    for (i, r) in &requests {
        let s: &PySurface = surfaces[*i].as_deref().expect("a surface");
        jobs[*i] = Some(Job::Surface(s, r.us(), r.vs()));
    }
    // Every chunk of every output is one task.
    let writers: Vec<&RowWriter> = outputs.iter().map(|(_, w)| w).collect();
    let tasks: Vec<(usize, std::ops::Range<usize>)> =
        writers.iter().enumerate().flat_map(|(i, w)| w.chunks().map(move |r| (i, r))).collect();
    py.detach(|| {
        on_pool(threads, || {
            tasks.par_iter().for_each(|(i, rows)| {
                // SAFETY: every (output, chunk) pair is one task, run once; the outputs are
                // alive until after this call; a curve's fill writes every value.
                match jobs[*i].as_ref().expect("a job per shape") {
                    Job::Curve(task) => unsafe {
                        writers[*i].write_uninit(rows.clone(), |out| task.fill(rows.clone(), out))
                    },
                    Job::Surface(s, us, vs) => unsafe {
                        writers[*i].write(rows.clone(), |out| s.fill_grid(us, vs, out))
                    },
                }
            })
        })
    })?;
    let results = PyList::empty(py);
    let mut surface_requests = requests.iter();
    for (i, (out, _)) in outputs.into_iter().enumerate() {
        if let Some(s) = &surfaces[i] {
            let (_, r) = surface_requests.next().expect("a request per surface");
            results.append(s.shaped(r, out.into_any())?)?;
        } else {
            results.append(out)?;
        }
    }
    Ok(results)
}
