//! Intersection curves of two surfaces in 3-D by seeded marching.
//!
//! Seeds: the intersections ([`intersect_with_cover`]) of [`SEED_LINES`] isocurves in
//! each direction of each surface (its boundary included) with the other surface. From
//! each seed not already on a traced branch, the curve is followed by [`Marcher::step`]
//! (predictor along N_a × N_b, Newton correction onto both surfaces, step control by the
//! chord error) in both directions until it leaves through a domain boundary or closes:
//! a branch is closed when, after at least three steps and farther than four closing
//! distances from its seed, a step passes within the closing distance (4·chord +
//! 10·tolerance) of it. Every branch that crosses one
//! of the seed isocurves is found; a closed loop lying entirely inside one cell of both
//! isocurve grids is not. Touching surfaces (parallel normals along the curve) are not
//! traced: marching stops there and says so.
//!
//! Limits: [`MAX_POINTS`] points per branch and [`MAX_BRANCHES`] branches; a branch that
//! stops for a limit, a step that cannot be accepted or parallel normals carries an
//! [`EarlyStop`].

use crate::Point;
use crate::curve::Interval;
use crate::error::{Error, Result};
use crate::query::curve_surface::intersect_with_cover;
use crate::query::surface_cover::SurfaceCover;
use crate::query::march::{MarchPoint, Marcher, StepEnd};
use crate::surface::Surface;
use crate::surface::iso_curve::{Direction, IsoCurve};

/// Isocurves per direction and surface that seed the marching.
pub const SEED_LINES: usize = 8;

/// The most pairs of pieces the seeding of one isocurve examines: an isocurve that lies in
/// the other surface gives up there (the isocurves across it seed that branch).
pub const SEED_PAIRS: usize = 5_000;

/// The most points on one branch.
pub const MAX_POINTS: usize = 200_000;

/// The most branches one intersection reports.
pub const MAX_BRANCHES: usize = 1000;

/// Why a branch stopped before it closed or left through a boundary.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum EarlyStop {
    /// The surfaces' normals became parallel (they touch).
    Tangential,
    /// No step down to the halving limit met the chord error.
    StepLimit,
    /// The branch reached [`MAX_POINTS`] points.
    PointLimit,
}

/// One branch of the intersection curve: a polyline in 3-D and in both parameter planes.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct IntersectionBranch {
    /// Points on both surfaces (within the tolerance), the chord error from the curve.
    pub points: Vec<Point<3>>,
    /// (u, v) on the first surface at each point.
    pub params_a: Vec<[f64; 2]>,
    /// (u, v) on the second surface at each point.
    pub params_b: Vec<[f64; 2]>,
    /// Whether the branch is a closed loop (its last point repeats the first).
    pub closed: bool,
    /// Why marching stopped early, in either direction, if it did.
    pub early_stop: Option<EarlyStop>,
}

/// Every branch of the intersection curve of `a` and `b` (see the module documentation):
/// points agree on both surfaces within `tolerance` (> 0), and the polylines are within
/// `chord` (> 0) of the curve.
pub fn intersect_surfaces<A, B>(a: &A, b: &B, tolerance: f64, chord: f64) -> Result<Vec<IntersectionBranch>>
where
    A: Surface<3> + ?Sized,
    B: Surface<3> + ?Sized,
{
    for (name, v) in [("tolerance", tolerance), ("chord", chord)] {
        if !(v > 0.0 && v.is_finite()) {
            return Err(Error::invalid(name, format!("must be finite and > 0, got {v}")));
        }
    }
    let size = extent(a).max(extent(b));
    let marcher = Marcher { a, b, tolerance, chord, max_step: size / 16.0 };
    let mut branches: Vec<IntersectionBranch> = Vec::new();
    for seed in seeds(&marcher)? {
        let reach = 4.0 * chord + 10.0 * tolerance;
        if branches.iter().any(|br| near_polyline(&br.points, &seed.point, reach)) {
            continue;
        }
        if branches.len() >= MAX_BRANCHES {
            return Err(Error::numerical("surface intersection", format!("more than {MAX_BRANCHES} branches")));
        }
        branches.push(trace(&marcher, seed, size / 128.0, reach));
    }
    Ok(branches)
}

/// The diagonal of the box of a 9 × 9 grid of the surface's points.
fn extent<S: Surface<3> + ?Sized>(s: &S) -> f64 {
    let (du, dv) = (s.domain_u(), s.domain_v());
    let pts: Vec<Point<3>> =
        (0..81).map(|k| s.point(du.lerp((k / 9) as f64 / 8.0), dv.lerp((k % 9) as f64 / 8.0))).collect();
    crate::query::bounds::Aabb::around(&pts, 0.0).diagonal()
}

/// The parameters of the seed isocurves across `domain`: [`SEED_LINES`] evenly spaced, ends
/// included (a closed direction's seam once).
fn lines(domain: Interval, closed: bool) -> Vec<f64> {
    let n = SEED_LINES;
    let denom = if closed { n } else { n - 1 } as f64;
    (0..n).map(|k| domain.lerp(k as f64 / denom)).collect()
}

/// Seeds from the isocurves of each surface against the other, u- and v-lines in turn.
/// Isocurves of both directions of one surface that lie in the other (their search gives
/// up) mean the surfaces coincide over a region: an error.
fn seeds<A: Surface<3> + ?Sized, B: Surface<3> + ?Sized>(m: &Marcher<'_, A, B>) -> Result<Vec<MarchPoint>> {
    let mut out = Vec::new();
    let zero = Point::<3>::zeros();
    let (cover_a, cover_b) = (SurfaceCover::new(m.a), SurfaceCover::new(m.b));
    for first in [true, false] {
        let (du, dv) = if first { (m.a.domain_u(), m.a.domain_v()) } else { (m.b.domain_u(), m.b.domain_v()) };
        let (cu, cv) =
            if first { (m.a.is_closed_u(), m.a.is_closed_v()) } else { (m.b.is_closed_u(), m.b.is_closed_v()) };
        let (lu, lv) = (lines(du, cu), lines(dv, cv));
        let mut lost = [false; 2];
        for (k, dir) in (0..SEED_LINES).flat_map(|k| [(k, Direction::U), (k, Direction::V)]) {
            let value = if dir == Direction::U { lu[k] } else { lv[k] };
            let hits = if first {
                intersect_with_cover(&IsoCurve::new(m.a, dir, value), m.b, &cover_b, m.tolerance, SEED_PAIRS)
            } else {
                intersect_with_cover(&IsoCurve::new(m.b, dir, value), m.a, &cover_a, m.tolerance, SEED_PAIRS)
            };
            let Ok(hits) = hits else {
                lost[(dir == Direction::V) as usize] = true;
                if lost[0] && lost[1] {
                    return Err(Error::numerical(
                        "surface intersection",
                        "the surfaces coincide over a region (isocurves of both directions of one lie in the other)",
                    ));
                }
                continue;
            };
            for h in hits {
                let on = if dir == Direction::U { [value, h.t] } else { [h.t, value] };
                let x = if first { [on[0], on[1], h.u, h.v] } else { [h.u, h.v, on[0], on[1]] };
                out.extend(m.point(x, &zero));
            }
        }
    }
    Ok(out)
}

/// Whether `q` lies within `reach` of a segment of the polyline.
fn near_polyline(points: &[Point<3>], q: &Point<3>, reach: f64) -> bool {
    if points.len() == 1 {
        return (points[0] - q).norm() <= reach;
    }
    points.windows(2).any(|w| segment_distance(&w[0], &w[1], q) <= reach)
}

fn segment_distance(p: &Point<3>, r: &Point<3>, q: &Point<3>) -> f64 {
    let d = r - p;
    let s = if d.norm_squared() > 0.0 { ((q - p).dot(&d) / d.norm_squared()).clamp(0.0, 1.0) } else { 0.0 };
    (p + d * s - q).norm()
}

/// The branch through `seed`: forward, and backward unless it closed.
fn trace<A: Surface<3> + ?Sized, B: Surface<3> + ?Sized>(
    m: &Marcher<'_, A, B>,
    seed: MarchPoint,
    h0: f64,
    reach: f64,
) -> IntersectionBranch {
    let (forward, closed, stop_f) = march(m, seed, h0, reach);
    let mut pts = if closed {
        forward
    } else {
        let back_seed = MarchPoint { tangent: -seed.tangent, ..seed };
        let (mut backward, _, stop_b) = march(m, back_seed, h0, 0.0);
        backward.reverse();
        backward.pop();
        backward.extend(forward);
        // Both ends on a seam stored as a boundary (a NURBS circle's): one closed loop.
        let (first, last) = (backward[0].point, backward[backward.len() - 1].point);
        let stop = stop_f.or(stop_b);
        let seam = stop.is_none() && backward.len() > 2 && (first - last).norm() <= reach;
        return branch(backward, seam, stop);
    };
    if closed {
        pts.push(seed);
    }
    branch(pts, closed, stop_f)
}

fn branch(pts: Vec<MarchPoint>, closed: bool, early_stop: Option<EarlyStop>) -> IntersectionBranch {
    IntersectionBranch {
        points: pts.iter().map(|p| p.point).collect(),
        params_a: pts.iter().map(|p| [p.x[0], p.x[1]]).collect(),
        params_b: pts.iter().map(|p| [p.x[2], p.x[3]]).collect(),
        closed,
        early_stop,
    }
}

/// Marches from `seed` along its tangent; closes the loop when `reach` > 0 and a step
/// passes within it of the seed after the march has been farther than 4·`reach` from it. The points (seed first), whether it closed, and why it
/// stopped early.
fn march<A: Surface<3> + ?Sized, B: Surface<3> + ?Sized>(
    m: &Marcher<'_, A, B>,
    seed: MarchPoint,
    h0: f64,
    reach: f64,
) -> (Vec<MarchPoint>, bool, Option<EarlyStop>) {
    let mut pts = vec![seed];
    let (mut h, mut far) = (h0, 0.0f64);
    while pts.len() < MAX_POINTS {
        let last = pts[pts.len() - 1];
        let (next, stop) = match m.step(&last, h) {
            StepEnd::Inside(p, grow) => {
                h = grow;
                (p, false)
            }
            StepEnd::Boundary(p) => (p, true),
            StepEnd::Tangential => return (pts, false, Some(EarlyStop::Tangential)),
            StepEnd::StepLimit => return (pts, false, Some(EarlyStop::StepLimit)),
        };
        far = far.max((next.point - seed.point).norm());
        let closes = reach > 0.0
            && pts.len() >= 4
            && far > 4.0 * reach
            && segment_distance(&last.point, &next.point, &seed.point) <= reach;
        if closes {
            return (pts, true, None);
        }
        pts.push(next);
        if stop {
            return (pts, false, None);
        }
    }
    (pts, false, Some(EarlyStop::PointLimit))
}
