//! Interpolation on given knots at given parameters for many right-hand sides with one
//! factorisation: the rows of a grid share their parameters, so the rows (then the
//! columns) of a tensor-product interpolation solve systems with one matrix.
//!
//! The collocation matrix A_ij = N_{j,p}(t_i) (n × n for n control points, row i non-zero
//! in columns span_i − p … span_i) is totally positive for increasing parameters (Karlin;
//! de Boor, *A Practical Guide to Splines*, XIII), and Gaussian elimination without
//! pivoting is backward stable for totally positive matrices (de Boor and Pinkus, 1977),
//! so A = LU is factored in its band — lower and upper bandwidths at most p, O(n p²) —
//! and each solve costs O(n p). A pivot that vanishes (parameters against the
//! Schoenberg–Whitney conditions) is an error.

use crate::Point;
use crate::basis::{Side, basis_functions, find_span};
use crate::error::{Error, Result};

/// A pivot at most this counts as zero (the rows of A are a partition of unity, so its
/// entries are at most 1).
const PIVOT_ZERO: f64 = 1e-14;

/// The LU factors of a collocation matrix in band storage.
#[derive(Debug, Clone)]
pub struct CollocationLu {
    n: usize,
    /// Lower and upper bandwidths.
    lower: usize,
    upper: usize,
    /// `band[i·w + (j + lower − i)]` = entry (i, j) of L (below the diagonal, unit diagonal
    /// not stored) and U (on and above it), w = lower + upper + 1.
    band: Vec<f64>,
}

impl CollocationLu {
    /// Factors the collocation matrix of degree `degree` on `knots` (clamped, n + p + 1 of
    /// them) at `params` (n increasing values in the domain).
    pub fn new(degree: usize, knots: &[f64], params: &[f64]) -> Result<Self> {
        let p = degree;
        let n = params.len();
        if n <= p {
            return Err(Error::invalid("params", format!("degree {p} needs more than {p} parameters, got {n}")));
        }
        if knots.len() != n + p + 1 {
            return Err(Error::count("knots", format!("{} for {n} parameters of degree {p}", n + p + 1), knots.len()));
        }
        if let Some(i) = params.windows(2).position(|w| w[1].partial_cmp(&w[0]) != Some(std::cmp::Ordering::Greater)) {
            return Err(Error::invalid("params", format!("must increase, got {} then {}", params[i], params[i + 1])));
        }
        let (start, end) = (knots[p], knots[n]);
        if let Some((i, t)) = params.iter().enumerate().find(|(_, t)| **t < start || **t > end) {
            return Err(Error::invalid(
                "params",
                format!("parameter {i} ({t}) is outside the domain [{start}, {end}]"),
            ));
        }
        let mut rows = Vec::with_capacity(n);
        let (mut lower, mut upper) = (0usize, 0usize);
        let mut basis = vec![0.0; p + 1];
        for (i, &t) in params.iter().enumerate() {
            let span = find_span(knots, p, n, t, Side::Right);
            basis_functions(knots, p, span, t, &mut basis);
            let first = span - p;
            lower = lower.max(i.saturating_sub(first));
            upper = upper.max((first + p).saturating_sub(i));
            rows.push((first, basis.clone()));
        }
        let w = lower + upper + 1;
        let mut band = vec![0.0; n * w];
        for (i, (first, values)) in rows.iter().enumerate() {
            for (r, v) in values.iter().enumerate() {
                band[i * w + first + r + lower - i] = *v;
            }
        }
        let mut lu = CollocationLu { n, lower, upper, band };
        lu.factor(params)?;
        Ok(lu)
    }

    fn at(&self, i: usize, j: usize) -> usize {
        i * (self.lower + self.upper + 1) + j + self.lower - i
    }

    /// Gaussian elimination without pivoting, in place.
    fn factor(&mut self, params: &[f64]) -> Result<()> {
        let (n, kl, ku) = (self.n, self.lower, self.upper);
        for k in 0..n {
            let pivot = self.band[self.at(k, k)];
            if pivot.is_nan() || pivot.abs() <= PIVOT_ZERO {
                return Err(Error::numerical(
                    "interpolation",
                    format!(
                        "the collocation matrix is singular at parameter {k} ({}): the parameters do not fit the knots (Schoenberg–Whitney)",
                        params[k]
                    ),
                ));
            }
            for i in k + 1..(k + kl + 1).min(n) {
                let l = self.band[self.at(i, k)] / pivot;
                if l == 0.0 {
                    continue;
                }
                let li = self.at(i, k);
                self.band[li] = l;
                for j in k + 1..(k + ku + 1).min(n) {
                    let (ij, kj) = (self.at(i, j), self.at(k, j));
                    self.band[ij] -= l * self.band[kj];
                }
            }
        }
        Ok(())
    }

    /// The control points interpolating `values` (one per parameter).
    pub fn solve<const D: usize>(&self, values: &[Point<D>]) -> Vec<Point<D>> {
        let (n, kl, ku) = (self.n, self.lower, self.upper);
        let mut x = values.to_vec();
        for i in 0..n {
            for k in i.saturating_sub(kl)..i {
                let l = self.band[self.at(i, k)];
                let xk = x[k];
                x[i] -= xk * l;
            }
        }
        for i in (0..n).rev() {
            for j in i + 1..(i + ku + 1).min(n) {
                let u = self.band[self.at(i, j)];
                let xj = x[j];
                x[i] -= xj * u;
            }
            x[i] /= self.band[self.at(i, i)];
        }
        x
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::curve::{BSplineCurve, Curve};

    #[test]
    fn interpolates_at_the_parameters_with_triple_knots() {
        // Cubic, not-a-knot on two spans joined by a triple knot at 0.5.
        let params: Vec<f64> = (0..=8).map(|k| k as f64 / 8.0).collect();
        let knots = vec![0.0, 0.0, 0.0, 0.0, 0.25, 0.5, 0.5, 0.5, 0.75, 1.0, 1.0, 1.0, 1.0];
        let lu = CollocationLu::new(3, &knots, &params).unwrap();
        let values: Vec<Point<2>> = params.iter().map(|&t| Point::<2>::new((7.0 * t).sin(), t * t)).collect();
        let curve = BSplineCurve::new(3, knots, lu.solve(&values)).unwrap();
        for (t, v) in params.iter().zip(&values) {
            assert!((curve.point(*t) - v).norm() < 1e-14, "at {t}");
        }
    }

    #[test]
    fn parameters_against_the_knots_are_refused() {
        // N_4 lives on [0.5, 1] and no parameter is there: the matrix is singular.
        let knots = vec![0.0, 0.0, 0.0, 0.0, 0.5, 1.0, 1.0, 1.0, 1.0];
        let params = [0.0, 0.1, 0.2, 0.3, 0.4];
        let e = CollocationLu::new(3, &knots, &params).unwrap_err().to_string();
        assert!(e.contains("Schoenberg"), "{e}");
    }
}
