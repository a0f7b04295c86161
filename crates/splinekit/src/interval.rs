//! Parameter intervals [start, end]: the one type for domains, supports and the ranges an
//! edit changes.

use crate::basis::Side;

/// A closed parameter interval [start, end].
///
/// # Examples
///
/// ```
/// use splinekit::Interval;
/// let i = Interval::new(2.0, 6.0);
/// assert_eq!((i.length(), i.lerp(0.25), i.clamp(7.0)), (4.0, 3.0, 6.0));
/// assert_eq!(i.wrap(7.0), 3.0);
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Interval {
    /// Lower end.
    pub start: f64,
    /// Upper end.
    pub end: f64,
}

impl Interval {
    /// The interval [start, end].
    pub const fn new(start: f64, end: f64) -> Self {
        Interval { start, end }
    }
    /// end − start.
    #[inline]
    pub fn length(&self) -> f64 {
        self.end - self.start
    }
    /// `t` clamped into the interval.
    #[inline]
    pub fn clamp(&self, t: f64) -> f64 {
        t.clamp(self.start, self.end)
    }
    /// `t` wrapped periodically into [start, end] (the end itself is kept).
    #[inline]
    pub fn wrap(&self, t: f64) -> f64 {
        if t >= self.start && t <= self.end {
            return t;
        }
        let len = self.length();
        let w = self.start + (t - self.start).rem_euclid(len);
        if w >= self.end { self.start } else { w }
    }
    /// `t` wrapped into one period for a periodic curve, honouring the side: the right
    /// limit at the end of the domain is the value at its start, and the left limit at the
    /// start is the value at its end, so c(start) and c(end) agree to the last bit.
    #[inline]
    pub fn wrap_periodic(&self, t: f64, side: Side) -> f64 {
        let w = if t >= self.start && t < self.end {
            t
        } else {
            let r = self.start + (t - self.start).rem_euclid(self.length());
            if r >= self.end { self.start } else { r }
        };
        if side == Side::Left && w == self.start { self.end } else { w }
    }
    /// The parameter start + s·(end − start).
    #[inline]
    pub fn lerp(&self, s: f64) -> f64 {
        self.start + s * (self.end - self.start)
    }
}

/// A rectangle of parameters [u₀, u₁] × [v₀, v₁].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ParamRect {
    /// [u₀, u₁].
    pub u: Interval,
    /// [v₀, v₁].
    pub v: Interval,
}

impl ParamRect {
    /// The rectangle u × v.
    pub const fn new(u: Interval, v: Interval) -> Self {
        ParamRect { u, v }
    }
}
