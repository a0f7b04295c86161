//! Bézier surfaces S(u, v) = Σ_i Σ_j B_{i,m}(u) B_{j,n}(v) P_ij on [0, 1]², evaluated by
//! de Casteljau in v for every row, then in u.

use smallvec::{SmallVec, smallvec};

use crate::Point;
use crate::curve::bezier::bezier_derivatives;
use crate::error::Result;
use crate::surface::Surface;
use crate::surface::tensor::checked_net;

/// A tensor-product Bézier surface of degrees (rows − 1, columns − 1).
#[derive(Debug, Clone, PartialEq)]
pub struct BezierSurface<const D: usize> {
    net: Vec<Vec<Point<D>>>,
}

impl<const D: usize> BezierSurface<D> {
    /// A surface from its control net (first index along u).
    ///
    /// # Examples
    ///
    /// ```
    /// use splinekit::Point;
    /// use splinekit::surface::{BezierSurface, Surface};
    /// // A biquadratic net lifted in the middle: S(½, ½) = Σ B_i(½) B_j(½) P_ij, B(½) = (¼, ½, ¼).
    /// let net: Vec<Vec<Point<3>>> = (0..3)
    ///     .map(|i| (0..3).map(|j| Point::<3>::new(i as f64, j as f64, if (i, j) == (1, 1) { 4.0 } else { 0.0 })).collect())
    ///     .collect();
    /// let s = BezierSurface::new(net).unwrap();
    /// assert_eq!(s.point(0.5, 0.5), Point::<3>::new(1.0, 1.0, 1.0));
    /// ```
    pub fn new(net: Vec<Vec<Point<D>>>) -> Result<Self> {
        checked_net(&net)?;
        Ok(BezierSurface { net })
    }
    /// The control net.
    pub fn control_points(&self) -> &[Vec<Point<D>>] {
        &self.net
    }
    /// Degrees (m, n).
    pub fn degrees(&self) -> (usize, usize) {
        (self.net.len() - 1, self.net[0].len() - 1)
    }
}

impl<const D: usize> Surface<D> for BezierSurface<D> {
    crate::curve::control_box::control_point_box!(net "a Bézier surface");
    crate::surface::unit_square::unit_square_domains!();
    fn eval_partials(&self, u: f64, v: f64, du: usize, dv: usize, out: &mut [Point<D>]) {
        let (u, v) = (u.clamp(0.0, 1.0), v.clamp(0.0, 1.0));
        let rows = self.net.len();
        let w = dv + 1;
        let mut tmp: SmallVec<[Point<D>; 32]> = smallvec![Point::<D>::zeros(); rows * w];
        for (r, row) in self.net.iter().enumerate() {
            bezier_derivatives(row, v, &mut tmp[r * w..(r + 1) * w]);
        }
        let mut col: SmallVec<[Point<D>; 16]> = smallvec![Point::<D>::zeros(); rows];
        let mut res: SmallVec<[Point<D>; 8]> = smallvec![Point::<D>::zeros(); du + 1];
        for j in 0..=dv {
            for r in 0..rows {
                col[r] = tmp[r * w + j];
            }
            bezier_derivatives(&col, u, &mut res);
            for i in 0..=du {
                out[i * w + j] = res[i];
            }
        }
    }
}
