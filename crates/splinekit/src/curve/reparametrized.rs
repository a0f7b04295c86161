//! A curve reparametrised onto another interval by an affine map.
//!
//! For a curve c on [a₀, a₁] and a new domain [b₀, b₁], the reparametrised curve is
//! m(t) = c(φ(t)) with φ(t) = a₀ + (a₁ − a₀)(t − b₀)/(b₁ − b₀); by the chain rule
//! m^{(j)}(t) = s^j c^{(j)}(φ(t)) with s = (a₁ − a₀)/(b₁ − b₀). φ goes through the
//! normalised parameter (t − b₀)/(b₁ − b₀), which is exactly 0 and 1 at the ends. Blends and derived surfaces use it to put curves on
//! [0, 1], blending splines to put explicit local curves on their supports, and the local
//! Bézier pieces of blending splines are Bézier curves reparametrised onto their supports.

use crate::error::{Error, Result};
use crate::{Interval, Point};

use super::Curve;
use crate::basis::Side;

/// The curve t ↦ c(φ(t)) on a new domain (see the module documentation).
///
/// Parameters outside the new domain are mapped all the same and the inner curve clamps
/// or wraps them in its own parameter, so the wrapper keeps the inner curve's convention;
/// it is closed when the inner curve is.
#[derive(Debug, Clone, PartialEq)]
pub struct Reparametrized<C> {
    curve: C,
    domain: Interval,
    /// a₀, the start of the inner curve's domain.
    inner_start: f64,
    /// a₁ − a₀.
    inner_length: f64,
    /// s = (a₁ − a₀)/(b₁ − b₀).
    scale: f64,
}

impl<C> Reparametrized<C> {
    /// `curve` with its domain mapped affinely onto `domain`; both must be finite and
    /// non-empty.
    ///
    /// # Examples
    ///
    /// ```
    /// use splinekit::{Interval, Point};
    /// use splinekit::curve::{Curve, Reparametrized};
    /// use splinekit::curve::model::Line;
    /// // The segment from (0, 0) to (4, 0) on [10, 12]: twice as fast, c′ = (2, 0).
    /// let line = Line::new(Point::<2>::new(0.0, 0.0), Point::<2>::new(4.0, 0.0)).unwrap();
    /// let m = Reparametrized::new(line, Interval::new(10.0, 12.0)).unwrap();
    /// assert_eq!(m.point(11.0), Point::<2>::new(2.0, 0.0));
    /// assert_eq!(m.derivative(11.0, 1), Point::<2>::new(2.0, 0.0));
    /// ```
    pub fn new<const D: usize>(curve: C, domain: Interval) -> Result<Self>
    where
        C: Curve<D>,
    {
        let inner = curve.domain();
        let usable = |i: Interval| i.start.is_finite() && i.end.is_finite() && i.start < i.end;
        if !(usable(inner) && usable(domain)) {
            return Err(Error::invalid(
                "domain",
                format!(
                    "a curve on [{}, {}] cannot be reparametrised onto [{}, {}]: both must be finite and non-empty",
                    inner.start, inner.end, domain.start, domain.end
                ),
            ));
        }
        let scale = inner.length() / domain.length();
        Ok(Reparametrized { curve, domain, inner_start: inner.start, inner_length: inner.length(), scale })
    }

    /// `curve` reparametrised onto [0, 1]: m(s) = c(a₀ + s (a₁ − a₀)).
    pub fn unit<const D: usize>(curve: C) -> Result<Self>
    where
        C: Curve<D>,
    {
        Self::new(curve, Interval::new(0.0, 1.0))
    }

    /// The inner curve.
    pub fn curve(&self) -> &C {
        &self.curve
    }

    /// The same map applied to the curve `f` makes of the inner one, which must keep the
    /// inner domain (moving control points does; this is how the local Bézier pieces of
    /// blending splines follow their frames).
    pub fn map_curve(&self, f: impl FnOnce(&C) -> C) -> Self {
        Reparametrized { curve: f(&self.curve), ..*self }
    }

    /// φ(t) = a₀ + (a₁ − a₀)(t − b₀)/(b₁ − b₀), the inner parameter of t.
    #[inline]
    pub fn inner_parameter(&self, t: f64) -> f64 {
        self.inner_start + (t - self.domain.start) / self.domain.length() * self.inner_length
    }
}

impl<const D: usize, C: Curve<D>> Curve<D> for Reparametrized<C> {
    fn domain(&self) -> Interval {
        self.domain
    }
    fn is_closed(&self) -> bool {
        self.curve.is_closed()
    }
    #[inline]
    fn eval_side(&self, t: f64, side: Side, out: &mut [Point<D>]) {
        self.curve.eval_side(self.inner_parameter(t), side, out);
        let mut s = 1.0;
        for o in out.iter_mut().skip(1) {
            s *= self.scale;
            *o *= s;
        }
    }
    /// The inner curve's breakpoints mapped back by φ⁻¹ (the ends exactly the domain's).
    fn breakpoints(&self) -> Vec<f64> {
        let mut b: Vec<f64> = self
            .curve
            .breakpoints()
            .into_iter()
            .map(|x| self.domain.start + (x - self.inner_start) / self.inner_length * self.domain.length())
            .filter(|&t| t > self.domain.start && t < self.domain.end)
            .collect();
        b.insert(0, self.domain.start);
        b.push(self.domain.end);
        b
    }
}
