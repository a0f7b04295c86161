//! Least squares for design matrices whose rows have at most w consecutive non-zeros
//! (B-spline collocation), by Givens rotations row by row — the method of FITPACK.
//!
//! R is kept as a band of width w for the first n − b columns plus a dense border of the
//! last b columns (b = 0 for open splines, b = p for periodic ones, whose rows wrap
//! around). Rows sorted by their first column cost O(w² + w·b) each, so a fit of m
//! samples costs O(m (w + b) w) time and O(n (w + b)) memory. QR never forms AᵀA, so the
//! accuracy depends on cond(A), not cond(A)²; [`BandedLeastSquares::solve`] rejects
//! rank-deficient problems and reports a condition estimate.

use crate::Point;
use crate::error::{Error, Result};

/// A pivot |R_kk| at most this fraction of the largest marks an unknown the data do not
/// determine (R singular to working precision).
const RANK_RELATIVE: f64 = 1e-14;

/// Below this, r² + x² may have lost digits to underflow and Givens takes `hypot`.
const SQUARES_UNDERFLOW: f64 = 1e-290;

/// Incremental banded least-squares problem A x ≈ B with D right-hand sides.
#[derive(Debug, Clone)]
pub struct BandedLeastSquares<const D: usize> {
    n: usize,
    width: usize,
    border: usize,
    band_cols: usize,
    /// `band[k·width + j]` = R(k, k + j) for k < band_cols, j < width (columns < band_cols only).
    band: Vec<f64>,
    /// R(k, band_cols + j) for every row k < n.
    border_part: Vec<f64>,
    rhs: Vec<Point<D>>,
    residual_sq: f64,
    rows: usize,
}

/// The solution of a banded least-squares problem.
#[derive(Debug, Clone)]
pub struct Solution<const D: usize> {
    /// The unknowns x.
    pub x: Vec<Point<D>>,
    /// Σ |residual|² (weighted).
    pub residual_sq: f64,
    /// max |R_kk| / min |R_kk|, a cheap lower estimate of cond(A).
    pub condition_estimate: f64,
}

impl<const D: usize> BandedLeastSquares<D> {
    /// A problem with `n` unknowns, rows of `width` consecutive (cyclic when `border` > 0)
    /// non-zeros, and `border` dense trailing columns (width − 1 for periodic splines).
    pub fn new(n: usize, width: usize, border: usize) -> Self {
        let border = border.min(n);
        let band_cols = n - border;
        BandedLeastSquares {
            n,
            width,
            border,
            band_cols,
            band: vec![0.0; band_cols * width],
            border_part: vec![0.0; n * border],
            rhs: vec![Point::<D>::zeros(); n],
            residual_sq: 0.0,
            rows: 0,
        }
    }

    /// Adds the row Σ_j `values[j]` x_{(first + j) mod n} ≈ rhs: its band part and border
    /// part are rotated into R (Givens), and what is left of the right-hand side adds to
    /// the residual.
    pub fn add_row(&mut self, first: usize, values: &[f64], rhs: Point<D>) {
        let (w, b, nb) = (self.width, self.border, self.band_cols);
        let mut xb = [0.0f64; 64];
        let mut xborder = [0.0f64; 64];
        let mut heap_b;
        let mut heap_border;
        let (xband, xbord): (&mut [f64], &mut [f64]) = if w <= 64 && b <= 64 {
            (&mut xb[..w], &mut xborder[..b])
        } else {
            heap_b = vec![0.0; w];
            heap_border = vec![0.0; b];
            (&mut heap_b[..], &mut heap_border[..])
        };
        let mut lead = usize::MAX;
        for (j, &v) in values.iter().enumerate() {
            let col = (first + j) % self.n;
            if col >= nb {
                xbord[col - nb] += v;
            } else if lead == usize::MAX {
                lead = col;
                xband[0] += v;
            } else {
                xband[col - lead] += v;
            }
        }
        let mut xr = rhs;
        self.rows += 1;
        if lead != usize::MAX && self.rotate_into_band(lead, xband, xbord, &mut xr) {
            return;
        }
        if self.rotate_into_border(xbord, &mut xr) {
            return;
        }
        self.residual_sq += xr.norm_squared();
    }

    /// Rotates the row (band part `xband` starting at column `lead`, border part `xbord`,
    /// right-hand side `xr`) into the band rows of R from row `lead` on, until its band
    /// part is zero. Returns whether the row filled an empty row of R instead (then
    /// nothing is left of it).
    fn rotate_into_band(&mut self, lead: usize, xband: &mut [f64], xbord: &mut [f64], xr: &mut Point<D>) -> bool {
        let (w, b, nb) = (self.width, self.border, self.band_cols);
        let mut k = lead;
        while k < nb {
            if xband[0] != 0.0 {
                let rrow = &mut self.band[k * w..(k + 1) * w];
                let rb = &mut self.border_part[k * b..(k + 1) * b];
                if rrow[0] == 0.0 {
                    // Empty row of R: the new row becomes it.
                    let cols = w.min(nb - k);
                    rrow[..cols].copy_from_slice(&xband[..cols]);
                    rb.copy_from_slice(xbord);
                    self.rhs[k] = *xr;
                    return true;
                }
                let (c, s) = givens(rrow[0], xband[0]);
                for j in 0..w.min(nb - k) {
                    let (r, x) = (rrow[j], xband[j]);
                    rrow[j] = c * r + s * x;
                    xband[j] = c * x - s * r;
                }
                for j in 0..b {
                    let (r, x) = (rb[j], xbord[j]);
                    rb[j] = c * r + s * x;
                    xbord[j] = c * x - s * r;
                }
                let r = self.rhs[k];
                self.rhs[k] = r * c + *xr * s;
                *xr = *xr * c - r * s;
            }
            xband.copy_within(1..w, 0);
            xband[w - 1] = 0.0;
            k += 1;
            if xband.iter().all(|&v| v == 0.0) {
                break;
            }
        }
        false
    }

    /// Rotates the border part `xbord` (and `xr`) into the dense border rows of R.
    /// Returns whether it filled an empty row of R instead.
    fn rotate_into_border(&mut self, xbord: &mut [f64], xr: &mut Point<D>) -> bool {
        let (b, nb) = (self.border, self.band_cols);
        for i in 0..b {
            if xbord[i] == 0.0 {
                continue;
            }
            let row = nb + i;
            let rb = &mut self.border_part[row * b..(row + 1) * b];
            if rb[i] == 0.0 {
                rb[i..].copy_from_slice(&xbord[i..]);
                self.rhs[row] = *xr;
                return true;
            }
            let (c, s) = givens(rb[i], xbord[i]);
            for j in i..b {
                let (r, x) = (rb[j], xbord[j]);
                rb[j] = c * r + s * x;
                xbord[j] = c * x - s * r;
            }
            let r = self.rhs[row];
            self.rhs[row] = r * c + *xr * s;
            *xr = *xr * c - r * s;
        }
        false
    }

    /// Back substitution. Fails (naming the unknown) when R is singular to working
    /// precision, i.e. when the data do not determine some unknown.
    pub fn solve(&self) -> Result<Solution<D>> {
        let (w, b, nb, n) = (self.width, self.border, self.band_cols, self.n);
        let diag = |k: usize| if k < nb { self.band[k * w] } else { self.border_part[k * b + (k - nb)] };
        let max = (0..n).map(|k| diag(k).abs()).fold(0.0, f64::max);
        let min = (0..n).map(|k| diag(k).abs()).fold(f64::INFINITY, f64::min);
        for k in 0..n {
            if diag(k).abs() <= max * RANK_RELATIVE || diag(k).is_nan() {
                return Err(Error::numerical(
                    "fit",
                    format!(
                        "unknown {k} of {n} is not determined by the data (no sample where its basis function is non-zero, or the samples are too few); use fewer control points or more samples"
                    ),
                ));
            }
        }
        let mut x = vec![Point::<D>::zeros(); n];
        for i in (0..b).rev() {
            let row = nb + i;
            let rb = &self.border_part[row * b..(row + 1) * b];
            let mut acc = self.rhs[row];
            for j in i + 1..b {
                acc -= x[nb + j] * rb[j];
            }
            x[row] = acc / rb[i];
        }
        for k in (0..nb).rev() {
            let rrow = &self.band[k * w..(k + 1) * w];
            let rb = &self.border_part[k * b..(k + 1) * b];
            let mut acc = self.rhs[k];
            for j in 1..w.min(nb - k) {
                acc -= x[k + j] * rrow[j];
            }
            for j in 0..b {
                acc -= x[nb + j] * rb[j];
            }
            x[k] = acc / rrow[0];
        }
        Ok(Solution { x, residual_sq: self.residual_sq, condition_estimate: max / min })
    }

    /// Number of rows added.
    pub fn rows(&self) -> usize {
        self.rows
    }
}

/// c, s with c·r + s·x = √(r² + x²), −s·r + c·x = 0. The plain square root is exact
/// enough and much faster than `hypot`; `hypot` takes over only where r² + x² would
/// overflow or underflow.
#[inline]
fn givens(r: f64, x: f64) -> (f64, f64) {
    let sq = r * r + x * x;
    let h = if sq.is_finite() && sq > SQUARES_UNDERFLOW { sq.sqrt() } else { r.hypot(x) };
    let inv = 1.0 / h;
    (r * inv, x * inv)
}
