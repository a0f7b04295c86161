//! Multi-threaded batch evaluation (feature `parallel`): the parameters are split into
//! contiguous chunks evaluated on rayon's thread pool, each with the curve's
//! single-threaded [`Curve::eval_many`] (so a sorted batch keeps its span cursor within a
//! chunk, and results are identical to the single-threaded call).

use rayon::prelude::*;

use crate::Point;
use crate::curve::Curve;

/// Parameters per chunk: large enough that a chunk's start-up (a span search, a task)
/// vanishes against its evaluation, small enough to balance the threads.
const MIN_CHUNK: usize = 16_384;

/// [`Curve::eval_many`] on all cores: `out[i·(order+1) + k]` = c^{(k)}(`params[i]`), the
/// same values as the single-threaded call. Batches under two chunks run on this thread.
///
/// # Examples
///
/// ```
/// use splinekit::{Point, curve::{BSplineCurve, Curve}};
/// let c = BSplineCurve::<2>::clamped_uniform(3, (0..50).map(|i| Point::<2>::new(i as f64, (i * i) as f64)).collect()).unwrap();
/// let t: Vec<f64> = (0..100_000).map(|i| i as f64 / 99_999.0).collect();
/// let (mut a, mut b) = (vec![Point::<2>::zeros(); 2 * t.len()], vec![Point::<2>::zeros(); 2 * t.len()]);
/// splinekit::curve::parallel::eval_many(&c, &t, 1, &mut a);
/// c.eval_many(&t, 1, &mut b);
/// assert_eq!(a, b);
/// ```
pub fn eval_many<const D: usize, C: Curve<D> + Sync + ?Sized>(
    curve: &C,
    params: &[f64],
    order: usize,
    out: &mut [Point<D>],
) {
    let w = order + 1;
    let out = &mut out[..params.len() * w];
    let threads = rayon::current_num_threads();
    if threads < 2 || params.len() < 2 * MIN_CHUNK {
        curve.eval_many(params, order, out);
        return;
    }
    // A few chunks per thread, so a slow thread (a busy core) does not hold up the rest.
    let chunk = params.len().div_ceil(4 * threads).max(MIN_CHUNK);
    out.par_chunks_mut(chunk * w).zip(params.par_chunks(chunk)).for_each(|(o, t)| curve.eval_many(t, order, o));
}
