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
//! The deviation max |S(t) − model(t)| is measured on 16 samples per piece (per direction
//! on surfaces) and refined by golden-section search around the worst sample.

use splinekit::Point;
use splinekit::basis::Side;
use splinekit::curve::{BSplineCurve, Curve};
use splinekit::surface::{BSplineSurface, Surface};

use crate::error::{Result, StepError};
use crate::geometry::{SplineCurve, SplineSurface};

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

fn binomial(n: usize, k: usize) -> f64 {
    (0..k).fold(1.0, |acc, i| acc * (n - i) as f64 / (i + 1) as f64)
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
        if d > worst {
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
    let max_deviation = breaks.windows(2).map(|w| piece_deviation(model, &spline, w[0], w[1])).fold(0.0, f64::max);
    Ok(Fitted { spline: spline_curve_data(&spline), max_deviation })
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
        let worst = devs.iter().copied().fold(0.0, f64::max);
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
                    if d > worst {
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
            if d > worst {
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
/// every cell of the break grid: per cell, P_kl = Σ T_u[k][i] T_v[l][j] ∂^{i+j}S(a, c)
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
    Ok(Fitted { spline: spline_surface_data(&spline), max_deviation })
}

fn hermite_cell(model: &dyn Surface<3>, (u0, u1): (f64, f64), (v0, v1): (f64, f64)) -> Vec<Vec<Point<3>>> {
    let mut corner = [[Point::<3>::zeros(); 9]; 4];
    for (c, (u, v)) in [(u0, v0), (u0, v1), (u1, v0), (u1, v1)].into_iter().enumerate() {
        model.eval_partials(u, v, 2, 2, &mut corner[c]);
    }
    // Hermite datum (i, j): u-side i / 3, u-order i % 3; v-side j / 3, v-order j % 3.
    let datum = |i: usize, j: usize| corner[(i / 3) * 2 + j / 3][(i % 3) * 3 + j % 3];
    let (hu, hv) = (hermite_to_bezier(u1 - u0), hermite_to_bezier(v1 - v0));
    (0..6)
        .map(|k| {
            (0..6)
                .map(|l| {
                    let mut p = Point::<3>::zeros();
                    for i in 0..6 {
                        for j in 0..6 {
                            let c = hu[k][i] * hv[l][j];
                            if c != 0.0 {
                                p += datum(i, j) * c;
                            }
                        }
                    }
                    p
                })
                .collect()
        })
        .collect()
}

/// Per-cell deviations on a break grid (cell (a, b) at `a · (bv.len() − 1) + b`) from 3 × 3
/// samples each, to decide where to refine; the reported deviation is
/// [`surface_deviation`]'s.
fn cell_deviations(model: &dyn Surface<3>, spline: &BSplineSurface<3>, bu: &[f64], bv: &[f64]) -> Vec<f64> {
    let dev = |u: f64, v: f64| (spline.point(u, v) - model.point(u, v)).norm();
    let mut out = Vec::with_capacity((bu.len() - 1) * (bv.len() - 1));
    for wu in bu.windows(2) {
        for wv in bv.windows(2) {
            let (hu, hv) = ((wu[1] - wu[0]) / 3.0, (wv[1] - wv[0]) / 3.0);
            let mut worst: f64 = 0.0;
            for i in 0..3 {
                for j in 0..3 {
                    worst = worst.max(dev(wu[0] + hu * (i as f64 + 0.5), wv[0] + hv * (j as f64 + 0.5)));
                }
            }
            out.push(worst);
        }
    }
    out
}

/// Biquintic Hermite approximation within `tolerance` (absolute) on a tensor grid of
/// breaks, starting from `breaks_u` × `breaks_v` (e.g. a blending surface's knots) and
/// bisecting every u-interval and v-interval that holds a cell above the tolerance.
pub fn hermite_surface(
    model: &dyn Surface<3>,
    breaks_u: &[f64],
    breaks_v: &[f64],
    tolerance: f64,
) -> Result<Fitted<SplineSurface>> {
    let (mut bu, mut bv) = (breaks_u.to_vec(), breaks_v.to_vec());
    loop {
        let mut cells = Vec::with_capacity((bu.len() - 1) * (bv.len() - 1));
        for wu in bu.windows(2) {
            for wv in bv.windows(2) {
                cells.push(hermite_cell(model, (wu[0], wu[1]), (wv[0], wv[1])));
            }
        }
        let spline = assemble_surface(&bu, &bv, (5, 5), &cells)?;
        let devs = cell_deviations(model, &spline, &bu, &bv);
        let mut worst = devs.iter().copied().fold(0.0, f64::max);
        // Where the cells' coarse samples all pass but the finer look does not, the cell
        // holding the finer look's worst point is the one to bisect (else the grid would
        // not change and the loop would never end).
        let mut missed = None;
        if worst <= tolerance {
            let (fine, at) = worst_deviation(model, &spline, &bu, &bv);
            worst = fine;
            if worst <= tolerance {
                return Ok(Fitted { spline: spline_surface_data(&spline), max_deviation: worst });
            }
            missed = Some(at);
        }
        if bu.len().max(bv.len()) > MAX_CELLS {
            return Err(StepError::plain(format!(
                "tolerance: cannot approximate within {tolerance:e} using {MAX_CELLS} patches per direction (reached {worst:e})"
            )));
        }
        let nv = bv.len() - 1;
        let mut bad_u: Vec<bool> = (0..bu.len() - 1).map(|a| (0..nv).any(|b| devs[a * nv + b] > tolerance)).collect();
        let mut bad_v: Vec<bool> = (0..nv).map(|b| (0..bu.len() - 1).any(|a| devs[a * nv + b] > tolerance)).collect();
        if let Some((u, v)) = missed {
            mark_interval(&bu, u, &mut bad_u);
            mark_interval(&bv, v, &mut bad_v);
        }
        bu = bisect(&bu, &bad_u);
        bv = bisect(&bv, &bad_v);
    }
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

    /// z = h·g(u)·g(v), g(x) = exp(−(x − c)²/w²): a bump narrow enough to hide between the
    /// corners and the 3 × 3 samples of the first cell, so only the finer look sees it.
    struct Bump;
    impl Bump {
        const C: f64 = 0.375;
        const W: f64 = 0.02;
        /// g, g′, g″ at x.
        fn g(x: f64) -> [f64; 3] {
            let (d, w2) = (x - Self::C, Self::W * Self::W);
            let g = (-d * d / w2).exp();
            [g, -2.0 * d / w2 * g, (4.0 * d * d / (w2 * w2) - 2.0 / w2) * g]
        }
    }
    impl Surface<3> for Bump {
        fn domain_u(&self) -> Interval {
            Interval::new(0.0, 1.0)
        }
        fn domain_v(&self) -> Interval {
            Interval::new(0.0, 1.0)
        }
        fn eval_partials(&self, u: f64, v: f64, du: usize, dv: usize, out: &mut [Point<3>]) {
            let (gu, gv) = (Self::g(u), Self::g(v));
            for i in 0..=du {
                for j in 0..=dv {
                    let x = if (i, j) == (0, 0) {
                        u
                    } else if (i, j) == (1, 0) {
                        1.0
                    } else {
                        0.0
                    };
                    let y = if (i, j) == (0, 0) {
                        v
                    } else if (i, j) == (0, 1) {
                        1.0
                    } else {
                        0.0
                    };
                    let z = if i <= 2 && j <= 2 { 0.01 * gu[i] * gv[j] } else { f64::NAN };
                    out[i * (dv + 1) + j] = Point::<3>::from([x, y, z]);
                }
            }
        }
    }

    #[test]
    fn a_bump_only_the_finer_look_sees_is_refined_not_looped_over() {
        // Before, the cells' coarse samples passed, the finer look failed, no interval was
        // marked and the grid never changed: the export hung.
        let f = hermite_surface(&Bump, &[0.0, 1.0], &[0.0, 1.0], 1e-5).unwrap();
        assert!(f.max_deviation <= 1e-5, "{}", f.max_deviation);
        assert!(f.spline.knots_u.len() > 8, "the bump was not refined: {:?}", f.spline.knots_u);
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
