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
        let n = self.frames.len() + p;
        let w = order + 1;
        let mut span = p;
        let mut lo = knots[p];
        let mut hi = knots[p + 1];
        let mut b: [T; W] = self.points[..W].try_into().expect("W points");
        let mut frame = self.frames[0];
        for (&t, o) in params.iter().zip(out.chunks_exact_mut(w)) {
            let t = map(t);
            if !(t >= lo && (t < hi || span + 1 == n)) {
                span = crate::basis::advance_span(knots, p, n, span, t);
                lo = knots[span];
                hi = knots[span + 1];
                let j = span - p;
                b = self.points[j * W..(j + 1) * W].try_into().expect("W points");
                frame = self.frames[j];
            }
            eval_fixed::<W, T>(&b, (t - frame.0) * frame.1, frame.1, o);
        }
    }
}

#[inline(always)]
fn eval_fixed<const W: usize, T: Coefficient>(b: &[T], u: f64, inv_h: f64, out: &mut [T]) {
    let p = W - 1;
    let b: &[T; W] = b.try_into().expect("p + 1 points per span");
    let s = 1.0 - u;
    let mut up = [1.0f64; W];
    let mut sp = [1.0f64; W];
    for k in 1..W {
        up[k] = up[k - 1] * u;
        sp[k] = sp[k - 1] * s;
    }
    let mut acc = T::zero();
    for k in 0..W {
        acc += b[k] * (BINOMIAL[p][k] * up[k] * sp[p - k]);
    }
    out[0] = acc;
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
        let q = p - k;
        let mut acc = T::zero();
        for i in 0..=q {
            acc += d[i] * (BINOMIAL[q][i] * up[i] * sp[q - i]);
        }
        out[k] = acc * scale;
    }
}
