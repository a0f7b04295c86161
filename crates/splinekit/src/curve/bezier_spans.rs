//! Every knot span of a spline as a Bézier segment, for fast evaluation.
//!
//! On the span [t_s, t_{s+1}) of length h the spline is a polynomial of degree p, whose
//! Bézier control points are blossom values b_k = f(t_s^{⟨p−k⟩}, t_{s+1}^{⟨k⟩}), computed
//! once by de Boor's algorithm with those arguments. A point is then
//! c(t) = Σ_k C(p,k) u^k (1−u)^{p−k} b_k with u = (t − t_s)/h, and the k-th derivative is
//! p!/(p−k)! h^{−k} times the degree-(p−k) Bernstein sum of the k-th differences Δ^k b.
//! All Bernstein weights are positive and sum to one, so the evaluation error stays at a
//! few ulps of the control points, like de Boor's; it needs no knot access and no division.

use crate::Coefficient;
use crate::curve::span_kernel::ReciprocalKnotDifferences;

/// Highest degree served by the Bézier-span path.
pub const MAX_DEGREE: usize = 7;

const BINOMIAL: [[f64; 8]; 8] = {
    let mut t = [[0.0; 8]; 8];
    let mut n = 0;
    while n < 8 {
        t[n][0] = 1.0;
        let mut k = 1;
        while k <= n {
            t[n][k] = t[n - 1][k - 1] + if k < n { t[n - 1][k] } else { 0.0 };
            k += 1;
        }
        n += 1;
    }
    t
};

/// The Bézier form of every span s ∈ [p, N − 1] of a spline of degree 1 … 7.
#[derive(Debug, Clone, PartialEq)]
pub struct BezierSpans<T> {
    degree: usize,
    first_span: usize,
    /// (t_s, 1/h) per span (1/h = 0 for empty spans, which are never evaluated).
    frames: Vec<(f64, f64)>,
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
            frames.push((knots[s], if h > 0.0 { 1.0 / h } else { 0.0 }));
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
        let (start, inv_h) = self.frames[i];
        let u = (t - start) * inv_h;
        let b = &self.points[i * w..(i + 1) * w];
        match self.degree {
            1 => eval_fixed::<2, T>(b, u, inv_h, out),
            2 => eval_fixed::<3, T>(b, u, inv_h, out),
            3 => eval_fixed::<4, T>(b, u, inv_h, out),
            4 => eval_fixed::<5, T>(b, u, inv_h, out),
            5 => eval_fixed::<6, T>(b, u, inv_h, out),
            6 => eval_fixed::<7, T>(b, u, inv_h, out),
            _ => eval_fixed::<8, T>(b, u, inv_h, out),
        }
    }
}

impl<T: Coefficient> BezierSpans<T> {
    /// Sorted-batch evaluation: `out[i·(order+1) + k]` = c^{(k)}(map(`params[i]`)).
    /// `knots` are the spline's knots (for span advance); `map` brings a parameter into the
    /// domain. Monomorphised on the degree; a span's points are loaded once per run of
    /// parameters inside it. Unsorted input is correct, only slower.
    pub fn eval_many(&self, knots: &[f64], params: &[f64], order: usize, out: &mut [T], map: impl Fn(f64) -> f64) {
        match self.degree {
            1 => self.eval_many_fixed::<2>(knots, params, order, out, map),
            2 => self.eval_many_fixed::<3>(knots, params, order, out, map),
            3 => self.eval_many_fixed::<4>(knots, params, order, out, map),
            4 => self.eval_many_fixed::<5>(knots, params, order, out, map),
            5 => self.eval_many_fixed::<6>(knots, params, order, out, map),
            6 => self.eval_many_fixed::<7>(knots, params, order, out, map),
            _ => self.eval_many_fixed::<8>(knots, params, order, out, map),
        }
    }

    #[inline(always)]
    fn eval_many_fixed<const W: usize>(
        &self,
        knots: &[f64],
        params: &[f64],
        order: usize,
        out: &mut [T],
        map: impl Fn(f64) -> f64,
    ) {
        let p = W - 1;
        let w = order + 1;
        let mut at = SpanCursor::<W, T>::first(self, knots);
        if order == 0 {
            // Points only: a loop without the derivative differences, so that the span's
            // points can stay in registers.
            for (&t, o) in params.iter().zip(out.iter_mut()) {
                let t = map(t);
                at.locate(self, knots, p, t);
                *o = bernstein_sum::<W, T>(&at.points, (t - at.frame.0) * at.frame.1);
            }
            return;
        }
        for (&t, o) in params.iter().zip(out.chunks_exact_mut(w)) {
            let t = map(t);
            at.locate(self, knots, p, t);
            eval_fixed::<W, T>(&at.points, (t - at.frame.0) * at.frame.1, at.frame.1, o);
        }
    }
}

/// The span of the last parameter of a sorted batch: its index, knot interval, Bézier
/// points and frame.
struct SpanCursor<const W: usize, T> {
    span: usize,
    lo: f64,
    hi: f64,
    points: [T; W],
    frame: (f64, f64),
}

impl<const W: usize, T: Coefficient> SpanCursor<W, T> {
    /// The first span.
    #[inline(always)]
    fn first(spans: &BezierSpans<T>, knots: &[f64]) -> Self {
        let p = W - 1;
        SpanCursor {
            span: p,
            lo: knots[p],
            hi: knots[p + 1],
            points: spans.points[..W].try_into().expect("W points"),
            frame: spans.frames[0],
        }
    }

    /// Moves to the span of `t` (a monotone walk from the current one when t is past it).
    #[inline(always)]
    fn locate(&mut self, spans: &BezierSpans<T>, knots: &[f64], p: usize, t: f64) {
        let n = spans.frames.len() + p;
        if !(t >= self.lo && (t < self.hi || self.span + 1 == n)) {
            self.span = crate::basis::advance_span(knots, p, n, self.span, t);
            self.lo = knots[self.span];
            self.hi = knots[self.span + 1];
            let j = self.span - p;
            self.points = spans.points[j * W..(j + 1) * W].try_into().expect("W points");
            self.frame = spans.frames[j];
        }
    }
}

/// The powers uᵏ and (1 − u)ᵏ, k < W.
#[inline(always)]
fn powers<const W: usize>(u: f64) -> ([f64; W], [f64; W]) {
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
fn bernstein<const W: usize, T: Coefficient>(b: &[T; W], up: &[f64; W], sp: &[f64; W], q: usize) -> T {
    let mut acc = T::zero();
    for i in 0..=q {
        acc += b[i] * (BINOMIAL[q][i] * up[i] * sp[q - i]);
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
fn eval_fixed<const W: usize, T: Coefficient>(b: &[T], u: f64, inv_h: f64, out: &mut [T]) {
    let p = W - 1;
    let b: &[T; W] = b.try_into().expect("p + 1 points per span");
    let (up, sp) = powers::<W>(u);
    out[0] = bernstein(b, &up, &sp, p);
    if out.len() == 1 {
        return;
    }
    let mut d = *b;
    let mut scale = 1.0;
    for k in 1..out.len() {
        if k > p {
            out[k] = T::zero();
            continue;
        }
        for i in 0..W - k {
            d[i] = d[i + 1] - d[i];
        }
        scale *= (p - k + 1) as f64 * inv_h;
        out[k] = bernstein(&d, &up, &sp, p - k) * scale;
    }
}
