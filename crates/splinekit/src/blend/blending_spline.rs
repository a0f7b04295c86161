//! Blending-spline (GERBS/ERBS) curves: c(t) = Σ_k B∘w_k(t) ℓ_k(t), built from local
//! curves ℓ_k blended by a B-function.
//!
//! Local curve k is centred at the knot c_k and supported on [c_{k−1}, c_{k+1}]
//! ([`BlendKnots`]). On [c_k, c_{k+1}) exactly two are active: c = ℓ_k + B(w)(ℓ_{k+1} − ℓ_k)
//! with w = (t − c_k)/Δ, Δ = c_{k+1} − c_k, and by Leibniz
//! c^{(m)} = ℓ_k^{(m)} + Σ_j C(m, j) B^{(j)}(w) Δ^{−j} (ℓ_{k+1} − ℓ_k)^{(m−j)}, any order.
//! Locals are evaluated at the global parameter and return derivatives with respect to it.
//!
//! Every local carries an affine frame about its origin o_k (its interpolation point):
//! world(p) = o_k + T_k(p − o_k), positions as points, derivatives as vectors. Moving local k
//! changes the curve only on (c_{k−1}, c_{k+1}) ([`BlendingSplineCurve::affected_ranges`]).
//!
//! Built from a model, the knots are uniform over the model's domain (or at equal chord
//! length along it); closed curves have n locals on n intervals, local 0 being evaluated one
//! period back on the last interval (no object aliased twice).

use std::sync::Arc;

use smallvec::{SmallVec, smallvec};

use super::animation::Track;
use super::curve_batch::{self, BezierLocal};
use super::hermite::{IntervalBezier, hermite_bezier};
use super::knots::BlendKnots;
use super::leibniz::blend_derivatives;
use super::osculating_arc::OsculatingArc;
use crate::Point;
use crate::basis::{BFunction, Side};
use crate::curve::{BezierCurve, Curve, Interval, Reparametrized};
use crate::error::{Error, Result};
use crate::frame::Affine;

/// How local curves are made from a model curve.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum LocalKind {
    /// The model itself around the knot.
    SubCurve,
    /// The Bézier curve of degree d matching the model's position and first d derivatives
    /// at the knot (on the support [c_{k−1}, c_{k+1}]).
    Bezier(usize),
    /// The osculating circle arc at the knot (position, tangent and curvature).
    Arc,
}

/// Where the knots of a blending spline built from a model go.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum KnotSpacing {
    /// Evenly spaced in the model's parameter.
    #[default]
    Uniform,
    /// At equal chord length along the model (its arc length, measured on a fine polyline).
    ChordLength,
    /// At equal arc length along the model (GMlib's `generateCuLenKnotVector`): the knots
    /// t_k with ∫_{t₀}^{t_k} |c′| = k L/(n − 1) (closed: k L/n), L the model's length, the
    /// integral by adaptive Gauss–Legendre quadrature and inverted by Newton's method
    /// ([`crate::query::ArcLengthTable`]) to 10⁻¹¹ L.
    ArcLength,
}

/// A local curve: a Bézier piece (kept with its frame applied to the control points, which
/// is exact by affine invariance and saves the map per evaluation) or any curve.
#[derive(Clone)]
enum LocalCurve<const D: usize> {
    Bezier { fitted: IntervalBezier<D>, world: IntervalBezier<D> },
    General(Arc<dyn Curve<D>>),
}

impl<const D: usize> LocalCurve<D> {
    fn bezier(b: IntervalBezier<D>) -> Self {
        LocalCurve::Bezier { world: b.clone(), fitted: b }
    }
}

/// One local curve with its frame.
#[derive(Clone)]
struct Local<const D: usize> {
    curve: LocalCurve<D>,
    origin: Point<D>,
    transform: Affine<D>,
}

impl<const D: usize> Local<D> {
    fn new(curve: LocalCurve<D>, at: f64) -> Self {
        let origin = match &curve {
            LocalCurve::Bezier { fitted, .. } => fitted.point(at),
            LocalCurve::General(c) => c.point(at),
        };
        Local { curve, origin, transform: Affine::identity() }
    }
    fn set_transform(&mut self, transform: Affine<D>) {
        self.transform = transform;
        if let LocalCurve::Bezier { fitted, world } = &mut self.curve {
            let o = self.origin;
            *world = fitted.map_curve(|b| b.map_points(|p| transform.apply_point_about(&o, p)));
        }
    }
    /// World values at t: o + T(ℓ − o) for the position, T's linear part for derivatives.
    #[inline]
    fn eval(&self, t: f64, side: Side, out: &mut [Point<D>]) {
        match &self.curve {
            LocalCurve::Bezier { world, .. } => world.eval_side(t, side, out),
            LocalCurve::General(c) => {
                c.eval_side(t, side, out);
                self.transform.apply_derivatives_about(&self.origin, out);
            }
        }
    }
    /// Applies the frame to values of the local's own curve: o + T(ℓ − o), T's linear
    /// part for derivatives.
    fn to_world(&self, out: &mut [Point<D>]) {
        self.transform.apply_derivatives_about(&self.origin, out);
    }
}

/// How [`BlendingSplineCurve::from_model`] makes a spline from a model. The defaults are
/// the shape documents': cubic Bézier locals, the default ERBS, the model's own closedness
/// and uniform knots.
#[derive(Debug, Clone, PartialEq)]
pub struct BlendingCurveOptions {
    /// How each local curve is made from the model.
    pub local: LocalKind,
    /// The B-function blending neighbouring locals.
    pub bfunction: BFunction,
    /// Closed (n locals on n intervals) or open; `None`: as the model is.
    pub closed: Option<bool>,
    /// Where the knots go.
    pub spacing: KnotSpacing,
}

impl Default for BlendingCurveOptions {
    fn default() -> Self {
        BlendingCurveOptions {
            local: LocalKind::Bezier(3),
            bfunction: BFunction::erbs_default(),
            closed: None,
            spacing: KnotSpacing::Uniform,
        }
    }
}

/// The model a spline was built from, kept so it can be rebuilt with other settings.
#[derive(Clone)]
struct ModelSource<const D: usize> {
    model: Arc<dyn Curve<D>>,
    kind: LocalKind,
    spacing: KnotSpacing,
}

/// A blending-spline curve.
#[derive(Clone)]
pub struct BlendingSplineCurve<const D: usize> {
    locals: Vec<Local<D>>,
    knots: BlendKnots,
    bfunction: BFunction,
    source: Option<ModelSource<D>>,
}

impl<const D: usize> BlendingSplineCurve<D> {
    /// `local_curves` local curves made from `model` over its domain as `options` say.
    ///
    /// # Examples
    ///
    /// ```
    /// use std::sync::Arc;
    /// use splinekit::blend::{BlendingCurveOptions, BlendingSplineCurve};
    /// use splinekit::curve::Curve;
    /// use splinekit::curve::model::Circle;
    /// // 8 cubic Bézier locals blended by ERBS: at every knot the spline reproduces the
    /// // circle's position and first three derivatives.
    /// let circle = Arc::new(Circle::new(2.0).unwrap());
    /// let c = BlendingSplineCurve::from_model(circle.clone(), 8, &BlendingCurveOptions::default()).unwrap();
    /// assert!(c.is_closed());
    /// let knot = c.centre(3);
    /// for order in 0..=3 {
    ///     assert!((c.derivative(knot, order) - circle.derivative(knot, order)).norm() < 1e-12);
    /// }
    /// ```
    pub fn from_model(model: Arc<dyn Curve<D>>, local_curves: usize, options: &BlendingCurveOptions) -> Result<Self> {
        let spacing = options.spacing;
        let closed = options.closed.unwrap_or_else(|| model.is_closed());
        let uniform = BlendKnots::uniform(model.domain(), local_curves, closed, "local_curves")?;
        let knots = match spacing {
            KnotSpacing::Uniform => uniform,
            KnotSpacing::ChordLength => BlendKnots::new(chord_length_knots(model.as_ref(), uniform.values()), closed)?,
            KnotSpacing::ArcLength => BlendKnots::new(arc_length_knots(model.as_ref(), uniform.values())?, closed)?,
        };
        Self::built(model, knots, options)
    }

    /// Locals made from `model` as `options` say, at the given `knots` (uneven ones, as
    /// [`Self::insert_local`] leaves them; `options.spacing` and `options.closed` are the
    /// knots' own). The knots must span the model's domain: their first and last value are
    /// its ends (to 10⁻¹² times its length, or 10⁻¹² when it is shorter than 1), so a closed spline's period is the model's.
    ///
    /// # Examples
    ///
    /// ```
    /// use std::sync::Arc;
    /// use splinekit::blend::{BlendKnots, BlendingCurveOptions, BlendingSplineCurve};
    /// use splinekit::curve::Curve;
    /// use splinekit::curve::model::Circle;
    /// use std::f64::consts::TAU;
    /// let circle = Arc::new(Circle::new(1.0).unwrap());
    /// let knots = BlendKnots::new(vec![0.0, 1.0, 1.5, 4.0, TAU], true).unwrap();
    /// let c = BlendingSplineCurve::from_model_with_knots(circle.clone(), knots, &BlendingCurveOptions::default()).unwrap();
    /// assert_eq!(c.local_count(), 4);
    /// assert!((c.point(1.5) - circle.point(1.5)).norm() < 1e-15);
    /// let short = BlendKnots::new(vec![0.0, 1.0, 2.0, 3.0], true).unwrap();
    /// let e = BlendingSplineCurve::from_model_with_knots(circle, short, &BlendingCurveOptions::default());
    /// assert!(e.err().unwrap().to_string().contains("knots"));
    /// ```
    pub fn from_model_with_knots(
        model: Arc<dyn Curve<D>>,
        knots: BlendKnots,
        options: &BlendingCurveOptions,
    ) -> Result<Self> {
        knots.check_spans(model.domain(), "knots")?;
        Self::built(model, knots, options)
    }

    /// Locals of `options.local` from `model` at `knots` (`options.closed` is the knots').
    fn built(model: Arc<dyn Curve<D>>, knots: BlendKnots, options: &BlendingCurveOptions) -> Result<Self> {
        let (kind, spacing) = (options.local, options.spacing);
        let mut locals = Vec::with_capacity(knots.count());
        for k in 0..knots.count() {
            locals.push(Local::new(local_from_model(&model, kind, &knots, k)?, knots.centre(k)));
        }
        let source = Some(ModelSource { model, kind, spacing });
        Ok(BlendingSplineCurve { locals, knots, bfunction: options.bfunction.clone(), source })
    }

    /// Explicit knots and local curves of any kind, one local per knot. Local k's own
    /// domain is mapped affinely onto its support [c_{k−1}, c_{k+1}] ([`Reparametrized`];
    /// past the ends of an open spline the end spacing is mirrored), so every local needs
    /// a finite, non-empty domain.
    ///
    /// # Examples
    ///
    /// ```
    /// use std::sync::Arc;
    /// use splinekit::Point;
    /// use splinekit::basis::BFunction;
    /// use splinekit::blend::{BlendKnots, BlendingSplineCurve};
    /// use splinekit::curve::Curve;
    /// use splinekit::curve::model::Line;
    /// let p = |x, y| Point::<2>::new(x, y);
    /// let line = |a, b| -> Arc<dyn Curve<2>> { Arc::new(Line::new(a, b).unwrap()) };
    /// // Two locals on the knots 0 and 1: the first line on [−1, 1], the second on [0, 2].
    /// let knots = BlendKnots::new(vec![0.0, 1.0], false).unwrap();
    /// let locals = vec![line(p(-1.0, 0.0), p(1.0, 0.0)), line(p(0.0, 1.0), p(2.0, 1.0))];
    /// let c = BlendingSplineCurve::from_locals(knots, locals, BFunction::erbs_default()).unwrap();
    /// // Each knot is its local's point there; halfway, B(½) = ½ blends them evenly.
    /// assert_eq!(c.point(0.0), p(0.0, 0.0));
    /// assert_eq!(c.point(1.0), p(1.0, 1.0));
    /// assert!((c.point(0.5) - p(0.5, 0.5)).norm() < 1e-15);
    /// ```
    pub fn from_locals(knots: BlendKnots, locals: Vec<Arc<dyn Curve<D>>>, bfunction: BFunction) -> Result<Self> {
        if locals.len() != knots.count() {
            return Err(Error::invalid(
                "local_curves",
                format!(
                    "expected {} local curves for {} knots, got {}",
                    knots.count(),
                    knots.values().len(),
                    locals.len()
                ),
            ));
        }
        let locals = locals
            .into_iter()
            .enumerate()
            .map(|(k, curve)| {
                let mapped: Arc<dyn Curve<D>> = Arc::new(Reparametrized::new(curve, knots.support(k))?);
                Ok(Local::new(LocalCurve::General(mapped), knots.centre(k)))
            })
            .collect::<Result<_>>()?;
        Ok(BlendingSplineCurve { locals, knots, bfunction, source: None })
    }

    /// The blending spline of Hermite data (GMlib's `PERBSCurve(DVector<DVector<Vector>>, t)`):
    /// `data[k]` = [c(c_k), c′(c_k), …, c^{(d)}(c_k)] at each knot c_k of `knots`, the same
    /// number d + 1 ≥ 2 of values at every knot (d ≤ 20). Local k is the Bézier curve of
    /// degree d on its support [c_{k−1}, c_{k+1}] whose value and first d derivatives at c_k
    /// are `data[k]` (its Taylor polynomial: P = H⁻¹ data[k], see [`super::hermite`]),
    /// its frame's origin the position `data[k][0]`.
    ///
    /// Since ℓ_k alone is active at c_k with B(0) = 0, B(1) = 1, the curve passes through
    /// every position; its derivative of order j ≤ d at c_k is `data[k][j]` when the
    /// B-function's derivatives of orders 1 … j vanish at 0 and 1 (every order for ERBS,
    /// up to the smoothness for the polynomial B-functions). Errors name `hermite` (counts,
    /// non-finite values) or `knots`.
    ///
    /// # Examples
    ///
    /// ```
    /// use splinekit::Point;
    /// use splinekit::basis::BFunction;
    /// use splinekit::blend::{BlendKnots, BlendingSplineCurve};
    /// use splinekit::curve::Curve;
    /// let p = |x, y| Point::<2>::new(x, y);
    /// // Positions, first and second derivatives at the knots 0, 1, 3.
    /// let data = vec![
    ///     vec![p(0.0, 0.0), p(1.0, 1.0), p(0.0, -1.0)],
    ///     vec![p(1.0, 1.0), p(1.0, 0.0), p(0.0, 0.0)],
    ///     vec![p(3.0, 0.0), p(1.0, -1.0), p(0.5, 0.0)],
    /// ];
    /// let knots = BlendKnots::new(vec![0.0, 1.0, 3.0], false).unwrap();
    /// let c = BlendingSplineCurve::from_hermite(knots, data.clone(), BFunction::erbs_default()).unwrap();
    /// for (k, &t) in [0.0, 1.0, 3.0].iter().enumerate() {
    ///     for j in 0..3 {
    ///         assert!((c.derivative(t, j) - data[k][j]).norm() < 1e-12);
    ///     }
    /// }
    /// ```
    pub fn from_hermite(knots: BlendKnots, data: Vec<Vec<Point<D>>>, bfunction: BFunction) -> Result<Self> {
        let n = knots.count();
        if data.len() != n {
            return Err(Error::invalid(
                "hermite",
                format!(
                    "expected {n} entries, one per local curve of the {} knots{}, got {}",
                    knots.values().len(),
                    if knots.is_closed() { " of a closed curve" } else { "" },
                    data.len()
                ),
            ));
        }
        let order = data[0].len();
        if !(2..=21).contains(&order) {
            return Err(Error::invalid(
                "hermite[0]",
                format!("expected a position and 1 to 20 derivatives, got {order} values"),
            ));
        }
        let mut locals = Vec::with_capacity(n);
        for (k, values) in data.iter().enumerate() {
            if values.len() != order {
                return Err(Error::invalid(
                    format!("hermite[{k}]"),
                    format!(
                        "expected {order} values (a position and {} derivatives) like hermite[0], got {}",
                        order - 1,
                        values.len()
                    ),
                ));
            }
            for (j, v) in values.iter().enumerate() {
                if !v.iter().all(|x| x.is_finite()) {
                    return Err(Error::invalid(format!("hermite[{k}][{j}]"), "must be finite"));
                }
            }
            let support = knots.support(k);
            let fitted = hermite_bezier(values, support, knots.centre(k)).map_err(|e| {
                Error::invalid(
                    format!("hermite[{k}]"),
                    format!("no Bézier local of these data on the support [{}, {}] ({e})", support.start, support.end),
                )
            })?;
            let curve = LocalCurve::bezier(fitted);
            locals.push(Local { curve, origin: values[0], transform: Affine::identity() });
        }
        Ok(BlendingSplineCurve { locals, knots, bfunction, source: None })
    }

    /// The same spline rebuilt from its model with `local_curves` locals of `kind` (frames
    /// are reset). An error for splines made from explicit locals.
    pub fn rebuilt(&self, local_curves: usize, kind: LocalKind) -> Result<Self> {
        let src = self.source.as_ref().ok_or_else(|| {
            Error::invalid("local_curves", "this blending spline was built from explicit locals, not a model")
        })?;
        let options = BlendingCurveOptions {
            local: kind,
            bfunction: self.bfunction.clone(),
            closed: Some(self.knots.is_closed()),
            spacing: src.spacing,
        };
        Self::from_model(src.model.clone(), local_curves, &options)
    }

    /// Replaces the B-function (the locals and frames stay).
    pub fn set_bfunction(&mut self, bfunction: BFunction) {
        self.bfunction = bfunction;
    }
    /// The B-function.
    pub fn bfunction(&self) -> &BFunction {
        &self.bfunction
    }

    /// Inserts a local curve at the new knot t* (strictly inside an interval [c_k, c_{k+1}])
    /// and returns its index, keeping the shape as closely as one new local allows.
    ///
    /// Method: with Bézier locals of degree d (or other explicit locals, d = 3) the new
    /// local is the Bézier of degree d Hermite-fitted to the *current* curve at t*: its
    /// value and first d derivatives there (the curve's Taylor polynomial of degree d at
    /// t*: the Hermite construction of every Bézier local, applied to the curve), on its
    /// support [c_k, c_{k+1}]. Sub-curve and arc locals made from a model get a new local
    /// of their kind made from the model at t*.
    /// The neighbours keep their polynomials: a Bézier neighbour whose support changes is
    /// re-expressed on the new one ([`super::hermite::rebased`], exact up to rounding).
    ///
    /// The new local's frame is the identity about the model's point at t* (built from a
    /// model: the centre every local of such a spline has, edited or not), else about its
    /// own point there.
    ///
    /// Exactness (ERBS, whose derivatives all vanish at 0 and 1): outside (c_k, c_{k+1})
    /// the curve does not change; at c_k, t* and c_{k+1} it keeps its value and first d
    /// derivatives (all of them at c_k and c_{k+1}). Inside, on [c_k, t*] the curve changes
    /// from ℓ_k + B(w)(ℓ_{k+1} − ℓ_k) = c to ℓ_k + B(w′)(ℓ* − ℓ_k), so since 0 ≤ B ≤ 1,
    /// |Δc| ≤ |ℓ* − c| + |c − ℓ_k| (and |ℓ* − c| + |c − ℓ_{k+1}| on [t*, c_{k+1}]): the
    /// Taylor remainder of the new local plus the neighbour's distance from the curve,
    /// O(h^{d+1}) for locals fitted to a smooth model on knots h apart. Sub-curve locals of
    /// an untransformed model-built spline are all the model, and then the curve does not
    /// change at all.
    pub fn insert_local(&mut self, t: f64) -> Result<usize> {
        let mut knots = self.knots.clone();
        let k = knots.insert(t)?;
        let n = self.locals.len();
        let neighbour = &self.locals[(k + n - 1) % n].curve;
        let curve = match (&self.source, neighbour) {
            (Some(src), _) if !matches!(src.kind, LocalKind::Bezier(_)) => {
                local_from_model(&src.model, src.kind, &knots, k)?
            }
            (_, LocalCurve::Bezier { fitted, .. }) => self.taylor_local(t, fitted.curve().degree(), &knots, k)?,
            (_, LocalCurve::General(_)) => self.taylor_local(t, 3, &knots, k)?,
        };
        // The frame's centre: the model's point at t*, as for every local made from a
        // model (edited or not); else the new local's own point there.
        let origin = match &self.source {
            Some(src) => src.model.point(t),
            None => Local::new(curve.clone(), t).origin,
        };
        self.knots = knots;
        self.locals.insert(k, Local { curve, origin, transform: Affine::identity() });
        // The neighbours k − 1 and k + 1 (wrapping when closed; an open spline has both,
        // since t* is strictly inside the domain).
        let m = self.locals.len();
        for j in [(k + m - 1) % m, (k + 1) % m] {
            let support = self.knots.support(j);
            let local = &mut self.locals[j];
            if let LocalCurve::Bezier { fitted, .. } = &local.curve {
                let moved = super::hermite::rebased(fitted, support)?;
                let transform = local.transform;
                local.curve = LocalCurve::bezier(moved);
                local.set_transform(transform);
            }
        }
        Ok(k)
    }

    /// The Bézier of degree d on local k's support (in `knots`) matching the curve's value
    /// and first d derivatives at t.
    fn taylor_local(&self, t: f64, d: usize, knots: &BlendKnots, k: usize) -> Result<LocalCurve<D>> {
        let mut target = vec![Point::<D>::zeros(); d + 1];
        self.eval(t, &mut target);
        Ok(LocalCurve::bezier(hermite_bezier(&target, knots.support(k), t)?))
    }

    /// Splits interior knot k: the knot is doubled and local k copied, so the two copies
    /// can be moved independently (a C⁰ joint at c_k that stays continuous under rotations
    /// and scalings about the local origin). The copy has index k + 1.
    ///
    /// The curve does not change: on [c_{k−1}, c_k) locals k − 1 and k are blended as
    /// before, on [c_k, c_{k+2}) the copy and the old local k + 1, and the zero-length
    /// interval between the two copies is never active. At c_k the left limit is local
    /// k's point there and the right limit the copy's: equal while the two frames agree
    /// there, so turning or scaling either copy about its origin (the model's point at
    /// c_k for a spline built from a model) keeps the curve continuous, while moving one
    /// opens a gap of the move. A Bézier copy is re-expressed on its new support (the
    /// left copy's [c_{k−1}, c_k], the right one's [c_k, c_{k+2}]; the same polynomial,
    /// [`super::hermite::rebased`]), so [`Self::local_bezier_points`] are relative to
    /// [`Self::local_support`] as for every other local.
    ///
    /// # Examples
    ///
    /// ```
    /// use std::sync::Arc;
    /// use splinekit::blend::{BlendingCurveOptions, BlendingSplineCurve};
    /// use splinekit::curve::Curve;
    /// use splinekit::curve::model::Circle;
    /// let circle = Arc::new(Circle::new(1.0).unwrap());
    /// let mut c = BlendingSplineCurve::from_model(circle, 6, &BlendingCurveOptions::default()).unwrap();
    /// let before = c.clone();
    /// c.split_knot(2).unwrap();
    /// assert_eq!((c.local_count(), c.centre(2), c.centre(3)), (7, before.centre(2), before.centre(2)));
    /// assert!((c.point(1.3) - before.point(1.3)).norm() < 1e-12);
    /// assert!(c.split_knot(2).unwrap_err().to_string().contains("already double"));
    /// ```
    pub fn split_knot(&mut self, k: usize) -> Result<()> {
        let mut knots = self.knots.clone();
        knots.split(k)?;
        let mut copy = self.locals[k].clone();
        let mut left = self.locals[k].clone();
        for (local, j) in [(&mut left, k), (&mut copy, k + 1)] {
            if let LocalCurve::Bezier { fitted, .. } = &local.curve {
                let moved = super::hermite::rebased(fitted, knots.support(j))?;
                let transform = local.transform;
                local.curve = LocalCurve::bezier(moved);
                local.set_transform(transform);
            }
        }
        self.knots = knots;
        self.locals[k] = left;
        self.locals.insert(k + 1, copy);
        Ok(())
    }

    /// Opens a closed spline or closes an open one, keeping every local piece it can
    /// (GMlib's `toggleClose`); a spline already so is left as it is.
    ///
    /// - **Opening** (n locals on c₀ … c_n, c_n = c₀ + P): the same knot values as an open
    ///   vector of n + 1 locals, local n a copy of local 0 moved one period on (ℓ_n(t) =
    ///   ℓ₀(t − P), with local 0's frame). The curve does not change on its domain.
    /// - **Closing** (n locals on c₀ … c_{n−1}): where the ends meet — value and first
    ///   derivative at c₀ and c_{n−1} equal to 10⁻⁹ of their size, as for a spline of a
    ///   closed model — local n − 1 is the same piece as local 0 one period on and is
    ///   dropped: n − 1 locals on the same knots, period c_{n−1} − c₀, the curve unchanged
    ///   up to that agreement. Otherwise every local is kept and one interval is added,
    ///   c_n = 2c_{n−1} − c_{n−2} (the mirrored end spacing the last local's support
    ///   already had): on it the curve bridges from local n − 1 to local 0 (at t − P), and
    ///   is unchanged on [c₀, c_{n−1}]. The bridge reaches past a model's domain, so such a
    ///   spline no longer counts as built from its model.
    ///
    /// Bézier locals whose support changes are re-expressed on the new one (the same
    /// polynomials). An error naming `closed` when a closed spline would have fewer than
    /// three locals.
    ///
    /// # Examples
    ///
    /// ```
    /// use std::sync::Arc;
    /// use splinekit::blend::{BlendingCurveOptions, BlendingSplineCurve};
    /// use splinekit::curve::Curve;
    /// use splinekit::curve::model::Circle;
    /// let circle = Arc::new(Circle::new(1.0).unwrap());
    /// let mut c = BlendingSplineCurve::from_model(circle, 6, &BlendingCurveOptions::default()).unwrap();
    /// let before = c.clone();
    /// c.set_closed(false).unwrap();
    /// assert_eq!((c.local_count(), c.is_closed()), (7, false));
    /// assert!((c.point(6.0) - before.point(6.0)).norm() < 1e-12);
    /// c.set_closed(true).unwrap(); // the ends meet: the copy goes again
    /// assert_eq!((c.local_count(), c.is_closed()), (6, true));
    /// assert!((c.point(6.0) - before.point(6.0)).norm() < 1e-12);
    /// ```
    pub fn set_closed(&mut self, closed: bool) -> Result<()> {
        if closed == self.knots.is_closed() {
            return Ok(());
        }
        let values = self.knots.values().to_vec();
        let n = self.locals.len();
        if !closed {
            let period = self.knots.domain().length();
            let knots = BlendKnots::new(values, false)?;
            let first = &self.locals[0];
            let curve = match &first.curve {
                LocalCurve::Bezier { fitted, .. } => {
                    let d = fitted.domain();
                    LocalCurve::bezier(Reparametrized::new(
                        fitted.curve().clone(),
                        Interval::new(d.start + period, d.end + period),
                    )?)
                }
                LocalCurve::General(c) => {
                    let d = c.domain();
                    let shifted = Interval::new(d.start + period, d.end + period);
                    LocalCurve::General(Arc::new(Reparametrized::new(c.clone(), shifted)?))
                }
            };
            let mut copy = Local { curve, origin: first.origin, transform: Affine::identity() };
            copy.set_transform(first.transform);
            self.locals.push(copy);
            self.knots = knots;
            // The copy of a sub-curve local is the model one period on, which is the model
            // itself only where the model has that period.
            if let Some(src) = &self.source
                && src.kind == LocalKind::SubCurve
                && !(src.model.is_closed() && (src.model.domain().length() - period).abs() <= 1e-12 * period)
            {
                self.source = None;
            }
        } else {
            let meet = {
                let (mut a, mut b) = ([Point::<D>::zeros(); 2], [Point::<D>::zeros(); 2]);
                self.eval_side(values[0], Side::Right, &mut a);
                self.eval_side(values[n - 1], Side::Left, &mut b);
                (0..2).all(|j| (a[j] - b[j]).norm() <= 1e-9 * a[j].norm().max(b[j].norm()).max(1.0))
            };
            let count = if meet { n - 1 } else { n };
            if count < 3 {
                return Err(Error::invalid(
                    "closed",
                    format!("a closed blending spline needs at least 3 local curves, this one would have {count}"),
                ));
            }
            let knots = if meet {
                BlendKnots::new(values, true)?
            } else {
                let mut v = values;
                v.push(2.0 * v[n - 1] - v[n - 2]);
                BlendKnots::new(v, true)?
            };
            if meet {
                self.locals.pop();
            } else {
                self.source = None;
            }
            self.knots = knots;
        }
        // Every Bézier local on its support in the new knots (most are where they were).
        for k in 0..self.locals.len() {
            let support = self.knots.support(k);
            let local = &mut self.locals[k];
            if let LocalCurve::Bezier { fitted, .. } = &local.curve
                && fitted.domain() != support
            {
                let moved = super::hermite::rebased(fitted, support)?;
                let transform = local.transform;
                local.curve = LocalCurve::bezier(moved);
                local.set_transform(transform);
            }
        }
        Ok(())
    }

    /// Number of local curves.
    pub fn local_count(&self) -> usize {
        self.locals.len()
    }
    /// The knot vector.
    pub fn knots(&self) -> &BlendKnots {
        &self.knots
    }
    /// The knot (centre) of local k.
    pub fn centre(&self, k: usize) -> f64 {
        self.knots.centre(k)
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
    /// The parameter interval [c_{k−1}, c_{k+1}] where local k takes part.
    pub fn local_support(&self, k: usize) -> Interval {
        self.knots.support(k)
    }
    /// The control points of local k's Bézier curve in its rest frame (before its
    /// transform; the coordinates of the model, where the origin is the model's point at
    /// the knot): the Hermite-fitted ones or those set by
    /// [`Self::set_local_bezier_points`]. `None` for other kinds of locals.
    pub fn local_bezier_points(&self, k: usize) -> Option<&[Point<D>]> {
        match &self.locals.get(k)?.curve {
            LocalCurve::Bezier { fitted, .. } => Some(fitted.curve().control_points()),
            LocalCurve::General(_) => None,
        }
    }
    /// The control points of local k's Bézier curve in the world: its frame applied,
    /// o + T(P_i − o). `None` for other kinds of locals.
    pub fn local_bezier_world_points(&self, k: usize) -> Option<&[Point<D>]> {
        match &self.locals.get(k)?.curve {
            LocalCurve::Bezier { world, .. } => Some(world.curve().control_points()),
            LocalCurve::General(_) => None,
        }
    }
    /// Replaces the control points of local k's Bézier curve (in its rest frame, as
    /// [`Self::local_bezier_points`] gives them) by `points`, keeping its support, its
    /// origin (the frame's centre stays the model's point at the knot) and its frame, as
    /// GMlib's `PBezierCurve` edits its coefficients; returns the parameter ranges whose
    /// points changed (the local's support, [`Self::affected_ranges`]). An error when
    /// local k is not a Bézier curve or `points` are not d + 1 finite points.
    ///
    /// # Examples
    ///
    /// ```
    /// use std::sync::Arc;
    /// use splinekit::Point;
    /// use splinekit::blend::{BlendingCurveOptions, BlendingSplineCurve};
    /// use splinekit::curve::Curve;
    /// use splinekit::curve::model::Circle;
    /// // Pull the middle control point of local 2 outwards: the curve moves on (c₁, c₃) only.
    /// let circle = Arc::new(Circle::new(1.0).unwrap());
    /// let mut c = BlendingSplineCurve::from_model(circle, 8, &BlendingCurveOptions::default()).unwrap();
    /// let before = c.clone();
    /// let mut p = c.local_bezier_points(2).unwrap().to_vec();
    /// p[1] *= 1.5;
    /// assert_eq!(c.set_local_bezier_points(2, p).unwrap(), vec![c.local_support(2)]);
    /// assert!((c.point(c.centre(2)) - before.point(c.centre(2))).norm() > 1e-3);
    /// assert_eq!(c.point(c.centre(4)), before.point(c.centre(4)));
    /// ```
    pub fn set_local_bezier_points(&mut self, k: usize, points: Vec<Point<D>>) -> Result<Vec<Interval>> {
        let n = self.locals.len();
        let local = self.locals.get_mut(k).ok_or_else(|| {
            Error::invalid("local_control_points", format!("local curve {k} does not exist (there are {n})"))
        })?;
        let LocalCurve::Bezier { fitted, .. } = &local.curve else {
            return Err(Error::invalid(
                "local_control_points",
                format!("local curve {k} is not a Bézier curve (only Bézier locals have control points)"),
            ));
        };
        let d = fitted.curve().degree();
        if points.len() != d + 1 {
            return Err(Error::invalid(
                "local_control_points",
                format!("expected {} control points for local curve {k} of degree {d}, got {}", d + 1, points.len()),
            ));
        }
        if let Some(i) = points.iter().position(|p| !p.iter().all(|x| x.is_finite())) {
            return Err(Error::invalid(
                "local_control_points",
                format!("control point {i} of local curve {k} is not finite"),
            ));
        }
        let bezier = BezierCurve::new(points)?;
        let edited = fitted.map_curve(|_| bezier);
        let transform = local.transform;
        local.curve = LocalCurve::bezier(edited);
        if transform != Affine::identity() {
            local.set_transform(transform);
        }
        Ok(self.affected_ranges(k))
    }
    /// Sets the frame of local k (about its origin); returns the parameter ranges whose
    /// points changed ([`Self::affected_ranges`]).
    ///
    /// # Examples
    ///
    /// ```
    /// use std::sync::Arc;
    /// use splinekit::Point;
    /// use splinekit::blend::{BlendingCurveOptions, BlendingSplineCurve};
    /// use splinekit::curve::Curve;
    /// use splinekit::curve::model::Helix;
    /// use splinekit::frame::Affine;
    /// // Lift local 3 of an open helix: the curve changes on (c₂, c₄) only.
    /// let helix = Arc::new(Helix::new(1.0, 1.0, 2.0).unwrap());
    /// let mut c = BlendingSplineCurve::from_model(helix, 8, &BlendingCurveOptions::default()).unwrap();
    /// let before = c.clone();
    /// let ranges = c.set_transform(3, Affine::translation(Point::<3>::new(0.0, 0.0, 0.5)));
    /// assert_eq!(ranges, vec![c.local_support(3)]);
    /// let (inside, outside) = (c.centre(3), c.centre(5));
    /// assert!((c.point(inside) - before.point(inside) - Point::<3>::new(0.0, 0.0, 0.5)).norm() < 1e-14);
    /// assert_eq!(c.point(outside), before.point(outside));
    /// ```
    pub fn set_transform(&mut self, k: usize, transform: Affine<D>) -> Vec<Interval> {
        self.locals[k].set_transform(transform);
        self.affected_ranges(k)
    }
    /// Poses the animated locals at `time`: local k's frame becomes track(time) ∘ `rest[k]`
    /// for each track (locals without a track keep their frames). Returns the parameter
    /// ranges that changed.
    pub fn animate(&mut self, rest: &[Affine<D>], tracks: &[Track<usize>], time: f64) -> Result<Vec<Interval>> {
        let n = self.local_count();
        if rest.len() != n {
            return Err(Error::invalid("rest", format!("expected {n} rest frames, got {}", rest.len())));
        }
        let mut frames = Vec::with_capacity(tracks.len());
        for (i, track) in tracks.iter().enumerate() {
            if track.local >= n {
                return Err(Error::invalid(
                    format!("animation[{i}].local"),
                    format!("local curve {} does not exist (there are {n})", track.local),
                ));
            }
            frames.push(track.at(time, &self.locals[track.local].origin)?.after(&rest[track.local]));
        }
        let mut ranges = Vec::new();
        for (track, frame) in tracks.iter().zip(frames) {
            ranges.extend(self.set_transform(track.local, frame));
        }
        Ok(ranges)
    }
    /// The frames of all locals (e.g. the rest pose for [`Self::animate`]).
    pub fn transforms(&self) -> Vec<Affine<D>> {
        self.locals.iter().map(|l| l.transform).collect()
    }

    /// The parameter ranges where local k is active: (c_{k−1}, c_{k+1}), clipped to the
    /// domain (and split at the seam of a closed curve).
    pub fn affected_ranges(&self, k: usize) -> Vec<Interval> {
        self.knots.affected_ranges(k)
    }
}

/// Local k made from the model according to `kind`.
fn local_from_model<const D: usize>(
    model: &Arc<dyn Curve<D>>,
    kind: LocalKind,
    knots: &BlendKnots,
    k: usize,
) -> Result<LocalCurve<D>> {
    let c = knots.centre(k);
    Ok(match kind {
        LocalKind::SubCurve => LocalCurve::General(model.clone()),
        LocalKind::Arc => LocalCurve::General(Arc::new(OsculatingArc::of(model.as_ref(), c)?)),
        LocalKind::Bezier(d) => {
            if d == 0 || d > 20 {
                return Err(Error::invalid("local", format!("Bézier degree must be between 1 and 20, got {d}")));
            }
            let mut target = vec![Point::<D>::zeros(); d + 1];
            model.eval(c, &mut target);
            LocalCurve::bezier(hermite_bezier(&target, knots.support(k), c)?)
        }
    })
}

/// Knots at equal arc length along the model: the uniform knots' count and ends, the
/// interior ones where the length from the start is k L/(number of intervals), inverted to
/// 10⁻¹¹ L. An error naming `knot_spacing` where the model has no length (a point).
fn arc_length_knots<const D: usize>(model: &dyn Curve<D>, uniform: &[f64]) -> Result<Vec<f64>> {
    let intervals = uniform.len() - 1;
    let rough = crate::ops::length::arc_length(model, model.domain(), 1e-6);
    if !(rough > 0.0 && rough.is_finite()) {
        return Err(Error::invalid(
            "knot_spacing",
            format!("arc-length knots need a model of finite, non-zero length, got {rough}"),
        ));
    }
    let table = crate::query::ArcLengthTable::new(model, 1e-11 * rough)?;
    let total = table.total();
    let mut knots = uniform.to_vec();
    for (k, knot) in knots.iter_mut().enumerate().take(intervals).skip(1) {
        *knot = table.parameter_at(total * k as f64 / intervals as f64)?;
    }
    Ok(knots)
}

/// Knots at equal chord length along the model: the uniform knots' count and ends, the
/// interior ones moved so the polyline length (256 chords per interval) between
/// neighbours is equal.
fn chord_length_knots<const D: usize>(model: &dyn Curve<D>, uniform: &[f64]) -> Vec<f64> {
    let intervals = uniform.len() - 1;
    let m = 256 * intervals;
    let (s, e) = (uniform[0], uniform[intervals]);
    let params: Vec<f64> = (0..=m).map(|i| s + (e - s) * i as f64 / m as f64).collect();
    let mut cumulative = vec![0.0; m + 1];
    let mut prev = model.point(s);
    for i in 1..=m {
        let p = model.point(params[i]);
        cumulative[i] = cumulative[i - 1] + (p - prev).norm();
        prev = p;
    }
    let total = cumulative[m];
    if total.is_nan() || total <= 0.0 {
        return uniform.to_vec();
    }
    let mut knots = uniform.to_vec();
    for (k, knot) in knots.iter_mut().enumerate().take(intervals).skip(1) {
        let target = total * k as f64 / intervals as f64;
        let i = cumulative.partition_point(|&c| c < target).clamp(1, m);
        let f = (target - cumulative[i - 1]) / (cumulative[i] - cumulative[i - 1]);
        *knot = params[i - 1] + f * (params[i] - params[i - 1]);
    }
    knots
}

impl<const D: usize> Curve<D> for BlendingSplineCurve<D> {
    fn domain(&self) -> Interval {
        self.knots.domain()
    }
    fn is_closed(&self) -> bool {
        self.knots.is_closed()
    }
    fn breakpoints(&self) -> Vec<f64> {
        self.knots.breakpoints()
    }
    /// Sub-curve locals are all the model: where both active locals see it at the same
    /// point (always but on the seam interval of a model closed by force), the model is
    /// evaluated once and both frames applied, so nested blending splines cost one
    /// evaluation per level, not two.
    fn eval_side(&self, t: f64, side: Side, out: &mut [Point<D>]) {
        let span = self.knots.locate(t, side);
        let n = out.len();
        let mut a: SmallVec<[Point<D>; 8]> = smallvec![Point::<D>::zeros(); n];
        let mut b: SmallVec<[Point<D>; 8]> = smallvec![Point::<D>::zeros(); n];
        match &self.source {
            Some(ModelSource { model, kind: LocalKind::SubCurve, .. })
                if span.second_shift == 0.0 || model.is_closed() =>
            {
                model.eval_side(span.t, side, &mut a);
                b.copy_from_slice(&a);
                self.locals[span.first].to_world(&mut a);
                self.locals[span.second].to_world(&mut b);
            }
            _ => {
                self.locals[span.first].eval(span.t, side, &mut a);
                self.locals[span.second].eval(span.t + span.second_shift, side, &mut b);
            }
        }
        let mut bf: SmallVec<[f64; 8]> = smallvec![0.0; n];
        self.bfunction.eval(span.w, &mut bf);
        blend_derivatives(&a, &b, &bf, 1.0 / span.width, out);
    }

    /// Bézier locals of one degree d ≤ 7 and orders ≤ 4: the batch path of
    /// [`super::curve_batch`] (each interval's two locals prepared once per run of
    /// parameters in it, Bernstein sums of their scaled differences); intervals with other
    /// locals, and other splines, evaluate each parameter as [`Curve::eval_side`] does.
    fn eval_many(&self, params: &[f64], order: usize, out: &mut [Point<D>]) {
        let w = order + 1;
        let degree = match &self.locals[0].curve {
            LocalCurve::Bezier { world, .. } => world.curve().degree(),
            LocalCurve::General(_) => 0,
        };
        if order > curve_batch::MAX_ORDER || !(1..=curve_batch::MAX_DEGREE).contains(&degree) {
            for (&t, o) in params.iter().zip(out.chunks_exact_mut(w)) {
                self.eval_side(t, Side::Right, o);
            }
            return;
        }
        let local = |k: usize| match &self.locals[k].curve {
            LocalCurve::Bezier { world, .. } => {
                Some(BezierLocal { points: world.curve().control_points(), support: world.domain() })
            }
            LocalCurve::General(_) => None,
        };
        let general = |t: f64, o: &mut [Point<D>]| self.eval_side(t, Side::Right, o);
        curve_batch::eval_many(&self.knots, &self.bfunction, local, general, params, order, out);
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::curve::model::Heart;

    fn heart(local: LocalKind) -> BlendingSplineCurve<3> {
        let heart: Arc<dyn Curve<3>> = Arc::new(Heart::new(1.0).unwrap());
        let options = BlendingCurveOptions { local, closed: Some(true), ..Default::default() };
        BlendingSplineCurve::from_model(heart, 10, &options).unwrap()
    }

    /// Local 3's control points pulled and local 5 turned and moved: a split of knot 3
    /// copies an edited local next to edited neighbours.
    fn edited(local: LocalKind) -> BlendingSplineCurve<3> {
        let mut c = heart(local);
        if let Some(p) = c.local_bezier_points(3) {
            let mut p = p.to_vec();
            p[1] += Point::<3>::new(0.8, -0.5, 0.3);
            c.set_local_bezier_points(3, p).unwrap();
        }
        let turn = Affine::rotation(Point::<3>::new(0.0, 0.0, 1.0), 0.2).unwrap();
        c.set_transform(5, Affine::translation(Point::<3>::new(0.4, 0.2, 0.0)).after(&turn));
        c
    }

    fn values(c: &BlendingSplineCurve<3>, t: f64, side: Side) -> [Point<3>; 3] {
        let mut out = [Point::<3>::zeros(); 3];
        c.eval_side(t, side, &mut out);
        out
    }

    #[test]
    fn a_split_knot_leaves_the_curve_as_it_was() {
        // (The heart has a cusp at knot 0, where arc locals have no tangent.)
        for local in [LocalKind::Bezier(2), LocalKind::Bezier(3), LocalKind::SubCurve] {
            for k in [3, 9] {
                let before = edited(local);
                let mut c = before.clone();
                c.split_knot(k).unwrap();
                assert_eq!(c.local_count(), 11);
                assert_eq!((c.centre(k), c.centre(k + 1)), (before.centre(k), before.centre(k)));
                // The copies' Bézier points are relative to their new supports.
                // (Local 3 is untransformed, local 9 moved: the world points are the rest
                // points under the local's frame, so the check holds for both.)
                for j in [k, k + 1] {
                    if let Some(p) = c.local_bezier_world_points(j) {
                        let support = c.local_support(j);
                        let at = |t: f64| {
                            let mut o = [Point::<3>::zeros(); 1];
                            c.eval_local(j, t, &mut o);
                            o[0]
                        };
                        let bezier = BezierCurve::new(p.to_vec()).unwrap();
                        assert!((at(support.start) - bezier.point(0.0)).norm() < 1e-12, "{local:?} {j}");
                        assert!((at(support.end) - bezier.point(1.0)).norm() < 1e-12, "{local:?} {j}");
                    }
                }
                let n = 997;
                let params: Vec<f64> = (0..=n).map(|i| c.domain().lerp(i as f64 / n as f64)).collect();
                let mut many = vec![Point::<3>::zeros(); 2 * params.len()];
                c.eval_many(&params, 1, &mut many);
                for (i, &t) in params.iter().chain([before.centre(k)].iter()).enumerate() {
                    for side in [Side::Left, Side::Right] {
                        let (a, b) = (values(&c, t, side), values(&before, t, side));
                        for order in 0..3 {
                            let tol = 1e-12 * 10f64.powi(order as i32 * 2) * b[order].norm().max(1.0);
                            assert!((a[order] - b[order]).norm() < tol, "{local:?} k={k} order {order} at {t}");
                        }
                    }
                    if i < params.len() {
                        assert!((many[2 * i] - before.point(t)).norm() < 1e-12, "{local:?} batch at {t}");
                    }
                }
            }
        }
    }

    #[test]
    fn turning_or_scaling_one_copy_keeps_the_joint_and_moving_it_opens_a_gap() {
        let mut c = heart(LocalKind::Bezier(3));
        let before = c.clone();
        c.split_knot(4).unwrap();
        let t = c.centre(4);
        let o = c.origin(5);
        let turn = Affine::rotation(Point::<3>::new(0.2, 0.1, 1.0), 0.7).unwrap().after(&Affine::uniform_scale(1.6));
        c.set_transform(5, turn);
        let (left, right) = (values(&c, t, Side::Left), values(&c, t, Side::Right));
        assert!((left[0] - right[0]).norm() < 1e-12, "C0: {} vs {}", left[0], right[0]);
        assert!((left[0] - before.point(t)).norm() < 1e-12 && (o - before.point(t)).norm() < 1e-12);
        // The tangents now differ: a corner.
        assert!((left[1] - right[1]).norm() > 0.1, "a kink: {} vs {}", left[1], right[1]);
        // Left of the joint nothing moved; right of it the turned copy's support did.
        let (a, b) = (c.centre(3), c.centre(6));
        assert!((c.point(0.5 * (a + t)) - before.point(0.5 * (a + t))).norm() < 1e-12);
        assert!((c.point(0.5 * (t + b)) - before.point(0.5 * (t + b))).norm() > 1e-3);
        // A move of the left copy opens a gap of its size at the joint.
        c.set_transform(4, Affine::translation(Point::<3>::new(0.0, 0.3, 0.0)));
        let gap = values(&c, t, Side::Left)[0] - values(&c, t, Side::Right)[0];
        assert!((gap.norm() - 0.3).abs() < 1e-12, "{gap}");
    }

    #[test]
    fn only_single_interior_knots_split() {
        let mut c = heart(LocalKind::Bezier(3));
        let e = c.split_knot(0).unwrap_err().to_string();
        assert!(e.contains("1..=9 can be split, got 0"), "{e}");
        assert!(c.split_knot(10).is_err());
        c.split_knot(9).unwrap();
        assert_eq!(c.local_count(), 11);
        assert!(c.split_knot(9).unwrap_err().to_string().contains("already double"));
        assert!(c.split_knot(10).unwrap_err().to_string().contains("already double"));
    }
}
