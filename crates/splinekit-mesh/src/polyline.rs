//! Polylines for curves: regular sampling, and adaptive flattening to a chord-height
//! tolerance.

use splinekit::curve::Curve;
use splinekit::{Error, Point, Result};

/// Most points a tessellation may produce.
pub const MAX_POINTS: usize = 20_000_000;

/// Segments of the regular polyline whose size [`Polyline::rough_size`] measures.
pub const ROUGH_SEGMENTS: usize = 64;

/// Points of a curve in parameter order. For a closed curve the last point is not repeated.
#[derive(Debug, Clone, PartialEq)]
pub struct Polyline<const D: usize> {
    /// Curve parameters of the points.
    pub params: Vec<f64>,
    /// The points c(`params[i]`).
    pub points: Vec<Point<D>>,
    /// Whether the last point connects back to the first.
    pub closed: bool,
}

impl<const D: usize> Polyline<D> {
    /// The size a flattening tolerance without a given one is relative to (the command
    /// line's, Python's and the renderer's): the largest distance of the points of the
    /// curve's regular polyline of [`ROUGH_SEGMENTS`] segments from its first point, about
    /// the curve's diameter. Their polylines are defined by this measure, so it is kept
    /// (here, once) rather than replaced by
    /// [`CurveExtent::extent`](splinekit::query::CurveExtent::extent).
    pub fn rough_size<C: Curve<D> + ?Sized>(curve: &C) -> Result<f64> {
        let rough = Self::regular(curve, ROUGH_SEGMENTS)?;
        Ok(rough.points.iter().map(|p| (p - rough.points[0]).norm()).fold(0.0, f64::max))
    }

    /// The flattening of a curve given no tolerance (the command line's and Python's):
    /// [`Self::adaptive_with_limit`] to 10⁻³ of [`Self::rough_size`].
    pub fn adaptive_by_size<C: Curve<D> + ?Sized>(curve: &C, max_points: usize) -> Result<Self> {
        let size = Self::rough_size(curve)?.max(1e-12);
        Self::adaptive_with_limit(curve, size * 1e-3, max_points)
    }

    /// `segments` equal parameter steps over the domain (closed curves: without the
    /// repeated end point).
    pub fn regular<C: Curve<D> + ?Sized>(curve: &C, segments: usize) -> Result<Self> {
        if segments == 0 || segments > MAX_POINTS {
            return Err(Error::invalid(
                "density",
                format!("segments must be between 1 and {MAX_POINTS}, got {segments}"),
            ));
        }
        let d = curve.domain();
        let closed = curve.is_closed();
        let count = if closed { segments } else { segments + 1 };
        let params: Vec<f64> =
            (0..count).map(|i| if i == segments { d.end } else { d.lerp(i as f64 / segments as f64) }).collect();
        let mut points = vec![Point::<D>::zeros(); count];
        curve.eval_many(&params, 0, &mut points);
        Ok(Polyline { params, points, closed })
    }

    /// Adaptive flattening to a chord-height `tolerance`.
    ///
    /// 1. Sample the domain regularly (about 256 samples, at least 8 between consecutive
    ///    breakpoints), so no feature larger than a sample step is missed.
    /// 2. Merge consecutive samples into one chord while every skipped sample stays within
    ///    `tolerance`/2 of it (breakpoints always stay vertices).
    /// 3. Halve each chord while any curve point at ¼, ½ or ¾ of its parameter range lies
    ///    farther than 0.8·`tolerance` from it (down to 2⁻²⁴ of the chord). The largest
    ///    deviation of a smooth arc can fall between the probes; the 20 % margin covers
    ///    that for arcs whose curvature varies moderately over a chord, so the polyline
    ///    stays within `tolerance` of the curve in practice (a sampled check, not a proof).
    pub fn adaptive<C: Curve<D> + ?Sized>(curve: &C, tolerance: f64) -> Result<Self> {
        Self::adaptive_with_limit(curve, tolerance, MAX_POINTS)
    }

    /// [`Self::adaptive`], refusing (with an error on `tolerance`) to make more than
    /// `max_points` points.
    pub fn adaptive_with_limit<C: Curve<D> + ?Sized>(curve: &C, tolerance: f64, max_points: usize) -> Result<Self> {
        if !(tolerance > 0.0 && tolerance.is_finite()) {
            return Err(Error::invalid("tolerance", format!("must be positive and finite, got {tolerance}")));
        }
        let bps = curve.breakpoints();
        // 1. Regular samples; `fixed` marks breakpoints.
        let (ts, fixed) = span_samples(&bps, 0..bps.len() - 1, curve.domain().length());
        let mut ps = vec![Point::<D>::zeros(); ts.len()];
        curve.eval_many(&ts, 0, &mut ps);
        let estimate = estimated_points(curve, &ts, &ps, tolerance);
        if estimate > max_points as f64 {
            return Err(Error::invalid(
                "tolerance",
                format!(
                    "{tolerance:?} needs about {estimate:.2e} points (estimated from the curve's flatness between its first samples), more than the limit of {max_points}"
                ),
            ));
        }
        let (mut params, mut points) = refined(curve, &ts, &ps, &fixed, tolerance, max_points)?;
        let closed = curve.is_closed();
        if closed {
            params.pop();
            points.pop();
        }
        Ok(Polyline { params, points, closed })
    }

    /// The vertices [`Self::adaptive_with_limit`] makes from breakpoint `spans.start` to
    /// breakpoint `spans.end` (indices into [`Curve::breakpoints`]), both included, bit for
    /// bit: breakpoints are always vertices and each span between two is flattened from its
    /// own samples alone, so a curve changed only between two breakpoints has its polyline
    /// changed only between them (the studio re-flattens just that run during a drag). The
    /// whole curve's point estimate is not made (a run of more than `max_points` vertices
    /// is refused) and a closed curve's end point is kept. An error on `spans` when it is
    /// empty or reaches past the last breakpoint.
    pub fn adaptive_span<C: Curve<D> + ?Sized>(
        curve: &C,
        tolerance: f64,
        spans: std::ops::Range<usize>,
        max_points: usize,
    ) -> Result<(Vec<f64>, Vec<Point<D>>)> {
        if !(tolerance > 0.0 && tolerance.is_finite()) {
            return Err(Error::invalid("tolerance", format!("must be positive and finite, got {tolerance}")));
        }
        let bps = curve.breakpoints();
        if spans.is_empty() || spans.end >= bps.len() {
            let n = bps.len().saturating_sub(1);
            return Err(Error::invalid("spans", format!("{spans:?} is not a run of the curve's {n} spans")));
        }
        let (ts, fixed) = span_samples(&bps, spans, curve.domain().length());
        let mut ps = vec![Point::<D>::zeros(); ts.len()];
        curve.eval_many(&ts, 0, &mut ps);
        refined(curve, &ts, &ps, &fixed, tolerance, max_points)
    }

    /// Total length of the polyline (closing segment included for closed ones).
    pub fn length(&self) -> f64 {
        let mut l: f64 = self.points.windows(2).map(|w| (w[1] - w[0]).norm()).sum();
        if self.closed && self.points.len() > 1 {
            l += (self.points[0] - self.points[self.points.len() - 1]).norm();
        }
        l
    }
}

/// Step 1 of adaptive flattening over the spans `spans` between the breakpoints `bps` of
/// a domain `total` long: regular samples (about 256 over the domain, at least 8 a span)
/// from `bps[spans.start]` to `bps[spans.end]`; `fixed` marks breakpoints.
fn span_samples(bps: &[f64], spans: std::ops::Range<usize>, total: f64) -> (Vec<f64>, Vec<bool>) {
    let mut ts = vec![bps[spans.start]];
    let mut fixed = vec![true];
    for w in bps[spans.start..=spans.end].windows(2) {
        let (a, b) = (w[0], w[1]);
        let pieces = ((256.0 * (b - a) / total).ceil() as usize).max(8);
        for i in 1..=pieces {
            ts.push(if i == pieces { b } else { a + (b - a) * i as f64 / pieces as f64 });
            fixed.push(i == pieces);
        }
    }
    (ts, fixed)
}

/// Steps 2 and 3 of adaptive flattening: greedy chords over the samples `ts`, `ps` (never
/// past a `fixed` one), each halved until within `tolerance`.
fn refined<const D: usize, C: Curve<D> + ?Sized>(
    curve: &C,
    ts: &[f64],
    ps: &[Point<D>],
    fixed: &[bool],
    tolerance: f64,
    max_points: usize,
) -> Result<(Vec<f64>, Vec<Point<D>>)> {
    // 2. Greedy chords over the samples.
    let mut keep = vec![0usize];
    let mut i = 0;
    while i + 1 < ts.len() {
        let mut j = i + 1;
        while j + 1 < ts.len()
            && !fixed[j]
            && (i + 1..=j).all(|k| distance_to_segment(&ps[k], &ps[i], &ps[j + 1]) <= 0.5 * tolerance)
        {
            j += 1;
        }
        keep.push(j);
        i = j;
    }
    // 3. Adaptive refinement of every chord.
    let mut params = vec![ts[0]];
    let mut points = vec![ps[0]];
    for w in keep.windows(2) {
        let mut stack = vec![(ts[w[0]], ps[w[0]], ts[w[1]], ps[w[1]], 0u32)];
        while let Some((s0, q0, s1, q1, depth)) = stack.pop() {
            let sm = 0.5 * (s0 + s1);
            let qm = curve.point(sm);
            let too_far = depth < 24
                && [0.25, 0.5, 0.75].iter().any(|&f| {
                    let q = if f == 0.5 { qm } else { curve.point(s0 + (s1 - s0) * f) };
                    distance_to_segment(&q, &q0, &q1) > 0.8 * tolerance
                });
            if too_far {
                stack.push((sm, qm, s1, q1, depth + 1));
                stack.push((s0, q0, sm, qm, depth + 1));
            } else {
                params.push(s1);
                points.push(q1);
                if points.len() > max_points {
                    return Err(Error::invalid(
                        "tolerance",
                        format!("{tolerance:?} needs more than {max_points} points"),
                    ));
                }
            }
        }
    }
    Ok((params, points))
}

/// An estimate of the points adaptive flattening to `tolerance` makes, before it starts:
/// a smooth arc's chord height falls as h² with its parameter step h, so a sample step whose
/// midpoint lies e from its chord needs about √(e / (0.8·tolerance)) segments (at least
/// one, at most 2²⁴ — the depth limit of the halving).
fn estimated_points<const D: usize, C: Curve<D> + ?Sized>(
    curve: &C,
    ts: &[f64],
    ps: &[Point<D>],
    tolerance: f64,
) -> f64 {
    let mids: Vec<f64> = ts.windows(2).map(|w| 0.5 * (w[0] + w[1])).collect();
    let mut qs = vec![Point::<D>::zeros(); mids.len()];
    curve.eval_many(&mids, 0, &mut qs);
    let most = (1u64 << 24) as f64;
    (0..mids.len())
        .map(|i| (distance_to_segment(&qs[i], &ps[i], &ps[i + 1]) / (0.8 * tolerance)).sqrt().clamp(1.0, most))
        .sum()
}

/// Distance from `p` to the segment [a, b].
pub fn distance_to_segment<const D: usize>(p: &Point<D>, a: &Point<D>, b: &Point<D>) -> f64 {
    let ab = b - a;
    let len2 = ab.norm_squared();
    if len2 == 0.0 {
        return (p - a).norm();
    }
    let s = ((p - a).dot(&ab) / len2).clamp(0.0, 1.0);
    (p - (a + ab * s)).norm()
}
