//! Plain spline evaluation, written from the textbook definitions and independent of the
//! crate's evaluation code: the independent truth of the differential tests
//! (`tests/fast_paths.rs`) and of the `fast_paths` fuzz target (`fuzz/`), which includes
//! this file by path.
//!
//! * Cox–de Boor: N_{i,0}(t) = 1 on the span s that holds t (0 elsewhere), and
//!   N_{i,q}(t) = (t − t_i)/(t_{i+q} − t_i) N_{i,q−1}(t) + (t_{i+q+1} − t)/(t_{i+q+1} − t_{i+1}) N_{i+1,q−1}(t);
//! * derivatives: D^k N_{i,q} = q (D^{k−1} N_{i,q−1}/(t_{i+q} − t_i) − D^{k−1} N_{i+1,q−1}/(t_{i+q+1} − t_{i+1}));
//! * every quotient with a zero knot difference is 0 (the usual 0/0 := 0);
//! * the span of t: the last non-empty span [t_s, t_{s+1}) with t_s ≤ t (right limit) or the
//!   first non-empty one with t ≤ t_{s+1} (left limit), s ∈ [p, n − 1];
//! * rational: with A = Σ N_i w_i P_i and w = Σ N_i w_i,
//!   C^{(k)} = (A^{(k)} − Σ_{j=1}^{k} C(k, j) w^{(j)} C^{(k−j)}) / w, and in two variables
//!   S^{(k,l)} = (A^{(k,l)} − Σ_{(i,j) ≠ (0,0)} C(k,i) C(l,j) w^{(i,j)} S^{(k−i,l−j)}) / w.
//!
//! Every loop is the definition; nothing is tabulated, unrolled or cached.
#![allow(dead_code)]

/// Which one-sided limit is taken at a knot.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Limit {
    /// t → t_k⁻.
    Left,
    /// t → t_k⁺.
    Right,
}

/// One direction of a plain spline: degree and the knots the evaluation runs on (for
/// periodic splines already extended by the period, see [`PlainAxis::periodic`]).
#[derive(Debug, Clone)]
pub struct PlainAxis {
    pub degree: usize,
    pub knots: Vec<f64>,
    /// Number of coefficients N (knots.len() = N + p + 1).
    pub count: usize,
    /// Some(T): periodic with period T.
    pub period: Option<f64>,
}

impl PlainAxis {
    /// An open (clamped or unclamped) direction.
    pub fn open(degree: usize, knots: &[f64]) -> Self {
        PlainAxis { degree, knots: knots.to_vec(), count: knots.len() - degree - 1, period: None }
    }

    /// A periodic direction from the n + p + 1 given knots of n control points: the
    /// bi-infinite sequence t_{i+n} = t_i + T is cut to n + 2p + 1 knots, and coefficient
    /// i of the unrolled spline is control point i mod n.
    pub fn periodic(degree: usize, knots: &[f64]) -> Self {
        let p = degree;
        let n = knots.len() - p - 1;
        let period = knots[n + p] - knots[p];
        let mut ext = knots.to_vec();
        for i in n + p + 1..n + 2 * p + 1 {
            ext.push(ext[i - n] + period);
        }
        PlainAxis { degree, knots: ext, count: n + p, period: Some(period) }
    }

    /// The domain [t_p, t_N].
    pub fn domain(&self) -> (f64, f64) {
        (self.knots[self.degree], self.knots[self.count])
    }

    /// Index of the control point behind coefficient i.
    pub fn point_index(&self, i: usize) -> usize {
        match self.period {
            Some(_) => i % (self.count - self.degree),
            None => i,
        }
    }

    /// The parameter brought into the domain: clamped (open) or wrapped into [a, b)
    /// (periodic; the left limit at a is taken at b).
    pub fn map(&self, t: f64, side: Limit) -> f64 {
        let (a, b) = self.domain();
        match self.period {
            None => t.max(a).min(b),
            Some(period) => {
                let mut w = t;
                if !(w >= a && w < b) {
                    w = a + (t - a).rem_euclid(period);
                    if w >= b {
                        w = a;
                    }
                }
                if side == Limit::Left && w == a { b } else { w }
            }
        }
    }

    /// The span s of a parameter already in the domain (see the module documentation).
    pub fn span(&self, t: f64, side: Limit) -> usize {
        let k = &self.knots;
        let spans: Vec<usize> = (self.degree..self.count).filter(|&s| k[s] < k[s + 1]).collect();
        match side {
            Limit::Right => spans.iter().rev().find(|&&s| k[s] <= t).copied().unwrap_or(spans[0]),
            Limit::Left => spans.iter().find(|&&s| t <= k[s + 1]).copied().unwrap_or(spans[spans.len() - 1]),
        }
    }

    /// `d[k][i]` = D^k N_{i,p}(t) for k ≤ `order`, i < N, on span `span`.
    pub fn basis(&self, span: usize, t: f64, order: usize) -> Vec<Vec<f64>> {
        let k = &self.knots;
        let m = k.len();
        // Degree 0: the indicator of the span, derivatives 0.
        let mut d: Vec<Vec<f64>> =
            (0..=order).map(|j| (0..m - 1).map(|i| if j == 0 && i == span { 1.0 } else { 0.0 }).collect()).collect();
        let quotient = |x: f64, y: f64| if y != 0.0 { x / y } else { 0.0 };
        for q in 1..=self.degree {
            let mut next = vec![vec![0.0; m - q - 1]; order + 1];
            for i in 0..m - q - 1 {
                let (d1, d2) = (k[i + q] - k[i], k[i + q + 1] - k[i + 1]);
                next[0][i] = quotient(t - k[i], d1) * d[0][i] + quotient(k[i + q + 1] - t, d2) * d[0][i + 1];
                for j in 1..=order {
                    next[j][i] = q as f64 * (quotient(d[j - 1][i], d1) - quotient(d[j - 1][i + 1], d2));
                }
            }
            d = next;
        }
        d
    }

    /// Basis derivatives at a raw parameter (mapped into the domain, span chosen by side).
    pub fn basis_at(&self, t: f64, side: Limit, order: usize) -> Vec<Vec<f64>> {
        let t = self.map(t, side);
        self.basis(self.span(t, side), t, order)
    }
}

/// C(n, k) as a float.
pub fn choose(n: usize, k: usize) -> f64 {
    (0..k).fold(1.0, |acc, i| acc * (n - i) as f64 / (i + 1) as f64)
}

/// Σ_i D^k N_i(t) P_i for k ≤ order (points as coordinate vectors), with the weights w_i
/// when given (then the rational curve's derivatives).
pub fn curve(
    axis: &PlainAxis,
    points: &[Vec<f64>],
    weights: Option<&[f64]>,
    t: f64,
    side: Limit,
    order: usize,
) -> Vec<Vec<f64>> {
    let dim = points[0].len();
    let b = axis.basis_at(t, side, order);
    let w = |i: usize| weights.map_or(1.0, |w| w[axis.point_index(i)]);
    let mut a = vec![vec![0.0; dim]; order + 1];
    let mut den = vec![0.0; order + 1];
    for k in 0..=order {
        for i in 0..axis.count {
            let p = &points[axis.point_index(i)];
            for c in 0..dim {
                a[k][c] += b[k][i] * w(i) * p[c];
            }
            den[k] += b[k][i] * w(i);
        }
    }
    if weights.is_none() {
        return a;
    }
    let mut out = vec![vec![0.0; dim]; order + 1];
    for k in 0..=order {
        for c in 0..dim {
            let mut v = a[k][c];
            for j in 1..=k {
                v -= choose(k, j) * den[j] * out[k - j][c];
            }
            out[k][c] = v / den[0];
        }
    }
    out
}

/// Partials S^{(i,j)}, i ≤ du, j ≤ dv, as `out[i·(dv+1) + j]`, of Σ N_a(u) M_b(v) P_ab
/// (rational with weights when given); `net[a][b]` indexed by control point.
#[allow(clippy::too_many_arguments)]
pub fn surface(
    u_axis: &PlainAxis,
    v_axis: &PlainAxis,
    net: &[Vec<Vec<f64>>],
    weights: Option<&[Vec<f64>]>,
    u: f64,
    v: f64,
    du: usize,
    dv: usize,
) -> Vec<Vec<f64>> {
    let dim = net[0][0].len();
    let bu = u_axis.basis_at(u, Limit::Right, du);
    let bv = v_axis.basis_at(v, Limit::Right, dv);
    let w = dv + 1;
    let mut a = vec![vec![0.0; dim]; (du + 1) * w];
    let mut den = vec![0.0; (du + 1) * w];
    for i in 0..=du {
        for j in 0..=dv {
            for ia in 0..u_axis.count {
                for ib in 0..v_axis.count {
                    let (pa, pb) = (u_axis.point_index(ia), v_axis.point_index(ib));
                    let n = bu[i][ia] * bv[j][ib];
                    if n == 0.0 {
                        continue;
                    }
                    let wt = weights.map_or(1.0, |w| w[pa][pb]);
                    for c in 0..dim {
                        a[i * w + j][c] += n * wt * net[pa][pb][c];
                    }
                    den[i * w + j] += n * wt;
                }
            }
        }
    }
    if weights.is_none() {
        return a;
    }
    let mut out = vec![vec![0.0; dim]; (du + 1) * w];
    for k in 0..=du {
        for l in 0..=dv {
            for c in 0..dim {
                let mut x = a[k * w + l][c];
                for i in 0..=k {
                    for j in 0..=l {
                        if i + j > 0 {
                            x -= choose(k, i) * choose(l, j) * den[i * w + j] * out[(k - i) * w + (l - j)][c];
                        }
                    }
                }
                out[k * w + l][c] = x / den[0];
            }
        }
    }
    out
}
