//! Intersection curves of two surfaces in 3-D by seeded marching.
//!
//! Seeds: [`pair_seeds`] subdivides pairs of patches of the two surfaces' covers until
//! their normals cannot be parallel (no closed loop fits inside such a pair) and puts a
//! seed by Newton's method on the curve in each such pair whose boxes meet. From each
//! seed not already on a traced branch, the curve is followed by [`Marcher::step`]
//! (predictor along N_a × N_b, Newton correction onto both surfaces, step control by the
//! chord error) in both directions until it leaves through a domain boundary or closes:
//! a branch is closed when, after at least three steps and farther than four closing
//! distances from its seed, a step passes within the closing distance (4·chord +
//! 10·tolerance) of it. Closed loops are found however small unless they lie inside
//! boxes below [`crate::query::surface_seeds::TOUCH_SIZE`] of the shapes' size (see
//! [`crate::query::surface_seeds`]).
//! Curves along which the surfaces touch (parallel normals all along) are found while
//! seeding and traced by the same marching on the touching system of
//! [`crate::query::touching`]; they come first, flagged [`IntersectionBranch::tangent`].
//! A crossing branch that runs into a touching point stops there and says so.
//!
//! Limits: [`MAX_POINTS`] points per branch, [`MAX_BRANCHES`] branches and
//! [`crate::query::surface_seeds::MAX_SEED_PAIRS`] pairs of patches while seeding; surfaces
//! that coincide over a region are an error; a branch that stops for a limit, a step that
//! cannot be accepted or parallel normals carries an [`EarlyStop`].

use crate::Point;
use crate::error::{Error, Result};
pub use crate::query::branch::{EarlyStop, IntersectionBranch};
use crate::query::branch::{near_polyline, segment_distance};
use crate::query::march::{Contact, StepEnd};
use crate::query::surface_cover::SurfaceCover;
use crate::query::surface_pair::{MarchPoint, Marcher};
use crate::query::surface_seeds::pair_seeds;
use crate::surface::Surface;

/// The most points on one branch.
pub const MAX_POINTS: usize = 200_000;

/// The most branches one intersection reports.
pub const MAX_BRANCHES: usize = 1000;

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
    let (cover_a, cover_b) = (SurfaceCover::new(a), SurfaceCover::new(b));
    let (h0, reach) = (size / 128.0, 4.0 * chord + 10.0 * tolerance);
    let tracer = |contact| Tracer { m: &marcher, h0, reach, contact };
    let seeds = pair_seeds(&marcher, &cover_a, &cover_b, |seed| tracer(Contact::Touching).trace(seed))?;
    let mut branches = seeds.touching;
    for seed in seeds.crossing {
        if branches.iter().any(|br| near_polyline(&br.points, &seed.point, reach)) {
            continue;
        }
        if branches.len() >= MAX_BRANCHES {
            break;
        }
        branches.push(tracer(Contact::Crossing).trace(seed));
    }
    if branches.len() >= MAX_BRANCHES {
        return Err(Error::numerical("surface intersection", format!("more than {MAX_BRANCHES} branches")));
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

/// The tracing of the branches of one contact: the marcher, its first step `h0`, the
/// closing distance `reach` (> 0) and the contact followed.
struct Tracer<'m, 's, A: ?Sized, B: ?Sized> {
    m: &'m Marcher<'s, A, B>,
    h0: f64,
    reach: f64,
    contact: Contact,
}

impl<A: Surface<3> + ?Sized, B: Surface<3> + ?Sized> Tracer<'_, '_, A, B> {
    /// The branch through `seed`: forward, and backward unless it closed.
    fn trace(&self, seed: MarchPoint) -> IntersectionBranch {
        let (reach, tangent) = (self.reach, self.contact == Contact::Touching);
        let (forward, closed, stop_f) = self.march(seed, true);
        let mut pts = if closed {
            forward
        } else {
            let back_seed = MarchPoint { tangent: -seed.tangent, ..seed };
            let (mut backward, _, stop_b) = self.march(back_seed, false);
            backward.reverse();
            backward.pop();
            backward.extend(forward);
            // Both ends on a seam stored as a boundary (a NURBS circle's): one closed loop.
            let (first, last) = (backward[0].point, backward[backward.len() - 1].point);
            let stop = stop_f.or(stop_b);
            let seam = stop.is_none() && backward.len() > 2 && (first - last).norm() <= reach;
            return branch(backward, seam, stop, tangent);
        };
        if closed {
            pts.push(seed);
        }
        branch(pts, closed, stop_f, tangent)
    }

    /// Marches from `seed` along its tangent; with `close`, closes the loop when a step
    /// passes within `reach` of the seed after the march has been farther than 4·`reach`
    /// from it. The points (seed first), whether it closed, and why it stopped early.
    fn march(&self, seed: MarchPoint, close: bool) -> (Vec<MarchPoint>, bool, Option<EarlyStop>) {
        let reach = self.reach;
        let mut pts = vec![seed];
        let (mut h, mut far) = (self.h0, 0.0f64);
        while pts.len() < MAX_POINTS {
            let last = pts[pts.len() - 1];
            let (next, stop) = match self.m.step(&last, h, self.contact) {
                StepEnd::Inside(p, grow) => {
                    h = grow;
                    (p, false)
                }
                StepEnd::Boundary(p) => (p, true),
                StepEnd::Tangential => return (pts, false, Some(EarlyStop::Tangential)),
                StepEnd::StepLimit => return (pts, false, Some(EarlyStop::StepLimit)),
            };
            far = far.max((next.point - seed.point).norm());
            let closes = close
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
}

fn branch(pts: Vec<MarchPoint>, closed: bool, early_stop: Option<EarlyStop>, tangent: bool) -> IntersectionBranch {
    IntersectionBranch {
        points: pts.iter().map(|p| p.point).collect(),
        params_a: pts.iter().map(|p| [p.x[0], p.x[1]]).collect(),
        params_b: pts.iter().map(|p| [p.x[2], p.x[3]]).collect(),
        closed,
        early_stop,
        tangent,
    }
}
