//! Adaptive cubic approximation of a raw offset, and its B-spline.
//!
//! Method: the parameter interval is cut at the curve's breakpoints (and into at least
//! [`MIN_PIECES`] equal pieces); on each piece [t₀, t₁] the cubic Hermite interpolant H of
//! o(t₀), o′(t₀), o(t₁), o′(t₁) ([`HermiteCurve`], exact values and derivatives of the raw
//! offset, [`RawOffset`]) is compared with the exact offset at s = k/8, k = 1 … 7; a piece
//! whose largest error is above half the tolerance is halved, at most down to
//! [`MIN_WIDTH`] of the interval and [`MAX_PIECES`] pieces (and four per span of the curve).
//!
//! Accuracy: H − o vanishes with its derivative at both ends, so on a piece short enough
//! that o⁗ is nearly constant, H − o ≈ K·s²(1 − s)² with K = −h⁴ o⁗/24, whose largest
//! value (at s = ½) is one of the samples and whose value between samples is below it; the
//! factor 2 between the acceptance level and the tolerance covers the variation of o⁗ over
//! the piece. The error shrinks like h⁴ as pieces are halved. `max_error` is the largest
//! error measured (a parametric error |H(t) − o(t)|, which bounds the distance from the
//! approximation to the exact offset curve).
//!
//! The pieces become one cubic B-spline: a double knot (C¹) where the one-sided
//! derivatives of the offset agree, a triple knot (C⁰) where they do not (a breakpoint of
//! the curve where its curvature jumps); over a closed curve's whole period with a smooth
//! seam, a periodic B-spline.

use crate::Point;
use crate::basis::Side;
use crate::curve::{BSplineCurve, Curve, HermiteCurve, Interval};
use crate::error::{Error, Result};
use crate::query::offset::check_resolvable;
use crate::query::offset::raw_curve::{RawOffset, RawSample};
pub use crate::query::offset::{MAX_PIECES, MAX_TOTAL_PIECES};

/// The fewest pieces an interval is cut into.
pub const MIN_PIECES: usize = 8;

/// Pieces are not halved below this fraction of the interval.
pub const MIN_WIDTH: f64 = 1e-12;

/// Samples per piece at which the error is measured (s = k/8, k = 1 … 7).
const SAMPLES: usize = 8;

/// Relative difference of one-sided derivatives below which a node is smooth (C¹).
const SMOOTH_RELATIVE: f64 = 1e-9;

/// The adaptive approximation of a raw offset over one interval.
#[derive(Debug, Clone)]
pub struct HermiteFit {
    /// The piecewise cubic as a B-spline (in plane coordinates).
    pub curve: BSplineCurve<2>,
    /// The largest error measured, max |H(t) − o(t)|.
    pub max_error: f64,
    /// The ends of the pieces (the nodes), increasing.
    pub nodes: Vec<f64>,
    /// The factor 1 + dκ at every sample taken, with its parameter, increasing in t.
    pub factors: Vec<(f64, f64)>,
}

/// A piece being refined: its two end samples (right limit at the start, left at the end).
struct Piece {
    start: RawSample,
    end: RawSample,
}

/// Evaluates the raw offset or names the parameter where the curve has no normal.
fn sample<C: Curve<2> + ?Sized>(raw: &RawOffset<'_, C>, t: f64, side: Side) -> Result<RawSample> {
    raw.at(t, side).ok_or_else(|| {
        Error::invalid("curve", format!("the tangent vanishes at t = {t}: the offset has no normal direction there"))
    })
}

/// Approximates the raw offset on `interval` (which may run past the end of a closed
/// curve's domain: parameters wrap) within `tolerance`; `periodic` asks for a periodic
/// B-spline (the interval is then one whole period).
pub fn fit_raw_offset<C: Curve<2> + ?Sized>(
    raw: &RawOffset<'_, C>,
    interval: Interval,
    tolerance: f64,
    periodic: bool,
) -> Result<HermiteFit> {
    let min_width = MIN_WIDTH * interval.length();
    let mut cuts = initial_cuts(raw.curve, interval);
    cuts.dedup_by(|b, a| *b - *a <= min_width);
    let max_pieces = (MAX_PIECES + 4 * cuts.len()).min(raw.pieces_left.get());
    let mut stack: Vec<Piece> = Vec::with_capacity(cuts.len());
    for w in cuts.windows(2).rev() {
        stack.push(Piece { start: sample(raw, w[0], Side::Right)?, end: sample(raw, w[1], Side::Left)? });
    }
    let scale = stack.iter().fold(0.0f64, |m, p| m.max(p.start.point.amax()).max(p.end.point.amax()));
    check_resolvable(tolerance, scale)?;
    let mut done: Vec<(Piece, [Point<2>; 4])> = Vec::new();
    let mut factors = Vec::new();
    let mut max_error = 0.0f64;
    while let Some(piece) = stack.pop() {
        let (t0, t1) = (piece.start.t, piece.end.t);
        let h = HermiteCurve::new(
            vec![piece.start.point, piece.end.point],
            vec![piece.start.derivative, piece.end.derivative],
            Some(vec![t0, t1]),
        )?;
        let mut error = 0.0f64;
        let mut inner = Vec::with_capacity(SAMPLES - 1);
        for k in 1..SAMPLES {
            let t = t0 + (t1 - t0) * k as f64 / SAMPLES as f64;
            let s = sample(raw, t, Side::Right)?;
            error = error.max((h.point(t) - s.point).norm());
            inner.push(s);
        }
        if error <= 0.5 * tolerance || t1 - t0 <= min_width {
            if error > tolerance {
                return Err(Error::numerical(
                    "tolerance",
                    format!(
                        "the offset is not within {tolerance:e} on pieces down to {min_width:e} wide near t = {t0} (error {error:e})"
                    ),
                ));
            }
            max_error = max_error.max(error);
            factors.push((t0, piece.start.factor));
            factors.extend(inner.iter().map(|s| (s.t, s.factor)));
            done.push((piece, *h.segment(0)));
            continue;
        }
        if done.len() + stack.len() + 2 > max_pieces {
            let spent = MAX_TOTAL_PIECES - raw.pieces_left.get();
            let so_far = if spent > 0 { format!(" (after {spent} in its other parts)") } else { String::new() };
            return Err(Error::numerical(
                "tolerance",
                format!(
                    "more than {max_pieces} pieces to approximate the offset within {tolerance:e}{so_far}; try a larger tolerance"
                ),
            ));
        }
        let mid = inner[SAMPLES / 2 - 1];
        stack.push(Piece { start: mid, end: piece.end });
        stack.push(Piece { start: piece.start, end: mid });
    }
    if let Some((last, _)) = done.last() {
        factors.push((last.end.t, last.end.factor));
    }
    raw.pieces_left.set(raw.pieces_left.get().saturating_sub(done.len()));
    let nodes: Vec<f64> = done.iter().map(|(p, _)| p.start.t).chain(done.last().map(|(p, _)| p.end.t)).collect();
    let curve = to_bspline(&done, periodic)?;
    Ok(HermiteFit { curve, max_error, nodes, factors })
}

/// The interval cut at the curve's breakpoints inside it (shifted by whole periods for a
/// closed curve) and into at least [`MIN_PIECES`] equal parts.
fn initial_cuts<C: Curve<2> + ?Sized>(curve: &C, interval: Interval) -> Vec<f64> {
    let dom = curve.domain();
    let mut cuts: Vec<f64> = (0..=MIN_PIECES).map(|k| interval.lerp(k as f64 / MIN_PIECES as f64)).collect();
    let breaks = curve.breakpoints();
    let shifts: Vec<f64> = if curve.is_closed() && dom.length() > 0.0 {
        let first = ((interval.start - dom.start) / dom.length()).floor() as i64;
        let last = ((interval.end - dom.start) / dom.length()).ceil() as i64;
        (first..=last.min(first + 4)).map(|k| k as f64 * dom.length()).collect()
    } else {
        vec![0.0]
    };
    for s in shifts {
        cuts.extend(breaks.iter().map(|b| b + s).filter(|&b| b > interval.start && b < interval.end));
    }
    cuts.sort_by(f64::total_cmp);
    cuts
}

/// Whether the one-sided derivatives at a node agree (the offset is C¹ there).
fn smooth(left: &Point<2>, right: &Point<2>) -> bool {
    (left - right).norm() <= SMOOTH_RELATIVE * left.norm().max(right.norm())
}

/// The pieces (in order, each with its Bézier control points) as one cubic B-spline.
fn to_bspline(pieces: &[(Piece, [Point<2>; 4])], periodic: bool) -> Result<BSplineCurve<2>> {
    let n = pieces.len();
    let first = &pieces[0];
    let last = &pieces[n - 1];
    let (t0, t1) = (first.0.start.t, last.0.end.t);
    let mut knots = vec![t0; 4];
    let mut control = vec![first.1[0]];
    for (i, (piece, bez)) in pieces.iter().enumerate() {
        control.push(bez[1]);
        control.push(bez[2]);
        if i + 1 < n {
            let next = &pieces[i + 1].0;
            if smooth(&piece.end.derivative, &next.start.derivative) {
                knots.extend([piece.end.t; 2]);
            } else {
                knots.extend([piece.end.t; 3]);
                control.push(bez[3]);
            }
        }
    }
    control.push(last.1[3]);
    knots.extend([t1; 4]);
    if periodic && n >= 2 && smooth(&last.0.end.derivative, &first.0.start.derivative) {
        // Drop the two seam points, move the last inner point to the front and start the
        // knots two before the seam (see the module documentation of the B-spline).
        let period = t1 - t0;
        let prev = knots[knots.len() - 6] - period;
        let mut inner: Vec<Point<2>> = control[1..control.len() - 1].to_vec();
        inner.rotate_right(1);
        let mut k = vec![prev, prev];
        k.extend_from_slice(&knots[2..knots.len() - 2]);
        return BSplineCurve::new_periodic(3, k, inner);
    }
    BSplineCurve::new(3, knots, control)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::curve::BezierCurve;

    #[test]
    fn the_allowance_of_pieces_is_shared_by_every_approximation_of_one_offset() {
        let arch = BezierCurve::new(vec![
            Point::<2>::new(0.0, 0.0),
            Point::<2>::new(1.0, 2.0),
            Point::<2>::new(3.0, -1.0),
            Point::<2>::new(4.0, 1.0),
        ])
        .unwrap();
        let raw = RawOffset::new(&arch, 0.3);
        let whole = arch.domain();
        let first = fit_raw_offset(&raw, whole, 1e-8, false).unwrap();
        let used = first.nodes.len() - 1;
        assert_eq!(raw.pieces_left.get(), MAX_TOTAL_PIECES - used);
        // The same approximation needs the same pieces again; leave fewer.
        raw.pieces_left.set(used - 1);
        let e = fit_raw_offset(&raw, whole, 1e-8, false).unwrap_err().to_string();
        let after = MAX_TOTAL_PIECES - (used - 1);
        assert!(
            e.contains(&format!("more than {} pieces", used - 1))
                && e.contains(&format!("after {after} in its other parts")),
            "{e}"
        );
        // With the allowance restored the same approximation comes back.
        raw.pieces_left.set(MAX_TOTAL_PIECES);
        let again = fit_raw_offset(&raw, whole, 1e-8, false).unwrap();
        assert_eq!(again.nodes, first.nodes);
        assert!(again.max_error <= 1e-8);
    }
}
