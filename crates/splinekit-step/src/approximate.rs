//! B-spline forms of curves and surfaces that STEP has no entity for, keeping their
//! parametrisation (the STEP curve at t is meant to be the splinekit curve at t):
//!
//! * **Exact** for piecewise polynomials of known breakpoints and degree m (blending
//!   splines with Bézier locals and a polynomial B-function): on each piece [a, b] the
//!   Bézier points come from the Taylor coefficients at a,
//!   b_i = Σ_{j≤i} C(i, j)/C(m, j) · h^j c^{(j)}(a)/j!, h = b − a (the Bernstein form of
//!   the Taylor polynomial), and the pieces join as a B-spline whose interior knots have
//!   multiplicity m.
//! * **Approximate** otherwise: piecewise quintic Hermite interpolation of position, first
//!   and second derivatives at the breaks (C² where the model is; error O(h⁶)), the breaks
//!   bisected until the measured deviation is below the tolerance.
//!
//! The deviation max |S(t) − model(t)| is measured on curves at 16 samples per piece and
//! refined by golden-section search around the worst sample; on surfaces at 4 × 4 samples
//! per cell, then on a 9 × 9 grid around the worst one. A deviation that is not a number
//! (a shape with no finite value there) is an error, never "within the tolerance".

use std::collections::HashMap;

use splinekit::Point;
use splinekit::basis::{Side, binomial};
use splinekit::curve::{BSplineCurve, Curve};
use splinekit::surface::{BSplineSurface, Surface};

use crate::error::{Result, StepError};
use crate::geometry::{SplineCurve, SplineSurface};

/// Whether deviation `d` is worse than `worst`: larger, or not a number (a model with no
/// finite value there) where `worst` still is one, so that a NaN is never passed over as
/// "within the tolerance".
fn worse(d: f64, worst: f64) -> bool {
    d > worst || d.is_nan() && !worst.is_nan()
}

/// Refuses a deviation that is not a number: the model (or its approximation) has no
/// finite value near `at`.
fn finite(deviation: f64, at: impl std::fmt::Display) -> Result<f64> {
    if deviation.is_nan() {
        return Err(StepError::plain(format!("the shape has no finite value near {at}, so it cannot be approximated")));
    }
    Ok(deviation)
}

/// Most pieces an approximation may use per direction before giving up.
pub const MAX_PIECES: usize = 1 << 15;
/// Most surface cells per direction.
pub const MAX_CELLS: usize = 512;

/// A B-spline form and the measured maximum deviation from its model.
#[derive(Debug, Clone)]
pub struct Fitted<T> {
    /// The B-spline data.
    pub spline: T,
    /// max |spline(t) − model(t)| as measured.
    pub max_deviation: f64,
}

/// T[i][j] = C(i, j)/C(m, j) · h^j / j!: Bézier points from Taylor derivatives at the start.
fn taylor_to_bezier(m: usize, h: f64) -> Vec<Vec<f64>> {
    let mut fact = 1.0;
    let mut scale = vec![1.0; m + 1];
    for j in 1..=m {
        fact *= j as f64;
        scale[j] = h.powi(j as i32) / fact;
    }
    (0..=m)
        .map(|i| (0..=m).map(|j| if j <= i { binomial(i, j) / binomial(m, j) * scale[j] } else { 0.0 }).collect())
        .collect()
}

/// H[i][k] maps the quintic Hermite data (f(a), f'(a), f''(a), f(b), f'(b), f''(b)) to the
/// Bézier points of the quintic on [a, b], h = b − a.
fn hermite_to_bezier(h: f64) -> [[f64; 6]; 6] {
    let (a, b) = (h / 5.0, h * h / 20.0);
    [
        [1.0, 0.0, 0.0, 0.0, 0.0, 0.0],
        [1.0, a, 0.0, 0.0, 0.0, 0.0],
        [1.0, 2.0 * a, b, 0.0, 0.0, 0.0],
        [0.0, 0.0, 0.0, 1.0, -2.0 * a, b],
        [0.0, 0.0, 0.0, 1.0, -a, 0.0],
        [0.0, 0.0, 0.0, 1.0, 0.0, 0.0],
    ]
}

fn to_vec(p: &Point<3>) -> Vec<f64> {
    vec![p[0], p[1], p[2]]
}

/// Bézier pieces on consecutive breaks as one clamped B-spline (interior multiplicity m).
fn assemble_curve(breaks: &[f64], m: usize, pieces: &[Vec<Point<3>>]) -> Result<BSplineCurve<3>> {
    let mut knots = vec![breaks[0]; m + 1];
    let mut pts = vec![pieces[0][0]];
    for (k, piece) in pieces.iter().enumerate() {
        pts.extend_from_slice(&piece[1..]);
        let t = breaks[k + 1];
        knots.extend(std::iter::repeat_n(t, if k + 1 == pieces.len() { m + 1 } else { m }));
    }
    BSplineCurve::new(m, knots, pts).map_err(|e| StepError::plain(format!("spline form: {e}")))
}

fn spline_curve_data(c: &BSplineCurve<3>) -> SplineCurve {
    SplineCurve {
        degree: c.degree(),
        knots: c.knots().to_vec(),
        points: c.control_points().iter().map(to_vec).collect(),
        weights: None,
        closed: false,
    }
}

/// Golden-section refinement of max_t f(t) on [lo, hi] around a sample.
fn refine_max(f: &dyn Fn(f64) -> f64, lo: f64, hi: f64) -> f64 {
    let g = 0.5 * (5f64.sqrt() - 1.0);
    let (mut a, mut b) = (lo, hi);
    let (mut x1, mut x2) = (b - g * (b - a), a + g * (b - a));
    let (mut f1, mut f2) = (f(x1), f(x2));
    for _ in 0..30 {
        if f1 > f2 {
            b = x2;
            x2 = x1;
            f2 = f1;
            x1 = b - g * (b - a);
            f1 = f(x1);
        } else {
            a = x1;
            x1 = x2;
            f1 = f2;
            x2 = a + g * (b - a);
            f2 = f(x2);
        }
    }
    f1.max(f2)
}

/// max |spline(t) − model(t)| on [a, b] (16 samples, then golden-section refinement).
fn piece_deviation(model: &dyn Curve<3>, spline: &BSplineCurve<3>, a: f64, b: f64) -> f64 {
    let dev = |t: f64| (spline.point(t) - model.point(t)).norm();
    let n = 16;
    let h = (b - a) / n as f64;
    let (mut worst, mut at) = (0.0, a);
    for i in 0..=n {
        let t = if i == n { b } else { a + h * (i as f64 + 0.5) };
        let d = dev(t);
        if worse(d, worst) {
            (worst, at) = (d, t);
        }
    }
    let (lo, hi) = ((at - h).max(a), (at + h).min(b));
    worst.max(refine_max(&dev, lo, hi))
}

/// The exact B-spline form of a curve that is a polynomial of degree ≤ m between
/// consecutive `breaks` (see the module documentation).
pub fn polynomial_curve(model: &dyn Curve<3>, breaks: &[f64], m: usize) -> Result<Fitted<SplineCurve>> {
    let mut pieces = Vec::with_capacity(breaks.len() - 1);
    let mut ders = vec![Point::<3>::zeros(); m + 1];
    for w in breaks.windows(2) {
        model.eval_side(w[0], Side::Right, &mut ders);
        let t = taylor_to_bezier(m, w[1] - w[0]);
        pieces.push((0..=m).map(|i| (0..=i).fold(Point::<3>::zeros(), |acc, j| acc + ders[j] * t[i][j])).collect());
    }
    let spline = assemble_curve(breaks, m, &pieces)?;
    let max_deviation = breaks
        .windows(2)
        .map(|w| piece_deviation(model, &spline, w[0], w[1]))
        .fold(0.0, |a, d| if worse(d, a) { d } else { a });
    Ok(Fitted { spline: spline_curve_data(&spline), max_deviation: finite(max_deviation, "one of its pieces")? })
}

fn hermite_piece(model: &dyn Curve<3>, a: f64, b: f64) -> Vec<Point<3>> {
    let (mut da, mut db) = ([Point::<3>::zeros(); 3], [Point::<3>::zeros(); 3]);
    model.eval_side(a, Side::Right, &mut da);
    model.eval_side(b, Side::Left, &mut db);
    let data = [da[0], da[1], da[2], db[0], db[1], db[2]];
    hermite_to_bezier(b - a)
        .iter()
        .map(|row| row.iter().zip(&data).fold(Point::<3>::zeros(), |acc, (c, d)| acc + d * *c))
        .collect()
}

/// Piecewise quintic Hermite approximation within `tolerance` (absolute), starting from the
/// model's breakpoints split into at least 8 pieces.
pub fn hermite_curve(model: &dyn Curve<3>, tolerance: f64) -> Result<Fitted<SplineCurve>> {
    let mut breaks = model.breakpoints();
    let intervals = breaks.len() - 1;
    let per = 8usize.div_ceil(intervals);
    breaks = breaks
        .windows(2)
        .flat_map(|w| (0..per).map(move |i| w[0] + (w[1] - w[0]) * i as f64 / per as f64))
        .chain(std::iter::once(*breaks.last().expect("two breakpoints")))
        .collect();
    loop {
        let pieces: Vec<Vec<Point<3>>> = breaks.windows(2).map(|w| hermite_piece(model, w[0], w[1])).collect();
        let spline = assemble_curve(&breaks, 5, &pieces)?;
        let devs: Vec<f64> = breaks.windows(2).map(|w| piece_deviation(model, &spline, w[0], w[1])).collect();
        let worst = devs.iter().copied().fold(0.0, |a, d| if worse(d, a) { d } else { a });
        if worst.is_nan() {
            let k = devs.iter().position(|d| d.is_nan()).unwrap_or(0);
            finite(worst, format!("t in [{}, {}]", breaks[k], breaks[k + 1]))?;
        }
        if worst <= tolerance {
            return Ok(Fitted { spline: spline_curve_data(&spline), max_deviation: worst });
        }
        if breaks.len() > MAX_PIECES {
            return Err(StepError::plain(format!(
                "tolerance: cannot approximate within {tolerance:e} using {MAX_PIECES} pieces (reached {worst:e})"
            )));
        }
        let mut next = vec![breaks[0]];
        for (w, d) in breaks.windows(2).zip(&devs) {
            if *d > tolerance {
                next.push(0.5 * (w[0] + w[1]));
            }
            next.push(w[1]);
        }
        breaks = next;
    }
}

/// Bézier nets of cells as one clamped B-spline surface (interior multiplicities m).
fn assemble_surface(
    bu: &[f64],
    bv: &[f64],
    (mu, mv): (usize, usize),
    cells: &[Vec<Vec<Point<3>>>],
) -> Result<BSplineSurface<3>> {
    let knots = |b: &[f64], m: usize| -> Vec<f64> {
        let mut k = vec![b[0]; m + 1];
        for (i, &t) in b[1..].iter().enumerate() {
            k.extend(std::iter::repeat_n(t, if i + 2 == b.len() { m + 1 } else { m }));
        }
        k
    };
    let (nu, nv) = (bu.len() - 1, bv.len() - 1);
    let mut net = vec![vec![Point::<3>::zeros(); nv * mv + 1]; nu * mu + 1];
    for a in 0..nu {
        for b in 0..nv {
            let cell = &cells[a * nv + b];
            for k in 0..=mu {
                for l in 0..=mv {
                    net[a * mu + k][b * mv + l] = cell[k][l];
                }
            }
        }
    }
    BSplineSurface::new((mu, mv), knots(bu, mu), knots(bv, mv), net, (false, false))
        .map_err(|e| StepError::plain(format!("spline form: {e}")))
}

fn spline_surface_data(s: &BSplineSurface<3>) -> SplineSurface {
    let (ku, kv) = s.knots();
    SplineSurface {
        degrees: s.degrees(),
        knots_u: ku.to_vec(),
        knots_v: kv.to_vec(),
        points: s.control_points().iter().map(|row| row.iter().map(to_vec).collect()).collect(),
        weights: None,
        closed: (false, false),
    }
}

/// max |spline − model| over the cells (4 × 4 samples per cell, then a finer 9 × 9 look
/// around the worst one).
fn surface_deviation(model: &dyn Surface<3>, spline: &BSplineSurface<3>, bu: &[f64], bv: &[f64]) -> f64 {
    worst_deviation(model, spline, bu, bv).0
}

/// [`surface_deviation`] with the (u, v) where it is reached.
fn worst_deviation(model: &dyn Surface<3>, spline: &BSplineSurface<3>, bu: &[f64], bv: &[f64]) -> (f64, (f64, f64)) {
    let dev = |u: f64, v: f64| (spline.point(u, v) - model.point(u, v)).norm();
    let (mut worst, mut at) = (0.0, (bu[0], bv[0], 0.0, 0.0));
    for wu in bu.windows(2) {
        for wv in bv.windows(2) {
            let (hu, hv) = ((wu[1] - wu[0]) / 4.0, (wv[1] - wv[0]) / 4.0);
            for i in 0..4 {
                for j in 0..4 {
                    let (u, v) = (wu[0] + hu * (i as f64 + 0.5), wv[0] + hv * (j as f64 + 0.5));
                    let d = dev(u, v);
                    if worse(d, worst) {
                        (worst, at) = (d, (u, v, hu, hv));
                    }
                }
            }
        }
    }
    let (u0, v0, hu, hv) = at;
    let mut place = (u0, v0);
    for i in -4..=4 {
        for j in -4..=4 {
            let u = (u0 + hu * i as f64 / 4.0).clamp(bu[0], bu[bu.len() - 1]);
            let v = (v0 + hv * j as f64 / 4.0).clamp(bv[0], bv[bv.len() - 1]);
            let d = dev(u, v);
            if worse(d, worst) {
                (worst, place) = (d, (u, v));
            }
        }
    }
    (worst, place)
}

/// Marks the interval of `breaks` that holds `t` (the last one for the right end).
fn mark_interval(breaks: &[f64], t: f64, marked: &mut [bool]) {
    let k = breaks[1..breaks.len() - 1].partition_point(|&b| b <= t);
    marked[k] = true;
}

/// The exact B-spline form of a surface that is a polynomial of bidegree ≤ (m_u, m_v) on
/// every cell of the break grid: per cell, P_kl = Σ T_u\[k\]\[i\] T_v\[l\]\[j\] ∂^{i+j}S(a, c)
/// (the tensor form of [`polynomial_curve`]).
pub fn polynomial_surface(
    model: &dyn Surface<3>,
    bu: &[f64],
    bv: &[f64],
    (mu, mv): (usize, usize),
) -> Result<Fitted<SplineSurface>> {
    let mut partials = vec![Point::<3>::zeros(); (mu + 1) * (mv + 1)];
    let mut cells = Vec::new();
    for wu in bu.windows(2) {
        let tu = taylor_to_bezier(mu, wu[1] - wu[0]);
        for wv in bv.windows(2) {
            let tv = taylor_to_bezier(mv, wv[1] - wv[0]);
            // Evaluate just inside the cell so one-sided pieces are the cell's own.
            let (u, v) = (wu[0], wv[0]);
            model.eval_partials(u, v, mu, mv, &mut partials);
            let cell = (0..=mu)
                .map(|k| {
                    (0..=mv)
                        .map(|l| {
                            let mut p = Point::<3>::zeros();
                            for i in 0..=k {
                                for j in 0..=l {
                                    p += partials[i * (mv + 1) + j] * (tu[k][i] * tv[l][j]);
                                }
                            }
                            p
                        })
                        .collect()
                })
                .collect();
            cells.push(cell);
        }
    }
    let spline = assemble_surface(bu, bv, (mu, mv), &cells)?;
    let max_deviation = surface_deviation(model, &spline, bu, bv);
    Ok(Fitted { spline: spline_surface_data(&spline), max_deviation: finite(max_deviation, "one of its cells")? })
}

/// The model's partials ∂^{i+j}S, i, j ≤ 2, at the grid nodes met so far (bisection keeps
/// every node, so each is evaluated once per export).
struct NodeCache<'a> {
    model: &'a dyn Surface<3>,
    nodes: HashMap<(u64, u64), [Point<3>; 9]>,
}

impl NodeCache<'_> {
    fn partials(&mut self, u: f64, v: f64) -> [Point<3>; 9] {
        *self.nodes.entry((u.to_bits(), v.to_bits())).or_insert_with(|| {
            let mut out = [Point::<3>::zeros(); 9];
            self.model.eval_partials(u, v, 2, 2, &mut out);
            out
        })
    }
}

/// The biquintic Bézier net of the Hermite patch on one cell from its corners' partials:
/// H_u · D · H_vᵀ with D the 6 × 6 Hermite data (each row of H has at most three terms).
fn hermite_cell(nodes: &mut NodeCache, (u0, u1): (f64, f64), (v0, v1): (f64, f64)) -> [[Point<3>; 6]; 6] {
    let corner = [nodes.partials(u0, v0), nodes.partials(u0, v1), nodes.partials(u1, v0), nodes.partials(u1, v1)];
    // Hermite datum (i, j): u-side i / 3, u-order i % 3; v-side j / 3, v-order j % 3.
    let datum = |i: usize, j: usize| {
        let p = corner[(i / 3) * 2 + j / 3][(i % 3) * 3 + j % 3];
        [p[0], p[1], p[2]]
    };
    let (hu, hv) = (hermite_to_bezier(u1 - u0), hermite_to_bezier(v1 - v0));
    let combine = |row: &[f64; 6], at: &dyn Fn(usize) -> [f64; 3]| {
        let mut p = [0.0; 3];
        for (i, &c) in row.iter().enumerate() {
            if c != 0.0 {
                let q = at(i);
                (0..3).for_each(|k| p[k] += c * q[k]);
            }
        }
        p
    };
    // T[i][l] = Σ_j D[i][j] H_v[l][j], then P[k][l] = Σ_i H_u[k][i] T[i][l].
    let t: Vec<[[f64; 3]; 6]> = (0..6).map(|i| std::array::from_fn(|l| combine(&hv[l], &|j| datum(i, j)))).collect();
    std::array::from_fn(|k| {
        std::array::from_fn(|l| {
            let p = combine(&hu[k], &|i| t[i][l]);
            Point::<3>::new(p[0], p[1], p[2])
        })
    })
}

/// The quintic Bernstein polynomials at s ∈ [0, 1].
fn bernstein5(s: f64) -> [f64; 6] {
    let t = 1.0 - s;
    let (s2, t2) = (s * s, t * t);
    [t2 * t2 * t, 5.0 * s * t2 * t2, 10.0 * s2 * t2 * t, 10.0 * s2 * s * t2, 5.0 * s2 * s2 * t, s2 * s2 * s]
}

/// The Bézier patch at (s, t) ∈ [0, 1]².
fn bezier_point(net: &[[Point<3>; 6]; 6], s: f64, t: f64) -> Point<3> {
    let (bu, bv) = (bernstein5(s), bernstein5(t));
    let mut p = [0.0; 3];
    for (row, cu) in net.iter().zip(bu) {
        for (c, cv) in row.iter().zip(bv) {
            let w = cu * cv;
            p[0] += w * c[0];
            p[1] += w * c[1];
            p[2] += w * c[2];
        }
    }
    Point::<3>::new(p[0], p[1], p[2])
}

/// Samples per direction of a cell's deviation check (at the midpoints of equal parts).
const CELL_SAMPLES: usize = 4;

/// max |patch − model| of one cell at [`CELL_SAMPLES`]² midpoints, and where.
fn cell_deviation(
    model: &dyn Surface<3>,
    net: &[[Point<3>; 6]; 6],
    (u0, u1): (f64, f64),
    (v0, v1): (f64, f64),
) -> (f64, (f64, f64)) {
    let mut worst = (0.0, (u0, v0));
    for i in 0..CELL_SAMPLES {
        for j in 0..CELL_SAMPLES {
            let (s, t) = ((i as f64 + 0.5) / CELL_SAMPLES as f64, (j as f64 + 0.5) / CELL_SAMPLES as f64);
            let (u, v) = (u0 + (u1 - u0) * s, v0 + (v1 - v0) * t);
            let d = (bezier_point(net, s, t) - model.point(u, v)).norm();
            if worse(d, worst.0) {
                worst = (d, (u, v));
            }
        }
    }
    worst
}

/// A cell's Bézier net and its sampled deviation (with where it is reached).
type CellFit = ([[Point<3>; 6]; 6], f64, (f64, f64));

/// Biquintic Hermite approximation within `tolerance` (absolute) on a tensor grid of
/// breaks, starting from `breaks_u` × `breaks_v` (e.g. a blending surface's knots) and
/// bisecting the u-intervals and v-intervals of the cells above the tolerance (across the
/// direction that helps, or both).
///
/// A cell's patch depends on its corners alone (C⁰ joins of Bézier patches), so the
/// model's partials are evaluated once per grid node and each cell's patch and deviation
/// once per cell: a bisection costs only the cells it creates. A cell's deviation is its
/// largest at 4 × 4 samples; when every cell passes, a finer look (9 × 9 points around the
/// worst sample, on the assembled spline) decides, and a failure there bisects that cell.
pub fn hermite_surface(
    model: &dyn Surface<3>,
    breaks_u: &[f64],
    breaks_v: &[f64],
    tolerance: f64,
) -> Result<Fitted<SplineSurface>> {
    let (mut bu, mut bv) = (breaks_u.to_vec(), breaks_v.to_vec());
    let mut nodes = NodeCache { model, nodes: HashMap::new() };
    let mut fits: HashMap<[u64; 4], CellFit> = HashMap::new();
    let mut fit = |nodes: &mut NodeCache, (u0, u1): (f64, f64), (v0, v1): (f64, f64)| -> CellFit {
        *fits.entry([u0.to_bits(), u1.to_bits(), v0.to_bits(), v1.to_bits()]).or_insert_with(|| {
            let net = hermite_cell(nodes, (u0, u1), (v0, v1));
            let (d, at) = cell_deviation(model, &net, (u0, u1), (v0, v1));
            (net, d, at)
        })
    };
    loop {
        let (nu, nv) = (bu.len() - 1, bv.len() - 1);
        let mut devs = Vec::with_capacity(nu * nv);
        let mut worst = (0.0, (bu[0], bv[0]));
        for wu in bu.windows(2) {
            for wv in bv.windows(2) {
                let (_, d, at) = fit(&mut nodes, (wu[0], wu[1]), (wv[0], wv[1]));
                devs.push(d);
                if worse(d, worst.0) {
                    worst = (d, at);
                }
            }
        }
        if worst.0.is_nan() {
            finite(worst.0, format!("(u, v) = ({}, {})", worst.1.0, worst.1.1))?;
        }
        // Where the cells' samples all pass but the finer look does not, the cell holding
        // the finer look's worst point is the one to bisect (else the grid would not
        // change and the loop would never end).
        let mut missed = None;
        let mut reached = worst.0;
        if worst.0 <= tolerance {
            let cells: Vec<Vec<Vec<Point<3>>>> = bu
                .windows(2)
                .flat_map(|wu| bv.windows(2).map(move |wv| (wu, wv)))
                .map(|(wu, wv)| {
                    fit(&mut nodes, (wu[0], wu[1]), (wv[0], wv[1])).0.iter().map(|row| row.to_vec()).collect()
                })
                .collect();
            let spline = assemble_surface(&bu, &bv, (5, 5), &cells)?;
            let (fine, at) = finer_look(model, &spline, &bu, &bv, worst);
            finite(fine, format!("(u, v) = ({}, {})", at.0, at.1))?;
            reached = fine;
            if fine <= tolerance {
                return Ok(Fitted { spline: spline_surface_data(&spline), max_deviation: fine });
            }
            missed = Some(at);
        }
        if bu.len().max(bv.len()) > MAX_CELLS {
            return Err(StepError::plain(format!(
                "tolerance: cannot approximate within {tolerance:e} using {MAX_CELLS} patches per direction (reached {reached:e})"
            )));
        }
        // Each failing cell is bisected across the direction(s) that matter: the halves'
        // patches across u and across v (from the nodes at the midpoints, which the
        // bisection needs anyway) are compared with the cell's at its samples, and a
        // direction whose halves change the patch less than a quarter as much as the
        // other's is left alone (near a singular edge of the model only the direction
        // across it converges; bisecting the other would multiply the cells for nothing).
        let (mut bad_u, mut bad_v) = (vec![false; nu], vec![false; nv]);
        for a in 0..nu {
            for b in 0..nv {
                if devs[a * nv + b] <= tolerance {
                    continue;
                }
                let (u, v) = ((bu[a], bu[a + 1]), (bv[b], bv[b + 1]));
                let net = fit(&mut nodes, u, v).0;
                let (change_u, change_v) = split_changes(&mut nodes, &net, u, v);
                bad_u[a] |= 4.0 * change_u >= change_v;
                bad_v[b] |= 4.0 * change_v >= change_u;
            }
        }
        if let Some((u, v)) = missed {
            mark_interval(&bu, u, &mut bad_u);
            mark_interval(&bv, v, &mut bad_v);
        }
        bu = bisect(&bu, &bad_u);
        bv = bisect(&bv, &bad_v);
    }
}

/// How much bisecting a cell across u, and across v, changes its patch: the largest
/// distance at the cell's samples between its patch and its halves' patches.
fn split_changes(
    nodes: &mut NodeCache,
    net: &[[Point<3>; 6]; 6],
    (u0, u1): (f64, f64),
    (v0, v1): (f64, f64),
) -> (f64, f64) {
    let (um, vm) = (0.5 * (u0 + u1), 0.5 * (v0 + v1));
    let halves_u = [hermite_cell(nodes, (u0, um), (v0, v1)), hermite_cell(nodes, (um, u1), (v0, v1))];
    let halves_v = [hermite_cell(nodes, (u0, u1), (v0, vm)), hermite_cell(nodes, (u0, u1), (vm, v1))];
    let (mut change_u, mut change_v) = (0.0_f64, 0.0_f64);
    for i in 0..CELL_SAMPLES {
        for j in 0..CELL_SAMPLES {
            let (s, t) = ((i as f64 + 0.5) / CELL_SAMPLES as f64, (j as f64 + 0.5) / CELL_SAMPLES as f64);
            let p = bezier_point(net, s, t);
            let half = |x: f64| if x < 0.5 { (0, 2.0 * x) } else { (1, 2.0 * x - 1.0) };
            let ((ku, su), (kv, tv)) = (half(s), half(t));
            change_u = change_u.max((bezier_point(&halves_u[ku], su, t) - p).norm());
            change_v = change_v.max((bezier_point(&halves_v[kv], s, tv) - p).norm());
        }
    }
    (change_u, change_v)
}

/// The largest deviation at 9 × 9 points around the worst cell sample `(d, (u, v))` of
/// the cells (a quarter cell apart, in the cells around it), and where.
fn finer_look(
    model: &dyn Surface<3>,
    spline: &BSplineSurface<3>,
    bu: &[f64],
    bv: &[f64],
    (d, (u0, v0)): (f64, (f64, f64)),
) -> (f64, (f64, f64)) {
    let width = |b: &[f64], t: f64| {
        let k = b[1..b.len() - 1].partition_point(|&x| x <= t);
        (b[k + 1] - b[k]) / CELL_SAMPLES as f64
    };
    let (hu, hv) = (width(bu, u0), width(bv, v0));
    let mut worst = (d, (u0, v0));
    for i in -4..=4 {
        for j in -4..=4 {
            let u = (u0 + hu * i as f64 / 4.0).clamp(bu[0], bu[bu.len() - 1]);
            let v = (v0 + hv * j as f64 / 4.0).clamp(bv[0], bv[bv.len() - 1]);
            let d = (spline.point(u, v) - model.point(u, v)).norm();
            if worse(d, worst.0) {
                worst = (d, (u, v));
            }
        }
    }
    worst
}

/// The breaks with the midpoint of every marked interval added.
fn bisect(breaks: &[f64], marked: &[bool]) -> Vec<f64> {
    let mut out = vec![breaks[0]];
    for (w, &m) in breaks.windows(2).zip(marked) {
        if m {
            out.push(0.5 * (w[0] + w[1]));
        }
        out.push(w[1]);
    }
    out
}

/// `n` equal intervals of a domain.
pub fn uniform_breaks(d: splinekit::curve::Interval, n: usize) -> Vec<f64> {
    (0..=n).map(|i| d.lerp(i as f64 / n as f64)).collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use splinekit::curve::Interval;
    use splinekit::curve::model::Heart;
    use splinekit::surface::model::Torus;

    /// The graph (u, v, h(u, v)) over the unit square, `h(u, v, i, j)` giving
    /// ∂^(i+j) h / ∂u^i ∂v^j (the x and y partials are those of u and v).
    struct Graph(fn(f64, f64, usize, usize) -> f64);
    impl Surface<3> for Graph {
        fn domain_u(&self) -> Interval {
            Interval::new(0.0, 1.0)
        }
        fn domain_v(&self) -> Interval {
            Interval::new(0.0, 1.0)
        }
        fn eval_partials(&self, u: f64, v: f64, du: usize, dv: usize, out: &mut [Point<3>]) {
            for i in 0..=du {
                for j in 0..=dv {
                    let x = [u, 1.0].get(i).copied().filter(|_| j == 0).unwrap_or(0.0);
                    let y = [v, 1.0].get(j).copied().filter(|_| i == 0).unwrap_or(0.0);
                    out[i * (dv + 1) + j] = Point::<3>::from([x, y, (self.0)(u, v, i, j)]);
                }
            }
        }
    }

    /// z = h·g(u)·g(v), g(x) = exp(−(x − c)²/w²): a bump narrow enough to hide between the
    /// corners and the 4 × 4 samples of the first cell (at 1/8, 3/8, …), a sixteenth away
    /// from the nearest, so only the finer look sees it (partials up to order 2 in each
    /// direction, NaN above).
    const BUMP: Graph = Graph(|u, v, i, j| {
        /// g, g′, g″ at x.
        fn g(x: f64) -> [f64; 3] {
            const C: f64 = 0.3125;
            const W: f64 = 0.02;
            let (d, w2) = (x - C, W * W);
            let g = (-d * d / w2).exp();
            [g, -2.0 * d / w2 * g, (4.0 * d * d / (w2 * w2) - 2.0 / w2) * g]
        }
        if i <= 2 && j <= 2 { 0.01 * g(u)[i] * g(v)[j] } else { f64::NAN }
    });

    #[test]
    fn a_bump_only_the_finer_look_sees_is_refined_not_looped_over() {
        // Before, the cells' coarse samples passed, the finer look failed, no interval was
        // marked and the grid never changed: the export hung.
        let f = hermite_surface(&BUMP, &[0.0, 1.0], &[0.0, 1.0], 1e-5).unwrap();
        assert!(f.max_deviation <= 1e-5, "{}", f.max_deviation);
        // One biquintic cell per direction has 12 knots; refinement adds interior ones.
        assert!(f.spline.knots_u.len() > 12, "the bump was not refined: {:?}", f.spline.knots_u);
    }

    /// The plane z = 0 with no value (NaN) on the strip 0.3 < u < 0.7 (which holds samples).
    const TORN: Graph = Graph(|u, _, _, _| if u > 0.3 && u < 0.7 { f64::NAN } else { 0.0 });

    #[test]
    fn a_shape_without_finite_values_is_refused_not_passed_as_within_tolerance() {
        let e = hermite_surface(&TORN, &[0.0, 1.0], &[0.0, 1.0], 1e-6).unwrap_err().to_string();
        assert!(e.contains("no finite value near (u, v) = (0.375, "), "{e}");
        let e = polynomial_surface(&TORN, &[0.0, 1.0], &[0.0, 1.0], (1, 1)).unwrap_err().to_string();
        assert!(e.contains("no finite value near one of its cells"), "{e}");
    }

    #[test]
    fn taylor_bezier_reproduces_a_cubic() {
        // c(t) = (t³, t², t) on [0.5, 2]: exact up to rounding.
        let c = BSplineCurve::<3>::new(
            3,
            vec![0.0, 0.0, 0.0, 0.0, 1.0, 1.0, 1.0, 1.0],
            vec![
                Point::<3>::new(0.0, 0.0, 0.0),
                Point::<3>::new(0.0, 0.0, 1.0 / 3.0),
                Point::<3>::new(0.0, 1.0 / 3.0, 2.0 / 3.0),
                Point::<3>::new(1.0, 1.0, 1.0),
            ],
        )
        .unwrap();
        let f = polynomial_curve(&c, &[0.0, 0.3, 1.0], 3).unwrap();
        assert!(f.max_deviation < 1e-15, "{}", f.max_deviation);
        let f = polynomial_curve(&c, &[0.0, 1.0], 5).unwrap();
        assert!(f.max_deviation < 1e-15, "{}", f.max_deviation);
    }

    #[test]
    fn hermite_meets_the_tolerance_and_the_measurement_is_honest() {
        let heart = Heart::new(1.0).unwrap();
        let f = hermite_curve(&heart, 1e-6).unwrap();
        assert!(f.max_deviation <= 1e-6);
        let s = BSplineCurve::<3>::new(
            5,
            f.spline.knots.clone(),
            f.spline.points.iter().map(|p| Point::<3>::new(p[0], p[1], p[2])).collect(),
        )
        .unwrap();
        // An independent dense check: 20 000 uniform parameters.
        let dense = (0..=20_000)
            .map(|i| {
                let t = heart.domain().lerp(i as f64 / 20_000.0);
                (s.point(t) - heart.point(t)).norm()
            })
            .fold(0.0, f64::max);
        assert!(dense <= f.max_deviation * (1.0 + 1e-9), "dense {dense} > measured {}", f.max_deviation);
        let torus = Torus::new(3.0, 1.0).unwrap();
        let breaks = uniform_breaks(torus.domain_u(), 4);
        let f = hermite_surface(&torus, &breaks, &breaks, 1e-6).unwrap();
        assert!(f.max_deviation <= 1e-6 && f.max_deviation > 0.0);
    }
}
