//! A surface over a quadrilateral of another surface's domain (GMlib's `PSubSurf`, not
//! bound to the axes): with the corners q₀₀, q₁₀, q₁₁, q₀₁ in the host's (u, v), the
//! bilinear map
//!
//! φ(s, t) = (1 − s)(1 − t) q₀₀ + s(1 − t) q₁₀ + s t q₁₁ + (1 − s) t q₀₁,  (s, t) ∈ [0, 1]²,
//!
//! and P(s, t) = S(φ(s, t)). A rectangle aligned with the axes gives the host's patch over
//! it, affinely reparametrised; any convex quadrilateral inside the domain gives a patch
//! whose iso-lines run across the host's.
//!
//! Partials of every order by the chain rule, exactly: at (s₀, t₀), with a = s − s₀,
//! b = t − t₀, φ(s, t) − φ(s₀, t₀) = a φ_s + b φ_t + ab φ_st (φ is bilinear, so this is
//! exact), and P = Σ_{m,n} ∂^{m,n}S (δu)^m (δv)^n / (m! n!) with (δu, δv) that polynomial in
//! (a, b). Each term has degree ≥ m + n, so the coefficients of a^i b^j for i ≤ d_s,
//! j ≤ d_t need the host's partials of total order ≤ d_s + d_t only; ∂^{i,j}P = i! j! times
//! that coefficient.

use crate::error::{Error, Result};
use crate::surface::Surface;
use crate::{Interval, Point};

/// Highest order in s plus order in t that [`QuadSubSurface`] evaluates (the host's
/// partials up to that total order).
pub const MAX_TOTAL_ORDER: usize = 12;

/// The host surface over the bilinear image of [0, 1]² with the given corners.
#[derive(Clone)]
pub struct QuadSubSurface<S> {
    host: S,
    /// q₀₀, q₁₀, q₁₁, q₀₁ (counter-clockwise from (s, t) = (0, 0)).
    corners: [[f64; 2]; 4],
}

impl<S> QuadSubSurface<S> {
    /// The sub-surface of `host` over the quadrilateral `corners` = [q₀₀, q₁₀, q₁₁, q₀₁]
    /// (the images of (s, t) = (0, 0), (1, 0), (1, 1), (0, 1)). The corners must be finite,
    /// inside the host's domain (so the whole quadrilateral is), and the map must not fold:
    /// the Jacobian det[φ_s, φ_t], bilinear in (s, t), must have one strict sign at the four
    /// corners (so everywhere), which holds for convex quadrilaterals of either orientation.
    /// Errors name `corners[i]` or `corners`.
    ///
    /// # Examples
    ///
    /// ```
    /// use splinekit::Point;
    /// use splinekit::surface::{QuadSubSurface, Surface};
    /// use splinekit::surface::model::Plane;
    /// // On the plane (u, v, 0) the sub-surface is the bilinear map itself.
    /// let plane = Plane::new(Point::<3>::zeros(), Point::<3>::x(), Point::<3>::y()).unwrap();
    /// let q = QuadSubSurface::new(plane, [[0.1, 0.1], [0.9, 0.2], [0.8, 0.9], [0.2, 0.7]]).unwrap();
    /// assert!((q.point(1.0, 1.0) - Point::<3>::new(0.8, 0.9, 0.0)).norm() < 1e-15);
    /// assert!((q.point(0.5, 0.5) - Point::<3>::new(0.5, 0.475, 0.0)).norm() < 1e-15);
    /// ```
    pub fn new<const D: usize>(host: S, corners: [[f64; 2]; 4]) -> Result<Self>
    where
        S: Surface<D>,
    {
        let (du, dv) = (host.domain_u(), host.domain_v());
        for (i, q) in corners.iter().enumerate() {
            if !q.iter().all(|x| x.is_finite()) {
                return Err(Error::invalid(format!("corners[{i}]"), format!("must be finite, got {q:?}")));
            }
            let inside = |x: f64, d: Interval| x >= d.start && x <= d.end;
            if !(inside(q[0], du) && inside(q[1], dv)) {
                return Err(Error::invalid(
                    format!("corners[{i}]"),
                    format!(
                        "({}, {}) is outside the surface's domain [{}, {}] × [{}, {}]",
                        q[0], q[1], du.start, du.end, dv.start, dv.end
                    ),
                ));
            }
        }
        let q = Self { host, corners };
        let dets: Vec<f64> = [(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)]
            .iter()
            .map(|&(s, t)| {
                let ((us, vs), (ut, vt)) = q.jacobian(s, t);
                us * vt - ut * vs
            })
            .collect();
        let scale = corners.iter().flat_map(|c| c.iter()).fold(0.0f64, |m, x| m.max(x.abs())).max(1e-300);
        let tiny = 1e-12 * scale * scale;
        let positive = dets.iter().all(|&d| d > tiny);
        let negative = dets.iter().all(|&d| d < -tiny);
        if !(positive || negative) {
            return Err(Error::invalid(
                "corners",
                format!(
                    "the quadrilateral folds or is degenerate: the Jacobian at its corners is {:?} (it must keep one strict sign; give the corners in order around a convex quadrilateral)",
                    dets
                ),
            ));
        }
        Ok(q)
    }

    /// The host surface.
    pub fn host(&self) -> &S {
        &self.host
    }
    /// The corners q₀₀, q₁₀, q₁₁, q₀₁.
    pub fn corners(&self) -> [[f64; 2]; 4] {
        self.corners
    }

    /// φ(s, t), the host's (u, v).
    pub fn map(&self, s: f64, t: f64) -> (f64, f64) {
        let [a, b, c, d] = self.corners;
        let w = [(1.0 - s) * (1.0 - t), s * (1.0 - t), s * t, (1.0 - s) * t];
        (w[0] * a[0] + w[1] * b[0] + w[2] * c[0] + w[3] * d[0], w[0] * a[1] + w[1] * b[1] + w[2] * c[1] + w[3] * d[1])
    }

    /// (φ_s, φ_t) at (s, t), each as (u, v).
    fn jacobian(&self, s: f64, t: f64) -> ((f64, f64), (f64, f64)) {
        let [a, b, c, d] = self.corners;
        let ds = |k: usize| (1.0 - t) * (b[k] - a[k]) + t * (c[k] - d[k]);
        let dt = |k: usize| (1.0 - s) * (d[k] - a[k]) + s * (c[k] - b[k]);
        ((ds(0), ds(1)), (dt(0), dt(1)))
    }

    /// φ_st, as (u, v).
    fn twist(&self) -> (f64, f64) {
        let [a, b, c, d] = self.corners;
        (c[0] - b[0] - d[0] + a[0], c[1] - b[1] - d[1] + a[1])
    }
}

/// A polynomial in (a, b) of degrees ≤ (I, J), coefficient of aⁱbʲ at i·(J + 1) + j.
fn poly_mul(x: &[f64], y: &[f64], (ni, nj): (usize, usize)) -> Vec<f64> {
    let mut out = vec![0.0; (ni + 1) * (nj + 1)];
    for i1 in 0..=ni {
        for j1 in 0..=nj {
            let p = x[i1 * (nj + 1) + j1];
            if p == 0.0 {
                continue;
            }
            for i2 in 0..=ni - i1 {
                for j2 in 0..=nj - j1 {
                    out[(i1 + i2) * (nj + 1) + j1 + j2] += p * y[i2 * (nj + 1) + j2];
                }
            }
        }
    }
    out
}

impl<const D: usize, S: Surface<D>> Surface<D> for QuadSubSurface<S> {
    fn domain_u(&self) -> Interval {
        Interval::new(0.0, 1.0)
    }
    fn domain_v(&self) -> Interval {
        Interval::new(0.0, 1.0)
    }

    /// Orders with d_s + d_t above [`MAX_TOTAL_ORDER`] are written as zero.
    fn eval_partials(&self, s: f64, t: f64, ds: usize, dt: usize, out: &mut [Point<D>]) {
        let (s, t) = (s.clamp(0.0, 1.0), t.clamp(0.0, 1.0));
        let w = (ds + 1) * (dt + 1);
        out[..w].iter_mut().for_each(|p| *p = Point::<D>::zeros());
        let total = (ds + dt).min(MAX_TOTAL_ORDER);
        let (u, v) = self.map(s, t);
        let mut host = vec![Point::<D>::zeros(); (total + 1) * (total + 1)];
        self.host.eval_partials(u, v, total, total, &mut host);
        let ((us, vs), (ut, vt)) = self.jacobian(s, t);
        let (ust, vst) = self.twist();
        let dims = (ds, dt);
        let mut du = vec![0.0; w];
        let mut dv = vec![0.0; w];
        let put = |p: &mut [f64], i: usize, j: usize, x: f64| {
            if i <= ds && j <= dt {
                p[i * (dt + 1) + j] = x;
            }
        };
        put(&mut du, 1, 0, us);
        put(&mut du, 0, 1, ut);
        put(&mut du, 1, 1, ust);
        put(&mut dv, 1, 0, vs);
        put(&mut dv, 0, 1, vt);
        put(&mut dv, 1, 1, vst);
        // (δu)^m for m = 0 … total, then (δu)^m (δv)^n / (m! n!).
        let mut one = vec![0.0; w];
        one[0] = 1.0;
        let mut du_pow = vec![one.clone()];
        let mut dv_pow = vec![one];
        for m in 1..=total {
            du_pow.push(poly_mul(&du_pow[m - 1], &du, dims));
            dv_pow.push(poly_mul(&dv_pow[m - 1], &dv, dims));
        }
        let mut fact = vec![1.0; 2 * total + 2];
        for k in 1..fact.len() {
            fact[k] = fact[k - 1] * k as f64;
        }
        for m in 0..=total {
            for n in 0..=total - m {
                let term = poly_mul(&du_pow[m], &dv_pow[n], dims);
                let f = 1.0 / (fact[m] * fact[n]);
                let partial = host[m * (total + 1) + n];
                for i in 0..=ds {
                    for j in 0..=dt {
                        if i + j > total {
                            continue;
                        }
                        let c = term[i * (dt + 1) + j];
                        if c != 0.0 {
                            out[i * (dt + 1) + j] += partial * (c * f * fact[i] * fact[j]);
                        }
                    }
                }
            }
        }
    }
}
