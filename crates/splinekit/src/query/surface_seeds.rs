//! Seeds for marching along the intersection curve of two surfaces: subdivision of pairs
//! of patches of the two surfaces' covers until their normals cannot be parallel.
//!
//! A pair of patches is dropped when their boxes (grown by the tolerance) are apart. A pair
//! whose [`normal_cone`]s are apart — the angle between the cone axes, as lines, exceeds
//! the sum of the half-angles, so no normal of one patch is parallel to a normal of the
//! other — holds no closed loop of the intersection curve: a closed loop bounding a disc on
//! each patch has a point on each with parallel normals (Sederberg and Meyers, 1988; the
//! signed height of one surface over the other along the loop's disc has a critical point).
//! Such a pair, once both patches are also [`FLAT`] (normal half-angles at most that), is a
//! leaf: Newton's method with minimum-norm steps from the centres of the two patches
//! ([`Marcher::converge`], kept within the pair's parameter boxes grown by their width on
//! each side) puts a seed on the curve where it crosses the pair. Other pairs are split —
//! the patch with the wider normals (or larger box) into four — until both boxes are below
//! [`TOUCH_SIZE`] of the shapes' size or the patches narrower than [`MIN_WIDTH`] of the
//! domains, where a pair is a leaf whatever its cones (a tangential contact, or a loop
//! smaller than that).
//!
//! What this guarantees: every closed loop passes through at least two leaf pairs unless it
//! lies in a pair of boxes smaller than [`TOUCH_SIZE`] of the shapes' size (so loops
//! wider than that are never missed for being small), and every branch through an examined
//! pair's boxes is in a leaf. Each leaf's seed comes from one Newton iteration from its
//! centre, which on flat transversal patches converges to the curve's point nearest the
//! centre.
//!
//! Touching curves: along a curve where the surfaces touch the normals are parallel, so
//! the pairs along it would be split down to [`TOUCH_SIZE`] all along. Instead a pair whose
//! normals may be parallel, once both boxes are below [`COINCIDENCE_SIZE`] of the shapes'
//! size, is first checked for coinciding surfaces (an error), then, down to
//! [`TOUCH_SEARCH_SIZE`], searched for a point of a touching curve ([`touching::find`],
//! itself an error where the surfaces coincide); the
//! curve found is traced at once by the caller, and later pairs of that size whose centres
//! both lie within their larger box's diagonal of a traced touching curve are dropped. So a
//! crossing branch is seeded from pairs outside that band around a touching curve (loops
//! inside it are not found). More than [`MAX_SEED_PAIRS`] pairs is an error.

use crate::Point;
use crate::curve::Interval;
use crate::error::Result;
pub use crate::query::branch::coincidence;
use crate::query::branch::{IntersectionBranch, near_polyline};
use crate::query::newton::{self, NEGLIGIBLE_STEP, Settle, cap};
use crate::query::normal_cone::normal_cone;
use crate::query::pair_count::PairCount;
use crate::query::surface_cover::{SearchPatch, SurfaceCover, SurfacePatch};
use crate::query::surface_pair::{MarchPoint, Marcher};
use crate::query::tangent_cone::{TangentCone, angle};
use crate::query::touching;
use crate::surface::Surface;
use std::f64::consts::{FRAC_PI_2, PI};
use std::rc::Rc;

/// The largest normal half-angle (radians) of the patches of a leaf pair.
pub const FLAT: f64 = 0.5;

/// Patches narrower than this fraction of their domain (in both directions) are not split.
pub const MIN_WIDTH: f64 = 1.0 / 4096.0;

/// Pairs whose normals may be parallel are checked for coinciding surfaces once both boxes
/// are below this fraction of the shapes' size.
pub const COINCIDENCE_SIZE: f64 = 1.0 / 16.0;

/// Pairs whose normals may be parallel are searched for a touching curve while the larger
/// box is between this fraction of the shapes' size and [`COINCIDENCE_SIZE`] (two levels of
/// subdivision: a touching curve through the pair is found there, and smaller pairs between
/// nearly parallel surfaces, as beside a flat crossing, are not searched again).
pub const TOUCH_SEARCH_SIZE: f64 = COINCIDENCE_SIZE / 4.0;

/// A pair whose boxes are both below this fraction of the shapes' size is a leaf.
pub const TOUCH_SIZE: f64 = 1e-3;

/// The most pairs of patches the seeding examines.
pub const MAX_SEED_PAIRS: usize = 200_000;

/// Whether no normal in `a` is parallel to one in `b`.
fn apart(a: &TangentCone<3>, b: &TangentCone<3>) -> bool {
    if a.half_angle >= FRAC_PI_2 || b.half_angle >= FRAC_PI_2 {
        return false;
    }
    let between = angle(&a.axis, &b.axis);
    between.min(PI - between) > a.half_angle + b.half_angle
}

/// Whether the patch can still be split (wider than [`MIN_WIDTH`] of a domain).
fn splittable(p: &SurfacePatch<3>, cover: &SurfaceCover<3>) -> bool {
    p.u().length() > MIN_WIDTH * cover.domain_u.length() || p.v().length() > MIN_WIDTH * cover.domain_v.length()
}

/// The first root box of a cover.
fn a_root_box(c: &SurfaceCover<3>) -> crate::query::bounds::Aabb<3> {
    c.nodes[0].patch.bounds
}

/// Whether the centre and corners of patch `a` lie on `m.b` near patch `b` within the
/// tolerance (Gauss–Newton for the nearest point from b's centre, clamped to b's box grown
/// by its width).
fn coincide<A, B>(m: &Marcher<'_, A, B>, a: &SurfacePatch<3>, b: &SurfacePatch<3>) -> bool
where
    A: Surface<3> + ?Sized,
    B: Surface<3> + ?Sized,
{
    // The centre off b's box: not on b there (a neighbour of b's may hold it, and is asked
    // in its own pair).
    if b.bounds.distance_to(&a.grid[4].point) > m.tolerance {
        return false;
    }
    let (iu, iv) = (grown(b.u()), grown(b.v()));
    [4usize, 0, 2, 6, 8].iter().all(|&k| {
        let p = a.grid[k].point;
        let start = (b.u().lerp(0.5), b.v().lerp(0.5));
        let ((u, v), singular) =
            newton::polish_on_surface(m.b, &p, start, (iu, iv), cap::SEED_POLISH, Settle::Relative(NEGLIGIBLE_STEP));
        if singular {
            return false;
        }
        (m.b.point(u, v) - p).norm() <= m.tolerance
    })
}

/// The parameter box of a patch grown by its width on each side.
fn grown(i: Interval) -> Interval {
    Interval::new(i.start - i.length(), i.end + i.length())
}

/// A patch shared between the pairs it is in, with its normal cone.
fn node(p: SearchPatch<'_, 3>) -> Rc<(SearchPatch<'_, 3>, TangentCone<3>)> {
    let cone = normal_cone(p.patch());
    Rc::new((p, cone))
}

/// What seeding found: seeds of crossing branches and the touching curves traced.
#[derive(Debug, Clone, Default)]
pub struct Seeds {
    /// Seeds on crossing branches, in the order the leaves were found.
    pub crossing: Vec<MarchPoint>,
    /// The touching curves, each traced by `trace_touching` from its first point.
    pub touching: Vec<IntersectionBranch>,
}

/// The seeds (see the module documentation); `trace_touching` traces the touching curve
/// through a point found.
pub fn pair_seeds<A, B>(
    m: &Marcher<'_, A, B>,
    ca: &SurfaceCover<3>,
    cb: &SurfaceCover<3>,
    mut trace_touching: impl FnMut(MarchPoint) -> IntersectionBranch,
) -> Result<Seeds>
where
    A: Surface<3> + ?Sized,
    B: Surface<3> + ?Sized,
{
    // Patches are shared between the pairs they are in, with their normal cones.
    let roots_b: Vec<_> = cb.nodes[..cb.roots].iter().map(|n| node(SearchPatch::Cached(n))).collect();
    let mut stack = Vec::new();
    for na in &ca.nodes[..ca.roots] {
        let na = node(SearchPatch::Cached(na));
        for nb in &roots_b {
            stack.push((na.clone(), nb.clone()));
        }
    }
    let (mut seeds, mut count) = (Seeds::default(), PairCount::new(MAX_SEED_PAIRS));
    let size = ca.nodes[..ca.roots]
        .iter()
        .chain(&cb.nodes[..cb.roots])
        .fold(a_root_box(ca), |bx, n| bx.union(&n.patch.bounds))
        .diagonal();
    let zero = Point::<3>::zeros();
    while let Some((na, nb)) = stack.pop() {
        count.next("surface intersection", "pairs of patches whose normals may be parallel")?;
        let ((pa, cone_a), (pb, cone_b)) = (&*na, &*nb);
        let (a, b) = (pa.patch(), pb.patch());
        if !a.bounds.overlaps(&b.bounds, m.tolerance) {
            continue;
        }
        let (split_a, split_b) = (splittable(a, ca), splittable(b, cb));
        let parted = apart(cone_a, cone_b);
        let larger = a.bounds.diagonal().max(b.bounds.diagonal());
        let small = larger <= COINCIDENCE_SIZE * size;
        if !parted && small && coincide(m, a, b) {
            return Err(coincidence(a.u().lerp(0.5), a.v().lerp(0.5)));
        }
        let centres = [a.u().lerp(0.5), a.v().lerp(0.5), b.u().lerp(0.5), b.v().lerp(0.5)];
        let within = [grown(a.u()), grown(a.v()), grown(b.u()), grown(b.v())];
        if !parted && small {
            let reach = a.bounds.diagonal().max(b.bounds.diagonal());
            let (pa, pb) = (a.grid[4].point, b.grid[4].point);
            let near = |br: &IntersectionBranch| {
                near_polyline(&br.points, &pa, reach) && near_polyline(&br.points, &pb, reach)
            };
            if seeds.touching.iter().any(near) {
                continue;
            }
            let searched = larger > TOUCH_SEARCH_SIZE * size;
            if let Some(p) = if searched { touching::find(m, centres, &within)? } else { None } {
                seeds.touching.push(trace_touching(p));
                continue;
            }
        }
        let leaf = parted && cone_a.half_angle <= FLAT && cone_b.half_angle <= FLAT;
        // Both boxes below TOUCH_SIZE of the shapes: a leaf whatever its cones (surfaces that
        // touch along a curve would otherwise be split along all of it down to MIN_WIDTH).
        let touch = a.bounds.diagonal().max(b.bounds.diagonal()) <= TOUCH_SIZE * size;
        if leaf || touch || (!split_a && !split_b) {
            if let Some(p) = m.converge(centres, &within).and_then(|x| m.point(x, &zero)) {
                seeds.crossing.push(p);
            }
            continue;
        }
        // Split the patch with the wider normals (the larger box when they are alike, or
        // when one box is below a quarter of the other: a flat patch beside a curved one
        // would never be split otherwise, and the pair never become small), so that the
        // cones narrow fastest.
        let first = if split_a && split_b {
            let (wa, wb) = (cone_a.half_angle.min(FRAC_PI_2), cone_b.half_angle.min(FRAC_PI_2));
            let (da, db) = (a.bounds.diagonal(), b.bounds.diagonal());
            if (wa - wb).abs() > 1e-3 && da.min(db) >= 0.25 * da.max(db) { wa > wb } else { da >= db }
        } else {
            split_a
        };
        if first {
            stack.extend(pa.split(ca, m.a).into_iter().map(|q| (node(q), nb.clone())));
        } else {
            stack.extend(pb.split(cb, m.b).into_iter().map(|q| (na.clone(), node(q))));
        }
    }
    Ok(seeds)
}
