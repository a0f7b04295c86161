//! Curves on surfaces (GMlib's `PSurfCurve`): a 2-D curve γ(t) = (u(t), v(t)) in a
//! surface's parameter domain, mapped onto the surface, c(t) = S(u(t), v(t)).
//!
//! Derivatives of every order by the chain rule (Faà di Bruno's formula in Taylor form):
//! at t₀, with a = t − t₀, δu(a) = Σ_{j≥1} u^{(j)}(t₀) aʲ/j! and δv likewise, and
//!
//! c(t₀ + a) = Σ_{m,n} ∂^{m,n}S(u(t₀), v(t₀)) (δu)^m (δv)^n / (m! n!).
//!
//! Each term has degree ≥ m + n in a, so the coefficient of a^k (k ≤ K) needs the host's
//! partials of total order ≤ K only; c^{(k)}(t₀) = k! times that coefficient. The
//! polynomials are truncated at degree K, so the work is O(K⁴) per point on top of the
//! host's partials — exact to rounding at every order the host's partials are.

use smallvec::{SmallVec, smallvec};

use crate::basis::Side;
use crate::curve::Curve;
use crate::error::{Error, Result};
use crate::query::extent::curve_extent;
use crate::surface::Surface;
use crate::{Interval, Point, taylor};

/// How far (relative to the domain's size) the curve's sampled box may leave an open
/// direction of the host's domain: rounding of the samples, nothing more.
const OUTSIDE_RELATIVE: f64 = 1e-9;

/// The surface `surface` along the 2-D curve `curve` in its (u, v) domain.
#[derive(Clone)]
pub struct CurveOnSurface<C, S> {
    curve: C,
    surface: S,
}

impl<C: Curve<2>, S> CurveOnSurface<C, S> {
    /// c(t) = S(γ(t)) on γ's domain. In a direction the surface is open in, γ must stay
    /// inside the surface's domain (its sampled box, [`curve_extent`], within 10⁻⁹ of the
    /// domain's size): outside it the surface clamps, and c would not be S∘γ with the
    /// chain rule's derivatives. In a closed direction the surface wraps γ's values, so γ
    /// may wind around it (a torus knot is a line on the torus). Errors name `curve`.
    ///
    /// # Examples
    ///
    /// ```
    /// use splinekit::Point;
    /// use splinekit::curve::{Curve, model::Line};
    /// use splinekit::surface::{CurveOnSurface, Surface, model::Torus};
    /// // The (2, 3) torus knot: the line from (0, 0) to (4π, 6π) on the torus.
    /// let tau = std::f64::consts::TAU;
    /// let line = Line::new(Point::<2>::new(0.0, 0.0), Point::<2>::new(2.0 * tau, 3.0 * tau)).unwrap();
    /// let torus = Torus::new(3.0, 1.0).unwrap();
    /// let knot = CurveOnSurface::new(line, torus.clone()).unwrap();
    /// let t = 0.3;
    /// assert!((knot.point(t) - torus.point(2.0 * tau * t, 3.0 * tau * t)).norm() < 1e-14);
    /// // c' = 4π S_u + 6π S_v.
    /// let want = torus.partial(2.0 * tau * t, 3.0 * tau * t, 1, 0) * 2.0 * tau
    ///     + torus.partial(2.0 * tau * t, 3.0 * tau * t, 0, 1) * 3.0 * tau;
    /// assert!((knot.derivative(t, 1) - want).norm() < 1e-13);
    /// ```
    pub fn new<const D: usize>(curve: C, surface: S) -> Result<Self>
    where
        S: Surface<D>,
    {
        let d = curve.domain();
        if !(d.start.is_finite() && d.end.is_finite() && d.start < d.end) {
            return Err(Error::invalid(
                "curve",
                format!("the curve's domain [{}, {}] must be finite and non-empty", d.start, d.end),
            ));
        }
        let b = curve_extent(&curve);
        let checks =
            [("u", 0, surface.domain_u(), surface.is_closed_u()), ("v", 1, surface.domain_v(), surface.is_closed_v())];
        for (name, k, dom, closed) in checks {
            if !(b.min[k].is_finite() && b.max[k].is_finite()) {
                return Err(Error::invalid("curve", format!("the curve's {name} is not finite")));
            }
            if closed {
                continue;
            }
            let slack = OUTSIDE_RELATIVE * dom.length().abs().max(dom.start.abs()).max(dom.end.abs()).max(1.0);
            if b.min[k] < dom.start - slack || b.max[k] > dom.end + slack {
                return Err(Error::invalid(
                    "curve",
                    format!(
                        "the curve's {name} runs over [{}, {}], outside the surface's {name}-domain [{}, {}] (open in {name}: a curve on a surface must stay in its domain there)",
                        b.min[k], b.max[k], dom.start, dom.end
                    ),
                ));
            }
        }
        Ok(CurveOnSurface { curve, surface })
    }
}

impl<C, S> CurveOnSurface<C, S> {
    /// The curve γ in the (u, v) domain.
    pub fn curve(&self) -> &C {
        &self.curve
    }
    /// The host surface S.
    pub fn surface(&self) -> &S {
        &self.surface
    }
}

impl<const D: usize, C: Curve<2>, S: Surface<D>> Curve<D> for CurveOnSurface<C, S> {
    fn domain(&self) -> Interval {
        self.curve.domain()
    }
    /// Closed when γ is (γ closed in a closed direction of S, or turning back to where it
    /// began).
    fn is_closed(&self) -> bool {
        self.curve.is_closed()
    }
    /// γ's breakpoints (the host's knot lines that γ crosses are not searched for).
    fn breakpoints(&self) -> Vec<f64> {
        self.curve.breakpoints()
    }
    fn eval_side(&self, t: f64, side: Side, out: &mut [Point<D>]) {
        let k = out.len() - 1;
        let mut g: SmallVec<[Point<2>; 8]> = smallvec![Point::<2>::zeros(); k + 1];
        self.curve.eval_side(t, side, &mut g);
        let (u, v) = (g[0][0], g[0][1]);
        if k == 0 {
            self.surface.eval_partials(u, v, 0, 0, out);
            return;
        }
        let w = k + 1;
        let mut host: SmallVec<[Point<D>; 16]> = smallvec![Point::<D>::zeros(); w * w];
        self.surface.eval_partials(u, v, k, k, &mut host);
        // Taylor coefficients: δu = Σ u^{(j)}/j! aʲ, δv likewise.
        let mut fact = vec![1.0; 2 * w];
        for i in 1..fact.len() {
            fact[i] = fact[i - 1] * i as f64;
        }
        let mut du = vec![0.0; w];
        let mut dv = vec![0.0; w];
        for j in 1..=k {
            du[j] = g[j][0] / fact[j];
            dv[j] = g[j][1] / fact[j];
        }
        // Powers (δu)^m, (δv)^n for m, n ≤ k, each truncated at degree k.
        let mut du_pow = vec![0.0; w * w];
        let mut dv_pow = vec![0.0; w * w];
        du_pow[0] = 1.0;
        dv_pow[0] = 1.0;
        for m in 1..=k {
            let (done, rest) = du_pow.split_at_mut(m * w);
            taylor::mul(&done[(m - 1) * w..], &du, &mut rest[..w]);
            let (done, rest) = dv_pow.split_at_mut(m * w);
            taylor::mul(&done[(m - 1) * w..], &dv, &mut rest[..w]);
        }
        out.iter_mut().for_each(|p| *p = Point::<D>::zeros());
        let mut term = vec![0.0; w];
        for m in 0..=k {
            for n in 0..=k - m {
                taylor::mul(&du_pow[m * w..(m + 1) * w], &dv_pow[n * w..(n + 1) * w], &mut term);
                let partial = host[m * w + n];
                let f = 1.0 / (fact[m] * fact[n]);
                // (δu)^m (δv)^n starts at degree m + n.
                for (i, o) in out.iter_mut().enumerate().skip(m + n) {
                    let c = term[i];
                    if c != 0.0 {
                        *o += partial * (c * f * fact[i]);
                    }
                }
            }
        }
    }
}
