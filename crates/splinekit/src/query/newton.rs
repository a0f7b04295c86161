//! One home for the Newton and Gauss–Newton iterations of the queries: the driver
//! ([`iterate`]), the stopping rules ([`settled`], [`scaled_small`]), the iteration caps
//! ([`cap`]) and the nearest-point polish on a curve ([`polish_on_curve`]) and on a surface
//! ([`polish_on_surface`]).
//!
//! Every solver supplies its own step (a Newton step, a Gauss–Newton step on the normal
//! equations, a minimum-norm step, a projected step with line search); the driver takes
//! steps until one settles, the step cannot be taken, or the cap is reached. The caps
//! differ per use: each is the count the query was tuned and tested with, and unifying them
//! would change which iterate a slowly converging search stops at (outputs are kept byte
//! for byte), so each is named here once.

use crate::Interval;
use crate::Point;
use crate::curve::Curve;
use crate::surface::Surface;

/// Iteration caps, one per use, named once.
pub mod cap {
    /// Curve–curve intersection: Gauss–Newton on c_a(s) = c_b(t).
    pub const CURVE_CURVE: usize = 60;
    /// Curve–surface intersection: Newton on c(t) = S(u, v), and the nearest-point polish
    /// that tests whether a piece of the curve lies in the surface.
    pub const CURVE_SURFACE: usize = 40;
    /// Surface–surface marching: one correction onto the intersection curve.
    pub const MARCH: usize = 20;
    /// Surface–surface seeds: the nearest-point polish that tests whether a patch lies in
    /// the other surface.
    pub const SEED_POLISH: usize = 20;
    /// Touching curves of two surfaces: one Gauss–Newton search or correction.
    pub const TOUCHING: usize = 30;
    /// Projection onto a surface: projected Newton for the minimum of the distance.
    pub const PROJECT_SURFACE: usize = 100;
    /// Projection onto a surface: halvings of one step until the distance decreases.
    pub const LINE_SEARCH: usize = 40;
    /// The nearest point of a curve to a point (the polish of curve overlaps).
    pub const CURVE_POLISH: usize = 30;
    /// The extent of a shape: one coordinate's extreme on a line (safeguarded Newton) or
    /// inside a surface.
    pub const EXTENT: usize = 60;
    /// The parameters of a point on (or within a file's tolerance of) a surface, from the
    /// parameters of a nearby point: Gauss–Newton (STEP reading's pcurves from 3-D edges).
    pub const POINT_PARAMETERS: usize = 40;
}

/// Relative step at which an iteration has reached rounding: 4ε.
pub const ROUNDING_STEP: f64 = 4.0 * f64::EPSILON;

/// The stopping rule of the parameter iterations: the move from `x` to `next` is at most
/// 4ε·max(|x|, len), len the length of the parameter's range — the step is at the level of
/// the rounding of x (or of the range, near 0).
pub fn settled(x: f64, next: f64, range: Interval) -> bool {
    (next - x).abs() <= ROUNDING_STEP * x.abs().max(range.length())
}

/// [`settled`] in every coordinate.
pub fn settled_all<const N: usize>(x: &[f64; N], next: &[f64; N], ranges: &[Interval; N]) -> bool {
    (0..N).all(|k| settled(x[k], next[k], ranges[k]))
}

/// A step of at most this fraction of the parameters' scale (1 + max|x|) is negligible:
/// a few units in the last place of the parameters.
pub const NEGLIGIBLE_STEP: f64 = 1e-14;

/// A Newton step of at most this fraction of the parameters' scale has converged once the
/// residual is within the tolerance: quadratic convergence leaves an error of the order of
/// the step's square.
pub const QUADRATIC_STEP: f64 = 1e-8;

/// The stopping rule of the iterations in several unknowns with steps of a known size:
/// `size ≤ factor·(1 + max|x|)`.
pub fn scaled_small<const N: usize>(size: f64, x: &[f64; N], factor: f64) -> bool {
    size <= factor * (1.0 + x.iter().fold(0.0f64, |m, v| m.max(v.abs())))
}

/// What one step of an iteration gives.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Step<const N: usize> {
    /// Move to this iterate; `true` when the iteration has settled there.
    To([f64; N], bool),
    /// Stop at the current iterate (the step cannot be taken: a singular system, no
    /// descent).
    Stop,
    /// Abandon the iteration (it left its region, or a step was not finite).
    Fail,
}

/// The driver: from `x`, takes the steps `step` gives until one settles, one cannot be
/// taken ([`Step::Stop`]) or `cap` steps were taken; the last iterate, or `None` when a
/// step abandoned the iteration ([`Step::Fail`]).
pub fn iterate<const N: usize>(
    cap: usize,
    mut x: [f64; N],
    mut step: impl FnMut(&[f64; N]) -> Step<N>,
) -> Option<[f64; N]> {
    for _ in 0..cap {
        match step(&x) {
            Step::To(next, done) => {
                x = next;
                if done {
                    break;
                }
            }
            Step::Stop => break,
            Step::Fail => return None,
        }
    }
    Some(x)
}

/// The parameter in `range` of the point of `curve` nearest to `p`, and the distance:
/// the best of nine samples, then Newton steps on g(t) = (c − p)·c′ with
/// g′ = |c′|² + (c − p)·c″, clamped to the range, until [`settled`] (at most
/// [`cap::CURVE_POLISH`] steps; a step stops where g′ ≤ 0).
pub fn polish_on_curve<const D: usize, C: Curve<D> + ?Sized>(curve: &C, range: Interval, p: &Point<D>) -> (f64, f64) {
    let t0 = (0..=8)
        .map(|k| {
            let t = range.lerp(k as f64 / 8.0);
            (t, (curve.point(t) - p).norm())
        })
        .min_by(|x, y| x.1.total_cmp(&y.1))
        .unwrap()
        .0;
    let mut o = [Point::<D>::zeros(); 3];
    let [t] = iterate(cap::CURVE_POLISH, [t0], |&[t]| {
        curve.eval(t, &mut o);
        let r = o[0] - p;
        let h = o[1].norm_squared() + r.dot(&o[2]);
        if h.is_nan() || h <= 0.0 {
            return Step::Stop;
        }
        let next = range.clamp(t - r.dot(&o[1]) / h);
        Step::To([next], settled(t, next, range))
    })
    .expect("the polish never abandons");
    (t, (curve.point(t) - p).norm())
}

/// When a [`polish_on_surface`] step settles.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Settle {
    /// [`settled`] in u and v.
    Rounding,
    /// |Δu| ≤ factor·(1 + |u|) and likewise in v.
    Relative(f64),
}

/// Gauss–Newton for the point of `surface` over `iu` × `iv` nearest to `p`, from `(u, v)`:
/// the step solves the normal equations [S_u·S_u S_u·S_v; S_u·S_v S_v·S_v] Δ = [S_u·r; S_v·r]
/// with r = p − S, clamped to the box, until it settles by `settle` or `cap` steps were
/// taken. The last iterate, and whether the iteration stopped at a singular system
/// (S_u × S_v = 0, or not finite).
pub fn polish_on_surface<S: Surface<3> + ?Sized>(
    surface: &S,
    p: &Point<3>,
    (u, v): (f64, f64),
    (iu, iv): (Interval, Interval),
    cap: usize,
    settle: Settle,
) -> ((f64, f64), bool) {
    let mut o = [Point::<3>::zeros(); 4];
    let mut singular = false;
    let [u, v] = iterate(cap, [u, v], |&[u, v]| {
        surface.eval_partials(u, v, 1, 1, &mut o);
        let (r, su, sv) = (p - o[0], o[2], o[1]);
        let (a, b, c) = (su.dot(&su), su.dot(&sv), sv.dot(&sv));
        let det = a * c - b * b;
        if !(det.is_finite() && det > 0.0) {
            singular = true;
            return Step::Stop;
        }
        let (gu, gv) = (su.dot(&r), sv.dot(&r));
        let next = [iu.clamp(u + (c * gu - b * gv) / det), iv.clamp(v + (a * gv - b * gu) / det)];
        let done = match settle {
            Settle::Rounding => settled_all(&[u, v], &next, &[iu, iv]),
            Settle::Relative(f) => {
                (next[0] - u).abs() <= f * (1.0 + u.abs()) && (next[1] - v).abs() <= f * (1.0 + v.abs())
            }
        };
        Step::To(next, done)
    })
    .expect("the polish never abandons");
    ((u, v), singular)
}
