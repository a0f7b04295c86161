//! STEP curves and surfaces evaluated in the parametrisations ISO 10303-42 gives them, and
//! points of a surface inverted to their parameters: what reading needs to compute the
//! pcurves that most CAD systems leave out of their files (see [`crate::pcurve`]).
//!
//! * Curves ([`CurveEval`]): `LINE` o + t d, `CIRCLE`/`ELLIPSE` o + a cos t x + b sin t y
//!   (t in radians), splines through the kernel's [`NurbsCurve`]; a `TRIMMED_CURVE` is its
//!   basis (same parameter).
//! * Surfaces ([`SurfaceEval`], a kernel [`Surface`]): with e(u) = cos u x + sin u y,
//!   - plane o + u x + v y;
//!   - cylinder o + r e(u) + v z;
//!   - cone o + (r + v tan α) e(u) + v z (v the height);
//!   - sphere o + R cos v e(u) + R sin v z;
//!   - torus o + (R + r cos v) e(u) + r sin v z;
//!   - revolution a + w∥ + cos u w⊥ + sin u (k × w), w = c(v) − a split along the unit
//!     axis k (the profile turned by u about the axis, right-handed);
//!   - extrusion c(u) + v d;
//!   - splines through the kernel's [`NurbsSurface`].
//!
//!   Partials of every order are exact: ∂ⁱ/∂uⁱ turns (cos u, sin u) by i quarter turns,
//!   and ∂ʲ/∂vʲ of a swept surface is the profile's j-th derivative in its place.
//!
//! Inversion ([`SurfaceEval::invert`]) is closed-form on the elementary surfaces (angles
//! by atan2, heights and plane coordinates by dot products) and Gauss–Newton
//! (`splinekit::query::newton::polish_on_surface`) on the others, from a hint (the
//! parameters of a nearby point) or from the kernel's global nearest point.

use splinekit::Point;
use splinekit::basis::Side;
use splinekit::curve::{Curve as KernelCurve, Interval, NurbsCurve};
use splinekit::query::newton::{Settle, cap, polish_on_surface};
use splinekit::query::project_surface::SurfaceProjector;
use splinekit::surface::{NurbsSurface, Surface};
use std::f64::consts::TAU;

use crate::error::{Result, StepError};
use crate::geometry::{Axes, Curve, SplineSurface, Surface as StepSurface};
use crate::kernel::nurbs;

/// (cos, sin) of u differentiated `order` times: each derivative turns the pair by a
/// quarter turn, (c, s) → (−s, c).
fn trig(u: f64, order: usize) -> (f64, f64) {
    let (s, c) = u.sin_cos();
    match order % 4 {
        0 => (c, s),
        1 => (-s, c),
        2 => (-c, -s),
        _ => (s, -c),
    }
}

/// A STEP curve ready to evaluate in its own parameter.
#[derive(Debug, Clone)]
pub enum CurveEval {
    /// o + t d.
    Line {
        /// Origin.
        origin: Point<3>,
        /// Direction with its magnitude.
        direction: Point<3>,
    },
    /// o + a cos t x + b sin t y (a circle when a = b).
    Conic {
        /// Centre and plane.
        axes: Axes,
        /// Semi-axis along x.
        a: f64,
        /// Semi-axis along y.
        b: f64,
    },
    /// A B-spline or NURBS curve.
    Spline(Box<NurbsCurve<3>>),
}

/// Up to three coordinates as a point (missing ones 0).
fn point3(v: &[f64]) -> Point<3> {
    Point::<3>::from_fn(|k, _| v.get(k).copied().unwrap_or(0.0))
}

impl CurveEval {
    /// The curve (a trimmed curve as its basis, whose parameter it keeps).
    pub fn new(c: &Curve) -> Result<Self> {
        Ok(match c {
            Curve::Line { origin, direction } => {
                CurveEval::Line { origin: point3(origin), direction: point3(direction) }
            }
            Curve::Circle { axes, radius } => CurveEval::Conic { axes: *axes, a: *radius, b: *radius },
            Curve::Ellipse { axes, a, b } => CurveEval::Conic { axes: *axes, a: *a, b: *b },
            Curve::Spline(s) => CurveEval::Spline(Box::new(nurbs::<3>(s)?)),
            Curve::Trimmed { basis, .. } => CurveEval::new(basis)?,
        })
    }

    /// c(t), c′(t), …, c⁽ᵏ⁾(t) into `out[0..=k]`.
    pub fn eval(&self, t: f64, out: &mut [Point<3>]) {
        match self {
            CurveEval::Line { origin, direction } => {
                for (k, o) in out.iter_mut().enumerate() {
                    *o = match k {
                        0 => origin + direction * t,
                        1 => *direction,
                        _ => Point::<3>::zeros(),
                    };
                }
            }
            CurveEval::Conic { axes, a, b } => {
                let y = axes.y();
                for (k, o) in out.iter_mut().enumerate() {
                    let (c, s) = trig(t, k);
                    *o = axes.x * (a * c) + y * (b * s) + if k == 0 { axes.origin } else { Point::<3>::zeros() };
                }
            }
            CurveEval::Spline(s) => s.eval_side(t, Side::Right, out),
        }
    }

    /// c(t).
    pub fn point(&self, t: f64) -> Point<3> {
        let mut o = [Point::<3>::zeros()];
        self.eval(t, &mut o);
        o[0]
    }

    /// The parameters the curve is defined over: a spline's knots, a conic's turn [0, 2π];
    /// `None` for a line.
    pub fn natural_domain(&self) -> Option<Interval> {
        match self {
            CurveEval::Line { .. } => None,
            CurveEval::Conic { .. } => Some(Interval::new(0.0, TAU)),
            CurveEval::Spline(s) => Some(s.domain()),
        }
    }
}

/// What a STEP surface is, for evaluation.
#[derive(Debug, Clone)]
enum Kind {
    Plane,
    Cylinder { radius: f64 },
    Cone { radius: f64, slope: f64 },
    Sphere { radius: f64 },
    Torus { major: f64, minor: f64 },
    Revolution { profile: CurveEval },
    Extrusion { profile: CurveEval, direction: Point<3> },
    Spline(Box<NurbsSurface<3>>),
}

/// A STEP surface in its own (u, v): evaluation of every partial, periods, inversion.
#[derive(Debug, Clone)]
pub struct SurfaceEval {
    kind: Kind,
    /// The placement of elementary surfaces; for a revolution its axis (origin a, z the
    /// unit axis k, x any unit vector across it).
    axes: Axes,
    domain: (Interval, Interval),
    closed: (bool, bool),
}

/// The whole real line, the domain of an unbounded parameter.
const UNBOUNDED: Interval = Interval::new(f64::NEG_INFINITY, f64::INFINITY);

/// A STEP spline surface as a kernel NURBS surface (weights 1 when not rational; the STEP
/// form is an open spline over its full knot vectors, closed or not).
pub fn spline_surface(s: &SplineSurface) -> Result<NurbsSurface<3>> {
    let net: Vec<Vec<Point<3>>> = s.points.iter().map(|row| row.iter().map(|p| point3(p)).collect()).collect();
    let weights = s.weights.clone().unwrap_or_else(|| net.iter().map(|row| vec![1.0; row.len()]).collect());
    NurbsSurface::new(s.degrees, s.knots_u.clone(), s.knots_v.clone(), net, weights, (false, false))
        .map_err(|e| StepError::plain(format!("B-spline surface: {e}")))
}

/// Whether a spline surface closes in u or v: its `u_closed`/`v_closed` flag (a periodic
/// spline, written unrolled) or a net whose first and last rows (columns) are equal.
fn spline_closed(s: &SplineSurface) -> (bool, bool) {
    let rows = &s.points;
    let same = |a: &[f64], b: &[f64]| a.iter().zip(b).all(|(x, y)| (x - y).abs() <= 1e-12 * (1.0 + x.abs()));
    let u = rows.len() > 1 && rows[0].iter().zip(&rows[rows.len() - 1]).all(|(a, b)| same(a, b));
    let v = rows.iter().all(|r| r.len() > 1 && same(&r[0], &r[r.len() - 1]));
    (s.closed.0 || u, s.closed.1 || v)
}

/// `x` moved by whole periods into the domain `d` when `closed` (a closed spline's
/// parameters continue around it).
fn wrapped(x: f64, d: Interval, closed: bool) -> f64 {
    if closed && x.is_finite() && !(d.start..=d.end).contains(&x) {
        d.start + (x - d.start).rem_euclid(d.length())
    } else {
        x
    }
}

impl SurfaceEval {
    /// The surface (a rectangular trimmed surface as its basis, whose parameters it keeps).
    pub fn new(s: &StepSurface) -> Result<Self> {
        let angle = Interval::new(0.0, TAU);
        let (kind, axes, domain, closed) = match s {
            StepSurface::Plane(a) => (Kind::Plane, *a, (UNBOUNDED, UNBOUNDED), (false, false)),
            StepSurface::Cylinder { axes, radius } => {
                (Kind::Cylinder { radius: *radius }, *axes, (angle, UNBOUNDED), (true, false))
            }
            StepSurface::Cone { axes, radius, semi_angle } => {
                (Kind::Cone { radius: *radius, slope: semi_angle.tan() }, *axes, (angle, UNBOUNDED), (true, false))
            }
            StepSurface::Sphere { axes, radius } => (
                Kind::Sphere { radius: *radius },
                *axes,
                (angle, Interval::new(-std::f64::consts::FRAC_PI_2, std::f64::consts::FRAC_PI_2)),
                (true, false),
            ),
            StepSurface::Torus { axes, major_radius, minor_radius } => {
                (Kind::Torus { major: *major_radius, minor: *minor_radius }, *axes, (angle, angle), (true, true))
            }
            StepSurface::Revolution { profile, axis_origin, axis } => {
                let profile = CurveEval::new(profile)?;
                let k = axis.normalize();
                let across = if k[0].abs() < 0.9 { Point::<3>::x() } else { Point::<3>::y() };
                let x = (across - k * across.dot(&k)).normalize();
                let v = profile.natural_domain().unwrap_or(UNBOUNDED);
                (Kind::Revolution { profile }, Axes { origin: *axis_origin, z: k, x }, (angle, v), (true, false))
            }
            StepSurface::Extrusion { profile, direction } => {
                let profile = CurveEval::new(profile)?;
                let u = profile.natural_domain().unwrap_or(UNBOUNDED);
                let closed = matches!(profile, CurveEval::Conic { .. });
                (Kind::Extrusion { profile, direction: *direction }, Axes::WORLD, (u, UNBOUNDED), (closed, false))
            }
            StepSurface::Spline(sp) => {
                let k = spline_surface(sp)?;
                let domain = (k.domain_u(), k.domain_v());
                (Kind::Spline(Box::new(k)), Axes::WORLD, domain, spline_closed(sp))
            }
            StepSurface::Trimmed { basis, .. } => return SurfaceEval::new(basis),
        };
        Ok(SurfaceEval { kind, axes, domain, closed })
    }

    /// The period of each parameter that is periodic (2π for angles, the knot span of a
    /// spline whose net closes).
    pub fn periods(&self) -> (Option<f64>, Option<f64>) {
        let period = |closed: bool, d: Interval| (closed && d.length().is_finite()).then(|| d.length());
        (period(self.closed.0, self.domain.0), period(self.closed.1, self.domain.1))
    }

    /// Whether (u, v) lies on a boundary of the domain that does not continue (an open
    /// spline's edge, a revolved profile's end).
    pub fn on_boundary(&self, p: Point<2>) -> bool {
        let at_end = |x: f64, d: Interval, closed: bool| {
            let e = 1e-12 * (1.0 + d.start.abs().max(d.end.abs()));
            !closed && ((x - d.start).abs() <= e || (x - d.end).abs() <= e)
        };
        at_end(p[0], self.domain.0, self.closed.0) || at_end(p[1], self.domain.1, self.closed.1)
    }

    /// Whether the surface is an elementary one (plane, cylinder, cone, sphere, torus),
    /// whose points invert in closed form.
    pub fn is_elementary(&self) -> bool {
        matches!(
            self.kind,
            Kind::Plane | Kind::Cylinder { .. } | Kind::Cone { .. } | Kind::Sphere { .. } | Kind::Torus { .. }
        )
    }

    /// The closed-form parameters of `q` on an elementary surface (`None` on the others):
    /// angles in [0, 2π) except where the angle is undefined (on the axis: a sphere's pole,
    /// a cone's apex), where u is `None`.
    fn elementary_parameters(&self, q: &Point<3>) -> Option<(Option<f64>, f64)> {
        let a = &self.axes;
        let w = q - a.origin;
        let (x, y, z) = (w.dot(&a.x), w.dot(&a.y()), w.dot(&a.z));
        let rho = x.hypot(y);
        let scale = w.norm().max(1.0);
        let angle = |x: f64, y: f64| {
            let t = y.atan2(x);
            if t < 0.0 { (t + TAU).min(TAU - TAU * f64::EPSILON) } else { t }
        };
        let around = (rho > 1e-13 * scale).then(|| angle(x, y));
        Some(match self.kind {
            Kind::Plane => (Some(x), y),
            Kind::Cylinder { .. } => (around, z),
            Kind::Cone { radius, slope } => {
                // The other nappe (r + v tan α < 0) has its points at u + π.
                let u = around.map(|u| if radius + z * slope < 0.0 { angle(-x, -y) } else { u });
                (u, z)
            }
            Kind::Sphere { .. } => (around, z.atan2(rho)),
            Kind::Torus { major, .. } => {
                let v = z.atan2(rho - major);
                (around, if v < 0.0 { v + TAU } else { v })
            }
            _ => return None,
        })
    }

    /// The parameters (u, v) of the point of the surface at `q` (a point on or near it):
    /// the one nearest to `hint` where `hint` is given (periodic parameters moved by whole
    /// periods to lie within half a period of it; on an axis, where u is undefined, the
    /// hint's u), else the global nearest point.
    pub fn invert(&self, q: &Point<3>, hint: Option<(f64, f64)>) -> Result<(f64, f64)> {
        let (u, v) = match self.elementary_parameters(q) {
            Some((u, v)) => (u.or(hint.map(|h| h.0)).unwrap_or(0.0), v),
            None => {
                let start = match hint {
                    Some(h) => h,
                    None => self.global_guess(q)?,
                };
                // Periodic parameters run on past the domain (the surface repeats there).
                let free = |d: Interval, closed: bool| if closed { UNBOUNDED } else { d };
                let ((u, v), _) = polish_on_surface(
                    self,
                    q,
                    start,
                    (free(self.domain.0, self.closed.0), free(self.domain.1, self.closed.1)),
                    cap::POINT_PARAMETERS,
                    Settle::Rounding,
                );
                let (u, v) = self.along_boundary(q, (u, v));
                self.undefined_on_degenerate_side((u, v), hint)
            }
        };
        let Some((hu, hv)) = hint else { return Ok((u, v)) };
        let (pu, pv) = self.periods();
        let near = |x: f64, h: f64, p: Option<f64>| match p {
            Some(p) => x + p * ((h - x) / p).round(),
            None => x,
        };
        Ok((near(u, hu, pu), near(v, hv, pv)))
    }

    /// On a side of the domain that the surface collapses to a point (a spline's pole:
    /// S_u = 0 all along v = v₀), u is undefined, as on a sphere's axis: the hint's u is
    /// taken (and likewise v where S_v vanishes).
    fn undefined_on_degenerate_side(&self, (u, v): (f64, f64), hint: Option<(f64, f64)>) -> (f64, f64) {
        let Some((hu, hv)) = hint else { return (u, v) };
        let mut o = [Point::<3>::zeros(); 4];
        self.eval_partials(u, v, 1, 1, &mut o);
        let (su, sv) = (o[2].norm(), o[1].norm());
        let tiny = 1e-10 * su.max(sv);
        match (su <= tiny, sv <= tiny) {
            (true, false) => (hu, v),
            (false, true) => (u, hv),
            _ => (u, v),
        }
    }

    /// The nearest point along the boundary where a clamped Gauss–Newton stopped on one: the
    /// clamped step still moved the free parameter by the coupled 2 × 2 system, which is
    /// not the nearest point along the boundary; Newton on the free parameter alone,
    /// t ← t + S_t·r / (S_t·S_t + S_tt·(−r)), finds it (a corner stays).
    fn along_boundary(&self, q: &Point<3>, (u, v): (f64, f64)) -> (f64, f64) {
        let on = |x: f64, d: Interval, closed: bool| {
            let e = 1e-12 * (1.0 + d.start.abs().max(d.end.abs()));
            !closed && ((x - d.start).abs() <= e || (x - d.end).abs() <= e)
        };
        let (fixed_u, fixed_v) = (on(u, self.domain.0, self.closed.0), on(v, self.domain.1, self.closed.1));
        if fixed_u == fixed_v {
            return (u, v);
        }
        let mut x = if fixed_v { u } else { v };
        let range = if fixed_v { self.domain.0 } else { self.domain.1 };
        let mut o = [Point::<3>::zeros(); 9];
        for _ in 0..cap::POINT_PARAMETERS {
            let (a, b) = if fixed_v { (x, v) } else { (u, x) };
            self.eval_partials(a, b, 2, 2, &mut o);
            let (st, stt) = if fixed_v { (o[3], o[6]) } else { (o[1], o[2]) };
            let r = q - o[0];
            let curvature = st.dot(&st) - stt.dot(&r);
            let denominator = if curvature > 0.0 { curvature } else { st.dot(&st) };
            if denominator.partial_cmp(&0.0) != Some(std::cmp::Ordering::Greater) {
                break;
            }
            let next = range.clamp(x + st.dot(&r) / denominator);
            let settled = (next - x).abs() <= 4.0 * f64::EPSILON * (1.0 + x.abs());
            x = next;
            if settled {
                break;
            }
        }
        if fixed_v { (x, v) } else { (u, x) }
    }

    /// A start for Gauss–Newton without a hint: the kernel's nearest point on surfaces of
    /// finite domain, the best of the profile's samples on an extrusion (each at the height
    /// that brings it nearest to `q`).
    fn global_guess(&self, q: &Point<3>) -> Result<(f64, f64)> {
        if let Kind::Extrusion { profile, direction } = &self.kind {
            let d2 = direction.norm_squared();
            let domain = profile.natural_domain().unwrap_or(Interval::new(-1.0, 1.0));
            let mut best = (f64::INFINITY, (domain.start, 0.0));
            for k in 0..=GUESS_SAMPLES {
                let u = domain.start + domain.length() * k as f64 / GUESS_SAMPLES as f64;
                let c = profile.point(u);
                let v = (q - c).dot(direction) / d2;
                let distance = (c + direction * v - q).norm();
                if distance < best.0 {
                    best = (distance, (u, v));
                }
            }
            return Ok(best.1);
        }
        if !(self.domain.0.length().is_finite() && self.domain.1.length().is_finite()) {
            // A revolved line (a cone or cylinder written as a revolution): its height and
            // distance from the axis fix the profile's parameter.
            if let Kind::Revolution { profile: CurveEval::Line { origin, direction } } = &self.kind {
                let k = self.axes.z;
                let along = |p: Point<3>| (p - self.axes.origin).dot(&k);
                let (h0, dh) = (along(*origin), direction.dot(&k));
                let v = if dh.abs() > 1e-300 { (along(*q) - h0) / dh } else { 0.0 };
                let c = origin + direction * v - self.axes.origin;
                let w = q - self.axes.origin;
                let (cx, cy) = (c.dot(&self.axes.x), c.dot(&self.axes.y()));
                let (wx, wy) = (w.dot(&self.axes.x), w.dot(&self.axes.y()));
                return Ok(((wy.atan2(wx) - cy.atan2(cx)).rem_euclid(TAU), v));
            }
            return Err(StepError::plain("a point cannot be inverted on an unbounded swept surface"));
        }
        let near = SurfaceProjector::new(self)
            .nearest(q, 0.0)
            .map_err(|e| StepError::plain(format!("a point's parameters on the surface: {e}")))?;
        Ok((near.u, near.v))
    }
}

/// Samples of a profile searched for the start of an inversion on an extrusion.
const GUESS_SAMPLES: usize = 64;

impl Surface<3> for SurfaceEval {
    fn domain_u(&self) -> Interval {
        self.domain.0
    }
    fn domain_v(&self) -> Interval {
        self.domain.1
    }
    fn is_closed_u(&self) -> bool {
        self.closed.0
    }
    fn is_closed_v(&self) -> bool {
        self.closed.1
    }

    fn eval_partials(&self, u: f64, v: f64, du: usize, dv: usize, out: &mut [Point<3>]) {
        let a = &self.axes;
        let y = a.y();
        let e = |i: usize| {
            let (c, s) = trig(u, i);
            a.x * c + y * s
        };
        let zero = Point::<3>::zeros();
        if let Kind::Spline(s) = &self.kind {
            let (u, v) = (wrapped(u, self.domain.0, self.closed.0), wrapped(v, self.domain.1, self.closed.1));
            s.eval_partials(u, v, du, dv, out);
            return;
        }
        let mut profile = Vec::new();
        match &self.kind {
            Kind::Revolution { profile: c } => {
                profile.resize(dv + 1, zero);
                c.eval(v, &mut profile);
            }
            Kind::Extrusion { profile: c, .. } => {
                profile.resize(du + 1, zero);
                c.eval(u, &mut profile);
            }
            _ => {}
        }
        for i in 0..=du {
            for j in 0..=dv {
                let base = if i == 0 && j == 0 { a.origin } else { zero };
                out[i * (dv + 1) + j] = match &self.kind {
                    Kind::Plane => match (i, j) {
                        (0, 0) => a.origin + a.x * u + y * v,
                        (1, 0) => a.x,
                        (0, 1) => y,
                        _ => zero,
                    },
                    Kind::Cylinder { radius } => match (i, j) {
                        (_, 0) => base + e(i) * *radius + if i == 0 { a.z * v } else { zero },
                        (0, 1) => a.z,
                        _ => zero,
                    },
                    Kind::Cone { radius, slope } => match j {
                        0 => base + e(i) * (radius + v * slope) + if i == 0 { a.z * v } else { zero },
                        1 => e(i) * *slope + if i == 0 { a.z } else { zero },
                        _ => zero,
                    },
                    Kind::Sphere { radius } => {
                        let (cv, sv) = trig(v, j);
                        base + e(i) * (radius * cv) + if i == 0 { a.z * (radius * sv) } else { zero }
                    }
                    Kind::Torus { major, minor } => {
                        let (cv, sv) = trig(v, j);
                        let ring = if j == 0 { major + minor * cv } else { minor * cv };
                        base + e(i) * ring + if i == 0 { a.z * (minor * sv) } else { zero }
                    }
                    Kind::Revolution { .. } => {
                        let w = if j == 0 { profile[0] - a.origin } else { profile[j] };
                        let along = a.z * w.dot(&a.z);
                        let across = w - along;
                        let (c, s) = trig(u, i);
                        across * c + a.z.cross(&across) * s + if i == 0 { along + base } else { zero }
                    }
                    Kind::Extrusion { direction, .. } => match (i, j) {
                        (i, 0) => profile[i] + if i == 0 { direction * v } else { zero },
                        (0, 1) => *direction,
                        _ => zero,
                    },
                    Kind::Spline(_) => unreachable!("evaluated above"),
                };
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn axes() -> Axes {
        let z = Point::<3>::new(0.3, -0.4, 0.8).normalize();
        let x = (Point::<3>::new(1.0, 0.2, 0.0) - z * Point::<3>::new(1.0, 0.2, 0.0).dot(&z)).normalize();
        Axes { origin: Point::<3>::new(1.0, 2.0, -0.5), z, x }
    }

    fn surfaces() -> Vec<StepSurface> {
        let a = axes();
        let profile = Curve::Spline(crate::geometry::SplineCurve {
            degree: 2,
            knots: vec![0.0, 0.0, 0.0, 1.0, 1.0, 1.0],
            points: vec![vec![2.0, 0.0, -1.0], vec![3.0, 0.5, 0.0], vec![2.0, 0.0, 1.5]],
            weights: None,
            closed: false,
        });
        vec![
            StepSurface::Plane(a),
            StepSurface::Cylinder { axes: a, radius: 1.5 },
            StepSurface::Cone { axes: a, radius: 1.5, semi_angle: 0.4 },
            StepSurface::Sphere { axes: a, radius: 2.0 },
            StepSurface::Torus { axes: a, major_radius: 3.0, minor_radius: 1.0 },
            StepSurface::Revolution { profile: profile.clone(), axis_origin: a.origin, axis: a.z },
            StepSurface::Extrusion { profile, direction: Point::<3>::new(0.2, 0.1, 2.0) },
        ]
    }

    #[test]
    fn partials_match_finite_differences() {
        let h = 1e-5;
        for s in surfaces() {
            let e = SurfaceEval::new(&s).unwrap();
            let (u, v) = (0.7, 0.3);
            let mut o = [Point::<3>::zeros(); 9];
            e.eval_partials(u, v, 2, 2, &mut o);
            let p = |u: f64, v: f64| e.point(u, v);
            let su = (p(u + h, v) - p(u - h, v)) / (2.0 * h);
            let sv = (p(u, v + h) - p(u, v - h)) / (2.0 * h);
            let suv = (p(u + h, v + h) - p(u + h, v - h) - p(u - h, v + h) + p(u - h, v - h)) / (4.0 * h * h);
            let svv = (p(u, v + h) - 2.0 * p(u, v) + p(u, v - h)) / (h * h);
            for (name, exact, fd, tol) in
                [("u", o[3], su, 1e-8), ("v", o[1], sv, 1e-8), ("uv", o[4], suv, 1e-5), ("vv", o[2], svv, 1e-4)]
            {
                assert!((exact - fd).norm() < tol, "{s:?} {name}: {exact:?} vs {fd:?}");
            }
        }
    }

    #[test]
    fn points_invert_to_their_parameters() {
        for s in surfaces() {
            let e = SurfaceEval::new(&s).unwrap();
            for &(u, v) in &[(0.3, 0.2), (2.0, 0.7), (5.9, 0.1)] {
                // Angles, or as far into a profile's parameters as into a turn.
                let du = e.domain_u();
                let u = if du.length().is_finite() { du.start + du.length() * u / TAU } else { u };
                let q = e.point(u, v);
                let (a, b) = e.invert(&q, Some((u + 0.05, v - 0.05))).unwrap();
                assert!((e.point(a, b) - q).norm() < 1e-12, "{s:?} at ({u}, {v}): ({a}, {b})");
                assert!((a - u).abs() < 1e-9 && (b - v).abs() < 1e-9, "{s:?} at ({u}, {v}): ({a}, {b})");
            }
        }
    }
}
