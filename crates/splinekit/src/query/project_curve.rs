//! Projection of a point onto a curve (point inversion): the global nearest point and
//! every local minimum of the distance.
//!
//! Method: branch and bound over the curve's [`CurveCover`]. The distance function
//! f(t) = |c(t) − q|²/2 has its minima at the domain ends, at kinks (breakpoints where
//! the slope jumps from − to +), and at the roots of its slope g = (c − q)·c′ where g
//! changes sign from − to +. Each piece is classified by the Bernstein coefficients of its
//! slope (`slope::classify`): monotone and flat pieces hold no interior minimum; a piece
//! with one bracketed sign change holds exactly one, found by safeguarded Newton iteration
//! on g (g′ = |c′|² + (c − q)·c″, bisection whenever a step leaves the bracket) to full
//! double precision; any other piece is split. For the global minimum, pieces whose box is
//! farther than the best distance found so far minus `accuracy` (at least the rounding
//! level of the coordinates) are dropped.
//!
//! What is guaranteed (wherever the cover's radii bound the curve, always for polynomial
//! pieces of degree ≤ 3, see [`crate::query::curve_cover`]): the nearest distance returned
//! is within `accuracy` of the true minimum, and every isolated local minimum is found
//! (one minimum found from two neighbouring pieces is reported once; minima at different
//! parameters of one point — a self-intersection, the two ends of a closed shape stored as
//! an open curve — are all reported). Where the minimum is not isolated —
//! the distance is constant along a stretch, as for a query at the centre of a circle —
//! the stretch is reported once, at its lowest parameter (on a closed curve the whole curve
//! is one stretch, reported at the domain start). Splitting stops at a width of
//! [`MIN_WIDTH`] times the domain, so no query runs forever.

use std::borrow::Cow;
use std::collections::BinaryHeap;

use crate::Interval;
use crate::Point;
use crate::curve::Curve;
use crate::error::{Error, Result, check_points_finite};
use crate::query::best_first::Ranked;
use crate::query::curve_cover::{CurveCover, CurvePiece, ROUNDING, Sample, SearchPiece};
use crate::query::slope::{DUPLICATE_DISTANCE, Shape, classify};

/// Pieces narrower than this fraction of the domain are not split further.
pub const MIN_WIDTH: f64 = 1e-13;

/// Two minima this close in parameter (relative to the domain) and in space are one.
const DUPLICATE_WIDTH: f64 = 1e-8;

/// Newton iterations allowed for one root of the slope (each halves the bracket at worst).
const MAX_ROOT_ITERATIONS: usize = 200;

/// The nearest point of a curve to a query point, or one local minimum of the distance.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Nearest<const D: usize> {
    /// The parameter t.
    pub t: f64,
    /// The point c(t).
    pub point: Point<D>,
    /// |c(t) − q|.
    pub distance: f64,
}

impl<const D: usize> Nearest<D> {
    fn at(t: f64, point: Point<D>, q: &Point<D>) -> Self {
        Nearest { t, point, distance: (point - q).norm() }
    }
}

/// The nearest point of a curve, a capability of every [`Curve`] (a blanket
/// implementation): `use splinekit::curve::CurveNearest` to call it.
pub trait CurveNearest<const D: usize>: Curve<D> {
    /// The point of the curve nearest to `query`, its distance within `accuracy`
    /// (absolute, ≥ 0) of the true minimum; an error for a non-finite query or accuracy.
    /// To project many points, build a [`CurveProjector`] once; for every local minimum
    /// see [`CurveProjector::local_minima`].
    ///
    /// ```
    /// use splinekit::{Point, curve::{BSplineCurve, CurveNearest}};
    /// let c = BSplineCurve::<2>::clamped_uniform(1, vec![Point::<2>::new(0.0, 0.0), Point::<2>::new(4.0, 0.0)]).unwrap();
    /// let near = c.closest_point(&Point::<2>::new(1.0, 3.0), 1e-12).unwrap();
    /// assert!((near.t - 0.25).abs() < 1e-15 && (near.distance - 3.0).abs() < 1e-15);
    /// ```
    fn closest_point(&self, query: &Point<D>, accuracy: f64) -> Result<Nearest<D>> {
        CurveProjector::new(self).nearest(query, accuracy)
    }
}

impl<const D: usize, C: Curve<D> + ?Sized> CurveNearest<D> for C {}

/// Projects many points onto one curve, building the curve's bounding hierarchy once.
#[derive(Debug, Clone)]
pub struct CurveProjector<'c, const D: usize, C: ?Sized> {
    curve: &'c C,
    cover: Cow<'c, CurveCover<D>>,
}

/// Checks a query point and an accuracy argument.
pub(crate) fn check_query<const D: usize>(q: &Point<D>, accuracy: f64) -> Result<()> {
    check_points_finite("point", std::slice::from_ref(q))?;
    if !(accuracy >= 0.0 && accuracy.is_finite()) {
        return Err(Error::invalid("accuracy", format!("must be finite and ≥ 0, got {accuracy}")));
    }
    Ok(())
}

impl<'c, const D: usize, C: Curve<D> + ?Sized> CurveProjector<'c, D, C> {
    /// Builds the bounding hierarchy of `curve` (see [`CurveCover`]).
    pub fn new(curve: &'c C) -> Self {
        CurveProjector { curve, cover: Cow::Owned(CurveCover::new(curve)) }
    }

    /// A projector on a cover built earlier for the same curve.
    pub fn with_cover(curve: &'c C, cover: &'c CurveCover<D>) -> Self {
        CurveProjector { curve, cover: Cow::Borrowed(cover) }
    }

    /// The point of the curve nearest to `q`, its distance within `accuracy` (≥ 0, absolute)
    /// of the true minimum; see the module documentation for what is guaranteed.
    pub fn nearest(&self, q: &Point<D>, accuracy: f64) -> Result<Nearest<D>> {
        check_query(q, accuracy)?;
        let mut best = Nearest::at(self.cover.domain.start, self.cover.nodes[0].piece.start.point, q);
        let offer = |s: &Sample<D>, best: &mut Nearest<D>| {
            let d = (s.point - q).norm();
            if d < best.distance {
                *best = Nearest { t: s.t, point: s.point, distance: d };
            }
        };
        let mut heap = BinaryHeap::new();
        for node in &self.cover.nodes[..self.cover.roots] {
            for s in [&node.piece.start, &node.piece.mid, &node.piece.end] {
                offer(s, &mut best);
            }
            heap.push(Ranked { bound: node.piece.bounds.distance_to(q), item: SearchPiece::Cached(node) });
        }
        let min_width = MIN_WIDTH * self.cover.domain.length();
        let slack = accuracy.max(ROUNDING * (q.amax() + self.cover.scale));
        while let Some(Ranked { bound, item: piece }) = heap.pop() {
            if bound >= best.distance - slack {
                break;
            }
            let p = piece.piece();
            match classify(p, q).shape {
                Shape::Increasing | Shape::Decreasing | Shape::Flat | Shape::OneMaximum => {}
                Shape::OneMinimum => {
                    let t = slope_root(self.curve, q, p.start.t, p.end.t);
                    let found = Nearest::at(t, self.curve.point(t), q);
                    if found.distance < best.distance {
                        best = found;
                    }
                }
                Shape::Unresolved if p.interval().length() <= min_width => {
                    if let Some(t) = bracketed_root(self.curve, q, p) {
                        let found = Nearest::at(t, self.curve.point(t), q);
                        if found.distance < best.distance {
                            best = found;
                        }
                    }
                }
                Shape::Unresolved => {
                    for half in piece.split(&self.cover, self.curve) {
                        offer(&half.piece().mid, &mut best);
                        let bound = half.piece().bounds.distance_to(q);
                        if bound < best.distance - slack {
                            heap.push(Ranked { bound, item: half });
                        }
                    }
                }
            }
        }
        Ok(best)
    }

    /// Every local minimum of the distance from `q` to the curve, in increasing parameter
    /// order (domain ends included where the distance grows away from them). See the module
    /// documentation.
    pub fn local_minima(&self, q: &Point<D>, accuracy: f64) -> Result<Vec<Nearest<D>>> {
        check_query(q, accuracy)?;
        let min_width = MIN_WIDTH * self.cover.domain.length();
        let mut leaves: Vec<Leaf<D>> = Vec::new();
        let mut interior: Vec<Nearest<D>> = Vec::new();
        // Depth first, right half pushed first, so leaves come out in parameter order.
        let mut stack: Vec<SearchPiece<'_, D>> =
            self.cover.nodes[..self.cover.roots].iter().rev().map(SearchPiece::Cached).collect();
        while let Some(piece) = stack.pop() {
            let p = piece.piece();
            let signs = classify(p, q);
            let root = match signs.shape {
                Shape::OneMinimum => Some(slope_root(self.curve, q, p.start.t, p.end.t)),
                Shape::Unresolved if p.interval().length() > min_width => {
                    let [a, b] = piece.split(&self.cover, self.curve);
                    stack.push(b);
                    stack.push(a);
                    continue;
                }
                Shape::Unresolved => bracketed_root(self.curve, q, p),
                _ => None,
            };
            if let Some(t) = root {
                interior.push(Nearest::at(t, self.curve.point(t), q));
            }
            leaves.push(Leaf {
                interval: p.interval(),
                start: signs.start,
                end: signs.end,
                flat: signs.shape == Shape::Flat,
                start_point: p.start.point,
                end_point: p.end.point,
            });
        }
        let mut minima = boundary_minima(&leaves, self.cover.closed, q);
        minima.extend(interior);
        Ok(merge_minima(minima, accuracy, self.cover.closed, self.cover.domain))
    }
}

/// A leaf of the local-minimum search, as the assembly of boundary minima needs it.
struct Leaf<const D: usize> {
    interval: Interval,
    start: i8,
    end: i8,
    flat: bool,
    start_point: Point<D>,
    end_point: Point<D>,
}

/// Minima at leaf boundaries (kinks, stationary points exactly at a boundary, domain ends)
/// and at the start of flat stretches; on closed curves the last leaf meets the first.
fn boundary_minima<const D: usize>(leaves: &[Leaf<D>], closed: bool, q: &Point<D>) -> Vec<Nearest<D>> {
    let n = leaves.len();
    let mut out = Vec::new();
    if leaves.iter().all(|l| l.flat) {
        out.push(Nearest::at(leaves[0].interval.start, leaves[0].start_point, q));
        return out;
    }
    // Start at a non-flat leaf so every flat run is seen whole (closed curves wrap).
    let first = if closed { leaves.iter().position(|l| !l.flat).unwrap_or(0) } else { 0 };
    let mut k = 0;
    while k < n {
        let i = (first + k) % n;
        if leaves[i].flat {
            // The run of flat leaves i … j.
            let mut len = 1;
            while k + len < n && leaves[(first + k + len) % n].flat {
                len += 1;
            }
            let j = (first + k + len - 1) % n;
            let left_ok = if i == 0 && !closed { true } else { leaves[(i + n - 1) % n].end < 0 };
            let right_ok = if j == n - 1 && !closed { true } else { leaves[(j + 1) % n].start > 0 };
            if left_ok && right_ok {
                out.push(Nearest::at(leaves[i].interval.start, leaves[i].start_point, q));
            }
            k += len;
            continue;
        }
        if i == 0 && !closed && leaves[0].start > 0 {
            out.push(Nearest::at(leaves[0].interval.start, leaves[0].start_point, q));
        }
        let last = i == n - 1;
        if last && !closed {
            if leaves[i].end < 0 {
                out.push(Nearest::at(leaves[i].interval.end, leaves[i].end_point, q));
            }
        } else {
            let next = &leaves[(i + 1) % n];
            if !next.flat && leaves[i].end < 0 && next.start > 0 {
                out.push(Nearest::at(next.interval.start, next.start_point, q));
            }
        }
        k += 1;
    }
    out
}

/// Sorts minima by parameter and merges duplicates — neighbours within `accuracy` (or
/// [`DUPLICATE_DISTANCE`] relative to the coordinates) in space
/// and [`DUPLICATE_WIDTH`] in parameter (relative to the domain), keeping the nearer —
/// including across the seam of a closed curve.
fn merge_minima<const D: usize>(
    mut minima: Vec<Nearest<D>>,
    accuracy: f64,
    closed: bool,
    domain: Interval,
) -> Vec<Nearest<D>> {
    minima.sort_by(|a, b| a.t.total_cmp(&b.t));
    let close = |a: &Nearest<D>, b: &Nearest<D>| {
        let scale = a.point.amax().max(b.point.amax()).max(1.0);
        let dt = (a.t - b.t).abs();
        let dt = if closed { dt.min(domain.length() - dt) } else { dt };
        (a.point - b.point).norm() <= accuracy.max(DUPLICATE_DISTANCE * scale)
            && dt <= DUPLICATE_WIDTH * domain.length()
    };
    let mut out: Vec<Nearest<D>> = Vec::with_capacity(minima.len());
    for m in minima {
        match out.last_mut() {
            Some(prev) if close(prev, &m) => {
                if m.distance < prev.distance {
                    *prev = m;
                }
            }
            _ => out.push(m),
        }
    }
    if closed && out.len() > 1 && close(&out[0], out.last().unwrap()) {
        let last = out.pop().unwrap();
        if last.distance < out[0].distance {
            out[0] = last;
        }
    }
    out
}

/// The root of the slope on a piece whose end slopes bracket a minimum (− at the start,
/// + at the end), or `None` when they do not.
fn bracketed_root<const D: usize, C: Curve<D> + ?Sized>(curve: &C, q: &Point<D>, p: &CurvePiece<D>) -> Option<f64> {
    let g0 = (p.start.point - q).dot(&p.start.derivative);
    let g1 = (p.end.point - q).dot(&p.end.derivative);
    (g0 < 0.0 && g1 > 0.0).then(|| slope_root(curve, q, p.start.t, p.end.t))
}

/// The root in [lo, hi] of g(t) = (c(t) − q)·c′(t), given g(lo) ≤ 0 ≤ g(hi): Newton steps
/// with g′ = |c′|² + (c − q)·c″, replaced by bisection whenever a step leaves the bracket
/// or fails to halve |g|; the bracket shrinks around the sign change every iteration.
pub(crate) fn slope_root<const D: usize, C: Curve<D> + ?Sized>(curve: &C, q: &Point<D>, lo: f64, hi: f64) -> f64 {
    let (mut lo, mut hi) = (lo, hi);
    let mut t = 0.5 * (lo + hi);
    let mut out = [Point::<D>::zeros(); 3];
    let mut last_g = f64::INFINITY;
    for _ in 0..MAX_ROOT_ITERATIONS {
        curve.eval(t, &mut out);
        let r = out[0] - q;
        let g = r.dot(&out[1]);
        if g == 0.0 {
            return t;
        }
        if g < 0.0 {
            lo = t;
        } else {
            hi = t;
        }
        let dg = out[1].norm_squared() + r.dot(&out[2]);
        let newton = t - g / dg;
        let next = if newton > lo && newton < hi && g.abs() < 0.5 * last_g { newton } else { 0.5 * (lo + hi) };
        last_g = g.abs();
        if (next - t).abs() <= 2.0 * f64::EPSILON * t.abs().max(f64::MIN_POSITIVE) || hi - lo <= f64::EPSILON * t.abs()
        {
            return next;
        }
        t = next;
    }
    t
}
