//! Intersections of two curves, and self-intersections of one, in any dimension.
//!
//! Method: interval subdivision with bounding volumes over the two curves'
//! [`CurveCover`]s, then Newton's method. A pair of pieces is dropped when their boxes
//! (grown by the tolerance) are apart. When the pieces' tangent cones share no line
//! direction ([`TangentCone::separated_lines`]) the pair holds at most one intersection,
//! which Gauss–Newton iteration on c_a(s) − c_b(t) = 0 (least squares in 3-D: (JᵀJ)δ = −JᵀF,
//! J = [c_a′, −c_b′]) inside the two pieces finds to full precision. Pairs whose cones
//! overlap are tested for coincidence (an overlapping stretch, recorded as two parameter
//! intervals) and otherwise split, the larger piece first, until both boxes are smaller than
//! the tolerance: there the nearest pair of points is a tangential contact when it is within
//! the tolerance. Overlaps shorter than [`MIN_OVERLAP`] of the curves' size are taken for
//! tangential contacts.
//!
//! What is guaranteed (where the cover's radii bound the curves, always for polynomial
//! pieces of degree ≤ 3): every point where the curves come within `tolerance` of each other
//! lies in a pair that is examined, so no crossing is missed, however close two crossings
//! are — crossings are separated down to pieces whose tangents point apart, and tangential
//! contacts to pieces of size `tolerance`; contacts and crossings closer than `tolerance`
//! to each other (in space) are reported once. A crossing is a point where the tangents
//! make an angle with sine above [`TANGENT_SINE`]; below it the point is a tangent contact.

use crate::Interval;
use crate::Point;
use crate::curve::Curve;
use crate::error::{Error, Result};
use crate::query::bounds::Aabb;
use crate::query::curve_cover::{CurveCover, SearchPiece};
use crate::query::newton::{self, Step, cap, settled_all};
use crate::query::pair_count::PairCount;
use crate::query::tangent_cone::TangentCone;

/// Sine of the angle below which an intersection counts as a tangential contact.
pub const TANGENT_SINE: f64 = 1e-6;

/// The most pairs of pieces one intersection examines before it reports an error.
pub const MAX_PAIRS: usize = 2_000_000;

/// Tangential contacts closer than this fraction of the curves' size are one.
pub const TANGENT_RESOLUTION: f64 = 1e-6;

/// Overlapping stretches shorter than this fraction of the curves' size are tangential
/// contacts.
pub const MIN_OVERLAP: f64 = 1e-3;

/// How two curves meet at an isolated point.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum IntersectionKind {
    /// The tangents make an angle (sine above [`TANGENT_SINE`]).
    Crossing,
    /// The curves touch with (nearly) parallel tangents.
    Tangent,
}

/// An isolated intersection point of two curves.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CurveIntersection<const D: usize> {
    /// Parameter on the first curve.
    pub t_a: f64,
    /// Parameter on the second curve.
    pub t_b: f64,
    /// The point (the midpoint of c_a(t_a) and c_b(t_b)).
    pub point: Point<D>,
    /// Crossing or tangent contact.
    pub kind: IntersectionKind,
}

/// A stretch along which two curves coincide (within the tolerance): parameters `a` on the
/// first curve and `b` on the second, where `b.0` corresponds to `a.start` and `b.1` to
/// `a.end` (so `b.0 > b.1` when the curves run in opposite directions).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CurveOverlap {
    /// The stretch of the first curve.
    pub a: Interval,
    /// The matching parameters on the second curve, at the start and end of `a`.
    pub b: (f64, f64),
}

/// Everything two curves have in common.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct CurveIntersections<const D: usize> {
    /// Isolated points, sorted by `t_a`.
    pub points: Vec<CurveIntersection<D>>,
    /// Overlapping stretches, sorted by `a.start`.
    pub overlaps: Vec<CurveOverlap>,
}

fn check_tolerance(tolerance: f64) -> Result<()> {
    if tolerance > 0.0 && tolerance.is_finite() {
        Ok(())
    } else {
        Err(Error::invalid("tolerance", format!("must be finite and > 0, got {tolerance}")))
    }
}

/// Every intersection of `a` and `b` (see the module documentation); `tolerance` (> 0,
/// absolute) is the distance below which the curves count as meeting.
pub fn intersect_curves<const D: usize, A, B>(a: &A, b: &B, tolerance: f64) -> Result<CurveIntersections<D>>
where
    A: Curve<D> + ?Sized,
    B: Curve<D> + ?Sized,
{
    check_tolerance(tolerance)?;
    let (cover_a, cover_b) = (CurveCover::new(a), CurveCover::new(b));
    let mut search = Search::new(a, b, tolerance, false, cover_size(&cover_a).max(cover_size(&cover_b)));
    let mut pairs = Vec::new();
    for na in &cover_a.nodes[..cover_a.roots] {
        for nb in &cover_b.nodes[..cover_b.roots] {
            pairs.push((SearchPiece::Cached(na), SearchPiece::Cached(nb)));
        }
    }
    search.run(pairs, &cover_a, &cover_b)?;
    Ok(search.finish())
}

/// Every self-intersection of `curve`: pairs of different parameters t_a < t_b with the
/// same point (for closed curves, the seam is not one). See the module documentation.
pub fn self_intersections<const D: usize, C: Curve<D> + ?Sized>(
    curve: &C,
    tolerance: f64,
) -> Result<CurveIntersections<D>> {
    check_tolerance(tolerance)?;
    let cover = CurveCover::new(curve);
    let mut search = Search::new(curve, curve, tolerance, true, cover_size(&cover));
    let roots: Vec<SearchPiece<'_, D>> = cover.nodes[..cover.roots].iter().map(SearchPiece::Cached).collect();
    let mut singles = roots.clone();
    let mut pairs = Vec::new();
    for i in 0..roots.len() {
        for j in i + 1..roots.len() {
            pairs.push((roots[i].clone(), roots[j].clone()));
        }
    }
    // A piece whose tangents all lie within 90° of one axis runs monotonically along it and
    // cannot meet itself; others are split into two halves and their pair.
    while let Some(piece) = singles.pop() {
        if TangentCone::of(piece.piece()).half_angle < std::f64::consts::FRAC_PI_2 {
            continue;
        }
        if piece.piece().interval().length() <= search.min_width() {
            continue;
        }
        let [l, r] = piece.split(&cover, curve);
        pairs.push((l.clone(), r.clone()));
        singles.push(l);
        singles.push(r);
    }
    search.run(pairs, &cover, &cover)?;
    Ok(search.finish())
}

/// The state of one intersection search.
struct Search<'c, const D: usize, A: ?Sized, B: ?Sized> {
    a: &'c A,
    b: &'c B,
    tolerance: f64,
    same: bool,
    /// The larger of the two curves' sizes (root box diagonals).
    size: f64,
    points: Vec<CurveIntersection<D>>,
    overlaps: Vec<CurveOverlap>,
}

impl<'c, const D: usize, A: Curve<D> + ?Sized, B: Curve<D> + ?Sized> Search<'c, D, A, B> {
    fn new(a: &'c A, b: &'c B, tolerance: f64, same: bool, size: f64) -> Self {
        Search { a, b, tolerance, same, size, points: Vec::new(), overlaps: Vec::new() }
    }

    /// For a closed curve against itself: whether the two intervals meet at the seam.
    fn across_seam(&self, x: Interval, y: Interval) -> bool {
        let d = self.a.domain();
        self.a.is_closed() && ((x.start == d.start && y.end == d.end) || (y.start == d.start && x.end == d.end))
    }

    /// For a curve against itself: whether parameters s and t name the same point of the
    /// parameter circle (equal, or the two ends of a closed curve's domain).
    fn same_parameter(&self, s: f64, t: f64) -> bool {
        let d = self.a.domain();
        let w = self.min_width();
        (s - t).abs() <= w || (self.a.is_closed() && ((s - t).abs() - d.length()).abs() <= w)
    }

    /// Pieces narrower than this are not split (relative to the whole domain).
    fn min_width(&self) -> f64 {
        crate::query::project_curve::MIN_WIDTH * self.a.domain().length().max(self.b.domain().length())
    }

    fn run<'p>(
        &mut self,
        mut pairs: Vec<(SearchPiece<'p, D>, SearchPiece<'p, D>)>,
        cover_a: &'p CurveCover<D>,
        cover_b: &'p CurveCover<D>,
    ) -> Result<()> {
        let mut count = PairCount::new(MAX_PAIRS);
        while let Some((pa, pb)) = pairs.pop() {
            count.next("intersection", "pairs of pieces; try a larger tolerance")?;
            let (x, y) = (pa.piece(), pb.piece());
            if !x.bounds.overlaps(&y.bounds, self.tolerance) {
                continue;
            }
            let adjacent = self.same
                && (x.end.t == y.start.t || y.end.t == x.start.t || self.across_seam(x.interval(), y.interval()));
            let (cx, cy) = (TangentCone::of(x), TangentCone::of(y));
            if adjacent && cx.union(&cy).half_angle < std::f64::consts::FRAC_PI_2 {
                continue;
            }
            if cx.separated_lines(&cy) && !adjacent {
                self.newton(x.interval(), y.interval(), false);
                continue;
            }
            let (dx, dy) = (x.bounds.diagonal(), y.bounds.diagonal());
            let tiny = dx <= self.tolerance && dy <= self.tolerance;
            let narrow = x.interval().length() <= self.min_width() && y.interval().length() <= self.min_width();
            if tiny || narrow {
                if !adjacent {
                    self.newton(x.interval(), y.interval(), true);
                }
                continue;
            }
            if !adjacent && self.coincide((x.interval(), &x.bounds), (y.interval(), &y.bounds), dx.min(dy)) {
                continue;
            }
            if dx >= dy {
                pairs.extend(pa.split(cover_a, self.a).into_iter().map(|h| (h, pb.clone())));
            } else {
                pairs.extend(pb.split(cover_b, self.b).into_iter().map(|h| (pa.clone(), h)));
            }
        }
        Ok(())
    }

    /// Gauss–Newton iteration for c_a(s) = c_b(t) inside the two intervals, from their
    /// middles; records the point when the curves meet within the tolerance there. With
    /// `contact` (pieces smaller than the tolerance, whose tangents may be parallel) the
    /// nearest pair of points is sought over the whole domains.
    fn newton(&mut self, ia: Interval, ib: Interval, contact: bool) {
        let start = [ia.lerp(0.5), ib.lerp(0.5)];
        // A contact is the nearest pair of points, which may lie outside the tiny pieces
        // that found it: search the whole domains, so that all of them find the same one.
        let ranges = if contact { [self.a.domain(), self.b.domain()] } else { [ia, ib] };
        let (mut oa, mut ob) = ([Point::<D>::zeros(); 2], [Point::<D>::zeros(); 2]);
        let [s, t] = newton::iterate(cap::CURVE_CURVE, start, |&[s, t]| {
            self.a.eval(s, &mut oa);
            self.b.eval(t, &mut ob);
            let f = oa[0] - ob[0];
            let (da, db) = (oa[1], -ob[1]);
            // Normal equations of the 2-unknown least-squares problem.
            let (m11, m12, m22) = (da.dot(&da), da.dot(&db), db.dot(&db));
            let (r1, r2) = (-da.dot(&f), -db.dot(&f));
            let det = m11 * m22 - m12 * m12;
            if det.is_nan() || det <= 1e-300 || det.is_infinite() {
                return Step::Stop;
            }
            let (ds, dt) = ((m22 * r1 - m12 * r2) / det, (m11 * r2 - m12 * r1) / det);
            let next = [ranges[0].clamp(s + ds), ranges[1].clamp(t + dt)];
            Step::To(next, settled_all(&[s, t], &next, &ranges))
        })
        .expect("Gauss–Newton on c_a = c_b never abandons");
        self.a.eval(s, &mut oa);
        self.b.eval(t, &mut ob);
        let gap = (oa[0] - ob[0]).norm();
        if gap > self.tolerance || (self.same && self.same_parameter(s, t)) {
            return;
        }
        let sine = sine_between(&oa[1], &ob[1]);
        let kind = if sine > TANGENT_SINE { IntersectionKind::Crossing } else { IntersectionKind::Tangent };
        let (t_a, t_b) = if self.same && t < s { (t, s) } else { (s, t) };
        self.points.push(CurveIntersection { t_a, t_b, point: (oa[0] + ob[0]) * 0.5, kind });
    }

    /// Whether the pieces run along each other within the tolerance; if so, records the
    /// stretch. Only pieces much larger than the tolerance are tested (small pieces near a
    /// crossing lie within the tolerance of each other without coinciding).
    /// The pieces come with their boxes (which hold them): a point farther than the
    /// tolerance from the other's box is not on it, and when fewer than two of the four
    /// ends can lie on the other piece there is no stretch, without searching.
    fn coincide(&mut self, (ia, box_a): (Interval, &Aabb<D>), (ib, box_b): (Interval, &Aabb<D>), size: f64) -> bool {
        if size <= 100.0 * self.tolerance {
            return false;
        }
        let tol = self.tolerance;
        let far = (f64::NAN, f64::INFINITY);
        let near_b =
            |p: &Point<D>| if box_b.distance_to(p) > tol { far } else { newton::polish_on_curve(self.b, ib, p) };
        let near_a =
            |p: &Point<D>| if box_a.distance_to(p) > tol { far } else { newton::polish_on_curve(self.a, ia, p) };
        let samples_a: Vec<f64> = (0..=4).map(|k| ia.lerp(k as f64 / 4.0)).collect();
        let on_a: Vec<(f64, f64)> = [ib.start, ib.end].iter().map(|&t| near_a(&self.b.point(t))).collect();
        let (first, last) = (near_b(&self.a.point(ia.start)), near_b(&self.a.point(ia.end)));
        if [first, last].iter().chain(&on_a).filter(|e| e.1 <= tol).count() < 2 {
            return false;
        }
        let on_b: Vec<(f64, f64)> = samples_a
            .iter()
            .enumerate()
            .map(|(k, &s)| match k {
                0 => first,
                4 => last,
                _ => near_b(&self.a.point(s)),
            })
            .collect();
        // The stretch of a that lies on b: from its own ends where they lie on b, or from
        // the images of b's ends.
        let mut ends_a: Vec<f64> = Vec::new();
        let mut ends_b: Vec<f64> = Vec::new();
        for (k, &(t, d)) in [(0usize, on_b[0]), (4, on_b[4])].iter().map(|(k, v)| (*k, v)) {
            if d <= tol {
                ends_a.push(samples_a[k]);
                ends_b.push(t);
            }
        }
        for (i, &(s, d)) in on_a.iter().enumerate() {
            if d <= tol {
                ends_a.push(s);
                ends_b.push(if i == 0 { ib.start } else { ib.end });
            }
        }
        if ends_a.len() < 2 {
            return false;
        }
        let lo = ends_a.iter().copied().enumerate().min_by(|x, y| x.1.total_cmp(&y.1)).unwrap();
        let hi = ends_a.iter().copied().enumerate().max_by(|x, y| x.1.total_cmp(&y.1)).unwrap();
        // A stretch shorter than MIN_OVERLAP of the shapes is a tangential contact seen at
        // the tolerance's resolution, not an overlap.
        if hi.1 - lo.1 <= 0.0 || (self.a.point(hi.1) - self.a.point(lo.1)).norm() < MIN_OVERLAP * self.size {
            return false;
        }
        // Every sample of a inside the stretch must lie on b.
        let inside = samples_a.iter().zip(&on_b).filter(|(s, _)| **s >= lo.1 && **s <= hi.1);
        if inside.clone().any(|(_, (_, d))| *d > tol) || inside.count() < 2 {
            return false;
        }
        self.overlaps.push(CurveOverlap { a: Interval::new(lo.1, hi.1), b: (ends_b[lo.0], ends_b[hi.0]) });
        true
    }

    /// Sorts, merges touching overlaps, drops points inside overlaps and duplicates.
    fn finish(mut self) -> CurveIntersections<D> {
        self.overlaps.sort_by(|x, y| x.a.start.total_cmp(&y.a.start));
        let mut overlaps: Vec<CurveOverlap> = Vec::new();
        for o in self.overlaps {
            match overlaps.last_mut() {
                Some(last) if (self.a.point(last.a.end) - self.a.point(o.a.start)).norm() <= self.tolerance => {
                    if o.a.end > last.a.end {
                        last.a.end = o.a.end;
                        last.b.1 = o.b.1;
                    }
                }
                _ => overlaps.push(o),
            }
        }
        self.points.sort_by(|x, y| x.t_a.total_cmp(&y.t_a));
        let tol = self.tolerance;
        let mut points: Vec<CurveIntersection<D>> = Vec::new();
        for p in self.points {
            let in_overlap = overlaps.iter().any(|o| p.t_a >= o.a.start && p.t_a <= o.a.end);
            // A tangential contact is located only to about √ε of the size along the tangent.
            let near = |q: &CurveIntersection<D>| {
                let tangent = q.kind == IntersectionKind::Tangent || p.kind == IntersectionKind::Tangent;
                let reach = if tangent { tol.max(TANGENT_RESOLUTION * self.size) } else { tol };
                (q.point - p.point).norm() <= reach
                    && ((q.t_b - p.t_b).abs() <= 1e-6 * (1.0 + q.t_b.abs())
                        || (q.t_a - p.t_a).abs() <= 1e-6 * (1.0 + q.t_a.abs()))
            };
            let dup = points.iter_mut().find(|q| near(q));
            match (in_overlap, dup) {
                (true, _) => {}
                (false, Some(q)) => {
                    if p.kind == IntersectionKind::Crossing {
                        *q = p;
                    }
                }
                (false, None) => points.push(p),
            }
        }
        CurveIntersections { points, overlaps }
    }
}

/// The diagonal of the box around all root pieces.
fn cover_size<const D: usize>(cover: &CurveCover<D>) -> f64 {
    let roots = &cover.nodes[..cover.roots];
    roots.iter().fold(roots[0].piece.bounds, |b, n| b.union(&n.piece.bounds)).diagonal()
}

/// |sin| of the angle between two vectors (Lagrange identity, any dimension); 0 when one
/// vanishes.
fn sine_between<const D: usize>(a: &Point<D>, b: &Point<D>) -> f64 {
    let (na, nb) = (a.norm(), b.norm());
    if na == 0.0 || nb == 0.0 {
        return 0.0;
    }
    let c = a.dot(b) / (na * nb);
    (1.0 - c * c).max(0.0).sqrt()
}
