//! The offset of a plane curve at signed distance d: the points at distance |d| from the
//! curve on its right-hand side (d > 0) or left-hand side (d < 0), as B-spline pieces.
//!
//! Method:
//! 1. The raw offset o(t) = c(t) + d·n(t) ([`RawOffset`]) is approximated over the whole
//!    domain by cubic Hermite pieces refined until the error is within the tolerance
//!    ([`fit_raw_offset`]); the factor 1 + dκ is sampled on every piece on the way.
//! 2. Cusps: where 1 + dκ changes sign between two samples, the root is bisected to full
//!    precision (o′ = (1 + dκ)c′ vanishes there and the offset turns back).
//! 3. Self-intersections: the raw offset is cut at its cusps into regular arcs, each
//!    approximated on its own; crossings of every arc with itself
//!    ([`self_intersections`]) and of every two arcs whose boxes meet ([`intersect_curves`])
//!    are found on the approximations (tolerance 10⁻² of the offset's).
//! 4. Trimming: the domain is cut at the cusps, at both parameters of every crossing and
//!    (open curves, curves with corners) where the raw offset crosses the circle of radius
//!    |d| about an end or a corner of the curve;
//!    a stretch whose points at ¼, ½ and ¾ of it are all at distance ≥ |d| − tolerance from
//!    the curve (by projection, [`CurveProjector`]) belongs to the true offset, the others
//!    (the swallowtails behind cusps, loops, the parts nearer to another stretch of the
//!    curve) are dropped. Each point of the raw offset is at distance |d| from its own foot
//!    c(t), so it is on the true offset exactly when no other point of the curve is nearer;
//!    that can only change at a crossing of the raw offset with itself or at a cusp.
//! 5. Kept stretches that meet at a crossing parameter (not at a cusp) are joined, across
//!    the seam for a closed curve, and each is approximated again on exactly its
//!    parameters; a closed curve whose raw offset needs no trimming gives one periodic
//!    B-spline.
//!
//! The pieces are parametrised by the curve's own parameter t (their domains are the kept
//! stretches of t, running past the end of a closed curve's domain for a piece across its
//! seam). Open curves get no arcs around their ends: the pieces are parts of the raw offset.
//! Where the curve's own tangent vanishes at an end of its domain (the seam of the heart
//! curve, a cusp of the curve where the normal flips), that end is moved inwards by
//! [`SINGULAR_END`] of the domain and a closed curve is offset as an open one; such a point
//! inside the domain is an error naming its parameter.
//! An offset that collapses to a point (a circle of radius r at d = −r) or is trimmed away
//! entirely (deeper inside a closed convex curve than its inradius) has no pieces.

use crate::Point;
use crate::basis::Side;
use crate::curve::{BSplineCurve, Curve, Interval};
use crate::error::{Error, Result};
use crate::query::bounds::Aabb;
use crate::query::offset::check_arguments;
use crate::query::offset::hermite_fit::{HermiteFit, fit_raw_offset};
use crate::query::offset::planar_frame::{InPlane, PlanarFrame};
use crate::query::offset::raw_curve::RawOffset;
use crate::query::{CurveProjector, intersect_curves, self_intersections};

/// The most cusps a raw offset may have.
pub const MAX_CUSPS: usize = 1000;

/// The raw offset counts as collapsed to a point where |1 + dκ| stays below this.
const COLLAPSED: f64 = 1e-9;

/// Crossings are located with this fraction of the offset's tolerance.
const CROSSING_TOLERANCE: f64 = 1e-2;

/// Arcs are searched for crossings without this fraction of them next to a cusp, where
/// the tangent of their approximation vanishes (crossings nearer to a cusp are not found).
pub const CUSP_GAP: f64 = 1e-6;

/// Two arcs meeting at a cusp are compared without this fraction of each next to it.
pub const CUSP_MARGIN: f64 = 0.02;

/// Ends of the domain where the curve's tangent vanishes are moved inwards by this
/// fraction of the domain.
pub const SINGULAR_END: f64 = 1e-9;

/// The raw offset jumps at a breakpoint (a corner of the curve) when its one-sided limits
/// are farther apart than this fraction of |d|.
const CORNER_JUMP: f64 = 1e-9;

/// Speed samples per span between breakpoints, searched for points where c′ vanishes.
const SPEED_SAMPLES: usize = 64;

/// A local minimum of the speed below this fraction of the mean speed is a singular point.
const SINGULAR_SPEED: f64 = 1e-7;

/// Golden-section steps refining a minimum of the speed.
const GOLDEN_STEPS: usize = 80;

/// Newton steps polishing one crossing.
const POLISH_STEPS: usize = 30;

/// Bisection steps for one root (a cusp, or where the offset crosses an end circle).
const BISECTION_STEPS: usize = 200;

/// One piece of an offset: a cubic B-spline within the tolerance of the exact offset.
#[derive(Debug, Clone)]
pub struct OffsetPiece<const D: usize> {
    /// The piece, on the parameters `params` of the curve.
    pub curve: BSplineCurve<D>,
    /// The stretch of the curve's parameter it offsets.
    pub params: Interval,
    /// The largest error measured against the exact offset, max |B(t) − o(t)|.
    pub max_error: f64,
}

/// The offset of a curve: its pieces after trimming, and what was trimmed.
#[derive(Debug, Clone)]
pub struct CurveOffset<const D: usize> {
    /// The pieces in increasing parameter order (empty when nothing is left).
    pub pieces: Vec<OffsetPiece<D>>,
    /// The largest error of any piece.
    pub max_error: f64,
    /// Parameters of the curve where the raw offset has a cusp (1 + dκ = 0).
    pub cusps: Vec<f64>,
    /// Parameter pairs (t_a < t_b) where the raw offset crosses itself.
    pub crossings: Vec<(f64, f64)>,
}

/// The offset of `curve` at signed distance `distance` within `tolerance` (> 0) of the
/// exact offset (see the module documentation). 2-D curves are offset in their plane
/// (`normal` absent or +z); a 3-D curve needs `normal`, the normal direction V of the plane
/// it lies in (within the tolerance), and is offset along T × V/|V|. d > 0 is the
/// right-hand side (outwards for a counter-clockwise curve).
///
/// ```
/// use splinekit::Point;
/// use splinekit::curve::{Curve, model::Circle};
/// use splinekit::query::offset_curve;
/// // The circle of radius 2 (in the plane z = 0) at distance 0.5: the circle of radius 2.5.
/// let c = Circle::new(2.0).unwrap();
/// let off = offset_curve(&c, 0.5, Some(Point::<3>::z()), 1e-7).unwrap();
/// assert_eq!(off.pieces.len(), 1);
/// let piece = &off.pieces[0].curve;
/// assert!(piece.is_closed() && off.max_error <= 1e-7);
/// assert!((piece.point(1.0).norm() - 2.5).abs() < 1e-7);
/// ```
pub fn offset_curve<const D: usize, C: Curve<D> + ?Sized>(
    curve: &C,
    distance: f64,
    normal: Option<Point<3>>,
    tolerance: f64,
) -> Result<CurveOffset<D>> {
    check_arguments(distance, tolerance)?;
    let frame = PlanarFrame::of(curve, normal, tolerance)?;
    let plane = without_singular_ends(InPlane::new(curve, frame), distance)?;
    let corners = corners(&plane, distance);
    // A curve with corners is offset as an open one, section by section.
    let plane = InPlane { closed: plane.closed && corners.is_empty(), ..plane };
    let raw = RawOffset::new(&plane, distance);
    let dom = plane.domain();
    let closed = plane.is_closed();
    let clip = |a: Interval| clip_at_corners(a, &corners, dom);
    let sections: Vec<Interval> =
        arcs_between(&corners.iter().map(|c| c.0).collect::<Vec<_>>(), dom, false).into_iter().map(clip).collect();
    let fits: Vec<HermiteFit> =
        sections.iter().map(|s| fit_raw_offset(&raw, *s, tolerance, closed)).collect::<Result<_>>()?;
    if fits.iter().flat_map(|f| &f.factors).all(|(_, f)| f.abs() <= COLLAPSED) {
        let max_error = fits.iter().fold(0.0f64, |m, f| m.max(f.max_error));
        return Ok(CurveOffset { pieces: Vec::new(), max_error, cusps: Vec::new(), crossings: Vec::new() });
    }
    let mut cusps = Vec::new();
    for f in &fits {
        find_cusps(&raw, f, &mut cusps)?;
    }
    let mut cuts: Vec<f64> = cusps.iter().copied().chain(corners.iter().map(|c| c.0)).collect();
    cuts.sort_by(f64::total_cmp);
    let arcs: Vec<Interval> = arcs_between(&cuts, dom, closed).into_iter().map(clip).collect();
    let crossings: Vec<(f64, f64)> =
        crossings(&raw, &arcs, &fits[0], &cusps, tolerance)?.into_iter().map(|c| polish(&raw, c, dom)).collect();
    let mut splits: Vec<f64> = cuts.clone();
    for &(a, b) in &crossings {
        splits.push(wrap(a, dom, closed));
        splits.push(wrap(b, dom, closed));
    }
    if !closed {
        splits.extend(end_circles(&raw, &fits, &corners, dom));
    }
    splits.sort_by(f64::total_cmp);
    splits.dedup_by(|b, a| (*b - *a).abs() <= 1e-12 * dom.length());
    let whole = &fits[0];
    let projector = CurveProjector::new(&plane);
    let mut kept: Vec<(Interval, bool)> = Vec::new();
    for stretch in arcs_between(&splits, dom, closed).into_iter().map(clip) {
        let keep = [0.25, 0.5, 0.75].into_iter().try_fold(true, |keep, s| -> Result<bool> {
            let p = raw.at(stretch.lerp(s), Side::Right).map(|r| r.point);
            let Some(p) = p else { return Ok(false) };
            Ok(keep && projector.nearest(&p, 0.0)?.distance >= distance.abs() - tolerance)
        })?;
        kept.push((stretch, keep));
    }
    let stretches = join_kept(&kept, &cuts, dom, closed);
    let mut pieces = Vec::with_capacity(stretches.len());
    for s in stretches {
        if closed && splits.is_empty() {
            pieces.push(piece_of(whole, s, &frame)?);
            continue;
        }
        let periodic = closed && (s.length() - dom.length()).abs() <= 1e-12 * dom.length();
        pieces.push(piece_of(&fit_raw_offset(&raw, s, tolerance, periodic)?, s, &frame)?);
    }
    let max_error = pieces.iter().fold(0.0f64, |m, p| m.max(p.max_error));
    Ok(CurveOffset { pieces, max_error, cusps, crossings })
}

/// The curve without the ends of its domain where c′ = 0 (the seam of the heart, a cusp of
/// the curve itself: the normal flips there and the raw offset jumps), each moved
/// [`SINGULAR_END`] of the domain inwards; a closed curve is then open.
fn without_singular_ends<'c, const D: usize, C: Curve<D> + ?Sized>(
    mut plane: InPlane<'c, D, C>,
    distance: f64,
) -> Result<InPlane<'c, D, C>> {
    let raw = RawOffset::new(&plane, distance);
    let dom = plane.domain;
    let eps = SINGULAR_END * dom.length();
    let (bad_start, bad_end) = (raw.at(dom.start, Side::Right).is_none(), raw.at(dom.end, Side::Left).is_none());
    if bad_start || bad_end {
        let start = if bad_start { dom.start + eps } else { dom.start };
        let end = if bad_end { dom.end - eps } else { dom.end };
        plane.domain = Interval::new(start, end);
        plane.closed = false;
    }
    Ok(plane)
}

/// Whether t is one of `params` (to 10⁻⁶ of the domain; wrapped for a closed curve).
fn is_at(params: &[f64], t: f64, dom: Interval, closed: bool) -> bool {
    params.iter().any(|&c| (wrap(t, dom, closed) - c).abs() <= 1e-6 * dom.length())
}

/// Parameters inside the domain where the raw offset jumps: the curve's tangent vanishes
/// (true: at a local minimum of the speed |c′| below [`SINGULAR_SPEED`] of its mean,
/// sampled at [`SPEED_SAMPLES`] points per span between breakpoints and refined by golden
/// section) or turns by a corner at a breakpoint (false).
fn corners<const D: usize, C: Curve<D> + ?Sized>(plane: &InPlane<'_, D, C>, distance: f64) -> Vec<(f64, bool)> {
    let raw = RawOffset::new(plane, distance);
    let dom = plane.domain();
    let mut out = Vec::new();
    for t in plane.breakpoints().into_iter().filter(|&t| t > dom.start && t < dom.end) {
        match (raw.at(t, Side::Left), raw.at(t, Side::Right)) {
            (Some(l), Some(r)) if (l.point - r.point).norm() <= CORNER_JUMP * distance.abs() => {}
            (Some(_), Some(_)) => out.push((t, false)),
            _ => out.push((t, true)),
        }
    }
    let speed = |t: f64| plane.derivative(t, 1).norm();
    let breaks = plane.breakpoints();
    let mut samples: Vec<(f64, f64)> = Vec::new();
    for w in breaks.windows(2) {
        let span = Interval::new(w[0], w[1]);
        for k in 1..SPEED_SAMPLES {
            let t = span.lerp(k as f64 / SPEED_SAMPLES as f64);
            samples.push((t, speed(t)));
        }
    }
    let mean = samples.iter().map(|s| s.1).sum::<f64>() / samples.len().max(1) as f64;
    for w in samples.windows(3) {
        if !(w[1].1 <= w[0].1 && w[1].1 <= w[2].1) {
            continue;
        }
        let (mut lo, mut hi) = (w[0].0, w[2].0);
        for _ in 0..GOLDEN_STEPS {
            let (m1, m2) = (lo + 0.382 * (hi - lo), lo + 0.618 * (hi - lo));
            if speed(m1) < speed(m2) { hi = m2 } else { lo = m1 }
        }
        let t = 0.5 * (lo + hi);
        let t = if speed(w[1].0) <= speed(t) { w[1].0 } else { t };
        if speed(t) <= SINGULAR_SPEED * mean && !out.iter().any(|c| (c.0 - t).abs() <= 1e-9 * dom.length()) {
            out.push((t, true));
        }
    }
    out.sort_by(|a, b| a.0.total_cmp(&b.0));
    out
}

/// A stretch with its ends at singular corners moved [`SINGULAR_END`] of the domain inwards.
fn clip_at_corners(a: Interval, corners: &[(f64, bool)], dom: Interval) -> Interval {
    let eps = SINGULAR_END * dom.length();
    let singular = |t: f64| corners.iter().any(|&(c, s)| s && (c - t).abs() <= 1e-12 * dom.length());
    let start = if singular(a.start) { a.start + eps } else { a.start };
    let end = if singular(a.end) { a.end - eps } else { a.end };
    Interval::new(start, end)
}

/// A parameter wrapped into the domain of a closed curve.
fn wrap(t: f64, dom: Interval, closed: bool) -> f64 {
    if closed { dom.wrap(t) } else { t }
}

/// Roots of 1 + dκ where it changes sign between consecutive samples of `fit`, by
/// bisection, added to `cusps` (at most [`MAX_CUSPS`] over the whole offset).
fn find_cusps<C: Curve<2> + ?Sized>(raw: &RawOffset<'_, C>, fit: &HermiteFit, cusps: &mut Vec<f64>) -> Result<()> {
    for w in fit.factors.windows(2) {
        let ((a, fa), (b, fb)) = (w[0], w[1]);
        if fa * fb >= 0.0 || fa.abs().max(fb.abs()) <= COLLAPSED || b <= a {
            continue;
        }
        cusps.push(bisect_sign_change(|t| Some(raw.at(t, Side::Right).map_or(0.0, |s| s.factor)), (a, b), fa));
        if cusps.len() > MAX_CUSPS {
            return Err(Error::invalid(
                "distance",
                format!(
                    "the raw offset at d = {} has more than {MAX_CUSPS} cusps (d is near a radius of curvature along a stretch of the curve)",
                    raw.distance
                ),
            ));
        }
    }
    Ok(())
}

/// A root of `g` in [a, b] where g(a) = `ga` and g(b) have opposite signs, by bisection
/// to the resolution of the doubles ([`BISECTION_STEPS`] at most); an exact zero ends it,
/// and so does a parameter where `g` has no value (the root is then the middle of what is
/// left).
fn bisect_sign_change(g: impl Fn(f64) -> Option<f64>, (mut a, mut b): (f64, f64), ga: f64) -> f64 {
    for _ in 0..BISECTION_STEPS {
        let m = 0.5 * (a + b);
        if m <= a || m >= b {
            break;
        }
        match g(m) {
            Some(0.0) => return m,
            Some(gm) if (gm > 0.0) == (ga > 0.0) => a = m,
            Some(_) => b = m,
            None => break,
        }
    }
    0.5 * (a + b)
}

/// The stretches of the domain between consecutive cut parameters (increasing); for a
/// closed curve the last runs across the seam to the first cut plus one period.
fn arcs_between(cuts: &[f64], dom: Interval, closed: bool) -> Vec<Interval> {
    let inner: Vec<f64> = cuts.iter().copied().filter(|&t| t > dom.start && t < dom.end).collect();
    if closed && !inner.is_empty() {
        let n = inner.len();
        let mut arcs: Vec<Interval> = inner.windows(2).map(|w| Interval::new(w[0], w[1])).collect();
        arcs.push(Interval::new(inner[n - 1], inner[0] + dom.length()));
        return arcs;
    }
    let mut ends = vec![dom.start];
    ends.extend(inner);
    ends.push(dom.end);
    ends.windows(2).map(|w| Interval::new(w[0], w[1])).collect()
}

/// Every crossing of the raw offset with itself, as parameter pairs t_a < t_b: found on
/// the approximations of its regular arcs (the whole fit when there are no cusps). Two
/// arcs that meet at a cusp stay within any tolerance of each other near it (their
/// distance grows like the cube of the parameter distance), so they are compared without
/// the [`CUSP_MARGIN`] of each next to the cusp they share.
fn crossings<C: Curve<2> + ?Sized>(
    raw: &RawOffset<'_, C>,
    arcs: &[Interval],
    whole: &HermiteFit,
    cusps: &[f64],
    tolerance: f64,
) -> Result<Vec<(f64, f64)>> {
    let itol = CROSSING_TOLERANCE * tolerance;
    let mut pairs = Vec::new();
    let mut add = |found: &crate::query::CurveIntersections<2>| {
        pairs.extend(found.points.iter().map(|p| (p.t_a, p.t_b)));
        pairs.extend(found.overlaps.iter().flat_map(|o| [(o.a.start, o.b.0), (o.a.end, o.b.1)]));
    };
    if arcs.len() == 1 {
        add(&self_intersections(&whole.curve, itol)?);
        return Ok(ordered(pairs));
    }
    let fit = |a: Interval| fit_raw_offset(raw, a, tolerance, false).map(|f| f.curve);
    // Arcs end at cusps, corners of the curve or the ends of an open curve's domain.
    let (dom, closed) = (raw.curve.domain(), raw.curve.is_closed());
    let at_cusp = |t: f64| is_at(cusps, t, dom, closed);
    let inside = |a: &Interval| {
        let m = CUSP_GAP * a.length();
        let start = if at_cusp(a.start) { a.start + m } else { a.start };
        let end = if at_cusp(a.end) { a.end - m } else { a.end };
        Interval::new(start, end)
    };
    let arcs: Vec<Interval> = arcs.iter().map(inside).collect();
    let fits: Vec<BSplineCurve<2>> = arcs.iter().map(|a| fit(*a)).collect::<Result<_>>()?;
    let boxes: Vec<Aabb<2>> = fits.iter().map(|f| Aabb::around(f.control_points(), itol)).collect();
    let n = arcs.len();
    for i in 0..n {
        add(&self_intersections(&fits[i], itol)?);
        for j in i + 1..n {
            if !boxes[i].overlaps(&boxes[j], 0.0) {
                continue;
            }
            // Arcs i and j share the cusp between them (or the one at the seam).
            let next = j == i + 1 && at_cusp(arcs[i].end);
            let across = closed && i == 0 && j == n - 1 && at_cusp(arcs[0].start);
            if next || across {
                let (a, b) = (arcs[i], arcs[j]);
                let (ma, mb) = (CUSP_MARGIN * a.length(), CUSP_MARGIN * b.length());
                let cut = |x: bool, m: f64| if x { m } else { 0.0 };
                let a = Interval::new(a.start + cut(across, ma), a.end - cut(next, ma));
                let b = Interval::new(b.start + cut(next, mb), b.end - cut(across, mb));
                add(&intersect_curves(&fit(a)?, &fit(b)?, itol)?);
            } else {
                add(&intersect_curves(&fits[i], &fits[j], itol)?);
            }
        }
    }
    Ok(ordered(pairs))
}

/// Where the raw offset crosses a circle of radius |d| about an end or a corner of the
/// curve: beyond such a point the offset is nearer to that end or corner than |d| and is
/// trimmed (the arc about the end itself is not added). Found as sign changes of
/// |o(t) − P| − |d| at the fits' samples, bisected.
fn end_circles<C: Curve<2> + ?Sized>(
    raw: &RawOffset<'_, C>,
    fits: &[HermiteFit],
    corners: &[(f64, bool)],
    dom: Interval,
) -> Vec<f64> {
    let mut centres = vec![raw.curve.point(dom.start), raw.curve.point(dom.end)];
    centres.extend(corners.iter().map(|c| raw.curve.point(c.0)));
    let r = raw.distance.abs();
    let mut out = Vec::new();
    for centre in &centres {
        let g = |t: f64| raw.at(t, Side::Right).map(|s| (s.point - centre).norm() - r);
        for fit in fits {
            for w in fit.factors.windows(2) {
                let (a, b) = (w[0].0, w[1].0);
                let (Some(ga), Some(gb)) = (g(a), g(b)) else { continue };
                if ga * gb >= 0.0 || b <= a {
                    continue;
                }
                out.push(bisect_sign_change(g, (a, b), ga));
            }
        }
    }
    out
}

/// A crossing found on the approximations, polished by Newton's method on the exact raw
/// offset: o(a) − o(b) = 0 with the Jacobian [o′(a), −o′(b)] (a shallow crossing, as where
/// the offsets of the two sides of a corner meet, is located to the tolerance divided by
/// the sine of its angle on the approximations, to rounding here). Steps that would leave
/// the neighbourhood of the start (10⁻³ of the domain) keep the start.
fn polish<C: Curve<2> + ?Sized>(raw: &RawOffset<'_, C>, start: (f64, f64), dom: Interval) -> (f64, f64) {
    let (mut a, mut b) = start;
    for _ in 0..POLISH_STEPS {
        let (Some(p), Some(q)) = (raw.at(a, Side::Right), raw.at(b, Side::Right)) else { return start };
        let f = p.point - q.point;
        let (j0, j1) = (p.derivative, -q.derivative);
        let det = j0.x * j1.y - j1.x * j0.y;
        if det.abs() <= f64::MIN_POSITIVE || !det.is_finite() {
            break;
        }
        let da = (f.x * j1.y - j1.x * f.y) / det;
        let db = (j0.x * f.y - f.x * j0.y) / det;
        (a, b) = (a - da, b - db);
        if da.abs().max(db.abs()) <= crate::query::newton::ROUNDING_STEP * dom.length() {
            break;
        }
    }
    let far = 1e-3 * dom.length();
    if (a - start.0).abs() > far || (b - start.1).abs() > far || !a.is_finite() || !b.is_finite() {
        return start;
    }
    if a <= b { (a, b) } else { (b, a) }
}

/// Parameter pairs with the smaller first.
fn ordered(pairs: Vec<(f64, f64)>) -> Vec<(f64, f64)> {
    pairs.into_iter().map(|(a, b)| if a <= b { (a, b) } else { (b, a) }).collect()
}

/// Consecutive kept stretches joined where they meet at a crossing (not at one of the
/// `cuts`, the cusps of the raw offset and the corners of the curve), across the seam of a
/// closed curve too.
fn join_kept(kept: &[(Interval, bool)], cuts: &[f64], dom: Interval, closed: bool) -> Vec<Interval> {
    let at_cusp = |t: f64| is_at(cuts, t, dom, closed);
    let mut out: Vec<Interval> = Vec::new();
    let mut open_run = false;
    for &(s, keep) in kept {
        if !keep {
            open_run = false;
            continue;
        }
        match out.last_mut() {
            Some(last) if open_run && !at_cusp(s.start) => last.end = s.end,
            _ => out.push(s),
        }
        open_run = true;
    }
    let wraps = closed && kept.len() > 1 && kept[0].1 && kept[kept.len() - 1].1 && !at_cusp(kept[0].0.start);
    if wraps && out.len() > 1 {
        let first = out.remove(0);
        let last = out.last_mut().expect("two stretches");
        last.end = first.end + dom.length();
    }
    out
}

/// A fitted stretch mapped from plane coordinates into ℝᴰ.
fn piece_of<const D: usize>(fit: &HermiteFit, params: Interval, frame: &PlanarFrame<D>) -> Result<OffsetPiece<D>> {
    let c = &fit.curve;
    let control: Vec<Point<D>> = c.control_points().iter().map(|q| frame.from_plane(q)).collect();
    let curve = if c.is_periodic() {
        BSplineCurve::new_periodic(3, c.knots().to_vec(), control)?
    } else {
        BSplineCurve::new(3, c.knots().to_vec(), control)?
    };
    Ok(OffsetPiece { curve, params, max_error: fit.max_error })
}
