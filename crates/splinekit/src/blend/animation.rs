//! Time-driven transforms of local pieces ("special effects"): each local piece of a
//! blending spline can follow a list of motions, evaluated at a time T (seconds) into an
//! affine frame about the piece's origin. Deterministic: the frame depends on T only.
//!
//! Motions, with θ(T) = 2π f T + φ:
//! - `Oscillate`: translation a·sin θ · direction,
//! - `Rotate`: rotation by ω T + φ about an axis (through the origin, or a pivot point),
//! - `Swing`: rotation by a·sin θ (a back-and-forth rotation),
//! - `Pulse`: uniform scaling by 1 + a·sin θ (|a| < 1).
//!
//! A track's motions compose in order (the first is applied first); the animated frame is
//! the track's map applied after the piece's rest frame.

use crate::Point;
use crate::error::{Error, Result};
use crate::frame::Affine;

/// One motion of a local piece.
#[derive(Debug, Clone, PartialEq)]
pub enum Motion {
    /// Translation by amplitude·sin(2π f T + φ) along `direction`.
    Oscillate {
        /// The direction (scaled by the amplitude; need not be unit length).
        direction: Vec<f64>,
        /// Amplitude a.
        amplitude: f64,
        /// Frequency f in hertz.
        frequency: f64,
        /// Phase φ in radians.
        phase: f64,
    },
    /// Rotation by speed·T + φ radians.
    Rotate {
        /// Axis (3-D); 2-D rotations need none.
        axis: Option<Vec<f64>>,
        /// Angular speed ω in radians per second.
        speed: f64,
        /// Phase φ in radians.
        phase: f64,
        /// The point the axis passes through (world coordinates); the piece's origin if `None`.
        pivot: Option<Vec<f64>>,
    },
    /// Rotation by amplitude·sin(2π f T + φ) radians.
    Swing {
        /// Axis (3-D); 2-D rotations need none.
        axis: Option<Vec<f64>>,
        /// Amplitude a in radians.
        amplitude: f64,
        /// Frequency f in hertz.
        frequency: f64,
        /// Phase φ in radians.
        phase: f64,
        /// The point the axis passes through (world coordinates); the piece's origin if `None`.
        pivot: Option<Vec<f64>>,
    },
    /// Uniform scaling by 1 + amplitude·sin(2π f T + φ) about the piece's origin.
    Pulse {
        /// Amplitude a, |a| < 1.
        amplitude: f64,
        /// Frequency f in hertz.
        frequency: f64,
        /// Phase φ in radians.
        phase: f64,
    },
}

/// The angle `theta` of a motion at `time` (2π f T + φ, or ω T + φ for a rotation),
/// refused when it overflowed: a time so large that the motion's phase is no longer a number.
fn finite_phase(theta: f64, time: f64) -> Result<f64> {
    if !theta.is_finite() {
        return Err(Error::invalid("time", format!("at {time} s the phase of a motion overflows (got {theta})")));
    }
    Ok(theta)
}

fn wave(amplitude: f64, frequency: f64, phase: f64, time: f64) -> Result<f64> {
    Ok(amplitude * finite_phase(std::f64::consts::TAU * frequency * time + phase, time)?.sin())
}

fn finite(field: &str, values: &[(&str, f64)]) -> Result<()> {
    for (name, x) in values {
        if !x.is_finite() {
            return Err(Error::invalid(format!("{field}.{name}"), format!("must be finite, got {x}")));
        }
    }
    Ok(())
}

impl Motion {
    /// Checks the parameters (finite numbers, |pulse amplitude| < 1, vector sizes).
    pub fn validate<const D: usize>(&self) -> Result<()> {
        let vector = |field: &str, v: &[f64]| -> Result<()> {
            if v.len() != D {
                return Err(Error::invalid(field.to_string(), format!("expected {D} coordinates, got {}", v.len())));
            }
            finite(field, &v.iter().map(|&x| ("", x)).collect::<Vec<_>>())
        };
        match self {
            Motion::Oscillate { direction, amplitude, frequency, phase } => {
                vector("oscillate.direction", direction)?;
                finite("oscillate", &[("amplitude", *amplitude), ("frequency", *frequency), ("phase", *phase)])
            }
            Motion::Rotate { axis, speed, phase, pivot } => {
                finite("rotate", &[("speed", *speed), ("phase", *phase)])?;
                if let Some(p) = pivot {
                    vector("rotate.pivot", p)?;
                }
                Affine::<D>::rotation_in(axis.as_deref(), 0.0).map(|_| ())
            }
            Motion::Swing { axis, amplitude, frequency, phase, pivot } => {
                finite("swing", &[("amplitude", *amplitude), ("frequency", *frequency), ("phase", *phase)])?;
                if let Some(p) = pivot {
                    vector("swing.pivot", p)?;
                }
                Affine::<D>::rotation_in(axis.as_deref(), 0.0).map(|_| ())
            }
            Motion::Pulse { amplitude, frequency, phase } => {
                finite("pulse", &[("amplitude", *amplitude), ("frequency", *frequency), ("phase", *phase)])?;
                if amplitude.abs() >= 1.0 {
                    return Err(Error::invalid(
                        "pulse.amplitude",
                        format!("must be below 1 in size (the scale 1 + a sin θ must stay positive), got {amplitude}"),
                    ));
                }
                Ok(())
            }
        }
    }

    /// The motion's map at `time`, in coordinates centred on the piece's `origin`.
    pub fn at<const D: usize>(&self, time: f64, origin: &Point<D>) -> Result<Affine<D>> {
        let about_pivot = |rotation: Affine<D>, pivot: &Option<Vec<f64>>| -> Affine<D> {
            match pivot {
                None => rotation,
                Some(p) => {
                    let q = Point::<D>::from_iterator(p.iter().copied()) - origin;
                    rotation.about(&q)
                }
            }
        };
        Ok(match self {
            Motion::Oscillate { direction, amplitude, frequency, phase } => Affine::translation(
                Point::<D>::from_iterator(direction.iter().copied()) * wave(*amplitude, *frequency, *phase, time)?,
            ),
            Motion::Rotate { axis, speed, phase, pivot } => {
                let angle = finite_phase(speed * time + phase, time)?;
                about_pivot(Affine::rotation_in(axis.as_deref(), angle)?, pivot)
            }
            Motion::Swing { axis, amplitude, frequency, phase, pivot } => {
                about_pivot(Affine::rotation_in(axis.as_deref(), wave(*amplitude, *frequency, *phase, time)?)?, pivot)
            }
            Motion::Pulse { amplitude, frequency, phase } => {
                Affine::uniform_scale(1.0 + wave(*amplitude, *frequency, *phase, time)?)
            }
        })
    }
}

/// The motions of one local piece, identified by `local` (an index for curves, a pair
/// (k, l) for surfaces).
#[derive(Debug, Clone, PartialEq)]
pub struct Track<K> {
    /// Which local piece moves.
    pub local: K,
    /// Its motions, applied in order.
    pub motions: Vec<Motion>,
}

impl<K> Track<K> {
    /// The composed map at `time` about `origin`: the last motion after the others.
    pub fn at<const D: usize>(&self, time: f64, origin: &Point<D>) -> Result<Affine<D>> {
        if !time.is_finite() {
            return Err(Error::invalid("time", format!("must be finite, got {time}")));
        }
        let mut a = Affine::identity();
        for m in &self.motions {
            a = m.at(time, origin)?.after(&a);
        }
        Ok(a)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn motions_follow_their_formulas() {
        let o = Point::<3>::new(1.0, 2.0, 0.0);
        let osc = Motion::Oscillate { direction: vec![2.0, 0.0, 0.0], amplitude: 0.5, frequency: 2.0, phase: 0.0 };
        let a = osc.at::<3>(0.125, &o).unwrap(); // sin(π/2) = 1
        assert!((a.translation - Point::<3>::new(1.0, 0.0, 0.0)).norm() < 1e-15);
        let rot =
            Motion::Rotate { axis: Some(vec![0.0, 0.0, 1.0]), speed: std::f64::consts::PI, phase: 0.0, pivot: None };
        let r = rot.at::<3>(0.5, &o).unwrap();
        assert!((r.apply_point(&Point::<3>::new(1.0, 0.0, 0.0)) - Point::<3>::new(0.0, 1.0, 0.0)).norm() < 1e-15);
        // About a pivot: the pivot stays put (in piece-centred coordinates pivot − origin).
        let piv = Motion::Rotate {
            axis: Some(vec![0.0, 0.0, 1.0]),
            speed: 1.0,
            phase: 0.3,
            pivot: Some(vec![4.0, 2.0, 0.0]),
        };
        let q = Point::<3>::new(3.0, 0.0, 0.0);
        assert!((piv.at::<3>(0.7, &o).unwrap().apply_point(&q) - q).norm() < 1e-14);
        let pulse = Motion::Pulse { amplitude: 0.2, frequency: 1.0, phase: std::f64::consts::FRAC_PI_2 };
        assert!((pulse.at::<2>(0.0, &Point::<2>::zeros()).unwrap().linear[(0, 0)] - 1.2).abs() < 1e-15);
        assert!(Motion::Pulse { amplitude: 1.0, frequency: 1.0, phase: 0.0 }.validate::<3>().is_err());
        assert!(
            Motion::Oscillate { direction: vec![1.0], amplitude: 1.0, frequency: 1.0, phase: 0.0 }
                .validate::<3>()
                .unwrap_err()
                .to_string()
                .contains("oscillate.direction")
        );
        // A track is periodic in time with the motions' common period.
        let t = Track { local: 3usize, motions: vec![osc, pulse] };
        let (a, b) = (t.at::<3>(0.3, &o).unwrap(), t.at::<3>(1.3, &o).unwrap());
        assert!((a.linear - b.linear).norm() < 1e-14 && (a.translation - b.translation).norm() < 1e-14);
    }

    #[test]
    fn a_time_that_overflows_the_phase_names_the_time() {
        let o = Point::<3>::zeros();
        let swing = Motion::Swing { axis: None, amplitude: 0.3, frequency: 2.0, phase: 0.0, pivot: None };
        let spin = Motion::Rotate { axis: None, speed: 4.0, phase: 0.0, pivot: None };
        for m in [swing, spin] {
            let e = Track { local: 0usize, motions: vec![m] }.at::<3>(1e308, &o).unwrap_err().to_string();
            assert!(e.starts_with("time:") && e.contains("overflows"), "{e}");
        }
    }
}
