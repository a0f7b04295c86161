//! Intersections of a curve with a surface in 3-D.
//!
//! Method: interval subdivision over the curve's [`CurveCover`] and the surface's
//! [`SurfaceCover`], then Newton's method. A pair (curve piece, patch) is dropped when
//! their boxes, grown by the tolerance, are apart. When the piece's tangent cone and the
//! patch's normal cone are [`transversal`] the pair holds at most one intersection, which
//! Newton's method on F(t, u, v) = c(t) − S(u, v) = 0 (the 3 × 3 Jacobian
//! [c′, −S_u, −S_v] solved by SVD, steps clamped to the pair's parameter box) finds to full
//! precision; if it does not converge there the pair is split like any other. Other pairs
//! are split, the one with the larger box first, until both boxes are smaller than
//! `max(tolerance, TANGENT_RESOLUTION · size)` or narrower than
//! [`MIN_WIDTH`] of the domains: there Gauss–Newton
//! from the pair's centre over the whole domains finds the nearest point pair, recorded
//! when it is within the tolerance.
//!
//! What is guaranteed (where the covers' radii bound the shapes, always for polynomial
//! pieces of degree ≤ 3): every place where the curve comes within `tolerance` of the
//! surface lies in an examined pair, so no transversal crossing is missed however close to
//! another; tangential contacts are found to the tangent resolution. A crossing is a point
//! where the tangent makes an angle with sine above [`TANGENT_SINE`] with the tangent plane;
//! below it the point is a tangent contact. Points closer than the tolerance (tangent
//! contacts: the tangent resolution) with nearby parameters are one. A curve that runs
//! inside the surface along a stretch has no isolated intersections: the search ends with
//! an error when three points of a piece (longer than 1000 tolerances and
//! [`MIN_OVERLAP`] of the shapes' size, so that a tangential contact's neighbourhood does
//! not count, inside a larger patch) lie on the patch within the tolerance, and after
//! [`MAX_PAIRS`] pairs at most.

use crate::Interval;
use crate::Point;
use crate::curve::Curve;
use crate::error::{Error, Result};
use crate::query::curve_cover::{CurveCover, SearchPiece};
use crate::query::curve_intersection::{IntersectionKind, MIN_OVERLAP, TANGENT_RESOLUTION, TANGENT_SINE};
use crate::query::newton::{self, Settle, Step, cap, settled_all};
use crate::query::normal_cone::{normal_cone, transversal};
use crate::query::pair_count::PairCount;
use crate::query::project_curve::MIN_WIDTH;
use crate::query::surface_cover::{SearchPatch, SurfaceCover};
use crate::query::tangent_cone::TangentCone;
use crate::surface::Surface;
use nalgebra::{Matrix3, Vector3};

/// The most (piece, patch) pairs one intersection examines before it reports an error.
pub const MAX_PAIRS: usize = 400_000;

/// A point where a curve meets a surface.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CurveSurfaceIntersection {
    /// Parameter on the curve.
    pub t: f64,
    /// Surface parameter u.
    pub u: f64,
    /// Surface parameter v.
    pub v: f64,
    /// The point (the midpoint of c(t) and S(u, v)).
    pub point: Point<3>,
    /// Crossing, or tangential contact.
    pub kind: IntersectionKind,
}

/// Every intersection of `curve` and `surface` (see the module documentation), sorted by
/// t; `tolerance` (> 0, absolute) is the distance below which they count as meeting.
pub fn intersect_curve_surface<C, S>(curve: &C, surface: &S, tolerance: f64) -> Result<Vec<CurveSurfaceIntersection>>
where
    C: Curve<3> + ?Sized,
    S: Surface<3> + ?Sized,
{
    intersect_with_limit(curve, surface, tolerance, MAX_PAIRS)
}

/// [`intersect_curve_surface`] that gives up after `max_pairs` pairs (an error).
pub fn intersect_with_limit<C, S>(
    curve: &C,
    surface: &S,
    tolerance: f64,
    max_pairs: usize,
) -> Result<Vec<CurveSurfaceIntersection>>
where
    C: Curve<3> + ?Sized,
    S: Surface<3> + ?Sized,
{
    intersect_with_cover(curve, surface, &SurfaceCover::new(surface), tolerance, max_pairs)
}

/// [`intersect_with_limit`] with the surface's cover built beforehand (`sc` must be
/// `SurfaceCover::new(surface)`), so that many curves against one surface share it.
pub fn intersect_with_cover<C, S>(
    curve: &C,
    surface: &S,
    sc: &SurfaceCover<3>,
    tolerance: f64,
    max_pairs: usize,
) -> Result<Vec<CurveSurfaceIntersection>>
where
    C: Curve<3> + ?Sized,
    S: Surface<3> + ?Sized,
{
    if !(tolerance > 0.0 && tolerance.is_finite()) {
        return Err(Error::invalid("tolerance", format!("must be finite and > 0, got {tolerance}")));
    }
    let cc = CurveCover::new(curve);
    let size = cover_diagonal(&cc, sc);
    let mut search = Search { curve, surface, tolerance, size, max_pairs, found: Vec::new() };
    let mut pairs = Vec::new();
    for n in &cc.nodes[..cc.roots] {
        for m in &sc.nodes[..sc.roots] {
            pairs.push((SearchPiece::Cached(n), SearchPatch::Cached(m)));
        }
    }
    search.run(pairs, &cc, sc)?;
    Ok(search.finish())
}

/// The diagonal of the box around both covers' roots.
fn cover_diagonal(cc: &CurveCover<3>, sc: &SurfaceCover<3>) -> f64 {
    let mut b = cc.nodes[0].piece.bounds;
    for n in &cc.nodes[..cc.roots] {
        b = b.union(&n.piece.bounds);
    }
    for m in &sc.nodes[..sc.roots] {
        b = b.union(&m.patch.bounds);
    }
    b.diagonal()
}

struct Search<'c, C: ?Sized, S: ?Sized> {
    curve: &'c C,
    surface: &'c S,
    tolerance: f64,
    size: f64,
    max_pairs: usize,
    found: Vec<CurveSurfaceIntersection>,
}

impl<C: Curve<3> + ?Sized, S: Surface<3> + ?Sized> Search<'_, C, S> {
    fn run<'p>(
        &mut self,
        mut pairs: Vec<(SearchPiece<'p, 3>, SearchPatch<'p, 3>)>,
        cc: &'p CurveCover<3>,
        sc: &'p SurfaceCover<3>,
    ) -> Result<()> {
        let tiny = self.tolerance.max(TANGENT_RESOLUTION * self.size);
        let (wt, wu, wv) =
            (MIN_WIDTH * cc.domain.length(), MIN_WIDTH * sc.domain_u.length(), MIN_WIDTH * sc.domain_v.length());
        let mut count = PairCount::new(self.max_pairs);
        while let Some((pc, ps)) = pairs.pop() {
            count.next(
                "curve-surface intersection",
                "pairs of pieces (does the curve run inside the surface?); try a larger tolerance",
            )?;
            let (x, y) = (pc.piece(), ps.patch());
            if !x.bounds.overlaps(&y.bounds, self.tolerance) {
                continue;
            }
            let boxes = (x.interval(), y.u(), y.v());
            if transversal(&TangentCone::of(x), &normal_cone(y)) && self.newton(boxes, false) {
                continue;
            }
            let (dx, dy) = (x.bounds.diagonal(), y.bounds.diagonal());
            if dx > (1000.0 * self.tolerance).max(MIN_OVERLAP * self.size)
                && dx <= dy
                && self.lies_in(x.interval(), y.u(), y.v())
            {
                return Err(Error::numerical(
                    "curve-surface intersection",
                    format!("the curve runs inside the surface (at least for t in [{}, {}])", x.start.t, x.end.t),
                ));
            }
            let narrow = x.interval().length() <= wt && y.u().length() <= wu && y.v().length() <= wv;
            if (dx <= tiny && dy <= tiny) || narrow {
                self.newton(boxes, true);
                continue;
            }
            if (dx >= dy || y.u().length() <= wu || y.v().length() <= wv) && x.interval().length() > wt {
                pairs.extend(pc.split(cc, self.curve).into_iter().map(|h| (h, ps.clone())));
            } else {
                pairs.extend(ps.split_around_points(sc, self.surface).into_iter().map(|q| (pc.clone(), q)));
            }
        }
        Ok(())
    }

    /// Newton's method for c(t) = S(u, v) from the centre of the parameter box `(it, iu,
    /// iv)`, steps clamped to it (with `contact`, to the whole domains: a contact is the
    /// nearest point pair, which may lie outside the tiny pair that found it). Records the
    /// point and returns true when the shapes meet within the tolerance there.
    fn newton(&mut self, (it, iu, iv): (Interval, Interval, Interval), contact: bool) -> bool {
        // From the pair's centre; a contact's steps may leave the pair (not the domains).
        let x0 = [it.lerp(0.5), iu.lerp(0.5), iv.lerp(0.5)];
        let ranges = if contact {
            [self.curve.domain(), self.surface.domain_u(), self.surface.domain_v()]
        } else {
            [it, iu, iv]
        };
        let x = newton::iterate(cap::CURVE_SURFACE, x0, |x| {
            let jet = Jet::at(self.curve, self.surface, &Vector3::from(*x));
            let j = Matrix3::from_columns(&[jet.dc, -jet.su, -jet.sv]);
            let scale = j.amax().max(f64::MIN_POSITIVE);
            let Ok(step) = j.svd(true, true).solve(&(jet.c - jet.s), 1e-13 * scale) else {
                return Step::Stop;
            };
            let next: [f64; 3] = std::array::from_fn(|k| ranges[k].clamp(x[k] - step[k]));
            Step::To(next, settled_all(x, &next, &ranges))
        })
        .expect("Newton on c = S never abandons");
        let x = Vector3::from(x);
        let jet = Jet::at(self.curve, self.surface, &x);
        let gap = (jet.c - jet.s).norm();
        if gap.is_nan() || gap > self.tolerance {
            return false;
        }
        // At a pole or apex S_u × S_v vanishes: the limit normal from just inside decides.
        let normal = crate::surface::normal_or_limit(self.surface, x[1], x[2], &jet.su, &jet.sv);
        let nt = jet.dc.norm();
        let cosine = match normal {
            Some(n) if nt > 0.0 => jet.dc.dot(&n).abs() / nt,
            _ => 0.0,
        };
        let kind = if cosine > TANGENT_SINE { IntersectionKind::Crossing } else { IntersectionKind::Tangent };
        self.found.push(CurveSurfaceIntersection { t: x[0], u: x[1], v: x[2], point: (jet.c + jet.s) * 0.5, kind });
        true
    }

    /// Whether c(t) at the quarter points of `it` lies within the tolerance of S over
    /// `iu` × `iv` (Gauss–Newton for the nearest point from the patch's centre, clamped).
    fn lies_in(&self, it: Interval, iu: Interval, iv: Interval) -> bool {
        [0.25, 0.5, 0.75].iter().all(|&s| {
            let p = self.curve.point(it.lerp(s));
            let start = (iu.lerp(0.5), iv.lerp(0.5));
            let ((u, v), _) =
                newton::polish_on_surface(self.surface, &p, start, (iu, iv), cap::CURVE_SURFACE, Settle::Rounding);
            (self.surface.point(u, v) - p).norm() <= self.tolerance
        })
    }

    /// Sorts by t and merges duplicates (a crossing wins over a contact).
    fn finish(mut self) -> Vec<CurveSurfaceIntersection> {
        self.found.sort_by(|a, b| a.t.total_cmp(&b.t));
        let mut out: Vec<CurveSurfaceIntersection> = Vec::new();
        let dt = 1e-6 * self.curve.domain().length().max(1e-300);
        for p in self.found {
            let near = |q: &CurveSurfaceIntersection| {
                let tangent = q.kind == IntersectionKind::Tangent || p.kind == IntersectionKind::Tangent;
                let reach = if tangent { self.tolerance.max(TANGENT_RESOLUTION * self.size) } else { self.tolerance };
                (q.point - p.point).norm() <= reach && (q.t - p.t).abs() <= dt
            };
            match out.iter_mut().find(|q| near(q)) {
                Some(q) if p.kind == IntersectionKind::Crossing => *q = p,
                Some(_) => {}
                None => out.push(p),
            }
        }
        out
    }
}

/// c, c′, S, S_u, S_v at (t, u, v).
struct Jet {
    c: Point<3>,
    dc: Point<3>,
    s: Point<3>,
    su: Point<3>,
    sv: Point<3>,
}

impl Jet {
    fn at<C: Curve<3> + ?Sized, S: Surface<3> + ?Sized>(curve: &C, surface: &S, x: &Vector3<f64>) -> Self {
        let mut oc = [Point::<3>::zeros(); 2];
        curve.eval(x[0], &mut oc);
        let mut os = [Point::<3>::zeros(); 4];
        surface.eval_partials(x[1], x[2], 1, 1, &mut os);
        Jet { c: oc[0], dc: oc[1], s: os[0], su: os[2], sv: os[1] }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::curve::model::Line;
    use crate::surface::model::Sphere;

    #[test]
    fn a_line_pierces_a_sphere_twice_and_touches_it_once() {
        let sphere = Sphere::new(2.0).unwrap();
        let through = Line::new(Point::<3>::new(-3.0, 0.5, 0.3), Point::<3>::new(3.0, 0.5, 0.3)).unwrap();
        let r = intersect_curve_surface(&through, &sphere, 1e-9).unwrap();
        assert_eq!(r.len(), 2, "{r:?}");
        let x = (4.0f64 - 0.25 - 0.09).sqrt();
        for (p, sign) in r.iter().zip([-1.0, 1.0]) {
            assert!((p.point - Point::<3>::new(sign * x, 0.5, 0.3)).norm() < 1e-12, "{p:?}");
            assert_eq!(p.kind, IntersectionKind::Crossing);
        }
        let touching = Line::new(Point::<3>::new(-3.0, 2.0, 0.5), Point::<3>::new(3.0, 2.0, -0.5)).unwrap();
        let r = intersect_curve_surface(&touching, &sphere, 1e-9).unwrap();
        assert_eq!(r.len(), 1, "{r:?}");
        assert_eq!(r[0].kind, IntersectionKind::Tangent);
        assert!((r[0].point - Point::<3>::new(0.0, 2.0, 0.0)).norm() < 1e-6, "{:?}", r[0]);
    }

    /// Issue 20: a line through both poles meets the sphere at the poles (it used to give
    /// up after 400 000 pairs: every patch around a pole holds the pole, and splitting
    /// them across it doubled them per level). Also a slanted line through one pole, and
    /// the exact NURBS sphere, whose poles are repeated control points.
    #[test]
    fn lines_through_the_poles_meet_the_sphere_at_the_poles() {
        let sphere = Sphere::new(2.0).unwrap();
        let axis = Line::new(Point::<3>::new(0.0, 0.0, -3.0), Point::<3>::new(0.0, 0.0, 3.0)).unwrap();
        let r = intersect_curve_surface(&axis, &sphere, 1e-9).unwrap();
        assert_eq!(r.len(), 2, "{r:?}");
        for (p, z) in r.iter().zip([-2.0, 2.0]) {
            assert!((p.point - Point::<3>::new(0.0, 0.0, z)).norm() < 1e-9, "{p:?}");
            assert_eq!(p.kind, IntersectionKind::Crossing, "{p:?}");
        }
        // Through the north pole and (2, 0, 0) on the equator.
        let slanted = Line::new(Point::<3>::new(-1.0, 0.0, 3.0), Point::<3>::new(3.0, 0.0, -1.0)).unwrap();
        let r = intersect_curve_surface(&slanted, &sphere, 1e-9).unwrap();
        assert_eq!(r.len(), 2, "{r:?}");
        assert!((r[0].point - Point::<3>::new(0.0, 0.0, 2.0)).norm() < 1e-9, "{r:?}");
        assert!((r[1].point - Point::<3>::new(2.0, 0.0, 0.0)).norm() < 1e-9, "{r:?}");
        let nurbs = crate::surface::NurbsSurface::sphere(2.0).unwrap();
        let r = intersect_curve_surface(&axis, &nurbs, 1e-9).unwrap();
        assert_eq!(r.len(), 2, "{r:?}");
        for (p, z) in r.iter().zip([-2.0, 2.0]) {
            assert!((p.point - Point::<3>::new(0.0, 0.0, z)).norm() < 1e-9, "{p:?}");
        }
    }
}
