//! Animations of blending splines: motions of local pieces (oscillate, rotate, swing,
//! pulse) grouped in tracks, evaluated at a time T by [`splinekit::blend::animation`].

use serde::{Deserialize, Serialize};
use splinekit::blend::{Motion, Track};

use crate::defaults::{one, tau};
use crate::error::{DocumentError, Result};

/// `{"direction":[..],"amplitude":a,"frequency":f,"phase":φ}`.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct OscillateDoc {
    /// Direction of the translation.
    pub direction: Vec<f64>,
    /// Amplitude (default 1).
    #[serde(default = "one")]
    pub amplitude: f64,
    /// Frequency in hertz (default 1).
    #[serde(default = "one")]
    pub frequency: f64,
    /// Phase in radians (default 0).
    #[serde(default)]
    pub phase: f64,
}

/// `{"axis":[..],"speed":ω,"phase":φ,"pivot":[..]}`.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RotateMotionDoc {
    /// Axis (3-D).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub axis: Option<Vec<f64>>,
    /// Radians per second (default 2π: a turn a second).
    #[serde(default = "tau")]
    pub speed: f64,
    /// Phase in radians (default 0).
    #[serde(default)]
    pub phase: f64,
    /// A point on the axis (default: the local origin).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub pivot: Option<Vec<f64>>,
}

/// `{"axis":[..],"amplitude":a,"frequency":f,"phase":φ,"pivot":[..]}`.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SwingDoc {
    /// Axis (3-D).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub axis: Option<Vec<f64>>,
    /// Amplitude in radians.
    pub amplitude: f64,
    /// Frequency in hertz (default 1).
    #[serde(default = "one")]
    pub frequency: f64,
    /// Phase in radians (default 0).
    #[serde(default)]
    pub phase: f64,
    /// A point on the axis (default: the local origin).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub pivot: Option<Vec<f64>>,
}

/// `{"amplitude":a,"frequency":f,"phase":φ}`.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct PulseDoc {
    /// Amplitude (|a| < 1).
    pub amplitude: f64,
    /// Frequency in hertz (default 1).
    #[serde(default = "one")]
    pub frequency: f64,
    /// Phase in radians (default 0).
    #[serde(default)]
    pub phase: f64,
}

/// One motion: `{"oscillate":{…}}`, `{"rotate":{…}}`, `{"swing":{…}}` or `{"pulse":{…}}`.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case", deny_unknown_fields)]
#[allow(missing_docs)]
pub enum MotionDoc {
    Oscillate(OscillateDoc),
    Rotate(RotateMotionDoc),
    Swing(SwingDoc),
    Pulse(PulseDoc),
}

impl MotionDoc {
    /// The kernel motion.
    pub fn motion(&self) -> Motion {
        match self.clone() {
            MotionDoc::Oscillate(d) => Motion::Oscillate {
                direction: d.direction,
                amplitude: d.amplitude,
                frequency: d.frequency,
                phase: d.phase,
            },
            MotionDoc::Rotate(d) => Motion::Rotate { axis: d.axis, speed: d.speed, phase: d.phase, pivot: d.pivot },
            MotionDoc::Swing(d) => Motion::Swing {
                axis: d.axis,
                amplitude: d.amplitude,
                frequency: d.frequency,
                phase: d.phase,
                pivot: d.pivot,
            },
            MotionDoc::Pulse(d) => Motion::Pulse { amplitude: d.amplitude, frequency: d.frequency, phase: d.phase },
        }
    }
}

/// `{"local": k (curves) or [k, l] (surfaces), "motions": [ … ]}`.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct TrackDoc<K> {
    /// Which local piece.
    pub local: K,
    /// Its motions, applied in order.
    pub motions: Vec<MotionDoc>,
}

/// The kernel tracks of `docs`, each motion checked for dimension D.
pub(crate) fn tracks<K: Clone, const D: usize>(docs: &[TrackDoc<K>]) -> Result<Vec<Track<K>>> {
    docs.iter()
        .enumerate()
        .map(|(i, t)| {
            let motions: Vec<Motion> = t.motions.iter().map(MotionDoc::motion).collect();
            for (j, m) in motions.iter().enumerate() {
                m.validate::<D>().map_err(|e| {
                    DocumentError::new(
                        format!("animation[{i}].motions[{j}]"),
                        e.to_string().replacen("invalid ", "", 1),
                    )
                })?;
            }
            Ok(Track { local: t.local.clone(), motions })
        })
        .collect()
}
