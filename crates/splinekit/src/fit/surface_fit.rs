//! Least-squares fitting and interpolation of B-spline surfaces to a grid of points.
//!
//! With grid data Q_ab at parameters (u_a, v_b), the design matrix is the Kronecker
//! product A_u ⊗ A_v, whose pseudo-inverse is A_u⁺ ⊗ A_v⁺. So fitting every row of the
//! grid in v and then every column of the result in u gives exactly the least-squares
//! surface, with banded QR solves in each direction: O(m_u m_v (p + q)) work.

use crate::Point;
use crate::error::{Error, Result, check_points_finite};
use crate::fit::collocation::CollocationLu;
use crate::fit::lsq::{FitWithKnotsOptions, fit_with_knots};
use crate::fit::parametrize::{KnotPlacement, Parametrization, fit_knots, parametrize};
use crate::surface::BSplineSurface;

/// Options of [`fit_surface`].
#[derive(Debug, Clone, PartialEq)]
pub struct SurfaceFitOptions {
    /// Degrees (p, q).
    pub degrees: (usize, usize),
    /// Control points (n_u, n_v).
    pub control_points: (usize, usize),
    /// Parameters of the grid rows and columns.
    pub params: Parametrization,
    /// Knot placement in both directions.
    pub knots: KnotPlacement,
}

/// Averaged parameters of a grid direction: the mean over all lines of the per-line
/// parametrisation (NURBS Book §9.2.5), so every row shares one set of v-parameters.
fn grid_params<const D: usize>(lines: &[Vec<Point<D>>], method: Parametrization) -> Result<Vec<f64>> {
    let m = lines[0].len();
    let mut sum = vec![0.0; m];
    for line in lines {
        let t = parametrize(line, method, false)?;
        for (s, x) in sum.iter_mut().zip(t) {
            *s += x;
        }
    }
    Ok(sum.into_iter().map(|s| s / lines.len() as f64).collect())
}

fn transpose<T: Clone>(net: &[Vec<T>]) -> Vec<Vec<T>> {
    (0..net[0].len()).map(|j| net.iter().map(|r| r[j].clone()).collect()).collect()
}

fn check_grid<const D: usize>(grid: &[Vec<Point<D>>]) -> Result<(usize, usize)> {
    let (mu, mv) = crate::surface::tensor::net_shape(grid, "points")?;
    for (i, row) in grid.iter().enumerate() {
        check_points_finite(&format!("points[{i}]"), row)?;
    }
    Ok((mu, mv))
}

/// Least-squares B-spline surface through a grid of points (`grid[a][b]`, rows along u),
/// with clamped knots on [0, 1]².
///
/// # Examples
///
/// ```
/// use splinekit::Point;
/// use splinekit::fit::{KnotPlacement, Parametrization, SurfaceFitOptions, fit_surface};
/// use splinekit::surface::Surface;
/// // A 6 × 5 grid on the plane z = x/2 + y/4 is fitted exactly by a bilinear patch.
/// let grid: Vec<Vec<Point<3>>> = (0..6)
///     .map(|a| (0..5).map(|b| (a as f64 / 5.0, b as f64 / 4.0)).map(|(x, y)| Point::<3>::new(x, y, x / 2.0 + y / 4.0)).collect())
///     .collect();
/// let options = SurfaceFitOptions {
///     degrees: (1, 1),
///     control_points: (2, 2),
///     params: Parametrization::Uniform,
///     knots: KnotPlacement::Uniform,
/// };
/// let s = fit_surface(&grid, &options).unwrap();
/// assert!((s.point(0.3, 0.6) - Point::<3>::new(0.3, 0.6, 0.3)).norm() < 1e-14);
/// ```
pub fn fit_surface<const D: usize>(grid: &[Vec<Point<D>>], options: &SurfaceFitOptions) -> Result<BSplineSurface<D>> {
    let (mu, mv) = check_grid(grid)?;
    let ((p, q), (nu, nv)) = (options.degrees, options.control_points);
    if p == 0 || q == 0 {
        return Err(Error::invalid("degree", "degrees must be at least 1"));
    }
    if nu < p + 1 || nu > mu || nv < q + 1 || nv > mv {
        return Err(Error::invalid(
            "control_points",
            format!("need {} ≤ n_u ≤ {mu} and {} ≤ n_v ≤ {mv} for a {mu} × {mv} grid, got {nu} × {nv}", p + 1, q + 1),
        ));
    }
    let vparams = grid_params(grid, options.params)?;
    let columns = transpose(grid);
    let uparams = grid_params(&columns, options.params)?;
    let kv = fit_knots(&vparams, q, nv, options.knots)?;
    let ku = fit_knots(&uparams, p, nu, options.knots)?;
    // Rows in v, then the columns of the intermediate net in u.
    let mut mid = Vec::with_capacity(mu);
    for row in grid {
        mid.push(
            fit_with_knots(row, &vparams, &FitWithKnotsOptions::new(q, kv.clone()))?.curve.control_points().to_vec(),
        );
    }
    let mut cols = Vec::with_capacity(nv);
    for col in transpose(&mid) {
        cols.push(
            fit_with_knots(&col, &uparams, &FitWithKnotsOptions::new(p, ku.clone()))?.curve.control_points().to_vec(),
        );
    }
    BSplineSurface::new((p, q), ku, kv, transpose(&cols), (false, false))
}

/// B-spline surface interpolating every grid point, degrees (p, q), knots by averaging.
pub fn interpolate_surface<const D: usize>(
    grid: &[Vec<Point<D>>],
    degrees: (usize, usize),
    params: Parametrization,
) -> Result<BSplineSurface<D>> {
    let (mu, mv) = check_grid(grid)?;
    let (p, q) = degrees;
    if mu < p + 1 || mv < q + 1 {
        return Err(Error::invalid("points", format!("a {mu} × {mv} grid is too small for degrees ({p}, {q})")));
    }
    let vparams = grid_params(grid, params)?;
    let uparams = grid_params(&transpose(grid), params)?;
    let (ku, kv) = (averaged_knots(&uparams, p), averaged_knots(&vparams, q));
    interpolate_surface_on_knots(grid, degrees, (&uparams, &ku), (&vparams, &kv))
}

/// Clamped knots on [0, 1] for interpolation at parameters `t` (one control point per
/// parameter): the interior knots are averages of `deg` consecutive parameters (de Boor).
fn averaged_knots(t: &[f64], deg: usize) -> Vec<f64> {
    let mut knots = vec![0.0; deg + 1];
    for j in 1..t.len() - deg {
        knots.push(t[j..j + deg].iter().sum::<f64>() / deg as f64);
    }
    knots.extend(vec![1.0; deg + 1]);
    knots
}

/// B-spline surface interpolating every grid point (`grid[a][b]` at (`u.0[a]`, `v.0[b]`)) on
/// the given knots (`u.1`, `v.1`; one control point per grid line each way, and the
/// parameters must satisfy the Schoenberg–Whitney conditions): every row is interpolated
/// in v, then every column of the result in u, each direction's collocation matrix factored
/// once ([`CollocationLu`]).
pub fn interpolate_surface_on_knots<const D: usize>(
    grid: &[Vec<Point<D>>],
    degrees: (usize, usize),
    u: (&[f64], &[f64]),
    v: (&[f64], &[f64]),
) -> Result<BSplineSurface<D>> {
    let (mu, mv) = check_grid(grid)?;
    let (p, q) = degrees;
    if u.0.len() != mu || v.0.len() != mv {
        return Err(Error::invalid(
            "params",
            format!("a {mu} × {mv} grid needs {mu} × {mv} parameters, got {} × {}", u.0.len(), v.0.len()),
        ));
    }
    // One factorisation per direction: every row shares the v-parameters, every column the u's.
    let (lu_u, lu_v) = (CollocationLu::new(p, u.1, u.0)?, CollocationLu::new(q, v.1, v.0)?);
    let mid: Vec<Vec<Point<D>>> = grid.iter().map(|row| lu_v.solve(row)).collect();
    let cols: Vec<Vec<Point<D>>> = transpose(&mid).iter().map(|col| lu_u.solve(col)).collect();
    BSplineSurface::new((p, q), u.1.to_vec(), v.1.to_vec(), transpose(&cols), (false, false))
}
