//! The circular helix (r cos t, r sin t, h t / 2π), t ∈ [0, 2π·turns], open.

use super::trig::{Term, TrigCurve, TrigSeries, finite, positive, trig_model_curve};
use crate::curve::Interval;
use std::f64::consts::TAU;

/// Helix of radius r rising by `pitch` per turn.
#[derive(Debug, Clone, PartialEq)]
pub struct Helix {
    curve: TrigCurve,
}

impl Helix {
    /// Radius > 0, pitch (rise per turn, any sign), turns > 0.
    pub fn new(radius: f64, pitch: f64, turns: f64) -> crate::Result<Self> {
        let r = positive("radius", radius)?;
        let pitch = finite("pitch", pitch)?;
        let turns = positive("turns", turns)?;
        let z = TrigSeries { linear: pitch / TAU, ..Default::default() };
        let curve = TrigCurve {
            coordinates: [TrigSeries::of(&[Term::cos(r, 1.0)]), TrigSeries::of(&[Term::sin(r, 1.0)]), z],
            domain: Interval::new(0.0, TAU * turns),
            closed: false,
        };
        Ok(Helix { curve })
    }
}

trig_model_curve!(Helix);
