//! A B-function as a 1-D curve t ↦ (B(t)) on [0, 1], for plots and checks.

use crate::Point;
use crate::basis::{BFunction, Side};
use crate::curve::{Curve, Interval};
use smallvec::{SmallVec, smallvec};

/// The curve t ↦ (B(t)), t ∈ [0, 1].
#[derive(Debug, Clone, PartialEq)]
pub struct BFunctionCurve(pub BFunction);

impl Curve<1> for BFunctionCurve {
    fn domain(&self) -> Interval {
        Interval::new(0.0, 1.0)
    }
    fn eval_side(&self, t: f64, _side: Side, out: &mut [Point<1>]) {
        let mut v: SmallVec<[f64; 8]> = smallvec![0.0; out.len()];
        self.0.eval(t, &mut v);
        for (o, x) in out.iter_mut().zip(v) {
            o[0] = x;
        }
    }
}
