//! Pcurves computed from 3-D edges. ISO 10303-42 lets an `EDGE_CURVE` carry its 3-D curve
//! alone (a `LINE`, `CIRCLE`, `ELLIPSE` or B-spline, no `SURFACE_CURVE` with `PCURVE`s),
//! and most CAD systems write their faces so; a face is bounded in its surface's (u, v)
//! though. Given the 3-D curve C(t) of an edge over [t₀, t₁] and the face's surface S, this
//! module finds a 2-D curve P with S(P(t)) = C(t) in the same parameter t, as a pcurve in
//! the file would be:
//!
//! * **Exact, on a plane:** the plane's inverse is affine, q ↦ ((q − o)·x, (q − o)·y), and
//!   maps a line to a line, a circle or an ellipse to one of the same parameter (its plane
//!   is the plane's, its sense ± that of the plane's normal), and a B-spline or NURBS curve
//!   to the one of the mapped control points and the same weights and knots.
//! * **Exact, a line in (u, v):** on every other surface the edges that CAD systems make
//!   most are iso-parameter lines run at constant speed: a circle about a cylinder's,
//!   cone's, sphere's, torus' or revolution's axis (v fixed, u = u₀ ± t), a line along a
//!   cylinder or through a cone's apex, a meridian of a sphere or a torus (u fixed, v = v₀ ±
//!   t), a line along an extrusion, the profile of an extrusion itself (u = t). The
//!   candidate P(t) = A + B t through the parameters of C at two parameters of the edge is
//!   accepted when S(P(t)) lies within the tolerance of C(t) at [`CHECKS`] parameters.
//! * **Fitted, elsewhere:** piecewise cubic Hermite interpolation of (u, v)(t) and its
//!   derivative (u′, v′) = (JᵀJ)⁻¹Jᵀ C′(t), J = [S_u S_v], at breaks bisected until the 3-D
//!   deviation |S(P(t)) − C(t)|, measured at [`SAMPLES_PER_PIECE`] parameters of each piece,
//!   is within the tolerance (at most [`MAX_PIECES`] pieces). Interpolation error falls as
//!   h⁴ with the piece length h.
//!
//! Parameters are followed continuously along the edge: each point is inverted from the
//! parameters of the one before it, periodic parameters (angles, closed splines) are moved
//! by whole periods to stay continuous, and on an axis, where u is undefined (a sphere's
//! pole, a cone's apex), u is its neighbour's. An edge on a periodic surface's seam (u ≡ 0
//! modulo the period all along) gets its twin on the other side of the domain, as a
//! `SEAM_CURVE` carries: a loop that uses the seam twice runs once along each.

use splinekit::Point;
use splinekit::surface::Surface as _;

use crate::error::{Result, StepError};
use crate::evaluate::{CurveEval, SurfaceEval};
use crate::geometry::{Axes, Curve, SplineCurve, Surface};

/// Parameters at which an exact candidate is checked against the edge.
pub const CHECKS: usize = 9;
/// Parameters of each fitted piece at which the deviation is measured.
pub const SAMPLES_PER_PIECE: usize = 4;
/// Most pieces of a fitted pcurve.
pub const MAX_PIECES: usize = 1024;
/// Shortest piece of a fitted pcurve, relative to the edge's parameter range: a piece that
/// still deviates at this length has parameters that jump, which no curve follows.
pub const SHORTEST_PIECE: f64 = 1e-9;
/// Pieces a fit starts from.
const FIRST_PIECES: usize = 4;

/// A pcurve computed for an edge, and its twin on a periodic surface's seam.
#[derive(Debug, Clone, PartialEq)]
pub struct Pcurve {
    /// The curve in (u, v), over the edge's parameter.
    pub curve: Curve,
    /// For an edge on the seam of a periodic surface, the same curve one period over.
    pub twin: Option<Curve>,
}

/// The pcurve on `surface` of the edge curve `space` over `range` (its parameters at the
/// edge's two ends, in increasing order), within `tolerance` in 3-D.
pub fn pcurve(space: &Curve, surface: &Surface, range: (f64, f64), tolerance: f64) -> Result<Pcurve> {
    let s = SurfaceEval::new(surface)?;
    let c = CurveEval::new(space)?;
    let curve = match (surface, space) {
        (Surface::Plane(axes), _) => on_plane(axes, space)?,
        (Surface::Trimmed { basis, .. }, _) if matches!(basis.as_ref(), Surface::Plane(_)) => {
            let Surface::Plane(axes) = basis.as_ref() else { unreachable!("matched") };
            on_plane(axes, space)?
        }
        _ => match straight(&s, &c, range, tolerance)? {
            Some(line) => line,
            None => fitted(&s, &c, range, tolerance)?,
        },
    };
    let twin = seam_twin(&s, &curve, range);
    Ok(Pcurve { curve, twin })
}

/// q ↦ ((q − o)·x, (q − o)·y, 0) of a plane's placement.
fn plane_coordinates(axes: &Axes, q: Point<3>) -> Point<3> {
    let w = q - axes.origin;
    Point::<3>::new(w.dot(&axes.x), w.dot(&axes.y()), 0.0)
}

/// The exact pcurve of a curve in a plane (see the module).
fn on_plane(axes: &Axes, space: &Curve) -> Result<Curve> {
    let to_vec = |p: Point<3>| vec![p[0], p[1]];
    let point3 = |v: &[f64]| Point::<3>::from_fn(|k, _| v.get(k).copied().unwrap_or(0.0));
    Ok(match space {
        Curve::Line { origin, direction } => {
            let d = point3(direction);
            Curve::Line {
                origin: to_vec(plane_coordinates(axes, point3(origin))),
                direction: vec![d.dot(&axes.x), d.dot(&axes.y())],
            }
        }
        Curve::Circle { axes: a, .. } | Curve::Ellipse { axes: a, .. } => {
            let x = Point::<3>::new(a.x.dot(&axes.x), a.x.dot(&axes.y()), 0.0);
            let placed = Axes {
                origin: plane_coordinates(axes, a.origin),
                z: Point::<3>::new(0.0, 0.0, a.z.dot(&axes.z).signum()),
                x: x.try_normalize(0.0).ok_or_else(|| StepError::plain("a conic edge across its face's plane"))?,
            };
            match space {
                Curve::Circle { radius, .. } => Curve::Circle { axes: placed, radius: *radius },
                Curve::Ellipse { a, b, .. } => Curve::Ellipse { axes: placed, a: *a, b: *b },
                _ => unreachable!("matched"),
            }
        }
        Curve::Spline(s) => Curve::Spline(SplineCurve {
            points: s.points.iter().map(|p| to_vec(plane_coordinates(axes, point3(p)))).collect(),
            ..s.clone()
        }),
        Curve::Trimmed { basis, .. } => on_plane(axes, basis)?,
    })
}

/// The parameters of C(t) from the parameters `hint` of a nearby point.
fn parameters(s: &SurfaceEval, c: &CurveEval, t: f64, hint: Option<(f64, f64)>) -> Result<Point<2>> {
    let (u, v) = s.invert(&c.point(t), hint)?;
    Ok(Point::<2>::new(u, v))
}

/// The parameters of C at each of `ts`, followed continuously from the first (see the
/// module): the first is inverted without a hint, unless u is undefined there (on an
/// axis), in which case the walk starts from the second and comes back.
fn walk(s: &SurfaceEval, c: &CurveEval, ts: &[f64], start: Option<(f64, f64)>) -> Result<Vec<Point<2>>> {
    let mut out = Vec::with_capacity(ts.len());
    let mut hint = start;
    for &t in ts {
        let p = parameters(s, c, t, hint)?;
        hint = Some((p[0], p[1]));
        out.push(p);
    }
    Ok(out)
}

/// P(t) = A + B t through the parameters of C at two parameters of the edge, if S(P(t))
/// follows C(t) within `tolerance` at [`CHECKS`] parameters (see the module).
fn straight(s: &SurfaceEval, c: &CurveEval, (t0, t1): (f64, f64), tolerance: f64) -> Result<Option<Curve>> {
    if t1.partial_cmp(&t0) != Some(std::cmp::Ordering::Greater) {
        return Err(StepError::plain(format!("an edge over the empty parameter range [{t0}, {t1}]")));
    }
    let at = |k: usize| t0 + (t1 - t0) * k as f64 / (CHECKS - 1) as f64;
    let ts: Vec<f64> = (0..CHECKS).map(at).collect();
    let mid = CHECKS / 2;
    // Walk out from the middle both ways, so that an end on an axis takes its
    // neighbour's u.
    let centre = parameters(s, c, ts[mid], None)?;
    let forward = walk(s, c, &ts[mid..], Some((centre[0], centre[1])))?;
    let mut backward = walk(s, c, &ts[..=mid].iter().rev().copied().collect::<Vec<_>>(), Some((centre[0], centre[1])))?;
    backward.reverse();
    let uv: Vec<Point<2>> = backward.into_iter().chain(forward.into_iter().skip(1)).collect();
    let (a, b) = (mid / 2, mid + mid / 2);
    let slope = (uv[b] - uv[a]) / (ts[b] - ts[a]);
    let origin = uv[a] - slope * ts[a];
    for (&t, f) in ts.iter().zip(&uv) {
        let p = origin + slope * t;
        let d = deviation(s, p, *f, &c.point(t));
        if d.is_nan() || d > tolerance {
            return Ok(None);
        }
    }
    Ok(Some(Curve::Line { origin: vec![origin[0], origin[1]], direction: vec![slope[0], slope[1]] }))
}

/// How much farther the pcurve's point S(p) is from the edge's point `q` than the foot of
/// `q` on the surface, S(f), is: the edge itself may lie off the surface by the file's
/// gap, which no pcurve can close, so a pcurve is judged by what it adds to that gap. Near
/// the foot the distance is flat (second order in the parameters), so feet found only to
/// within rounding or along a boundary's kinks judge alike.
fn deviation(s: &SurfaceEval, p: Point<2>, f: Point<2>, q: &Point<3>) -> f64 {
    (s.point(p[0], p[1]) - q).norm() - (s.point(f[0], f[1]) - q).norm()
}

/// (u′, v′) = (JᵀJ)⁻¹Jᵀ C′(t) at the parameters `p` of C(t); `None` where J is singular.
fn parameter_speed(s: &SurfaceEval, c: &CurveEval, t: f64, p: Point<2>) -> Option<Point<2>> {
    let mut d = [Point::<3>::zeros(); 2];
    c.eval(t, &mut d);
    let mut o = [Point::<3>::zeros(); 4];
    s.eval_partials(p[0], p[1], 1, 1, &mut o);
    let (su, sv) = (o[2], o[1]);
    let (a, b, e) = (su.dot(&su), su.dot(&sv), sv.dot(&sv));
    let det = a * e - b * b;
    if det.is_nan() || det <= 1e-24 * (a * e).max(f64::MIN_POSITIVE) {
        return None;
    }
    let (gu, gv) = (su.dot(&d[1]), sv.dot(&d[1]));
    Some(Point::<2>::new((e * gu - b * gv) / det, (a * gv - b * gu) / det))
}

/// One break of a fitted pcurve: t, (u, v) and (u′, v′).
#[derive(Debug, Clone, Copy)]
struct Break {
    t: f64,
    p: Point<2>,
    d: Point<2>,
}

/// The cubic Bézier points of the Hermite piece between two breaks.
fn hermite(a: &Break, b: &Break) -> [Point<2>; 4] {
    let h = (b.t - a.t) / 3.0;
    [a.p, a.p + a.d * h, b.p - b.d * h, b.p]
}

/// The cubic at s ∈ [0, 1] of its Bézier points.
fn bezier(q: &[Point<2>; 4], s: f64) -> Point<2> {
    let r = 1.0 - s;
    q[0] * (r * r * r) + q[1] * (3.0 * r * r * s) + q[2] * (3.0 * r * s * s) + q[3] * (s * s * s)
}

/// Breaks at `ts` with their parameters `uv`. The derivative is the Jacobian's, (JᵀJ)⁻¹Jᵀ
/// C′, where the edge lies on the surface within `tolerance` and inside its domain; where
/// it does not (an edge off the surface by the file's gap, or along a boundary, where the
/// foot of the edge's point stops while C′ points on), the derivative of the feet is
/// taken instead, by central differences of feet a thousandth of the neighbouring piece
/// apart; on an axis, where J is singular, the difference of the neighbouring parameters.
fn breaks(s: &SurfaceEval, c: &CurveEval, ts: &[f64], uv: &[Point<2>], tolerance: f64) -> Result<Vec<Break>> {
    let n = ts.len();
    let mut out = Vec::with_capacity(n);
    for k in 0..n {
        let (i, j) = (k.saturating_sub(1), (k + 1).min(n - 1));
        let chord = (uv[j] - uv[i]) / (ts[j] - ts[i]);
        let on_surface = (s.point(uv[k][0], uv[k][1]) - c.point(ts[k])).norm() <= 0.1 * tolerance;
        let d = match parameter_speed(s, c, ts[k], uv[k]) {
            Some(d) if on_surface && !s.on_boundary(uv[k]) => d,
            Some(_) => {
                let h = 1e-3 * (ts[j] - ts[i]).abs().max(f64::MIN_POSITIVE);
                let hint = Some((uv[k][0], uv[k][1]));
                let (lo, hi) = ((ts[k] - h).max(ts[0]), (ts[k] + h).min(ts[n - 1]));
                let (a, b) = (parameters(s, c, lo, hint)?, parameters(s, c, hi, hint)?);
                let d = (b - a) / (hi - lo);
                if hi > lo && d.iter().all(|x| x.is_finite()) { d } else { chord }
            }
            None => chord,
        };
        out.push(Break { t: ts[k], p: uv[k], d });
    }
    Ok(out)
}

/// The fitted pcurve (see the module): a cubic B-spline with double interior knots.
fn fitted(s: &SurfaceEval, c: &CurveEval, (t0, t1): (f64, f64), tolerance: f64) -> Result<Curve> {
    let mut ts: Vec<f64> = (0..=FIRST_PIECES).map(|k| t0 + (t1 - t0) * k as f64 / FIRST_PIECES as f64).collect();
    if let CurveEval::Spline(sp) = c {
        use splinekit::curve::Curve as _;
        ts.extend(sp.breakpoints().into_iter().filter(|&k| k > t0 && k < t1));
        ts.sort_by(f64::total_cmp);
        ts.dedup_by(|a, b| (*a - *b).abs() <= 1e-12 * (t1 - t0));
    }
    let centre = parameters(s, c, ts[0], None)?;
    let mut uv = walk(s, c, &ts, Some((centre[0], centre[1])))?;
    loop {
        let bs = breaks(s, c, &ts, &uv, tolerance)?;
        let mut split = Vec::new();
        for (k, w) in bs.windows(2).enumerate() {
            let q = hermite(&w[0], &w[1]);
            let mut worst = 0.0_f64;
            for m in 1..=SAMPLES_PER_PIECE {
                let f = m as f64 / (SAMPLES_PER_PIECE + 1) as f64;
                let p = bezier(&q, f);
                let t = w[0].t + (w[1].t - w[0].t) * f;
                let foot = parameters(s, c, t, Some((p[0], p[1])))?;
                let d = deviation(s, p, foot, &c.point(t));
                if d > worst || d.is_nan() {
                    worst = d;
                }
            }
            if worst.is_nan() || worst > tolerance {
                split.push(k);
            }
        }
        if split.is_empty() {
            return Ok(Curve::Spline(assemble(&bs)));
        }
        let shortest = split.iter().map(|&k| ts[k + 1] - ts[k]).fold(f64::INFINITY, f64::min);
        if ts.len() - 1 + split.len() > MAX_PIECES || shortest <= SHORTEST_PIECE * (t1 - t0) {
            // The feet jump (the edge runs through a pole of the surface, where its
            // parameters turn discontinuously, or off a surface that folds back).
            return Err(StepError::plain(format!(
                "an edge's pcurve could not be fitted within {tolerance:e}: its parameters on the surface are not continuous"
            )));
        }
        // Bisect the pieces that deviate, each midpoint inverted from its piece's start.
        let mut new_ts = Vec::with_capacity(ts.len() + split.len());
        let mut new_uv = Vec::with_capacity(ts.len() + split.len());
        let mut next = split.iter().peekable();
        for k in 0..ts.len() {
            new_ts.push(ts[k]);
            new_uv.push(uv[k]);
            if next.peek() == Some(&&k) {
                next.next();
                let t = 0.5 * (ts[k] + ts[k + 1]);
                new_ts.push(t);
                new_uv.push(parameters(s, c, t, Some((uv[k][0], uv[k][1])))?);
            }
        }
        (ts, uv) = (new_ts, new_uv);
    }
}

/// The piecewise cubic Hermite curve of the breaks as a B-spline with double interior
/// knots (C¹): each piece's two inner Bézier points are control points, and a joint, which
/// a double knot makes the combination (h₊ P₋ + h₋ P₊)/(h₋ + h₊) of its neighbours P∓ =
/// J ∓ J′h∓/3, is the Hermite joint J itself.
fn assemble(bs: &[Break]) -> SplineCurve {
    let n = bs.len();
    let mut knots = vec![bs[0].t; 4];
    let mut points = vec![vec![bs[0].p[0], bs[0].p[1]]];
    for (k, w) in bs.windows(2).enumerate() {
        let q = hermite(&w[0], &w[1]);
        points.extend(q[1..3].iter().map(|p| vec![p[0], p[1]]));
        knots.extend(std::iter::repeat_n(w[1].t, if k + 2 == n { 4 } else { 2 }));
    }
    points.push(vec![bs[n - 1].p[0], bs[n - 1].p[1]]);
    SplineCurve { degree: 3, knots, points, weights: None, closed: false }
}

/// The curve moved by one period to the other side of the domain, when it runs along a
/// periodic parameter's seam (that parameter within rounding of a multiple of its period at
/// the edge's ends and middle).
fn seam_twin(s: &SurfaceEval, curve: &Curve, (t0, t1): (f64, f64)) -> Option<Curve> {
    let (pu, pv) = s.periods();
    let at = |t: f64| -> Option<Point<2>> {
        Some(match curve {
            Curve::Line { origin, direction } => {
                Point::<2>::new(origin[0] + t * direction[0], origin[1] + t * direction[1])
            }
            Curve::Spline(sp) => {
                use splinekit::curve::Curve as _;
                let k = crate::kernel::nurbs::<2>(sp).ok()?;
                k.point(t)
            }
            _ => return None,
        })
    };
    let points = [at(t0)?, at(0.5 * (t0 + t1))?, at(t1)?];
    for (axis, period) in [(0, pu), (1, pv)] {
        let Some(p) = period else { continue };
        let turns: Vec<f64> = points.iter().map(|q| q[axis] / p).collect();
        let on_seam = turns.iter().all(|k| (k - k.round()).abs() <= 1e-9);
        if !on_seam {
            continue;
        }
        // Towards the middle of the domain's period: from 0 up, from a period down.
        let shift = if turns[1].round() <= 0.0 { p } else { -p };
        let mut offset = [0.0, 0.0];
        offset[axis] = shift;
        return Some(match curve {
            Curve::Line { origin, direction } => {
                Curve::Line { origin: vec![origin[0] + offset[0], origin[1] + offset[1]], direction: direction.clone() }
            }
            Curve::Spline(sp) => Curve::Spline(SplineCurve {
                points: sp.points.iter().map(|q| vec![q[0] + offset[0], q[1] + offset[1]]).collect(),
                ..sp.clone()
            }),
            _ => return None,
        });
    }
    None
}
