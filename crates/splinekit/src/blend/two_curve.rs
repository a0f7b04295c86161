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

use super::leibniz::blend_derivatives;
use crate::Point;
use crate::basis::{BFunction, Side};
use crate::curve::{Curve, Interval, Reparametrized};
use crate::error::{Error, Result};

/// A curve of a blend, reparametrised to [0, 1].
type UnitCurve<const D: usize> = Reparametrized<Box<dyn Curve<D>>>;

/// The seeds' blend of two curves with overlap x.
pub struct TwoCurveBlend<const D: usize> {
    first: UnitCurve<D>,
    second: UnitCurve<D>,
    overlap: f64,
    bfunction: BFunction,
}

impl<const D: usize> TwoCurveBlend<D> {
    /// Blends `first` into `second` over the overlap fraction x ∈ (0, 1); both curves need
    /// finite, non-empty domains.
    ///
    /// # Examples
    ///
    /// ```
    /// use splinekit::Point;
    /// use splinekit::basis::BFunction;
    /// use splinekit::blend::TwoCurveBlend;
    /// use splinekit::curve::Curve;
    /// use splinekit::curve::model::Line;
    /// let p = |x, y| Point::<2>::new(x, y);
    /// let first = Box::new(Line::new(p(0.0, 0.0), p(1.0, 0.0)).unwrap());
    /// let second = Box::new(Line::new(p(0.5, 0.0), p(1.5, 1.0)).unwrap());
    /// let blend = TwoCurveBlend::new(first, second, 0.5, BFunction::Trigonometric).unwrap();
    /// // The first curve alone before x, the second alone after 1.
    /// assert_eq!(blend.point(0.25), p(0.25, 0.0));
    /// assert_eq!(blend.point(1.25), p(1.25, 0.75));
    /// ```
    pub fn new(
        first: Box<dyn Curve<D>>,
        second: Box<dyn Curve<D>>,
        overlap: f64,
        bfunction: BFunction,
    ) -> Result<Self> {
        if !(overlap > 0.0 && overlap < 1.0) {
            return Err(Error::invalid("overlap", format!("must be in (0, 1), got {overlap}")));
        }
        let (first, second) = (Reparametrized::unit(first)?, Reparametrized::unit(second)?);
        Ok(TwoCurveBlend { first, second, overlap, bfunction })
    }
}

impl<const D: usize> Curve<D> for TwoCurveBlend<D> {
    fn domain(&self) -> Interval {
        Interval::new(0.0, 1.0 + self.overlap)
    }
    fn breakpoints(&self) -> Vec<f64> {
        vec![0.0, self.overlap, 1.0, 1.0 + self.overlap]
    }
    fn eval_side(&self, t: f64, side: Side, out: &mut [Point<D>]) {
        let x = self.overlap;
        let t = t.clamp(0.0, 1.0 + x);
        let before = |b: f64| t < b || (t == b && side == Side::Left);
        if before(x) {
            self.first.eval_side(t, side, out);
        } else if !before(1.0) {
            self.second.eval_side(t - x, side, out);
        } else {
            let n = out.len();
            let mut a: SmallVec<[Point<D>; 8]> = smallvec![Point::<D>::zeros(); n];
            let mut b: SmallVec<[Point<D>; 8]> = smallvec![Point::<D>::zeros(); n];
            self.first.eval_side(t, side, &mut a);
            self.second.eval_side(t - x, side, &mut b);
            let mut bf: SmallVec<[f64; 8]> = smallvec![0.0; n];
            self.bfunction.eval((t - x) / (1.0 - x), &mut bf);
            blend_derivatives(&a, &b, &bf, 1.0 / (1.0 - x), out);
        }
    }
}

/// The plain blend c₁(t) + B(t)(c₂(t) − c₁(t)) of two curves on a common domain [0, 1].
pub struct PlainBlend<const D: usize> {
    first: UnitCurve<D>,
    second: UnitCurve<D>,
    bfunction: BFunction,
}

impl<const D: usize> PlainBlend<D> {
    /// Blends `first` into `second` (both reparametrised to [0, 1], so their domains must
    /// be finite and non-empty).
    pub fn new(first: Box<dyn Curve<D>>, second: Box<dyn Curve<D>>, bfunction: BFunction) -> Result<Self> {
        Ok(PlainBlend { first: Reparametrized::unit(first)?, second: Reparametrized::unit(second)?, bfunction })
    }
}

impl<const D: usize> Curve<D> for PlainBlend<D> {
    fn domain(&self) -> Interval {
        Interval::new(0.0, 1.0)
    }
    fn eval_side(&self, t: f64, side: Side, out: &mut [Point<D>]) {
        let t = t.clamp(0.0, 1.0);
        let n = out.len();
        let mut a: SmallVec<[Point<D>; 8]> = smallvec![Point::<D>::zeros(); n];
        let mut b: SmallVec<[Point<D>; 8]> = smallvec![Point::<D>::zeros(); n];
        self.first.eval_side(t, side, &mut a);
        self.second.eval_side(t, side, &mut b);
        let mut bf: SmallVec<[f64; 8]> = smallvec![0.0; n];
        self.bfunction.eval(t, &mut bf);
        blend_derivatives(&a, &b, &bf, 1.0, out);
    }
}
