//! Every knot span of a spline as a Bézier segment, for fast evaluation.
//!
//! On the span [t_s, t_{s+1}) of length h the spline is a polynomial of degree p, whose
//! Bézier control points are blossom values b_k = f(t_s^{⟨p−k⟩}, t_{s+1}^{⟨k⟩}), computed
//! once by de Boor's algorithm with those arguments. A point is then
//! c(t) = Σ_k C(p,k) u^k (1−u)^{p−k} b_k with u = (t − t_s)/h, and the k-th derivative is
//! p!/(p−k)! h^{−k} times the degree-(p−k) Bernstein sum of the k-th differences Δ^k b.
//! All Bernstein weights are positive and sum to one, so the evaluation error stays at a
//! few ulps of the control points, like de Boor's; it needs no knot access and no division.

use crate::basis::bernstein::binomial_table;
use crate::curve::output_slot::Slot;
use crate::curve::span_kernel::ReciprocalKnotDifferences;
use crate::{Coefficient, Point};

/// Highest degree served by the Bézier-span path.
pub const MAX_DEGREE: usize = 7;

/// C(n, k) for n, k ≤ [`MAX_DEGREE`].
pub(crate) const BINOMIAL: [[f64; 8]; 8] = binomial_table::<8>();

/// The Bézier form of every span s ∈ [p, N − 1] of a spline of degree 1 … 7.
#[derive(Debug, Clone, PartialEq)]
pub struct BezierSpans<T> {
    degree: usize,
    first_span: usize,
    /// (t_s, t_{s+1}, 1/h) per span, h = t_{s+1} − t_s (1/h = 0 for empty spans, which
    /// are never evaluated).
    frames: Vec<(f64, f64, f64)>,
    /// p + 1 control points per span.
    points: Vec<T>,
}

impl<T: Coefficient> BezierSpans<T> {
    /// Converts the spline Σ N_{i,p} c_i on `knots`; `None` for degree 0 or above
    /// [`MAX_DEGREE`].
    pub fn new(knots: &[f64], inv: &ReciprocalKnotDifferences, coefficients: &[T], degree: usize) -> Option<Self> {
        let p = degree;
        if p == 0 || p > MAX_DEGREE {
            return None;
        }
        let n = coefficients.len();
        let mut frames = Vec::with_capacity(n - p);
        let mut points = Vec::with_capacity((n - p) * (p + 1));
        let mut d = [T::zero(); 8];
        let mut args = [0.0; 8];
        for s in p..n {
            let h = knots[s + 1] - knots[s];
            frames.push((knots[s], knots[s + 1], if h > 0.0 { 1.0 / h } else { 0.0 }));
            for k in 0..=p {
                if h <= 0.0 {
                    points.push(T::zero());
                    continue;
                }
                for (r, a) in args.iter_mut().enumerate().take(p) {
                    *a = if r < p - k { knots[s] } else { knots[s + 1] };
                }
                d[..=p].copy_from_slice(&coefficients[s - p..=s]);
                for r in 1..=p {
                    let x = args[r - 1];
                    for j in (r..=p).rev() {
                        let i = s - p + j;
                        let alpha = (x - knots[i]) * inv.get(i + p + 1 - r, p + 1 - r);
                        d[j] = d[j - 1] * (1.0 - alpha) + d[j] * alpha;
                    }
                }
                points.push(d[p]);
            }
        }
        Some(BezierSpans { degree, first_span: p, frames, points })
    }

    /// Writes c^{(k)}(t), k = 0 … out.len() − 1, using span `span` (which contains t).
    #[inline]
    pub fn eval(&self, span: usize, t: f64, out: &mut [T]) {
        let w = self.degree + 1;
        let i = span - self.first_span;
        let (start, _, inv_h) = self.frames[i];
        let u = (t - start) * inv_h;
        let b = &self.points[i * w..(i + 1) * w];
        by_width!(self.degree, W => eval_fixed::<W, T, T>(b, u, inv_h, out))
    }
}

/// `by_width!(degree, W => body)`: `body` with the constant `W` = p + 1, the width of a
/// span of degree p = 1 … 7, so that the code under it (`f::<W>(…)`) is monomorphised on W
/// and its sums unroll (p = 0 is never asked for; the widest, 8, takes every degree above
/// 6). One match on the degree for every fixed-width kernel.
macro_rules! by_width {
    ($degree:expr, $w:ident => $body:expr) => {
        match $degree {
            1 => $crate::curve::bezier_spans::by_width!(@ $w = 2, $body),
            2 => $crate::curve::bezier_spans::by_width!(@ $w = 3, $body),
            3 => $crate::curve::bezier_spans::by_width!(@ $w = 4, $body),
            4 => $crate::curve::bezier_spans::by_width!(@ $w = 5, $body),
            5 => $crate::curve::bezier_spans::by_width!(@ $w = 6, $body),
            6 => $crate::curve::bezier_spans::by_width!(@ $w = 7, $body),
            _ => $crate::curve::bezier_spans::by_width!(@ $w = 8, $body),
        }
    };
    (@ $w:ident = $width:literal, $body:expr) => {{
        const $w: usize = $width;
        $body
    }};
}
pub(crate) use by_width;

impl<T: Coefficient> BezierSpans<T> {
    /// The point c(t) on span `span` (which contains t): the Bernstein sum alone, without
    /// the derivative machinery of [`BezierSpans::eval`] (the same value as its `out[0]`).
    #[inline(always)]
    pub fn point(&self, span: usize, t: f64) -> T {
        let j = span - self.first_span;
        by_width!(self.degree, W => self.point_fixed::<W>(j, t))
    }

    #[inline(always)]
    fn point_fixed<const W: usize>(&self, j: usize, t: f64) -> T {
        let (b, start, inv_h) = self.span_at::<W>(j);
        bernstein_sum::<W, T>(b, (t - start) * inv_h)
    }

    /// Batch evaluation: `out[i·(order+1) + k]` = c^{(k)}(map(`params[i]`)), in any order of
    /// the parameters. `map` brings a parameter into the domain; `locate(hint, t)` returns
    /// the span of t (t_s ≤ t < t_{s+1}, the last span at the end of the domain) given the
    /// span of the previous parameter ([`crate::basis::SplineAxis::span`]: O(1) for knots
    /// spread about evenly, O(log n) at worst, in any order). Monomorphised on the degree;
    /// a span's points are loaded once per run of parameters inside it.
    pub fn eval_many(
        &self,
        params: &[f64],
        order: usize,
        out: &mut [T],
        map: impl Fn(f64) -> f64,
        locate: impl Fn(usize, f64) -> usize,
    ) {
        by_width!(self.degree, W => self.eval_many_fixed::<W>(params, order, out, map, locate))
    }

    #[inline(always)]
    fn eval_many_fixed<const W: usize>(
        &self,
        params: &[f64],
        order: usize,
        out: &mut [T],
        map: impl Fn(f64) -> f64,
        locate: impl Fn(usize, f64) -> usize,
    ) {
        let w = order + 1;
        let mut at = SpanCursor::<W, T>::first(self);
        if order == 0 {
            // Points only: a loop without the derivative differences, so that the span's
            // points can stay in registers (points in ℝᴰ have a faster loop still,
            // `eval_many_points`).
            for (&t, o) in params.iter().zip(out.iter_mut()) {
                let t = map(t);
                *o = match at.find(self, t, &locate) {
                    None => bernstein_sum::<W, T>(&at.points, (t - at.start) * at.inv_h),
                    Some(j) => {
                        let (b, start, inv_h) = self.span_at::<W>(j);
                        bernstein_sum::<W, T>(b, (t - start) * inv_h)
                    }
                };
            }
            return;
        }
        for (&t, o) in params.iter().zip(out.chunks_exact_mut(w)) {
            let t = map(t);
            match at.find(self, t, &locate) {
                None => eval_fixed::<W, T, T>(&at.points, (t - at.start) * at.inv_h, at.inv_h, o),
                Some(j) => {
                    let (b, start, inv_h) = self.span_at::<W>(j);
                    eval_fixed::<W, T, T>(b, (t - start) * inv_h, inv_h, o)
                }
            }
        }
    }

    /// The Bézier points, start and 1/h of span index j (counted from the first span).
    #[inline(always)]
    fn span_at<const W: usize>(&self, j: usize) -> (&[T; W], f64, f64) {
        let (start, _, inv_h) = self.frames[j];
        (self.points[j * W..(j + 1) * W].try_into().expect("W points"), start, inv_h)
    }
}

impl<const D: usize> BezierSpans<Point<D>> {
    /// [`BezierSpans::eval_many`] for points in ℝᴰ and orders 0 … [`MAX_LANE_ORDER`]: the
    /// same values, bit for bit, by blocks of parameters evaluated in step (see `lanes`),
    /// compiled for AVX2 where the CPU has it (chosen at run time; the portable build
    /// stays SSE2); higher orders go to [`BezierSpans::eval_many`].
    pub fn eval_many_lanes<O: Slot<Point<D>>>(
        &self,
        params: &[f64],
        order: usize,
        out: &mut [O],
        map: impl Fn(f64) -> f64,
        locate: impl Fn(usize, f64) -> usize,
    ) {
        macro_rules! fixed {
            ($w:ident, $k:literal) => {{
                #[cfg(target_arch = "x86_64")]
                if std::arch::is_x86_feature_detected!("avx2") {
                    // SAFETY: the CPU has AVX2 (checked just above).
                    return unsafe { self.lanes_avx2::<$w, $k, O>(params, out, map, locate) };
                }
                self.lanes::<$w, $k, O>(params, out, map, locate)
            }};
        }
        if order > MAX_LANE_ORDER {
            return self.eval_many(params, order, O::initialised(out), map, locate);
        }
        by_width!(self.degree, W => match order {
            0 => fixed!(W, 1),
            1 => fixed!(W, 2),
            _ => fixed!(W, 3),
        })
    }

    /// [`Self::lanes`] compiled for AVX2 (four lanes of doubles): the same operations in
    /// the same order, so the same bits as the portable build (Rust never contracts a
    /// product and a sum into a fused multiply-add), wider instructions.
    ///
    /// # Safety
    /// The CPU must support AVX2.
    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx2")]
    unsafe fn lanes_avx2<const W: usize, const K: usize, O: Slot<Point<D>>>(
        &self,
        params: &[f64],
        out: &mut [O],
        map: impl Fn(f64) -> f64,
        locate: impl Fn(usize, f64) -> usize,
    ) {
        self.lanes::<W, K, O>(params, out, map, locate)
    }

    /// The batch of K = order + 1 outputs per parameter by blocks of [`LANES`] parameters:
    /// a block inside the cursor's span is evaluated lane by lane in step (powers,
    /// Bernstein weights and sums as arrays over the lanes, which vectorise), a block from
    /// the cursor's span into the next twice so (once with each span, every lane keeping
    /// its own span's values: cheaper than four single evaluations when a span holds
    /// only a few parameters), a block in no order (random parameters) lane by lane, each
    /// in its own span read in place, any other sorted block (over more than two spans:
    /// parameters sparser than the knots, as when a large curve is drawn) lane by lane too
    /// (`sparse_block`, 10.3–10.7 → 8.1–8.8 ns a point at one parameter a span of 10⁵,
    /// against the cursor's one-at-a-time step, which copied each span it moved into).
    /// The parameters after the last block go one at a time with the cursor, as
    /// [`BezierSpans::eval_many`] does.
    /// Every value is computed by the operations of `eval_fixed` (`bernstein_sum` for
    /// points) in their order, so the result does not depend on the blocking.
    /// (Non-temporal stores for large outputs were tried: slower here than ordinary ones.)
    #[inline(always)]
    fn lanes<const W: usize, const K: usize, O: Slot<Point<D>>>(
        &self,
        params: &[f64],
        out: &mut [O],
        map: impl Fn(f64) -> f64,
        locate: impl Fn(usize, f64) -> usize,
    ) {
        let mut at = SpanCursor::<W, Point<D>>::first(self);
        // The last span that is not empty: the end of the domain belongs to it (the spans
        // of knots repeated at the end are empty and never evaluated, nor moved into).
        let last_span = self.first_span + self.frames.iter().rposition(|f| f.0 < f.1).unwrap_or(self.frames.len() - 1);
        let one = |at: &mut SpanCursor<W, Point<D>>, t: f64, o: &mut [O]| self.one::<W, K, O>(at, map(t), o, &locate);
        // Whether t lies in the span [start, end) (the last span closed at its end), the
        // comparisons combined without branches (`&`, `|`), so that a test over the four
        // lanes of a block costs no branch per lane.
        let in_span = |t: f64, start: f64, end: f64, span: usize| (t >= start) & ((t < end) | (span == last_span));
        let mut blocks = params.chunks_exact(LANES).zip(out.chunks_exact_mut(LANES * K));
        for (raw, os) in &mut blocks {
            let ts: [f64; LANES] = std::array::from_fn(|l| map(raw[l]));
            // Every lane in the cursor's span (most blocks of a sorted batch): in step. The
            // test, and the order test below, are computed without a branch per lane, so
            // that random parameters do not make the processor mispredict them.
            let all_in = |at: &SpanCursor<W, Point<D>>| {
                ts.iter().fold(true, |all, &t| all & in_span(t, at.start, at.end, at.span))
            };
            if all_in(&at) {
                bernstein_lanes::<W, K, D, O>(&at.points, at.start, at.inv_h, &ts, os);
                continue;
            }
            // Parameters in no order (a random batch): each lane's span located and read in
            // place, the cursor left at the last lane's span (a reversed batch runs on from
            // there).
            if !ts.windows(2).fold(true, |all, w| all & (w[0] <= w[1])) {
                self.lanes_in_place::<W, K, O>(&mut at, &ts, os, &locate);
                continue;
            }
            // A sorted block that starts just past the cursor's span: the next span.
            if ts[0] >= at.end && at.span < last_span {
                let (start, end, _) = self.frames[at.span + 1 - self.first_span];
                if in_span(ts[0], start, end, at.span + 1) {
                    at.load(self, at.span + 1);
                    if all_in(&at) {
                        bernstein_lanes::<W, K, D, O>(&at.points, at.start, at.inv_h, &ts, os);
                        continue;
                    }
                }
            }
            // A sorted block running from the cursor's span into the next (a dense batch
            // crosses a knot in about (LANES − 1)/(parameters a span) of its blocks):
            // evaluated in step twice, with each span's points, each lane keeping the
            // values of its own span — the operations of `eval_fixed` on that span, as
            // one at a time.
            if at.span < last_span && in_span(ts[0], at.start, at.end, at.span) {
                let (start, end, _) = self.frames[at.span + 1 - self.first_span];
                let next = |t: f64| in_span(t, start, end, at.span + 1);
                if next(ts[LANES - 1]) && ts.iter().all(|&t| next(t) || in_span(t, at.start, at.end, at.span)) {
                    let mut before = [Point::<D>::zeros(); 3 * LANES];
                    let before = &mut before[..LANES * K];
                    bernstein_lanes::<W, K, D, Point<D>>(&at.points, at.start, at.inv_h, &ts, before);
                    let old_end = at.end;
                    at.load(self, at.span + 1);
                    bernstein_lanes::<W, K, D, O>(&at.points, at.start, at.inv_h, &ts, os);
                    for (l, &t) in ts.iter().enumerate() {
                        if t < old_end {
                            for k in 0..K {
                                os[l * K + k].put(before[l * K + k]);
                            }
                        }
                    }
                    continue;
                }
            }
            // A sorted block over more than two spans (parameters sparser than the knots)
            // or past the next span: lane by lane, out of line.
            self.sparse_block::<W, K, O>(&mut at, &ts, os, &locate);
        }
        let rest = params.len() - params.len() % LANES;
        for (&t, o) in params[rest..].iter().zip(out[rest * K..].chunks_exact_mut(K)) {
            one(&mut at, t, o);
        }
    }
}

impl<const D: usize> BezierSpans<Point<D>> {
    /// A block of [`LANES`] sorted parameters over more than two spans:
    /// [`Self::lanes_in_place`] out of line, so that the blocked loop stays as it is for
    /// the blocks that matter to it (inlined a second time, this path slowed random
    /// batches by a sixth).
    #[inline(never)]
    fn sparse_block<const W: usize, const K: usize, O: Slot<Point<D>>>(
        &self,
        at: &mut SpanCursor<W, Point<D>>,
        ts: &[f64; LANES],
        os: &mut [O],
        locate: &impl Fn(usize, f64) -> usize,
    ) {
        self.lanes_in_place::<W, K, O>(at, ts, os, locate)
    }

    /// A block of [`LANES`] parameters lane by lane: each lane's span located and its
    /// Bézier points read in place, the cursor left at the last lane's span.
    #[inline(always)]
    fn lanes_in_place<const W: usize, const K: usize, O: Slot<Point<D>>>(
        &self,
        at: &mut SpanCursor<W, Point<D>>,
        ts: &[f64; LANES],
        os: &mut [O],
        locate: &impl Fn(usize, f64) -> usize,
    ) {
        let mut span = at.span;
        for (&t, o) in ts.iter().zip(os.chunks_exact_mut(K)) {
            span = locate(span, t);
            let (b, start, inv_h) = self.span_at::<W>(span - self.first_span);
            put_outputs::<W, K, D, O>(b, start, inv_h, t, o);
        }
        at.load(self, span);
    }

    /// The K = order + 1 outputs at one parameter `t` (in the domain) of a batch, by the
    /// cursor: in its span, or in t's span read in place (`SpanCursor::find`). Always
    /// inlined, so that `locate` is inlined into the batch loop.
    #[inline(always)]
    fn one<const W: usize, const K: usize, O: Slot<Point<D>>>(
        &self,
        at: &mut SpanCursor<W, Point<D>>,
        t: f64,
        o: &mut [O],
        locate: &impl Fn(usize, f64) -> usize,
    ) {
        let (b, start, inv_h) = match at.find(self, t, locate) {
            None => (&at.points, at.start, at.inv_h),
            Some(j) => self.span_at::<W>(j),
        };
        put_outputs::<W, K, D, O>(b, start, inv_h, t, o);
    }
}

/// The K outputs at `t` of the span with Bézier points `b`, start and 1/h: the point alone
/// by [`bernstein_sum`], with derivatives by `eval_fixed` (one home for a batch's single
/// evaluation).
#[inline(always)]
fn put_outputs<const W: usize, const K: usize, const D: usize, O: Slot<Point<D>>>(
    b: &[Point<D>; W],
    start: f64,
    inv_h: f64,
    t: f64,
    o: &mut [O],
) {
    let u = (t - start) * inv_h;
    if K == 1 {
        o[0].put(bernstein_sum::<W, Point<D>>(b, u));
    } else {
        eval_fixed::<W, Point<D>, O>(b, u, inv_h, o);
    }
}

/// The span of the batch's current run of parameters: its index, knot interval
/// [start, end), 1/(end − start) and Bézier points (copied, to stay in registers).
struct SpanCursor<const W: usize, T> {
    span: usize,
    /// The span of the last parameter evaluated in place.
    missed: usize,
    start: f64,
    end: f64,
    inv_h: f64,
    points: [T; W],
}

impl<const W: usize, T: Coefficient> SpanCursor<W, T> {
    /// The first span.
    #[inline(always)]
    fn first(spans: &BezierSpans<T>) -> Self {
        let mut at = SpanCursor {
            span: spans.first_span,
            missed: usize::MAX,
            start: 0.0,
            end: 0.0,
            inv_h: 0.0,
            points: [T::zero(); W],
        };
        at.load(spans, spans.first_span);
        at
    }

    /// Loads span `span`.
    #[inline(always)]
    fn load(&mut self, spans: &BezierSpans<T>, span: usize) {
        let j = span - spans.first_span;
        let (start, end, inv_h) = spans.frames[j];
        self.span = span;
        (self.start, self.end, self.inv_h) = (start, end, inv_h);
        self.points = spans.points[j * W..(j + 1) * W].try_into().expect("W points");
    }

    /// Where to evaluate t: `None` in the cursor's span, moved there when t left it for the
    /// next span or for the span of the previous miss (a sorted batch, forwards or
    /// backwards); otherwise `Some(j)`, the index of t's span to read in place, leaving the
    /// cursor (random order: no copy of a span that serves one parameter).
    #[inline(always)]
    fn find(&mut self, spans: &BezierSpans<T>, t: f64, locate: &impl Fn(usize, f64) -> usize) -> Option<usize> {
        let last = self.span + 1 == spans.first_span + spans.frames.len();
        if t >= self.start && (t < self.end || last) {
            return None;
        }
        let span = locate(self.span, t);
        if span == self.span + 1 || span == self.missed {
            self.load(spans, span);
            return None;
        }
        self.missed = span;
        Some(span - spans.first_span)
    }
}

/// The powers uᵏ and (1 − u)ᵏ, k < W.
#[inline(always)]
pub(crate) fn powers<const W: usize>(u: f64) -> ([f64; W], [f64; W]) {
    let s = 1.0 - u;
    let mut up = [1.0f64; W];
    let mut sp = [1.0f64; W];
    for k in 1..W {
        up[k] = up[k - 1] * u;
        sp[k] = sp[k - 1] * s;
    }
    (up, sp)
}

/// The Bernstein sum Σ_{i ≤ q} C(q,i) uⁱ (1−u)^{q−i} b_i from the powers of u and 1 − u.
#[inline(always)]
pub(crate) fn bernstein<const W: usize, T: Coefficient>(b: &[T; W], up: &[f64; W], sp: &[f64; W], q: usize) -> T {
    // Starting from the first term (not from zero, which the compiler may not fold away
    // because 0 + (−0) = +0).
    let mut acc = b[0] * (BINOMIAL[q][0] * up[0] * sp[q]);
    for i in 1..=q {
        acc += b[i] * (BINOMIAL[q][i] * up[i] * sp[q - i]);
    }
    acc
}

/// Highest derivative order of [`BezierSpans::eval_many_lanes`]'s blocked loop.
pub const MAX_LANE_ORDER: usize = 2;

/// Parameters evaluated in step by [`BezierSpans::eval_many_lanes`].
const LANES: usize = 4;

/// `eval_fixed` (K outputs; [`bernstein_sum`] for K = 1) at LANES parameters of one span
/// (start, 1/h, points `b`) into `out` (K per parameter), each lane and coordinate by the
/// same operations in the same order (so with the same result), laid out lane-innermost
/// so that they vectorise.
///
/// The control points are first transposed to one array per coordinate, so that the
/// differences Δᵏb stay in registers (differencing the points in place in memory made the
/// reads straddle the copy's stores: a store-forwarding stall that took a third of the
/// first-derivative batch), and each derivative level is its own call with a constant
/// degree, so that every loop has constant bounds and unrolls.
#[inline(always)]
fn bernstein_lanes<const W: usize, const K: usize, const D: usize, O: Slot<Point<D>>>(
    b: &[Point<D>; W],
    start: f64,
    inv_h: f64,
    ts: &[f64; LANES],
    out: &mut [O],
) {
    let out = &mut out[..LANES * K];
    let p = W - 1;
    let u: [f64; LANES] = std::array::from_fn(|l| (ts[l] - start) * inv_h);
    let mut up = [[1.0f64; LANES]; W];
    let mut sp = [[1.0f64; LANES]; W];
    for k in 1..W {
        for l in 0..LANES {
            up[k][l] = up[k - 1][l] * u[l];
            sp[k][l] = sp[k - 1][l] * (1.0 - u[l]);
        }
    }
    let mut d: [[f64; W]; D] = std::array::from_fn(|c| std::array::from_fn(|i| b[i][c]));
    let level0 = lane_level::<W, D>(&d, &up, &sp, p);
    for l in 0..LANES {
        out[l * K].put(Point::<D>::from_fn(|c, _| level0[c][l]));
    }
    let mut scale = 1.0;
    // k = 1, 2 (K ≤ 3), written out so that q = p − k is a constant of each call.
    if K > 1 {
        lane_derivative::<W, K, D, O>(1, &mut d, &mut scale, inv_h, &up, &sp, out);
    }
    if K > 2 {
        lane_derivative::<W, K, D, O>(2, &mut d, &mut scale, inv_h, &up, &sp, out);
    }
}

/// Level k ≥ 1 of [`bernstein_lanes`]: Δᵏb from Δᵏ⁻¹b in `d` (per coordinate), the scale
/// p!/(p−k)! h⁻ᵏ, and the degree-(p−k) Bernstein sums into output k of every lane (zero
/// when k > p).
#[inline(always)]
fn lane_derivative<const W: usize, const K: usize, const D: usize, O: Slot<Point<D>>>(
    k: usize,
    d: &mut [[f64; W]; D],
    scale: &mut f64,
    inv_h: f64,
    up: &[[f64; LANES]; W],
    sp: &[[f64; LANES]; W],
    out: &mut [O],
) {
    let p = W - 1;
    if k > p {
        for l in 0..LANES {
            out[l * K + k].put(Point::<D>::zeros());
        }
        return;
    }
    for dc in d.iter_mut() {
        for i in 0..W - k {
            dc[i] = dc[i + 1] - dc[i];
        }
    }
    *scale *= (p - k + 1) as f64 * inv_h;
    let level = lane_level::<W, D>(d, up, sp, p - k);
    for l in 0..LANES {
        out[l * K + k].put(Point::<D>::from_fn(|c, _| level[c][l] * *scale));
    }
}

/// The degree-q Bernstein sums Σ_{i ≤ q} C(q,i) uⁱ(1−u)^{q−i} d_i of each coordinate at
/// every lane, by the operations of [`bernstein`] in its order.
#[inline(always)]
fn lane_level<const W: usize, const D: usize>(
    d: &[[f64; W]; D],
    up: &[[f64; LANES]; W],
    sp: &[[f64; LANES]; W],
    q: usize,
) -> [[f64; LANES]; D] {
    let mut weights = [[0.0f64; LANES]; W];
    for (i, wi) in weights.iter_mut().enumerate().take(q + 1) {
        for l in 0..LANES {
            wi[l] = BINOMIAL[q][i] * up[i][l] * sp[q - i][l];
        }
    }
    let mut acc = [[0.0f64; LANES]; D];
    for (ac, dc) in acc.iter_mut().zip(d) {
        for l in 0..LANES {
            ac[l] = dc[0] * weights[0][l];
        }
        for i in 1..=q {
            for l in 0..LANES {
                ac[l] += dc[i] * weights[i][l];
            }
        }
    }
    acc
}

/// c(u) = Σ_k C(p,k) uᵏ (1−u)^{p−k} b_k, p = W − 1.
#[inline(always)]
fn bernstein_sum<const W: usize, T: Coefficient>(b: &[T; W], u: f64) -> T {
    let (up, sp) = powers::<W>(u);
    bernstein(b, &up, &sp, W - 1)
}

#[inline(always)]
fn eval_fixed<const W: usize, T: Coefficient, O: Slot<T>>(b: &[T], u: f64, inv_h: f64, out: &mut [O]) {
    let p = W - 1;
    let b: &[T; W] = b.try_into().expect("p + 1 points per span");
    let (up, sp) = powers::<W>(u);
    out[0].put(bernstein(b, &up, &sp, p));
    if out.len() == 1 {
        return;
    }
    let mut d = *b;
    let mut scale = 1.0;
    for k in 1..out.len() {
        if k > p {
            out[k].put(T::zero());
            continue;
        }
        for i in 0..W - k {
            d[i] = d[i + 1] - d[i];
        }
        scale *= (p - k + 1) as f64 * inv_h;
        out[k].put(bernstein(&d, &up, &sp, p - k) * scale);
    }
}
