//! Blending two curves with a B-function (the seeds' construction).
//!
//! Both curves are reparametrised to [0, 1]. With overlap x ∈ (0, 1) the blend lives on
//! [0, 1 + x]:
//!
//! c(t) = c₁(t) on [0, x), c₁(t) + B(w)(c₂(t − x) − c₁(t)) on [x, 1) with
//! w = (t − x)/(1 − x), and c₂(t − x) on [1, 1 + x].
//!
//! Derivatives by Leibniz: c^{(k)} = c₁^{(k)} + Σ_j C(k, j) B^{(j)}(w) (1 − x)^{−j}
//! (c₂ − c₁)^{(k−j)} in the middle. The joins at x and 1 are C^r when B^{(j)} vanishes at
//! 0 and 1 for 1 ≤ j ≤ r (and the curves match there as the construction requires).

use smallvec::{SmallVec, smallvec};

use crate::Point;
use crate::basis::{BFunction, Side, binomial};
use crate::curve::unit_parameter::unit_derivatives;
use crate::curve::{Curve, Interval};
use crate::error::{Error, Result};

/// The seeds' blend of two curves with overlap x.
pub struct TwoCurveBlend<const D: usize> {
    first: Box<dyn Curve<D>>,
    second: Box<dyn Curve<D>>,
    overlap: f64,
    bfunction: BFunction,
}

impl<const D: usize> TwoCurveBlend<D> {
    /// Blends `first` into `second` over the overlap fraction x ∈ (0, 1).
    pub fn new(
        first: Box<dyn Curve<D>>,
        second: Box<dyn Curve<D>>,
        overlap: f64,
        bfunction: BFunction,
    ) -> Result<Self> {
        if !(overlap > 0.0 && overlap < 1.0) {
            return Err(Error::invalid("overlap", format!("must be in (0, 1), got {overlap}")));
        }
        Ok(TwoCurveBlend { first, second, overlap, bfunction })
    }
}

impl<const D: usize> Curve<D> for TwoCurveBlend<D> {
    fn domain(&self) -> Interval {
        Interval::new(0.0, 1.0 + self.overlap)
    }
    fn is_closed(&self) -> bool {
        false
    }
    fn breakpoints(&self) -> Vec<f64> {
        vec![0.0, self.overlap, 1.0, 1.0 + self.overlap]
    }
    fn eval_side(&self, t: f64, side: Side, out: &mut [Point<D>]) {
        let x = self.overlap;
        let t = t.clamp(0.0, 1.0 + x);
        let k = out.len() - 1;
        let before = |b: f64| t < b || (t == b && side == Side::Left);
        if before(x) {
            out.copy_from_slice(&unit_derivatives(self.first.as_ref(), t, side, k));
        } else if !before(1.0) {
            out.copy_from_slice(&unit_derivatives(self.second.as_ref(), t - x, side, k));
        } else {
            let a = unit_derivatives(self.first.as_ref(), t, side, k);
            let b = unit_derivatives(self.second.as_ref(), t - x, side, k);
            let mut bf: SmallVec<[f64; 8]> = smallvec![0.0; k + 1];
            self.bfunction.eval((t - x) / (1.0 - x), &mut bf);
            let inv = 1.0 / (1.0 - x);
            for m in 0..=k {
                let mut v = a[m];
                let mut scale = 1.0;
                for j in 0..=m {
                    v += (b[m - j] - a[m - j]) * (binomial(m, j) * bf[j] * scale);
                    scale *= inv;
                }
                out[m] = v;
            }
        }
    }
}

/// The plain blend c₁(t) + B(t)(c₂(t) − c₁(t)) of two curves on a common domain [0, 1].
pub struct PlainBlend<const D: usize> {
    first: Box<dyn Curve<D>>,
    second: Box<dyn Curve<D>>,
    bfunction: BFunction,
}

impl<const D: usize> PlainBlend<D> {
    /// Blends `first` into `second` (both reparametrised to [0, 1]).
    pub fn new(first: Box<dyn Curve<D>>, second: Box<dyn Curve<D>>, bfunction: BFunction) -> Self {
        PlainBlend { first, second, bfunction }
    }
}

impl<const D: usize> Curve<D> for PlainBlend<D> {
    fn domain(&self) -> Interval {
        Interval::new(0.0, 1.0)
    }
    fn is_closed(&self) -> bool {
        false
    }
    fn eval_side(&self, t: f64, side: Side, out: &mut [Point<D>]) {
        let t = t.clamp(0.0, 1.0);
        let k = out.len() - 1;
        let a = unit_derivatives(self.first.as_ref(), t, side, k);
        let b = unit_derivatives(self.second.as_ref(), t, side, k);
        let mut bf: SmallVec<[f64; 8]> = smallvec![0.0; k + 1];
        self.bfunction.eval(t, &mut bf);
        for m in 0..=k {
            let mut v = a[m];
            for j in 0..=m {
                v += (b[m - j] - a[m - j]) * (binomial(m, j) * bf[j]);
            }
            out[m] = v;
        }
    }
}
