//! The animation clock: play/pause, speed, and the time within the scene's duration.

use std::time::Instant;

/// The time at which the scene is posed.
#[derive(Debug, Clone)]
pub struct Clock {
    /// Seconds into the animation, in [0, duration).
    pub time: f64,
    /// Whether the clock runs.
    pub playing: bool,
    /// Speed factor (1: real time).
    pub speed: f64,
    last: Instant,
}

impl Clock {
    /// A running clock at 0.
    pub fn new() -> Self {
        Clock { time: 0.0, playing: true, speed: 1.0, last: Instant::now() }
    }

    /// Advances by the wall time since the last tick (when playing), wrapping at `duration`.
    pub fn tick(&mut self, duration: f64) {
        let now = Instant::now();
        if self.playing {
            self.time = (self.time + self.speed * now.duration_since(self.last).as_secs_f64()) % duration.max(1e-3);
        }
        self.last = now;
    }
}

impl Default for Clock {
    fn default() -> Self {
        Self::new()
    }
}
