//! `eval --arc-length`: curve parameters at equal arc-length spacing.

use anyhow::Result;
use splinekit::curve::{Curve, CurveArcLength};
use splinekit::query::ArcLengthTable;

/// Relative accuracy of the arc lengths behind `--arc-length` (of the curve's length).
pub const RELATIVE_ACCURACY: f64 = 1e-10;

/// `n` ≥ 2 parameters of `curve` at equal arc-length spacing, ends included; the lengths
/// between consecutive ones agree to [`RELATIVE_ACCURACY`] of the whole length.
pub fn equal_length_params<const D: usize>(curve: &dyn Curve<D>, n: usize) -> Result<Vec<f64>> {
    let rough = curve.length(1e-6);
    let accuracy = RELATIVE_ACCURACY * rough.max(f64::MIN_POSITIVE.sqrt());
    let table = ArcLengthTable::new(curve, accuracy)?;
    Ok(table.equal_length_parameters(n)?)
}
