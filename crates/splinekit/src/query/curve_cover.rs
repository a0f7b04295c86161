//! A cover of a curve by cubic Hermite pieces with error radii: the bounding hierarchy
//! that projection and intersection search.
//!
//! On a piece [t₀, t₁] (h = t₁ − t₀) the cubic Hermite interpolant H of c(t₀), c′(t₀),
//! c(t₁), c′(t₁) has the Bézier control points
//! b₀ = c(t₀), b₁ = c(t₀) + h/3·c′(t₀), b₂ = c(t₁) − h/3·c′(t₁), b₃ = c(t₁).
//! Its error is estimated from the midpoint m, where the curve is sampled anyway to split
//! the piece: for c − H = K s²(1 − s)² (a constant fourth derivative) the error peaks at
//! s = ½ with value K/16 and its s-derivative peaks at 3.08·K/16, so
//! `radius` = SAFETY·(|c(m) − H(½)| + ¼|c_s(m) − H_s(½)|) bounds |c − H| and
//! `slope_radius` = SAFETY·(3.1·|c(m) − H(½)| + |c_s(m) − H_s(½)|) bounds |c_s − H_s|
//! (c_s = h·c′, the derivative in the piece's own parameter s ∈ [0, 1]) when the fourth
//! derivative varies by less than the factor SAFETY over the piece. For polynomial pieces
//! of degree ≤ 3 (cubic B-splines, cut at their knots) H is the curve and both radii are
//! rounding-sized; for every other curve they shrink like h⁴ and h³ as pieces are split.
//! The curve then lies in the convex hull of b₀ … b₃ grown by `radius`, so the bounding
//! box of the control points grown by `radius` holds the piece.
//!
//! Pieces never straddle a breakpoint ([`Curve::breakpoints`]): the curve is smooth inside
//! each, and the ends are evaluated one-sidedly.

use crate::Interval;
use crate::Point;
use crate::basis::Side;
use crate::curve::Curve;
use crate::query::bounds::Aabb;

/// Factor by which the measured midpoint error is enlarged into a bound.
pub const SAFETY: f64 = 2.0;

/// Relative size of floating-point noise in evaluated points, as a multiple of the
/// coordinates' magnitude: radii never drop below it.
pub const ROUNDING: f64 = 64.0 * f64::EPSILON;

/// The fewest root pieces a curve is cut into (more where it has more breakpoints).
const MIN_ROOT_PIECES: usize = 8;

/// A piece or patch is tame (its box says something useful) when `radius` ≤ TAME · its
/// size.
const TAME: f64 = 0.05;

/// Whether the box of a piece's or patch's Hermite control points, widened by the error
/// `radius`, says something useful: the radius is at most [`TAME`] times the control
/// box's diagonal, or at rounding level (2·[`ROUNDING`] times the largest coordinate, as on
/// a piece that is a single point). Curve pieces and surface patches share it.
#[inline]
pub(crate) fn is_tame<const D: usize>(control: &[Point<D>], radius: f64) -> bool {
    let scale = control.iter().fold(0.0f64, |m, p| m.max(p.amax()));
    radius <= TAME * Aabb::around(control, 0.0).diagonal() || radius <= 2.0 * ROUNDING * scale
}

/// The cached hierarchy stops below this fraction of the domain; queries go on deeper.
const CACHE_DEPTH_WIDTH: f64 = 1.0 / 4096.0;

/// Position and first derivative (with respect to the curve's parameter) at t.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Sample<const D: usize> {
    /// Parameter.
    pub t: f64,
    /// c(t).
    pub point: Point<D>,
    /// c′(t).
    pub derivative: Point<D>,
}

impl<const D: usize> Sample<D> {
    /// Evaluates c and c′ at t with the one-sided limit `side`.
    pub fn at<C: Curve<D> + ?Sized>(curve: &C, t: f64, side: Side) -> Self {
        let mut out = [Point::<D>::zeros(); 2];
        curve.eval_side(t, side, &mut out);
        Sample { t, point: out[0], derivative: out[1] }
    }
}

/// One cubic Hermite piece of the cover (see the module documentation).
#[derive(Debug, Clone, PartialEq)]
pub struct CurvePiece<const D: usize> {
    /// The sample at the start (right limit).
    pub start: Sample<D>,
    /// The sample at the middle.
    pub mid: Sample<D>,
    /// The sample at the end (left limit).
    pub end: Sample<D>,
    /// Bézier control points of the Hermite cubic, in s = (t − t₀)/h ∈ [0, 1].
    pub control: [Point<D>; 4],
    /// Bound on |c − H| over the piece.
    pub radius: f64,
    /// Bound on |c_s − H_s| over the piece (s-derivatives).
    pub slope_radius: f64,
    /// The control points' box grown by `radius`: it holds the piece.
    pub bounds: Aabb<D>,
}

impl<const D: usize> CurvePiece<D> {
    /// The piece between two samples; evaluates the curve at the middle.
    pub fn new<C: Curve<D> + ?Sized>(curve: &C, start: Sample<D>, end: Sample<D>) -> Self {
        let mid = Sample::at(curve, 0.5 * (start.t + end.t), Side::Right);
        Self::from_samples(start, mid, end)
    }

    fn from_samples(start: Sample<D>, mid: Sample<D>, end: Sample<D>) -> Self {
        let h = end.t - start.t;
        let control = [
            start.point,
            start.point + start.derivative * (h / 3.0),
            end.point - end.derivative * (h / 3.0),
            end.point,
        ];
        // H(½) = (b₀ + 3b₁ + 3b₂ + b₃)/8 and H_s(½) = ¾(b₃ + b₂ − b₁ − b₀).
        let h_mid = (control[0] + (control[1] + control[2]) * 3.0 + control[3]) / 8.0;
        let hs_mid = (control[3] + control[2] - control[1] - control[0]) * 0.75;
        let err = (mid.point - h_mid).norm();
        let err_s = (mid.derivative * h - hs_mid).norm();
        let scale = control.iter().fold(0.0f64, |m, p| m.max(p.amax()));
        let radius = SAFETY * (err + 0.25 * err_s) + ROUNDING * scale;
        let slope_radius = SAFETY * (3.1 * err + err_s) + ROUNDING * scale;
        let bounds = Aabb::around(&control, radius);
        CurvePiece { start, mid, end, control, radius, slope_radius, bounds }
    }

    /// The parameter interval [t₀, t₁].
    #[inline]
    pub fn interval(&self) -> Interval {
        Interval::new(self.start.t, self.end.t)
    }

    /// The halves [t₀, m] and [m, t₁] (two new evaluations).
    pub fn split<C: Curve<D> + ?Sized>(&self, curve: &C) -> [Self; 2] {
        [CurvePiece::new(curve, self.start, self.mid), CurvePiece::new(curve, self.mid, self.end)]
    }

    /// Whether the box says something useful: the error radius is small beside the piece
    /// (or at rounding level, as on a piece that is a single point).
    pub fn is_tame(&self) -> bool {
        is_tame(&self.control, self.radius)
    }
}

/// A node of the cached hierarchy: a piece and, unless it is a leaf, its two halves.
#[derive(Debug, Clone, PartialEq)]
pub struct CoverNode<const D: usize> {
    /// The piece.
    pub piece: CurvePiece<D>,
    /// Indices of the two halves in [`CurveCover::nodes`], `None` for a leaf.
    pub children: Option<[u32; 2]>,
}

/// The cached bounding hierarchy of a curve: root pieces between breakpoints (at least
/// `MIN_ROOT_PIECES`), each split until its box is tame. Built once and shared by many
/// queries (batch projection), which split leaves further on their own.
#[derive(Debug, Clone, PartialEq)]
pub struct CurveCover<const D: usize> {
    /// Every node; the roots first.
    pub nodes: Vec<CoverNode<D>>,
    /// How many roots (`nodes[..roots]`), in increasing parameter order.
    pub roots: usize,
    /// The curve's domain.
    pub domain: Interval,
    /// Whether the curve is closed (the ends of the domain are one point).
    pub closed: bool,
    /// The largest coordinate magnitude of the root boxes (for rounding-level tolerances).
    pub scale: f64,
}

impl<const D: usize> CurveCover<D> {
    /// Builds the cover of `curve`.
    pub fn new<C: Curve<D> + ?Sized>(curve: &C) -> Self {
        let domain = curve.domain();
        let breaks: Vec<f64> = {
            let mut b: Vec<f64> =
                curve.breakpoints().into_iter().filter(|&t| t >= domain.start && t <= domain.end).collect();
            b.dedup();
            b
        };
        let spans = breaks.len().saturating_sub(1).max(1);
        let per_span = MIN_ROOT_PIECES.div_ceil(spans);
        let mut cuts = Vec::new();
        for w in breaks.windows(2).filter(|w| w[1] > w[0]) {
            cuts.extend((0..per_span).map(|i| w[0] + (w[1] - w[0]) * i as f64 / per_span as f64));
        }
        cuts.push(domain.end);
        if cuts.len() < 2 {
            cuts = vec![domain.start, domain.end];
        }
        let mut nodes: Vec<CoverNode<D>> = cuts
            .windows(2)
            .map(|w| {
                let piece =
                    CurvePiece::new(curve, Sample::at(curve, w[0], Side::Right), Sample::at(curve, w[1], Side::Left));
                CoverNode { piece, children: None }
            })
            .collect();
        let roots = nodes.len();
        let min_width = CACHE_DEPTH_WIDTH * domain.length();
        let mut k = 0;
        while k < nodes.len() {
            let piece = &nodes[k].piece;
            if !piece.is_tame() && piece.interval().length() > min_width {
                let [a, b] = piece.split(curve);
                let first = nodes.len() as u32;
                nodes.push(CoverNode { piece: a, children: None });
                nodes.push(CoverNode { piece: b, children: None });
                nodes[k].children = Some([first, first + 1]);
            }
            k += 1;
        }
        let scale =
            nodes[..roots].iter().fold(0.0f64, |m, n| m.max(n.piece.bounds.min.amax()).max(n.piece.bounds.max.amax()));
        CurveCover { nodes, roots, domain, closed: curve.is_closed(), scale }
    }

    /// The root nodes' indices.
    pub fn root_indices(&self) -> std::ops::Range<u32> {
        0..self.roots as u32
    }
}

/// A piece being searched: a node of the cached hierarchy (whose halves are cached) or a
/// piece split off during the query.
#[derive(Debug, Clone)]
pub enum SearchPiece<'a, const D: usize> {
    /// A cached node.
    Cached(&'a CoverNode<D>),
    /// A piece made by the query.
    Owned(Box<CurvePiece<D>>),
}

impl<'a, const D: usize> SearchPiece<'a, D> {
    /// The piece.
    pub fn piece(&self) -> &CurvePiece<D> {
        match self {
            SearchPiece::Cached(n) => &n.piece,
            SearchPiece::Owned(p) => p,
        }
    }

    /// The two halves: cached ones when the hierarchy has them, else freshly evaluated.
    pub fn split<C: Curve<D> + ?Sized>(&self, cover: &'a CurveCover<D>, curve: &C) -> [SearchPiece<'a, D>; 2] {
        match self {
            SearchPiece::Cached(CoverNode { children: Some([a, b]), .. }) => {
                [SearchPiece::Cached(&cover.nodes[*a as usize]), SearchPiece::Cached(&cover.nodes[*b as usize])]
            }
            _ => self.piece().split(curve).map(|p| SearchPiece::Owned(Box::new(p))),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::curve::BSplineCurve;
    use crate::curve::model::Circle;

    #[test]
    fn cubic_pieces_are_exact_and_circle_pieces_bound_the_curve() {
        let pts: Vec<Point<2>> = (0..7).map(|i| Point::<2>::new(i as f64, ((i * i) % 5) as f64)).collect();
        let spline = BSplineCurve::clamped_uniform(3, pts).unwrap();
        let cover = CurveCover::new(&spline);
        for node in &cover.nodes[..cover.roots] {
            assert!(node.piece.radius < 1e-12, "radius {}", node.piece.radius);
        }
        let circle = Circle::new(3.0).unwrap();
        let cover = CurveCover::new(&circle);
        for node in &cover.nodes {
            let p = &node.piece;
            for k in 0..=50 {
                let t = p.interval().lerp(k as f64 / 50.0);
                let s = k as f64 / 50.0;
                let b = crate::curve::BezierCurve::new(p.control.to_vec()).unwrap().point(s);
                assert!((circle.point(t) - b).norm() <= p.radius, "piece {:?} at {t}", p.interval());
            }
        }
    }
}
