//! Stored samples of a curve that can be refreshed on parameter ranges only: after an edit
//! that reports the ranges it changed (e.g. moving a local of a blending spline), only the
//! samples inside them are evaluated again.

use crate::basis::Side;
use crate::curve::Curve;
use crate::error::{Error, Result};
use crate::{Interval, Point};

/// `count` evenly spaced samples of a curve with derivatives up to `order`.
#[derive(Debug, Clone)]
pub struct CurveSamples<const D: usize> {
    params: Vec<f64>,
    order: usize,
    values: Vec<Point<D>>,
}

impl<const D: usize> CurveSamples<D> {
    /// Samples at `count` ≥ 2 parameters evenly over the domain (the last one evaluated
    /// from the left), each with the value and `order` derivatives.
    pub fn uniform<C: Curve<D> + ?Sized>(curve: &C, count: usize, order: usize) -> Result<Self> {
        if !(2..=100_000_000).contains(&count) {
            return Err(Error::invalid("samples", format!("need 2 to 100000000 samples, got {count}")));
        }
        let dom = curve.domain();
        let params = (0..count).map(|i| dom.lerp(i as f64 / (count - 1) as f64)).collect();
        let mut s = CurveSamples { params, order, values: vec![Point::<D>::zeros(); count * (order + 1)] };
        s.evaluate(curve, 0..count);
        Ok(s)
    }
    fn evaluate<C: Curve<D> + ?Sized>(&mut self, curve: &C, range: std::ops::Range<usize>) {
        let last = self.params.len() - 1;
        let w = self.order + 1;
        for i in range {
            let side = if i == last { Side::Left } else { Side::Right };
            curve.eval_side(self.params[i], side, &mut self.values[i * w..(i + 1) * w]);
        }
    }
    /// Re-evaluates the samples whose parameters lie in any of the closed `ranges`;
    /// returns how many were evaluated.
    pub fn refresh<C: Curve<D> + ?Sized>(&mut self, curve: &C, ranges: &[Interval]) -> usize {
        let mut done = 0;
        for range in ranges {
            let lo = self.params.partition_point(|&t| t < range.start);
            let hi = self.params.partition_point(|&t| t <= range.end);
            if lo < hi {
                self.evaluate(curve, lo..hi);
                done += hi - lo;
            }
        }
        done
    }
    /// The sample parameters.
    pub fn params(&self) -> &[f64] {
        &self.params
    }
    /// Value and derivatives at sample i.
    pub fn at(&self, i: usize) -> &[Point<D>] {
        let w = self.order + 1;
        &self.values[i * w..(i + 1) * w]
    }
    /// The sampled points.
    pub fn points(&self) -> impl Iterator<Item = &Point<D>> + '_ {
        self.values.iter().step_by(self.order + 1)
    }
}
