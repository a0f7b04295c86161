//! Projection of a point onto a surface: the global nearest point and every local minimum
//! of the distance.
//!
//! Method: branch and bound over the surface's [`SurfaceCover`], as for curves
//! ([`crate::query::project_curve`]). The minima of f(u, v) = |S − q|²/2 over the domain
//! lie at interior stationary points (∇f = ((S − q)·S_u, (S − q)·S_v) = 0) or on the
//! boundary edges of open directions. Edges are projected as curves (their iso-curves;
//! a degenerate edge such as a sphere's pole or a cone's apex is a single point, which the
//! curve search reports once). Patches are classified by the Bernstein nets of the gradient
//! and the Hessian ([`classify_patch`]): patches where a gradient component keeps its sign
//! hold no stationary point; on patches where f is convex, projected Newton iteration
//! (with a backtracking line search, inside the patch) finds the only candidate; others are
//! split, down to [`NEWTON_WIDTH`] of each domain, where Newton iteration from the patch
//! centre decides (or [`DEGENERATE_WIDTH`] where one gradient component vanishes on the
//! whole patch, as it does along a circle of nearest points). For the global minimum, patches whose box is farther than the best
//! distance so far minus `accuracy` (at least the rounding level of the coordinates) are
//! dropped.
//!
//! What is guaranteed (where the cover's radii bound the surface, always for bicubic
//! patches): the nearest distance returned is within `accuracy` of the true minimum; every
//! isolated local minimum is found whose patch at width [`NEWTON_WIDTH`] holds no other
//! stationary point. Where the minimum is not isolated — a sphere about its centre, a circle of
//! nearest points for a query on the axis of a surface of revolution — the points at that
//! distance are reported once, at the lowest (u, v) found. A query spends at most
//! [`MAX_PATCHES`] patches; past that, patches are decided by Newton iteration at the size
//! they have, so no query runs forever.

use std::collections::BinaryHeap;

use crate::Interval;
use crate::Point;
use crate::error::Result;
use crate::query::best_first::Ranked;
use crate::query::bounds::Aabb;
use crate::query::curve_cover::{CurveCover, ROUNDING};
use crate::query::newton::{self, Step, cap, settled_all};
use crate::query::project_curve::{CurveProjector, check_query};
use crate::query::slope::{DUPLICATE_DISTANCE, ZERO_SLOPE, is_rounding_sized};
use crate::query::surface_cover::{SearchPatch, SurfaceCover, SurfacePatch};
use crate::query::surface_slope::{BoundarySides, PatchShape, classify_patch};
use crate::surface::{Direction, IsoCurve, Surface};

/// Unresolved patches narrower than this fraction of a domain are decided by Newton
/// iteration from their centre.
pub const NEWTON_WIDTH: f64 = 1.0 / 4096.0;

/// Patches on which one gradient component vanishes identically (half-flat, see
/// [`PatchShape::HalfFlat`]) narrower than this fraction of a domain are decided by Newton
/// iteration.
pub const DEGENERATE_WIDTH: f64 = 1.0 / 64.0;

/// The most patches one query examines.
pub const MAX_PATCHES: usize = 200_000;

/// The nearest point of a surface to a query point, or one local minimum of the distance.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct NearestOnSurface<const D: usize> {
    /// The parameter u.
    pub u: f64,
    /// The parameter v.
    pub v: f64,
    /// The point S(u, v).
    pub point: Point<D>,
    /// |S(u, v) − q|.
    pub distance: f64,
}

impl<const D: usize> NearestOnSurface<D> {
    fn at(u: f64, v: f64, point: Point<D>, q: &Point<D>) -> Self {
        NearestOnSurface { u, v, point, distance: (point - q).norm() }
    }
}

/// One boundary edge of an open direction: which parameter is fixed, where, and on which
/// side of the domain (f must not decrease into the domain for an edge minimum).
#[derive(Debug, Clone)]
struct Edge<const D: usize> {
    direction: Direction,
    fixed: f64,
    /// +1 at the lower end of the fixed parameter (the domain lies above), −1 at the upper.
    inward: f64,
    cover: CurveCover<D>,
    /// The edge is a single point (a sphere's pole, a cone's apex): every direction into
    /// the domain must be checked at an edge minimum, not just the one at its parameter.
    degenerate: bool,
    /// A box holding the whole edge.
    bounds: Aabb<D>,
}

/// The nearest point of a surface, a capability of every [`Surface`] (a blanket
/// implementation): `use splinekit::surface::SurfaceNearest` to call it.
pub trait SurfaceNearest<const D: usize>: Surface<D> {
    /// The point of the surface nearest to `query`, its distance within `accuracy`
    /// (absolute, ≥ 0) of the true minimum; an error for a non-finite query or accuracy.
    /// Trimming is not taken into account yet: a trimmed surface is projected as its
    /// untrimmed base surface. To project many points, build a [`SurfaceProjector`] once;
    /// for every local minimum see [`SurfaceProjector::local_minima`].
    ///
    /// ```
    /// use splinekit::{Point, surface::{SurfaceNearest, model::Sphere}};
    /// let sphere = Sphere::new(2.0).unwrap();
    /// let near = sphere.closest_point(&Point::<3>::new(0.0, 0.0, 5.0), 1e-12).unwrap();
    /// assert!((near.distance - 3.0).abs() < 1e-12 && (near.point[2] - 2.0).abs() < 1e-12);
    /// ```
    fn closest_point(&self, query: &Point<D>, accuracy: f64) -> Result<NearestOnSurface<D>> {
        SurfaceProjector::new(self).nearest(query, accuracy)
    }
}

impl<const D: usize, S: Surface<D> + ?Sized> SurfaceNearest<D> for S {}

/// Projects many points onto one surface, building the bounding hierarchy once.
#[derive(Debug, Clone)]
pub struct SurfaceProjector<'s, const D: usize, S: ?Sized> {
    surface: &'s S,
    cover: SurfaceCover<D>,
    edges: Vec<Edge<D>>,
}

/// What a search does with one patch.
enum Decision<const D: usize> {
    /// No stationary point inside.
    Skip,
    /// The distance is constant on it.
    Flat,
    /// Decided by Newton iteration.
    Leaf(Stationary<D>),
    /// Split into quarters.
    Split,
}

/// The local data Newton iteration needs.
struct SecondOrder<const D: usize> {
    point: Point<D>,
    distance: f64,
    gradient: (f64, f64),
    hessian: (f64, f64, f64),
    speeds: (f64, f64),
}

/// A stationary point found by Newton iteration, with what the caller needs to judge it.
struct Stationary<const D: usize> {
    found: NearestOnSurface<D>,
    /// ∇f vanishes (to rounding) there.
    stationary: bool,
    /// The Hessian is positive definite there (not merely semidefinite).
    isolated: bool,
}

impl<'s, const D: usize, S: Surface<D> + ?Sized> SurfaceProjector<'s, D, S> {
    /// Builds the bounding hierarchy of `surface` and of its open boundary edges.
    pub fn new(surface: &'s S) -> Self {
        let (du, dv) = (surface.domain_u(), surface.domain_v());
        let mut edges = Vec::new();
        let mut add = |direction, domain: Interval, closed: bool| {
            if !closed {
                for (fixed, inward) in [(domain.start, 1.0), (domain.end, -1.0)] {
                    let cover = CurveCover::new(&IsoCurve::new(surface, direction, fixed));
                    let whole = cover.nodes[..cover.roots]
                        .iter()
                        .fold(cover.nodes[0].piece.bounds, |b, n| b.union(&n.piece.bounds));
                    let degenerate = is_rounding_sized(&whole, &Point::<D>::zeros());
                    edges.push(Edge { direction, fixed, inward, cover, degenerate, bounds: whole });
                }
            }
        };
        add(Direction::U, du, surface.is_closed_u());
        add(Direction::V, dv, surface.is_closed_v());
        SurfaceProjector { surface, cover: SurfaceCover::new(surface), edges }
    }

    fn edge_projector<'a>(&'a self, edge: &'a Edge<D>) -> (IsoCurve<'a, S>, &'a CurveCover<D>) {
        (IsoCurve::new(self.surface, edge.direction, edge.fixed), &edge.cover)
    }

    fn on_edge(&self, edge: &Edge<D>, t: f64, point: Point<D>, q: &Point<D>) -> NearestOnSurface<D> {
        match edge.direction {
            Direction::U => NearestOnSurface::at(edge.fixed, t, point, q),
            Direction::V => NearestOnSurface::at(t, edge.fixed, point, q),
        }
    }

    /// The point of the surface nearest to `q`, its distance within `accuracy` (≥ 0,
    /// absolute) of the true minimum; see the module documentation.
    pub fn nearest(&self, q: &Point<D>, accuracy: f64) -> Result<NearestOnSurface<D>> {
        check_query(q, accuracy)?;
        let g = &self.cover.nodes[0].patch.grid[0];
        let mut best = NearestOnSurface::at(g.u, g.v, g.point, q);
        let offer = |c: NearestOnSurface<D>, best: &mut NearestOnSurface<D>| {
            if c.distance < best.distance {
                *best = c;
            }
        };
        let offer_grid = |p: &SurfacePatch<D>, best: &mut NearestOnSurface<D>| {
            for s in &p.grid {
                offer(NearestOnSurface::at(s.u, s.v, s.point, q), best);
            }
        };
        let mut heap = BinaryHeap::new();
        for node in &self.cover.nodes[..self.cover.roots] {
            offer_grid(&node.patch, &mut best);
            heap.push(Ranked { bound: node.patch.bounds.distance_to(q), item: SearchPatch::Cached(node) });
        }
        let slack = accuracy.max(ROUNDING * (q.amax() + self.cover.scale));
        let mut examined = 0;
        while let Some(Ranked { bound, item: patch }) = heap.pop() {
            if bound >= best.distance - slack {
                break;
            }
            examined += 1;
            let p = patch.patch();
            match self.decide(p, q, examined) {
                Decision::Skip | Decision::Flat => {}
                Decision::Leaf(st) => offer(st.found, &mut best),
                Decision::Split => {
                    for quarter in patch.split(&self.cover, self.surface) {
                        offer_grid(quarter.patch(), &mut best);
                        let bound = quarter.patch().bounds.distance_to(q);
                        if bound < best.distance - slack {
                            heap.push(Ranked { bound, item: quarter });
                        }
                    }
                }
            }
        }
        // The boundary edges last, each only when its box may hold a nearer point.
        for edge in &self.edges {
            if edge.bounds.distance_to(q) >= best.distance - slack {
                continue;
            }
            let (iso, cover) = self.edge_projector(edge);
            let n = CurveProjector::with_cover(&iso, cover).nearest(q, accuracy)?;
            offer(self.on_edge(edge, n.t, n.point, q), &mut best);
        }
        Ok(best)
    }

    /// Every local minimum of the distance from `q` to the surface (interior stationary
    /// minima and minima on the boundary edges of open directions where the distance grows
    /// into the domain), sorted by (u, v). See the module documentation.
    pub fn local_minima(&self, q: &Point<D>, accuracy: f64) -> Result<Vec<NearestOnSurface<D>>> {
        check_query(q, accuracy)?;
        let mut found: Vec<(NearestOnSurface<D>, bool)> = Vec::new();
        let mut flat: Vec<NearestOnSurface<D>> = Vec::new();
        let mut stack: Vec<SearchPatch<'_, D>> =
            self.cover.nodes[..self.cover.roots].iter().map(SearchPatch::Cached).collect();
        let mut examined = 0;
        while let Some(patch) = stack.pop() {
            examined += 1;
            let p = patch.patch();
            match self.decide(p, q, examined) {
                Decision::Skip => {}
                Decision::Flat => {
                    let s = &p.grid[0];
                    flat.push(NearestOnSurface::at(s.u, s.v, s.point, q));
                }
                Decision::Leaf(st) => {
                    if st.stationary {
                        found.push((st.found, st.isolated));
                    }
                }
                Decision::Split => stack.extend(patch.split(&self.cover, self.surface)),
            }
        }
        for edge in &self.edges {
            let (iso, cover) = self.edge_projector(edge);
            for m in CurveProjector::with_cover(&iso, cover).local_minima(q, accuracy)? {
                let c = self.on_edge(edge, m.t, m.point, q);
                let directions: Vec<f64> = if edge.degenerate {
                    edge.cover.nodes[..edge.cover.roots].iter().flat_map(|n| [n.piece.start.t, n.piece.mid.t]).collect()
                } else {
                    vec![m.t]
                };
                if directions.iter().all(|&t| self.grows_inward(edge, &self.on_edge(edge, t, m.point, q), q)) {
                    found.push((c, true));
                }
            }
        }
        Ok(self.merge(found, flat, accuracy))
    }

    /// The sides of `p` on the boundary of an open direction.
    fn boundary_sides(&self, p: &SurfacePatch<D>) -> BoundarySides {
        let c = &self.cover;
        let (u, v) = (p.u(), p.v());
        [
            !c.closed.0 && u.start == c.domain_u.start,
            !c.closed.0 && u.end == c.domain_u.end,
            !c.closed.1 && v.start == c.domain_v.start,
            !c.closed.1 && v.end == c.domain_v.end,
        ]
    }

    /// What to do with a patch: skip it, record it as flat, decide it by Newton iteration
    /// (convex patches; unresolved ones at [`NEWTON_WIDTH`] or past [`MAX_PATCHES`]; and
    /// half-flat ones at [`DEGENERATE_WIDTH`], so that a circle of stationary points is not
    /// followed down to [`NEWTON_WIDTH`]), or split it.
    fn decide(&self, p: &SurfacePatch<D>, q: &Point<D>, examined: usize) -> Decision<D> {
        let narrower = |fraction: f64| {
            p.u().length() <= fraction * self.cover.domain_u.length()
                || p.v().length() <= fraction * self.cover.domain_v.length()
        };
        match classify_patch(p, q, self.boundary_sides(p)) {
            PatchShape::NoStationaryPoint => Decision::Skip,
            PatchShape::Flat => Decision::Flat,
            PatchShape::Convex => Decision::Leaf(self.newton(p, q)),
            PatchShape::HalfFlat if narrower(DEGENERATE_WIDTH) => Decision::Leaf(self.newton(p, q)),
            _ if narrower(NEWTON_WIDTH) || examined >= MAX_PATCHES => Decision::Leaf(self.newton(p, q)),
            PatchShape::Unresolved | PatchShape::HalfFlat => Decision::Split,
        }
    }

    /// At a minimum of an edge, f does not decrease into the domain: its inward slope is
    /// positive, or zero to rounding with a positive second derivative (which rejects the
    /// pole of a sphere seen from above the other pole).
    fn grows_inward(&self, edge: &Edge<D>, c: &NearestOnSurface<D>, q: &Point<D>) -> bool {
        let mut o = [Point::<D>::zeros(); 3];
        match edge.direction {
            Direction::U => self.surface.eval_partials(c.u, c.v, 2, 0, &mut o),
            Direction::V => self.surface.eval_partials(c.u, c.v, 0, 2, &mut o),
        }
        let r = o[0] - q;
        let slope = r.dot(&o[1]) * edge.inward;
        let zero = ZERO_SLOPE * (c.distance + c.point.amax()).max(f64::MIN_POSITIVE) * o[1].norm();
        slope > zero || (slope >= -zero && o[1].norm_squared() + r.dot(&o[2]) >= 0.0)
    }

    /// Projected Newton iteration for the minimum of f on the patch, from its centre: a
    /// Newton step where the Hessian is positive definite, a gradient step otherwise, clipped
    /// to the patch and halved until f decreases.
    fn newton(&self, p: &SurfacePatch<D>, q: &Point<D>) -> Stationary<D> {
        let (ru, rv) = (p.u(), p.v());
        let f_at = |u: f64, v: f64| 0.5 * (self.surface.point(u, v) - q).norm_squared();
        let ranges = [ru, rv];
        let [u, v] = newton::iterate(cap::PROJECT_SURFACE, [p.grid[4].u, p.grid[4].v], |&[u, v]| {
            let local = self.second_order(u, v, q);
            let (a, b, c) = local.hessian;
            let det = a * c - b * b;
            let (gu, gv) = local.gradient;
            let (mut du, mut dv) = if a > 0.0 && det > 0.0 {
                ((c * gu - b * gv) / det, (a * gv - b * gu) / det)
            } else {
                let scale = (a.abs() + c.abs()).max(f64::MIN_POSITIVE);
                (gu / scale, gv / scale)
            };
            let f0 = 0.5 * local.distance * local.distance;
            for _ in 0..cap::LINE_SEARCH {
                let next = [ru.clamp(u - du), rv.clamp(v - dv)];
                if f_at(next[0], next[1]) <= f0 {
                    return Step::To(next, settled_all(&[u, v], &next, &ranges));
                }
                du *= 0.5;
                dv *= 0.5;
            }
            Step::Stop
        })
        .expect("projected Newton never abandons");
        let local = self.second_order(u, v, q);
        let found = NearestOnSurface::at(u, v, local.point, q);
        let zero = ZERO_SLOPE * (found.distance + local.point.amax()).max(f64::MIN_POSITIVE);
        let (gu, gv) = local.gradient;
        let stationary = gu.abs() <= zero * local.speeds.0.max(f64::MIN_POSITIVE)
            && gv.abs() <= zero * local.speeds.1.max(f64::MIN_POSITIVE);
        let (a, b, c) = local.hessian;
        let isolated = a > 0.0 && a * c - b * b > ZERO_SLOPE * (a * c).abs();
        Stationary { found, stationary: stationary && a >= 0.0 && c >= 0.0, isolated }
    }

    /// f's gradient and Hessian at (u, v), with the point, its distance and |S_u|, |S_v|.
    fn second_order(&self, u: f64, v: f64, q: &Point<D>) -> SecondOrder<D> {
        let mut o = [Point::<D>::zeros(); 9];
        self.surface.eval_partials(u, v, 2, 2, &mut o);
        let r = o[0] - q;
        let (su, sv, suu, suv, svv) = (o[3], o[1], o[6], o[4], o[2]);
        SecondOrder {
            point: o[0],
            distance: r.norm(),
            gradient: (r.dot(&su), r.dot(&sv)),
            hessian: (su.dot(&su) + r.dot(&suu), su.dot(&sv) + r.dot(&suv), sv.dot(&sv) + r.dot(&svv)),
            speeds: (su.norm(), sv.norm()),
        }
    }

    /// Merges duplicates (within `accuracy` or [`DUPLICATE_DISTANCE`] in space), non-isolated minima at one
    /// distance, and minima inside flat regions, as the module documentation says.
    fn merge(
        &self,
        mut found: Vec<(NearestOnSurface<D>, bool)>,
        flat: Vec<NearestOnSurface<D>>,
        accuracy: f64,
    ) -> Vec<NearestOnSurface<D>> {
        let same_distance = |a: f64, b: f64| (a - b).abs() <= ZERO_SLOPE * 1e3 * a.max(b).max(f64::MIN_POSITIVE);
        let lowest = |a: &NearestOnSurface<D>, b: &NearestOnSurface<D>| (a.u, a.v) < (b.u, b.v);
        // Flat regions: one representative per distance.
        let mut regions: Vec<NearestOnSurface<D>> = Vec::new();
        for f in flat {
            match regions.iter_mut().find(|r| same_distance(r.distance, f.distance)) {
                Some(r) if lowest(&f, r) => *r = f,
                Some(_) => {}
                None => regions.push(f),
            }
        }
        found.retain(|(m, _)| !regions.iter().any(|r| same_distance(r.distance, m.distance)));
        // Non-isolated minima: one per distance.
        let mut out: Vec<NearestOnSurface<D>> = regions;
        let mut degenerate: Vec<NearestOnSurface<D>> = Vec::new();
        for (m, isolated) in found {
            let bucket = if isolated { &mut out } else { &mut degenerate };
            let dup = bucket.iter_mut().find(|r| {
                (r.point - m.point).norm() <= accuracy.max(DUPLICATE_DISTANCE * (1.0 + r.point.amax()))
                    || (!isolated && same_distance(r.distance, m.distance))
            });
            match dup {
                Some(r) if lowest(&m, r) && !isolated => *r = m,
                Some(r) if m.distance < r.distance => *r = m,
                Some(_) => {}
                None => bucket.push(m),
            }
        }
        for d in degenerate {
            if !out
                .iter()
                .any(|r| (r.point - d.point).norm() <= accuracy.max(DUPLICATE_DISTANCE * (1.0 + r.point.amax())))
            {
                out.push(d);
            }
        }
        out.sort_by(|a, b| a.u.total_cmp(&b.u).then(a.v.total_cmp(&b.v)));
        out
    }
}
