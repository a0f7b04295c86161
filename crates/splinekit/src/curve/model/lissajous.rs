//! Lissajous curves (A sin(a t + δ), B sin(b t), C sin(c t)), t ∈ [0, 2π].

use super::trig::{Term, TrigCurve, TrigSeries, finite, trig_model_curve};

/// Lissajous figure with amplitudes (A, B, C) and frequencies (a, b, c); c = 0 or C = 0
/// keeps it planar. Closed over [0, 2π] when the frequencies are integers.
#[derive(Debug, Clone, PartialEq)]
pub struct Lissajous {
    curve: TrigCurve,
}

impl Lissajous {
    /// Amplitudes, frequencies and the phase δ of the x-coordinate.
    pub fn new(amplitudes: [f64; 3], frequencies: [f64; 3], delta: f64) -> crate::Result<Self> {
        for (i, v) in amplitudes.iter().enumerate() {
            finite(&format!("amplitudes[{i}]"), *v)?;
        }
        for (i, v) in frequencies.iter().enumerate() {
            finite(&format!("frequencies[{i}]"), *v)?;
        }
        finite("delta", delta)?;
        let mut x = Term::sin(amplitudes[0], frequencies[0]);
        x.phase += delta;
        let curve = TrigCurve::one_turn(
            [
                TrigSeries::of(&[x]),
                TrigSeries::of(&[Term::sin(amplitudes[1], frequencies[1])]),
                TrigSeries::of(&[Term::sin(amplitudes[2], frequencies[2])]),
            ],
            frequencies.iter().all(|f| f.fract() == 0.0),
        );
        Ok(Lissajous { curve })
    }
}

trig_model_curve!(Lissajous);
