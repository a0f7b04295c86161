//! Blending-spline (GERBS/ERBS) curves: c(t) = Σ_k B∘w_k(t) ℓ_k(t), built from local
//! curves ℓ_k blended by a B-function.
//!
//! Local curve k is centred at the knot c_k and supported on [c_{k−1}, c_{k+1}]. On
//! [c_k, c_{k+1}) exactly two are active: c = ℓ_k + B(w)(ℓ_{k+1} − ℓ_k) with
//! w = (t − c_k)/Δ, Δ = c_{k+1} − c_k, and by Leibniz
//! c^{(m)} = ℓ_k^{(m)} + Σ_j C(m, j) B^{(j)}(w) Δ^{−j} (ℓ_{k+1} − ℓ_k)^{(m−j)}, any order.
//! Locals are evaluated at the global parameter and return derivatives with respect to it.
//!
//! Every local carries an affine frame about its origin o_k (its interpolation point):
//! world(p) = o_k + T_k(p − o_k), positions as points, derivatives as vectors. Moving local k
//! changes the curve only on (c_{k−1}, c_{k+1}) ([`BlendingSplineCurve::affected_range`]).
//!
//! Knots are uniform over the model's domain [s, e]: open curves have n locals centred at
//! s + k (e − s)/(n − 1); closed ones n locals at s + k (e − s)/n, indices wrapping (local 0
//! is evaluated one period back on the last interval — no object is aliased twice).

use std::sync::Arc;

use smallvec::{SmallVec, smallvec};

use crate::Point;
use crate::basis::{BFunction, Side, binomial};
use crate::curve::bezier::bezier_derivatives;
use crate::curve::{Curve, Interval};
use crate::error::{Error, Result};
use crate::frame::Affine;

/// How local curves are made from a model curve.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum LocalKind {
    /// The model itself around the knot.
    SubCurve,
    /// The Bézier curve of degree d matching the model's position and first d derivatives
    /// at the knot (on the support [c_k − Δ, c_k + Δ]).
    Bezier(usize),
}

/// A Bézier curve on the parameter interval [start, start + length], evaluated with
/// derivatives with respect to that parameter.
struct IntervalBezier<const D: usize> {
    points: Vec<Point<D>>,
    start: f64,
    length: f64,
}

impl<const D: usize> Curve<D> for IntervalBezier<D> {
    fn domain(&self) -> Interval {
        Interval::new(self.start, self.start + self.length)
    }
    fn is_closed(&self) -> bool {
        false
    }
    fn eval_side(&self, t: f64, _side: Side, out: &mut [Point<D>]) {
        bezier_derivatives(&self.points, (t - self.start) / self.length, out);
        let mut s = 1.0;
        for o in out.iter_mut().skip(1) {
            s /= self.length;
            *o *= s;
        }
    }
}

/// The Bézier of degree d on [a, a + h] whose value and first d derivatives at the
/// parameter a + u₀h equal `target` (the Hermite/Bernstein system solved directly).
fn hermite_bezier<const D: usize>(target: &[Point<D>], a: f64, h: f64, u0: f64) -> Result<IntervalBezier<D>> {
    let d = target.len() - 1;
    // Row j: the j-th derivative (w.r.t. t) of each Bernstein polynomial at u₀.
    let mut m = nalgebra::DMatrix::<f64>::zeros(d + 1, d + 1);
    for i in 0..=d {
        let mut unit = vec![0.0; d + 1];
        unit[i] = 1.0;
        let mut ders = vec![0.0; d + 1];
        bezier_derivatives(&unit, u0, &mut ders);
        for j in 0..=d {
            m[(j, i)] = ders[j] / h.powi(j as i32);
        }
    }
    let lu = m.lu();
    let mut points = vec![Point::<D>::zeros(); d + 1];
    for c in 0..D {
        let rhs = nalgebra::DVector::from_iterator(d + 1, target.iter().map(|p| p[c]));
        let x = lu.solve(&rhs).ok_or_else(|| Error::numerical("blending spline", "singular Hermite system"))?;
        for i in 0..=d {
            points[i][c] = x[i];
        }
    }
    Ok(IntervalBezier { points, start: a, length: h })
}

/// One local curve with its frame.
pub struct Local<const D: usize> {
    curve: Box<dyn Curve<D>>,
    origin: Point<D>,
    transform: Affine<D>,
}

impl<const D: usize> Local<D> {
    /// World values at t: o + T(ℓ − o) for the position, T's linear part for derivatives.
    fn eval(&self, t: f64, side: Side, out: &mut [Point<D>]) {
        self.curve.eval_side(t, side, out);
        out[0] = self.origin + self.transform.apply_point(&(out[0] - self.origin));
        for o in out.iter_mut().skip(1) {
            *o = self.transform.apply_vector(o);
        }
    }
}

/// A blending-spline curve.
pub struct BlendingSplineCurve<const D: usize> {
    locals: Vec<Local<D>>,
    centres: Vec<f64>,
    domain: Interval,
    closed: bool,
    bfunction: BFunction,
}

impl<const D: usize> BlendingSplineCurve<D> {
    /// `count` local curves of `kind` made from `model` over its domain, blended by
    /// `bfunction`; closed when `closed` (a closed model is expected then).
    pub fn from_model(
        model: Arc<dyn Curve<D>>,
        count: usize,
        kind: LocalKind,
        bfunction: BFunction,
        closed: bool,
    ) -> Result<Self> {
        if count < 2 || (closed && count < 3) || count > 100_000 {
            return Err(Error::invalid(
                "local_curves",
                format!("need {} to 100000 local curves, got {count}", if closed { 3 } else { 2 }),
            ));
        }
        let dom = model.domain();
        let dt = dom.length() / if closed { count } else { count - 1 } as f64;
        let centres: Vec<f64> = (0..count).map(|k| dom.start + k as f64 * dt).collect();
        let mut locals = Vec::with_capacity(count);
        for &c in &centres {
            let origin = model.point(c);
            let curve: Box<dyn Curve<D>> = match kind {
                LocalKind::SubCurve => Box::new(SharedCurve(model.clone())),
                LocalKind::Bezier(d) => {
                    if d == 0 || d > 20 {
                        return Err(Error::invalid(
                            "local",
                            format!("Bézier degree must be between 1 and 20, got {d}"),
                        ));
                    }
                    let mut target = vec![Point::<D>::zeros(); d + 1];
                    model.eval(c, &mut target);
                    Box::new(hermite_bezier(&target, c - dt, 2.0 * dt, 0.5)?)
                }
            };
            locals.push(Local { curve, origin, transform: Affine::identity() });
        }
        Ok(BlendingSplineCurve { locals, centres, domain: dom, closed, bfunction })
    }

    /// Number of local curves.
    pub fn local_count(&self) -> usize {
        self.locals.len()
    }
    /// The knot (centre) of local k.
    pub fn centre(&self, k: usize) -> f64 {
        self.centres[k]
    }
    /// The interpolation point (frame origin) of local k.
    pub fn origin(&self, k: usize) -> Point<D> {
        self.locals[k].origin
    }
    /// The frame of local k.
    pub fn transform(&self, k: usize) -> &Affine<D> {
        &self.locals[k].transform
    }
    /// Local curve k in world coordinates (its frame applied) at the global parameter t,
    /// with derivatives: `out[j]` = ℓ_k^{(j)}(t). Meaningful on [`Self::local_support`].
    pub fn eval_local(&self, k: usize, t: f64, out: &mut [Point<D>]) {
        self.locals[k].eval(t, Side::Right, out)
    }
    /// The parameter interval [c_k − Δ, c_k + Δ] where local k takes part.
    pub fn local_support(&self, k: usize) -> (f64, f64) {
        let dt = self.centres.get(1).map_or(self.domain.length(), |c1| c1 - self.centres[0]);
        (self.centres[k] - dt, self.centres[k] + dt)
    }
    /// Sets the frame of local k (about its origin); returns the parameter ranges whose
    /// points changed ([`BlendingSplineCurve::affected_range`]).
    pub fn set_transform(&mut self, k: usize, transform: Affine<D>) -> Vec<(f64, f64)> {
        self.locals[k].transform = transform;
        self.affected_range(k)
    }
    /// The parameter ranges where local k is active: (c_{k−1}, c_{k+1}), clipped to the
    /// domain (and split at the seam of a closed curve).
    pub fn affected_range(&self, k: usize) -> Vec<(f64, f64)> {
        let dt = self.centres.get(1).map_or(self.domain.length(), |c1| c1 - self.centres[0]);
        let (a, b) = (self.centres[k] - dt, self.centres[k] + dt);
        if !self.closed {
            return vec![(a.max(self.domain.start), b.min(self.domain.end))];
        }
        let (s, e, p) = (self.domain.start, self.domain.end, self.domain.length());
        if a < s {
            vec![(s, b), (a + p, e)]
        } else if b > e {
            vec![(a, e), (s, b - p)]
        } else {
            vec![(a, b)]
        }
    }
}

/// A local that is the (shared) model curve itself.
struct SharedCurve<const D: usize>(Arc<dyn Curve<D>>);

impl<const D: usize> Curve<D> for SharedCurve<D> {
    fn domain(&self) -> Interval {
        self.0.domain()
    }
    fn is_closed(&self) -> bool {
        self.0.is_closed()
    }
    fn eval_side(&self, t: f64, side: Side, out: &mut [Point<D>]) {
        self.0.eval_side(t, side, out)
    }
}

impl<const D: usize> Curve<D> for BlendingSplineCurve<D> {
    fn domain(&self) -> Interval {
        self.domain
    }
    fn is_closed(&self) -> bool {
        self.closed
    }
    fn breakpoints(&self) -> Vec<f64> {
        let mut b = self.centres.clone();
        if self.closed {
            b.push(self.domain.end);
        }
        b
    }
    fn eval_side(&self, t: f64, side: Side, out: &mut [Point<D>]) {
        let n = self.locals.len();
        let t = if self.closed { self.domain.wrap_periodic(t, side) } else { self.domain.clamp(t) };
        let intervals = if self.closed { n } else { n - 1 };
        let dt = self.domain.length() / intervals as f64;
        let x = (t - self.domain.start) / dt;
        let mut k = (x.floor().max(0.0) as usize).min(intervals - 1);
        // At a knot, the left limit uses the interval that ends there.
        if side == Side::Left && k > 0 && x == k as f64 {
            k -= 1;
        }
        let m = out.len() - 1;
        let next = (k + 1) % n;
        // Local 0 on the last interval of a closed curve lives one period back.
        let t_next = if self.closed && next == 0 { t - self.domain.length() } else { t };
        let mut a: SmallVec<[Point<D>; 8]> = smallvec![Point::<D>::zeros(); m + 1];
        let mut b: SmallVec<[Point<D>; 8]> = smallvec![Point::<D>::zeros(); m + 1];
        self.locals[k].eval(t, side, &mut a);
        self.locals[next].eval(t_next, side, &mut b);
        let mut bf: SmallVec<[f64; 8]> = smallvec![0.0; m + 1];
        self.bfunction.eval((t - self.centres[k]) / dt, &mut bf);
        let inv = 1.0 / dt;
        for r in 0..=m {
            let mut v = a[r];
            let mut scale = 1.0;
            for j in 0..=r {
                v += (b[r - j] - a[r - j]) * (binomial(r, j) * bf[j] * scale);
                scale *= inv;
            }
            out[r] = v;
        }
    }
}
