//! The offset of a surface in ℝ³ at signed distance d: O(u, v) = S(u, v) + d·N(u, v), with
//! N = (S_u × S_v)/|S_u × S_v|, as a bicubic B-spline within a tolerance.
//!
//! Method: bicubic tensor-product interpolation ([`interpolate_surface_on_knots`]) of O at
//! a grid of S's parameters: m equally spaced lines on every span between S's breakpoints
//! each way (starting at 5), not-a-knot cubics on each span joined by triple knots at the
//! breakpoints (where O, built from S's first derivatives, may be only C¹). The error
//! |B − O| is measured at the grid of the nodes and the midpoints between them: at the
//! midpoints in u, in v and at the cell centres. While the largest error is above half the
//! tolerance the grid is doubled (m → 2m − 1) in u where the u-midpoints are off, in v
//! where the v-midpoints are, in both where only the centres are; interpolation error
//! shrinks like h⁴, and an interpolant's error is largest between its nodes, where it is
//! measured. The answer is on S's parameters; a closed direction of S gives a surface
//! whose two boundary curves coincide (it is not stored periodic).
//!
//! Defined answers at degenerate normals: where S_u × S_v = 0 (the poles of a sphere, the
//! apex of a cone) N is the limit from just inside the domain, taken from the neighbouring
//! points at 10⁻⁷ of the domain in eight directions. Where those limits disagree, or grid
//! nodes at the same point (every node on a sphere's pole edge) get different normals, the
//! surface has no normal at that point (a cone's apex) and the offset is refused with an
//! error naming the point. A distance at which the offset folds (1 − d·k ≤ 0 for a principal
//! curvature k at a node, with k < 0 where the surface bends away from N, so a sphere's
//! offset along its outer normal collapses at d = −r) is refused too: surface offsets are
//! not trimmed.

use crate::Point;
use crate::curve::Interval;
use crate::error::{Error, Result};
use crate::fit::interpolate_surface_on_knots;
use crate::query::offset::{check_arguments, check_resolvable};
use crate::surface::{BSplineSurface, Curvatures, FundamentalForms, Surface, unit_normal};
use std::collections::{HashMap, HashSet};

/// The most grid points (m_u · m_v) one surface offset may interpolate.
pub const MAX_GRID_POINTS: usize = 1 << 18;

/// The first grid: this many nodes on each span between breakpoints, each way.
const FIRST_SAMPLES: usize = 5;

/// Step to the neighbouring points whose normals give the limit at a singular point
/// (fraction of the domain).
const LIMIT_STEP: f64 = 1e-7;

/// Normals of the limits at one point agree when they differ by less than this.
const LIMIT_AGREEMENT: f64 = 1e-4;

/// The offset of a surface, a B-spline, and how close it is.
#[derive(Debug, Clone)]
pub struct SurfaceOffset {
    /// The bicubic B-spline, on the domain of the surface.
    pub surface: BSplineSurface<3>,
    /// The largest error measured against the exact offset, max |B(u, v) − O(u, v)|.
    pub max_error: f64,
    /// The interpolation grid (m_u, m_v).
    pub grid: (usize, usize),
}

/// The unit normal at (u, v) and whether it is a limit (a singular point), or an error
/// where the surface has no normal there.
fn normal_at<S: Surface<3> + ?Sized>(s: &S, u: f64, v: f64) -> Result<(Point<3>, bool)> {
    let mut o = [Point::<3>::zeros(); 4];
    s.eval_partials(u, v, 1, 1, &mut o);
    if let Some(n) = unit_normal(&o[2], &o[1]) {
        return Ok((n, false));
    }
    let (du, dv) = (s.domain_u(), s.domain_v());
    let (hu, hv) = (LIMIT_STEP * du.length(), LIMIT_STEP * dv.length());
    let inside = |x: f64, d: &Interval| x >= d.start && x <= d.end;
    let mut limits: Vec<Point<3>> = Vec::new();
    for (a, b) in [(0.0, hv), (0.0, -hv), (hu, 0.0), (-hu, 0.0), (hu, hv), (-hu, -hv), (hu, -hv), (-hu, hv)] {
        let (x, y) = (u + a, v + b);
        if inside(x, &du) && inside(y, &dv) {
            s.eval_partials(x, y, 1, 1, &mut o);
            if let Some(n) = unit_normal(&o[2], &o[1]) {
                limits.push(n);
            }
        }
    }
    let p = s.point(u, v);
    let Some(first) = limits.first() else {
        return Err(no_normal(&p, u, v, "the surface is degenerate around it"));
    };
    if let Some(other) = limits.iter().find(|n| (*n - first).norm() > LIMIT_AGREEMENT) {
        let angle = first.dot(other).clamp(-1.0, 1.0).acos().to_degrees();
        return Err(no_normal(&p, u, v, &format!("the normals around it differ by {angle:.1}°, an apex")));
    }
    Ok((*first, true))
}

fn no_normal(p: &Point<3>, u: f64, v: f64, why: &str) -> Error {
    Error::invalid(
        "surface",
        format!(
            "no normal at ({}, {}, {}) (u = {u}, v = {v}): {why}; its offset is not a surface there",
            p.x, p.y, p.z
        ),
    )
}

/// The exact offset O = S + d·N at every (u, v) evaluated so far, each evaluated once: a
/// doubled grid keeps the old nodes, and the midpoints where the error is measured become
/// the next grid's nodes. New values come from [`Surface::eval_grid`] on the rows and
/// columns that hold them (tensor-product surfaces evaluate their bases once per row and
/// column); folds are checked once per node.
struct OffsetCache<'s, S: ?Sized> {
    surface: &'s S,
    distance: f64,
    values: HashMap<(u64, u64), Point<3>>,
    /// Points where the normal is a limit: (point, normal, u, v).
    singular: Vec<(Point<3>, Point<3>, f64, f64)>,
    folds_checked: HashSet<(u64, u64)>,
}

fn key(u: f64, v: f64) -> (u64, u64) {
    (u.to_bits(), v.to_bits())
}

impl<'s, S: Surface<3> + ?Sized> OffsetCache<'s, S> {
    fn new(surface: &'s S, distance: f64) -> Self {
        OffsetCache { surface, distance, values: HashMap::new(), singular: Vec::new(), folds_checked: HashSet::new() }
    }

    /// O at the grid us × vs (`out[a][b]` at (us[a], vs[b])).
    fn grid(&mut self, us: &[f64], vs: &[f64]) -> Result<Vec<Vec<Point<3>>>> {
        let missing = |u: f64, v: f64| !self.values.contains_key(&key(u, v));
        let rows: Vec<f64> = us.iter().copied().filter(|&u| vs.iter().any(|&v| missing(u, v))).collect();
        let cols: Vec<f64> = vs.iter().copied().filter(|&v| rows.iter().any(|&u| missing(u, v))).collect();
        if !rows.is_empty() {
            let mut out = vec![Point::<3>::zeros(); rows.len() * cols.len() * 4];
            self.surface.eval_grid(&rows, &cols, 1, 1, &mut out);
            for (a, &u) in rows.iter().enumerate() {
                for (b, &v) in cols.iter().enumerate() {
                    let o = &out[(a * cols.len() + b) * 4..][..4];
                    let n = match unit_normal(&o[2], &o[1]) {
                        Some(n) => n,
                        None => {
                            let (n, _) = normal_at(self.surface, u, v)?;
                            self.singular.push((o[0], n, u, v));
                            n
                        }
                    };
                    self.values.insert(key(u, v), o[0] + n * self.distance);
                }
            }
        }
        Ok(us.iter().map(|&u| vs.iter().map(|&v| self.values[&key(u, v)]).collect()).collect())
    }

    /// 1 − d·k > 0 for both principal curvatures at every regular node not checked before
    /// (second partials by [`Surface::eval_grid`] on the rows and columns that hold them),
    /// or an error.
    fn check_folds(&mut self, us: &[f64], vs: &[f64]) -> Result<()> {
        let d = self.distance;
        let new = |u: f64, v: f64| !self.folds_checked.contains(&key(u, v));
        let rows: Vec<f64> = us.iter().copied().filter(|&u| vs.iter().any(|&v| new(u, v))).collect();
        let cols: Vec<f64> = vs.iter().copied().filter(|&v| rows.iter().any(|&u| new(u, v))).collect();
        let mut out = vec![Point::<3>::zeros(); rows.len() * cols.len() * 9];
        self.surface.eval_grid(&rows, &cols, 2, 2, &mut out);
        for (a, &u) in rows.iter().enumerate() {
            for (b, &v) in cols.iter().enumerate() {
                self.folds_checked.insert(key(u, v));
                // o[i·3 + j] = ∂^{i+j}S/∂uⁱ∂vʲ.
                let o = &out[(a * cols.len() + b) * 9..][..9];
                let Some(ff) = FundamentalForms::from_partials(&o[3], &o[1], &o[6], &o[4], &o[2]) else { continue };
                let (k1, k2) = Curvatures::of(&ff).principal;
                for k in [k1, k2] {
                    if 1.0 - d * k <= 0.0 {
                        return Err(Error::invalid(
                            "distance",
                            format!(
                                "the offset at d = {d} folds at u = {u}, v = {v}, where the radius of curvature is {:e} (surface offsets are not trimmed)",
                                1.0 / k.abs()
                            ),
                        ));
                    }
                }
            }
        }
        Ok(())
    }

    /// The largest of |B − O| on the grid us × vs.
    fn error_at(&mut self, b: &BSplineSurface<3>, us: &[f64], vs: &[f64]) -> Result<f64> {
        let exact = self.grid(us, vs)?;
        let mut fitted = vec![Point::<3>::zeros(); us.len() * vs.len()];
        b.eval_grid(us, vs, 0, 0, &mut fitted);
        let exact = exact.iter().flatten();
        Ok(fitted.iter().zip(exact).fold(0.0f64, |m, (p, q)| m.max((p - q).norm())))
    }
}

/// Singular nodes at one point must share their normal (a pole), else it is an apex.
fn check_singular(singular: &[(Point<3>, Point<3>, f64, f64)], size: f64) -> Result<()> {
    for (i, (p, n, u, v)) in singular.iter().enumerate() {
        for (q, m, _, _) in &singular[i + 1..] {
            if (p - q).norm() <= 1e-9 * size && (n - m).norm() > LIMIT_AGREEMENT {
                let angle = n.dot(m).clamp(-1.0, 1.0).acos().to_degrees();
                return Err(no_normal(p, *u, *v, &format!("the normals around it differ by {angle:.1}°, an apex")));
            }
        }
    }
    Ok(())
}

/// The offset of `surface` at signed distance `distance` (along S_u × S_v) within
/// `tolerance` (> 0) of the exact offset; see the module documentation.
///
/// ```
/// use splinekit::surface::{Surface, model::Sphere};
/// use splinekit::query::offset_surface;
/// // The sphere of radius 2 at distance 0.5 along its outer normal: radius 2.5.
/// let off = offset_surface(&Sphere::new(2.0).unwrap(), 0.5, 1e-5).unwrap();
/// assert!(off.max_error <= 1e-5);
/// assert!((off.surface.point(1.0, 0.3).norm() - 2.5).abs() < 1e-5);
/// ```
pub fn offset_surface<S: Surface<3> + ?Sized>(surface: &S, distance: f64, tolerance: f64) -> Result<SurfaceOffset> {
    check_arguments(distance, tolerance)?;
    let dom = (surface.domain_u(), surface.domain_v());
    let breaks = (spans(&surface.breakpoints_u(), dom.0), spans(&surface.breakpoints_v(), dom.1));
    let (mut mu, mut mv) = (FIRST_SAMPLES, FIRST_SAMPLES);
    let mut cache = OffsetCache::new(surface, distance);
    loop {
        let ((us, ku), (vs, kv)) = (span_grid(&breaks.0, mu), span_grid(&breaks.1, mv));
        if us.len() * vs.len() > MAX_GRID_POINTS {
            return Err(Error::numerical(
                "tolerance",
                format!(
                    "the offset within {tolerance:e} would need more than {MAX_GRID_POINTS} grid points ({} × {}); try a larger tolerance",
                    us.len(),
                    vs.len()
                ),
            ));
        }
        let points = cache.grid(&us, &vs)?;
        let flat: Vec<Point<3>> = points.iter().flatten().copied().collect();
        let size = crate::query::Aabb::around(&flat, 0.0).diagonal().max(f64::MIN_POSITIVE);
        let scale = flat.iter().fold(0.0f64, |m, p| m.max(p.amax()));
        check_resolvable(tolerance, scale)?;
        check_singular(&cache.singular, size)?;
        cache.check_folds(&us, &vs)?;
        let b = interpolate_surface_on_knots(&points, (3, 3), (&us, &ku), (&vs, &kv))?;
        // The midpoints, as the doubled grid will place them (so their values are reused).
        let mids =
            |b: &[f64], m: usize| -> Vec<f64> { span_grid(b, 2 * m - 1).0.into_iter().skip(1).step_by(2).collect() };
        let (mid_u, mid_v) = (mids(&breaks.0, mu), mids(&breaks.1, mv));
        let e_u = cache.error_at(&b, &mid_u, &vs)?;
        let e_v = cache.error_at(&b, &us, &mid_v)?;
        let e_c = cache.error_at(&b, &mid_u, &mid_v)?;
        let error = e_u.max(e_v).max(e_c);
        if error <= 0.5 * tolerance {
            return Ok(SurfaceOffset { surface: b, max_error: error, grid: (us.len(), vs.len()) });
        }
        let (mut ru, mut rv) = (e_u > 0.5 * tolerance, e_v > 0.5 * tolerance);
        if !ru && !rv {
            (ru, rv) = (true, true);
        }
        // The error shrinks like h⁴: the grid it would take, refused at once when far too big.
        let factor = (error / (0.5 * tolerance)).powf(0.25);
        let grow = |n: usize, r: bool| if r { n as f64 * factor } else { n as f64 };
        let needed = grow(us.len(), ru) * grow(vs.len(), rv);
        if needed > 4.0 * MAX_GRID_POINTS as f64 {
            return Err(Error::numerical(
                "tolerance",
                format!(
                    "the offset is not within {tolerance:e} with a {} × {} grid (error {error:e}); reaching it would take about {needed:.0} grid points, more than {MAX_GRID_POINTS}; try a larger tolerance",
                    us.len(),
                    vs.len()
                ),
            ));
        }
        if ru {
            mu = 2 * mu - 1;
        }
        if rv {
            mv = 2 * mv - 1;
        }
    }
}

/// The breakpoints inside the domain, with its ends, increasing and distinct.
fn spans(breaks: &[f64], dom: Interval) -> Vec<f64> {
    let mut b: Vec<f64> = breaks.iter().copied().filter(|&t| t > dom.start && t < dom.end).collect();
    b.insert(0, dom.start);
    b.push(dom.end);
    b.sort_by(f64::total_cmp);
    b.dedup_by(|x, y| *x - *y <= 1e-12 * dom.length());
    b
}

/// `m` equally spaced parameters on each span between breakpoints (shared ends), and the
/// cubic knots interpolating at them: not-a-knot on each span (interior knots at its
/// parameters 2 … m − 3) and a triple knot at every inner breakpoint (C⁰ there, where the
/// offset of a C² surface is only C¹).
fn span_grid(breaks: &[f64], m: usize) -> (Vec<f64>, Vec<f64>) {
    let mut params = vec![breaks[0]];
    let mut knots = vec![breaks[0]; 4];
    for (k, w) in breaks.windows(2).enumerate() {
        let span = Interval::new(w[0], w[1]);
        let x: Vec<f64> = (0..m).map(|j| span.lerp(j as f64 / (m - 1) as f64)).collect();
        params.extend_from_slice(&x[1..]);
        knots.extend_from_slice(&x[2..m - 2]);
        knots.extend([w[1]; 3]);
        if k + 2 == breaks.len() {
            knots.push(w[1]);
        }
    }
    (params, knots)
}
