//! Multi-threaded grid evaluation (feature `parallel`): the rows of u are split into
//! chunks evaluated on rayon's thread pool, each with the single-threaded fast path.

use rayon::prelude::*;

use crate::Point;
use crate::surface::Surface;

/// [`Surface::eval_grid_with_normals`] on all cores; same layout and results.
pub fn eval_grid_with_normals<const D: usize, S: Surface<D> + Sync + ?Sized>(
    surface: &S,
    us: &[f64],
    vs: &[f64],
    points: &mut [Point<D>],
    normals: &mut [Point<D>],
) {
    let rows = (us.len() / (4 * rayon::current_num_threads()).max(1)).max(1);
    let chunk = rows * vs.len();
    points
        .par_chunks_mut(chunk)
        .zip(normals.par_chunks_mut(chunk))
        .zip(us.par_chunks(rows))
        .for_each(|((p, n), u)| surface.eval_grid_with_normals(u, vs, p, n));
}

/// [`Surface::eval_grid`] on all cores; same layout and results.
pub fn eval_grid<const D: usize, S: Surface<D> + Sync + ?Sized>(
    surface: &S,
    us: &[f64],
    vs: &[f64],
    du: usize,
    dv: usize,
    out: &mut [Point<D>],
) {
    let rows = (us.len() / (4 * rayon::current_num_threads()).max(1)).max(1);
    let chunk = rows * vs.len() * (du + 1) * (dv + 1);
    out.par_chunks_mut(chunk).zip(us.par_chunks(rows)).for_each(|(o, u)| surface.eval_grid(u, vs, du, dv, o));
}
