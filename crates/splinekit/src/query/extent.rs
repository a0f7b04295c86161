//! The extent of a curve or a surface: the axis-aligned box of its points, what
//! [`CurveExtent::extent`] and [`SurfaceExtent::extent`] give for shapes without an
//! enclosing box of their own.
//!
//! Method. Each direction of the domain is cut at the shape's breakpoints and every span
//! sampled regularly: [`CURVE_SAMPLES`] samples over a curve's domain at least,
//! [`SURFACE_SAMPLES`] over each direction of a surface's, [`MIN_PER_SPAN`] per span.
//! Along a curve, and along every iso-line of a surface through a sample (u = uᵢ along v,
//! v = vⱼ along u), an interval between neighbouring samples is halved while the tangent
//! turns, or may turn by its turning rate, by more than π/8 over it. On each interval the
//! derivative of each coordinate x_k is compared at the ends: a sign change brackets an
//! extreme of x_k, which safeguarded Newton steps on x_k′ = 0 (with x_k″; bisection when a
//! step leaves the bracket) locate to rounding; equal signs with a sign change of x_k″
//! bracket an extreme of x_k′, found by bisection on x_k″, and where x_k′ has the other
//! sign there the two extremes of x_k on either side are located as before. On a surface,
//! the best extreme of each coordinate found on each family of iso-lines then starts Newton
//! steps on ∇x_k = 0 with the Hessian of x_k, which reach an interior extreme lying between
//! iso-lines; the result counts only when the steps stay in the domain. The box holds
//! every sample and every point these searches reach.
//!
//! Guarantee. Every point the box is made of lies on the shape, so the box lies inside the
//! shape's true box; it equals it (to rounding) when the searches reach every extreme: each
//! extreme of a coordinate shows as a sign change of its first or second derivative between
//! the ends of an interval (on a surface: the extremes on the boundary, and the interior
//! ones that the Newton steps from the best iso-line extreme reach). Where a coordinate
//! rises and falls back unseen between two samples, the box falls short by that excursion:
//! this is a sampled box, not a certified enclosure. Trimming is ignored: a trimmed
//! surface's box is that of the whole surface, which holds the trimmed one.
//!
//! [`sampled_curve_box`] and [`sampled_surface_box`] are the plain boxes of a regular
//! sample set (no refinement): the size some tolerances were defined by, kept so that their
//! outputs stay what they were.

use crate::Interval;
use crate::Point;
use crate::basis::Side;
use crate::curve::Curve;
use crate::query::bounds::Aabb;
use crate::query::newton::{self, Step, settled, settled_all};
use crate::surface::Surface;

/// The fewest samples over a curve's domain.
pub const CURVE_SAMPLES: usize = 64;

/// The fewest samples over each direction of a surface's domain (and along each iso-line).
pub const SURFACE_SAMPLES: usize = 32;

/// The fewest samples in each breakpoint span.
pub const MIN_PER_SPAN: usize = 2;

/// The spans between distinct breakpoints of a direction, each with its number of
/// sampling intervals: ⌈`samples` / spans⌉, at least [`MIN_PER_SPAN`].
fn spans(domain: Interval, breakpoints: &[f64], samples: usize) -> Vec<(Interval, usize)> {
    let mut cuts: Vec<f64> = breakpoints.iter().copied().filter(|t| t.is_finite()).collect();
    cuts.push(domain.start);
    cuts.push(domain.end);
    cuts.retain(|t| *t >= domain.start && *t <= domain.end);
    cuts.sort_by(f64::total_cmp);
    cuts.dedup();
    let count = cuts.len().saturating_sub(1).max(1);
    let per = samples.div_ceil(count).max(MIN_PER_SPAN);
    if cuts.len() < 2 {
        return vec![(domain, per)];
    }
    cuts.windows(2).map(|w| (Interval::new(w[0], w[1]), per)).collect()
}

/// Most halvings of a sampling interval where the tangent turns.
const MAX_DEPTH: usize = 12;

/// An interval is halved while its tangent may turn by more than this angle over it, π/8.
const TURN: f64 = std::f64::consts::FRAC_PI_8;

/// The cosine of [`TURN`].
const TURN_COS: f64 = 0.923_879_532_511_286_7;

/// Position, first and second derivative at a parameter.
type Jet<const D: usize> = [Point<D>; 3];

/// A parameter and the jet there.
type Sample<const D: usize> = (f64, Jet<D>);

/// Visits the samples of a line (a curve, or an iso-line of a surface) and the extremes of
/// each coordinate between them. `eval(t, side)` gives the position and the first two
/// derivatives at t (`side` selects the limit at a span's end); `found(t, p)` receives
/// every point.
///
/// Each span's regular samples are refined by halving an interval while the tangent turns
/// by more than π/8 over it ([`turns`]; at most [`MAX_DEPTH`] times). On each final interval, a sign
/// change of a coordinate's derivative x_k′ between the ends brackets an extreme of x_k;
/// equal signs with a sign change of x_k″ bracket the extreme of x_k′, where x_k′ may
/// cross zero and come back: that point is found (bisection on x_k″) and, where x_k′ has
/// the other sign there, the two extremes of x_k it brackets with the ends.
fn line_extremes<const D: usize>(
    spans: &[(Interval, usize)],
    eval: impl Fn(f64, Side) -> Jet<D>,
    mut found: impl FnMut(f64, &Point<D>),
) {
    for &(span, n) in spans {
        let samples: Vec<Sample<D>> = (0..=n)
            .map(|j| {
                let (t, side) =
                    if j == n { (span.end, Side::Left) } else { (span.lerp(j as f64 / n as f64), Side::Right) };
                (t, eval(t, side))
            })
            .collect();
        for (t, v) in &samples {
            found(*t, &v[0]);
        }
        let mut stack: Vec<(Sample<D>, Sample<D>, usize)> = samples.windows(2).map(|w| (w[0], w[1], 0)).rev().collect();
        while let Some((a, b, depth)) = stack.pop() {
            if depth < MAX_DEPTH && turns(b.0 - a.0, &a.1, &b.1) {
                let t = 0.5 * (a.0 + b.0);
                let mid = (t, eval(t, Side::Right));
                found(mid.0, &mid.1[0]);
                stack.push((mid, b, depth + 1));
                stack.push((a, mid, depth + 1));
                continue;
            }
            for k in 0..D {
                for t in interval_extremes(&eval, k, &a, &b, span) {
                    found(t, &eval(t, Side::Right)[0]);
                }
            }
        }
    }
}

/// Whether the tangent may turn by more than π/8 over the interval from `a` to `b`: the
/// tangents at the ends differ by more, or the turning rate at an end,
/// ω = |c′ ∧ c″|/|c′|² (from |c′|²|c″|² − (c′·c″)²), times the interval's length is more
/// (the second test sees a tangent that turns a full loop and comes back).
fn turns<const D: usize>(h: f64, a: &Jet<D>, b: &Jet<D>) -> bool {
    let (na, nb) = (a[1].norm(), b[1].norm());
    if !(na > 0.0 && nb > 0.0) {
        return false;
    }
    let rate = |j: &Jet<D>, n: f64| {
        let wedge = (n * n * j[2].norm_squared() - j[1].dot(&j[2]).powi(2)).max(0.0).sqrt();
        wedge / (n * n)
    };
    a[1].dot(&b[1]) < TURN_COS * na * nb || h * rate(a, na).max(rate(b, nb)) > TURN
}

/// The parameters in (a, b) where coordinate `k` may have an extreme (see
/// [`line_extremes`]).
fn interval_extremes<const D: usize>(
    eval: &impl Fn(f64, Side) -> Jet<D>,
    k: usize,
    (ta, a): &Sample<D>,
    (tb, b): &Sample<D>,
    span: Interval,
) -> Vec<f64> {
    let (ga, gb) = (a[1][k], b[1][k]);
    if ga * gb < 0.0 {
        return vec![coordinate_critical(eval, k, 1, (*ta, *tb), ga, span)];
    }
    if ga * gb > 0.0 && a[2][k] * b[2][k] < 0.0 {
        // x_k′ has an extreme inside; where it has the other sign, x_k′ crosses zero twice.
        let tm = coordinate_critical(eval, k, 2, (*ta, *tb), a[2][k], span);
        let gm = eval(tm, Side::Right)[1][k];
        if gm * ga < 0.0 {
            return vec![
                tm,
                coordinate_critical(eval, k, 1, (*ta, tm), ga, span),
                coordinate_critical(eval, k, 1, (tm, *tb), gm, span),
            ];
        }
        return vec![tm];
    }
    Vec::new()
}

/// The zero of the derivative of order `order` (1 or 2) of x_k in the bracket (a, b),
/// where it is `ga` at a and has the other sign at b. For x_k′: Newton steps with x_k″,
/// a bisection whenever a step would leave the bracket; for x_k″ (no third derivative at
/// hand): bisection. Until [`settled`] or [`newton::cap::EXTENT`] steps.
fn coordinate_critical<const D: usize>(
    eval: &impl Fn(f64, Side) -> Jet<D>,
    k: usize,
    order: usize,
    (a, b): (f64, f64),
    ga: f64,
    span: Interval,
) -> f64 {
    let mut bracket = (a, b);
    let start = [0.5 * (a + b)];
    let end = newton::iterate(newton::cap::EXTENT, start, |&[t]| {
        let v = eval(t, Side::Right);
        let g = v[order][k];
        if g == 0.0 {
            return Step::Stop;
        }
        if (g < 0.0) == (ga < 0.0) {
            bracket.0 = t;
        } else {
            bracket.1 = t;
        }
        let newton_step = if order == 1 { t - g / v[2][k] } else { f64::NAN };
        let next = if newton_step.is_finite() && newton_step > bracket.0 && newton_step < bracket.1 {
            newton_step
        } else {
            0.5 * (bracket.0 + bracket.1)
        };
        Step::To([next], settled(t, next, span) || bracket.1 - bracket.0 <= newton::ROUNDING_STEP * span.length())
    });
    end.map_or(start[0], |[t]| t)
}

/// The extent of a curve, a capability of every [`Curve`] (a blanket implementation):
/// `use splinekit::curve::CurveExtent` to call it.
pub trait CurveExtent<const D: usize>: Curve<D> {
    /// An axis-aligned box of the curve, for anything that needs a box or a size (its
    /// [`diagonal`](Aabb::diagonal)): the kind's [`Curve::enclosing_box`] where it has one
    /// (B-spline, Bézier and NURBS curves: the box of the control points, which holds the
    /// curve but is not tight in general), else [`curve_extent`]: samples on every
    /// breakpoint span and the extremes of each coordinate between them, located by Newton
    /// steps — exact to rounding where every extreme shows as a sign change of the
    /// coordinate's derivative between neighbouring samples (the circle, the ellipse), a
    /// sampled box inside the true one otherwise, not a certified enclosure.
    ///
    /// ```
    /// use splinekit::{Point, curve::{CurveExtent, model::Circle}};
    /// let b = Circle::new(2.0).unwrap().extent();
    /// assert!((b.min - Point::<3>::new(-2.0, -2.0, 0.0)).norm() < 1e-15);
    /// assert!((b.max - Point::<3>::new(2.0, 2.0, 0.0)).norm() < 1e-15);
    /// ```
    fn extent(&self) -> Aabb<D> {
        self.enclosing_box().unwrap_or_else(|| curve_extent(self))
    }
}

impl<const D: usize, C: Curve<D> + ?Sized> CurveExtent<D> for C {}

/// The extent of a surface, a capability of every [`Surface`] (a blanket
/// implementation): `use splinekit::surface::SurfaceExtent` to call it.
pub trait SurfaceExtent<const D: usize>: Surface<D> {
    /// An axis-aligned box of the surface, for anything that needs a box or a size: the
    /// kind's [`Surface::enclosing_box`] where it has one (B-spline, Bézier and NURBS
    /// surfaces: the box of the control net; subdivision limits: the cage's box), else
    /// [`surface_extent`]: samples on every breakpoint patch, the extremes of each
    /// coordinate along the iso-lines through them and Newton steps on the coordinate's
    /// gradient from the best — exact to rounding where those searches reach every extreme
    /// (a bilinear patch, a sphere), a sampled box inside the true one otherwise, not a
    /// certified enclosure. Trimming is ignored (the box of the whole surface holds the
    /// trimmed one).
    fn extent(&self) -> Aabb<D> {
        self.enclosing_box().unwrap_or_else(|| surface_extent(self))
    }
}

impl<const D: usize, S: Surface<D> + ?Sized> SurfaceExtent<D> for S {}

/// The extent of a curve (see the module documentation): samples on every breakpoint
/// span and the extremes of each coordinate between them.
pub fn curve_extent<const D: usize, C: Curve<D> + ?Sized>(curve: &C) -> Aabb<D> {
    let mut out = Aabb::empty();
    let eval = |t: f64, side: Side| {
        let mut v = [Point::<D>::zeros(); 3];
        curve.eval_side(t, side, &mut v);
        v
    };
    line_extremes(&spans(curve.domain(), &curve.breakpoints(), CURVE_SAMPLES), eval, |_, p| out.include(p));
    out
}

/// The best value of one coordinate found so far, in one sense, and where.
#[derive(Debug, Clone, Copy)]
struct Best {
    value: f64,
    at: Option<(f64, f64)>,
}

/// The extent of a surface (see the module documentation): every iso-line through a
/// sample searched for the extremes of each coordinate, then Newton steps on ∇x_k = 0 from
/// the best of them.
pub fn surface_extent<const D: usize, S: Surface<D> + ?Sized>(surface: &S) -> Aabb<D> {
    let (du, dv) = (surface.domain_u(), surface.domain_v());
    let (su, sv) =
        (spans(du, &surface.breakpoints_u(), SURFACE_SAMPLES), spans(dv, &surface.breakpoints_v(), SURFACE_SAMPLES));
    let grid = |spans: &[(Interval, usize)]| -> Vec<f64> {
        let mut ts: Vec<f64> =
            spans.iter().flat_map(|&(s, n)| (0..n).map(move |j| s.lerp(j as f64 / n as f64))).collect();
        ts.push(spans.last().map_or(0.0, |s| s.0.end));
        ts
    };
    let (us, vs) = (grid(&su), grid(&sv));
    let mut out = Aabb::empty();
    // best[k] = (largest, smallest) of x_k per family of iso-lines (along v, along u).
    let fresh = |v: f64| Best { value: v, at: None };
    let mut best = vec![[(fresh(f64::NEG_INFINITY), fresh(f64::INFINITY)); 2]; D];
    let mut record = |family: usize, u: f64, v: f64, p: &Point<D>, out: &mut Aabb<D>| {
        out.include(p);
        for k in 0..D {
            let (hi, lo) = &mut best[k][family];
            if p[k] > hi.value {
                *hi = Best { value: p[k], at: Some((u, v)) };
            }
            if p[k] < lo.value {
                *lo = Best { value: p[k], at: Some((u, v)) };
            }
        }
    };
    for &u in &us {
        let along_v = |v: f64, _: Side| {
            let mut o = [Point::<D>::zeros(); 3];
            surface.eval_partials(u, v, 0, 2, &mut o);
            o
        };
        line_extremes(&sv, along_v, |v, p| record(0, u, v, p, &mut out));
    }
    for &v in &vs {
        let along_u = |u: f64, _: Side| {
            let mut o = [Point::<D>::zeros(); 3];
            surface.eval_partials(u, v, 2, 0, &mut o);
            o
        };
        line_extremes(&su, along_u, |u, p| record(1, u, v, p, &mut out));
    }
    for (k, per_family) in best.iter().enumerate() {
        for (hi, lo) in per_family {
            for start in [hi.at, lo.at].into_iter().flatten() {
                if let Some(p) = interior_critical(surface, k, start, (du, dv)) {
                    out.include(&p);
                }
            }
        }
    }
    out
}

/// Newton steps on ∇x_k(u, v) = 0 with the Hessian of x_k from `start`, until
/// [`settled_all`] or [`newton::cap::EXTENT`] steps; the point reached, or `None` when a
/// step leaves the domain, the Hessian is singular or a value is not finite.
fn interior_critical<const D: usize, S: Surface<D> + ?Sized>(
    surface: &S,
    k: usize,
    start: (f64, f64),
    (du, dv): (Interval, Interval),
) -> Option<Point<D>> {
    let [u, v] = newton::iterate(newton::cap::EXTENT, [start.0, start.1], |&[u, v]| {
        let mut o = [Point::<D>::zeros(); 9];
        surface.eval_partials(u, v, 2, 2, &mut o);
        // o[i·3 + j] = ∂^{i+j}S/∂uⁱ∂vʲ.
        let (gu, gv) = (o[3][k], o[1][k]);
        let (huu, huv, hvv) = (o[6][k], o[4][k], o[2][k]);
        let det = huu * hvv - huv * huv;
        if gu == 0.0 && gv == 0.0 {
            return Step::Stop;
        }
        if det == 0.0 || !det.is_finite() {
            return Step::Fail;
        }
        let next = [u - (hvv * gu - huv * gv) / det, v - (huu * gv - huv * gu) / det];
        if !next.iter().all(|x| x.is_finite())
            || next[0] < du.start
            || next[0] > du.end
            || next[1] < dv.start
            || next[1] > dv.end
        {
            return Step::Fail;
        }
        Step::To(next, settled_all(&[u, v], &next, &[du, dv]))
    })?;
    let p = surface.point(u, v);
    p.iter().all(|x| x.is_finite()).then_some(p)
}

/// The box of the curve's points at the `segments + 1` regular parameters
/// a + i·(b − a)/`segments` (no refinement): a size measure defined by that sample set.
pub fn sampled_curve_box<const D: usize, C: Curve<D> + ?Sized>(curve: &C, segments: usize) -> Aabb<D> {
    let d = curve.domain();
    let n = segments.max(1);
    let points: Vec<Point<D>> = (0..=n).map(|i| curve.point(d.lerp(i as f64 / n as f64))).collect();
    Aabb::around(&points, 0.0)
}

/// The box of the surface's points on the regular (`segments` + 1)² grid of its domain,
/// u outer and v inner (no refinement): a size measure defined by that sample set.
pub fn sampled_surface_box<const D: usize, S: Surface<D> + ?Sized>(surface: &S, segments: usize) -> Aabb<D> {
    let (du, dv) = (surface.domain_u(), surface.domain_v());
    let n = segments.max(1);
    let points: Vec<Point<D>> = (0..=n)
        .flat_map(|i| (0..=n).map(move |j| (i, j)))
        .map(|(i, j)| surface.point(du.lerp(i as f64 / n as f64), dv.lerp(j as f64 / n as f64)))
        .collect();
    Aabb::around(&points, 0.0)
}
