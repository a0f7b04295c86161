//! Curves along which two surfaces touch: tangential branches of their intersection, where
//! the normals are parallel at every point (a unit sphere in a unit cylinder along the
//! equator, a plane on a cylinder along a line, two equal cylinders side by side).
//!
//! With x = (u, v, s, t), A(u, v), B(s, t), D = A − B and N = A_u × A_v, such a curve solves
//!
//!   F(x) = (D·B_s, D·B_t, N·B_s, N·B_t) = 0
//!
//! (B(s, t) is the foot of A(u, v) on B, and A's normal is B's), together with |D| = 0. On
//! a touching curve the solutions form a one-parameter family: the Jacobian F′ has rank 3
//! and its kernel, mapped by A's partials, is the curve's tangent T (moving both points by
//! T keeps them together with parallel normals; across the curve the surfaces part to
//! second order, which F′ sees through the second partials). Elsewhere the solutions are
//! isolated points (an isolated touching point, as where the Villarceau plane touches a
//! torus, or parallel normals at distance > 0, which is no contact), and where F′ has rank 2
//! the surfaces coincide over a region.
//!
//! Method: Gauss–Newton with minimum-norm steps (the pseudo-inverse of F′ by its singular
//! value decomposition, unknowns scaled to lengths by the partials' norms and rows to unit
//! norm) from the centres of a pair of patches finds a point ([`find`]); marching follows
//! the curve as for crossing branches ([`crate::query::march`]: predictor along T, step
//! control by the chord error and the turn), with the correction by Gauss–Newton on the
//! five equations F = 0, (A − q)·T = 0 (q the predicted point), or with a parameter held on
//! the boundary the step crosses ([`correct`]). A point counts as touching when |D| is
//! within the tolerance, the normals make an angle with sine at most [`TOUCH_SINE`], and
//! the smallest singular value of the scaled F′ is at most [`KERNEL`] of the largest while
//! the next one is not.

use crate::Point;
use crate::curve::Interval;
use crate::error::Result;
use crate::query::branch::coincidence;
use crate::query::newton::{self, QUADRATIC_STEP, Step, cap, scaled_small};
use crate::query::surface_pair::{MarchPoint, Marcher};
use crate::surface::Surface;
use nalgebra::{SMatrix, SVector};

/// Sine of the angle between the normals above which a point is not a touching point.
pub const TOUCH_SINE: f64 = 1e-7;

/// Singular values of the scaled Jacobian at most this fraction of the largest count as zero.
pub const KERNEL: f64 = 1e-6;

/// S, S_u, S_v, S_uu, S_uv, S_vv at (u, v).
fn frame<S: Surface<3> + ?Sized>(s: &S, u: f64, v: f64) -> [Point<3>; 6] {
    let mut o = [Point::<3>::zeros(); 9];
    s.eval_partials(u, v, 2, 2, &mut o);
    [o[0], o[3], o[1], o[6], o[4], o[2]]
}

/// F, F′ and the frames of both surfaces at x.
struct System {
    f: [f64; 4],
    j: [[f64; 4]; 4],
    a: [Point<3>; 6],
    b: [Point<3>; 6],
}

impl System {
    fn at<A: Surface<3> + ?Sized, B: Surface<3> + ?Sized>(m: &Marcher<'_, A, B>, x: &[f64; 4]) -> Self {
        let (a, b) = (frame(m.a, x[0], x[1]), frame(m.b, x[2], x[3]));
        let d = a[0] - b[0];
        let n = a[1].cross(&a[2]);
        let nu = a[3].cross(&a[2]) + a[1].cross(&a[4]);
        let nv = a[4].cross(&a[2]) + a[1].cross(&a[5]);
        let [_, bs, bt, bss, bst, btt] = b;
        let f = [d.dot(&bs), d.dot(&bt), n.dot(&bs), n.dot(&bt)];
        let j = [
            [a[1].dot(&bs), a[2].dot(&bs), d.dot(&bss) - bs.dot(&bs), d.dot(&bst) - bt.dot(&bs)],
            [a[1].dot(&bt), a[2].dot(&bt), d.dot(&bst) - bs.dot(&bt), d.dot(&btt) - bt.dot(&bt)],
            [nu.dot(&bs), nv.dot(&bs), n.dot(&bss), n.dot(&bst)],
            [nu.dot(&bt), nv.dot(&bt), n.dot(&bst), n.dot(&btt)],
        ];
        System { f, j, a, b }
    }

    /// The unknowns' scales: the partials' norms (unknowns in units of length).
    fn columns(&self) -> [f64; 4] {
        let c = [self.a[1].norm(), self.a[2].norm(), self.b[1].norm(), self.b[2].norm()];
        let top = c.iter().fold(0.0f64, |m, v| m.max(*v)).max(f64::MIN_POSITIVE);
        c.map(|v| v.max(1e-12 * top))
    }

    /// The rows (F′ with an optional fifth row) scaled: columns by [`System::columns`], each
    /// row to unit norm; and the right-hand side scaled alike.
    fn scaled(&self, fifth: Option<([f64; 4], f64)>) -> (SMatrix<f64, 5, 4>, SVector<f64, 5>) {
        let c = self.columns();
        let (mut j, mut r) = (SMatrix::<f64, 5, 4>::zeros(), SVector::<f64, 5>::zeros());
        let rows = (0..4).map(|i| (self.j[i], self.f[i])).chain(fifth);
        for (i, (row, value)) in rows.enumerate() {
            let scaled: [f64; 4] = std::array::from_fn(|k| row[k] / c[k]);
            let norm = scaled.iter().map(|v| v * v).sum::<f64>().sqrt();
            if norm > 0.0 && norm.is_finite() {
                for k in 0..4 {
                    j[(i, k)] = scaled[k] / norm;
                }
                r[i] = value / norm;
            }
        }
        (j, r)
    }

    /// |D| and the sine of the angle between the normals.
    fn contact(&self) -> (f64, f64) {
        let (na, nb) = (self.a[1].cross(&self.a[2]), self.b[1].cross(&self.b[2]));
        let scale = na.norm() * nb.norm();
        let sine = if scale > 0.0 { na.cross(&nb).norm() / scale } else { f64::INFINITY };
        ((self.a[0] - self.b[0]).norm(), sine)
    }
}

/// The minimum-norm Gauss–Newton step of the scaled system, in the unknowns' own units.
fn step(sys: &System, fifth: Option<([f64; 4], f64)>) -> Option<[f64; 4]> {
    let (j, r) = sys.scaled(fifth);
    let svd = j.svd(true, true);
    let top = svd.singular_values.max();
    let y = svd.solve(&r, KERNEL * 1e-4 * top).ok()?;
    let c = sys.columns();
    let out: [f64; 4] = std::array::from_fn(|k| y[k] / c[k]);
    out.iter().all(|v| v.is_finite()).then_some(out)
}

/// What the rank of the scaled F′ at x says.
enum Rank {
    /// Full: an isolated point.
    Isolated,
    /// 3: a touching curve, with its unit tangent.
    Curve(Point<3>),
    /// 2 or less: the surfaces coincide around x.
    Region,
}

fn rank(sys: &System) -> Rank {
    let (j, _) = sys.scaled(None);
    let j4 = j.fixed_view::<4, 4>(0, 0).into_owned();
    let Some(svd) = j4.try_svd(false, true, f64::EPSILON, 0) else { return Rank::Isolated };
    let Some(vt) = svd.v_t else { return Rank::Isolated };
    let mut order: Vec<usize> = (0..4).collect();
    order.sort_by(|&p, &q| svd.singular_values[p].total_cmp(&svd.singular_values[q]));
    let top = svd.singular_values[order[3]];
    if top.is_nan() || top <= 0.0 || svd.singular_values[order[0]] > KERNEL * top {
        return Rank::Isolated;
    }
    if svd.singular_values[order[1]] <= KERNEL * top {
        return Rank::Region;
    }
    let c = sys.columns();
    let k = order[0];
    let t = sys.a[1] * (vt[(k, 0)] / c[0]) + sys.a[2] * (vt[(k, 1)] / c[1]);
    let tb = sys.b[1] * (vt[(k, 2)] / c[2]) + sys.b[2] * (vt[(k, 3)] / c[3]);
    // Both points move by the same vector along the kernel; use their mean.
    let t = (t + tb) * 0.5;
    if t.norm() > 0.0 { Rank::Curve(t.normalize()) } else { Rank::Isolated }
}

/// Whether x is a touching point (distance within the tolerance, normals parallel).
fn touches<A: Surface<3> + ?Sized, B: Surface<3> + ?Sized>(m: &Marcher<'_, A, B>, sys: &System) -> bool {
    let (distance, sine) = sys.contact();
    distance <= m.tolerance && sine <= TOUCH_SINE
}

/// The march point at x (a touching point on a touching curve, its tangent oriented along
/// `along`), or `None`.
pub fn point<A: Surface<3> + ?Sized, B: Surface<3> + ?Sized>(
    m: &Marcher<'_, A, B>,
    x: [f64; 4],
    along: &Point<3>,
) -> Option<MarchPoint> {
    let sys = System::at(m, &x);
    if !touches(m, &sys) {
        return None;
    }
    let Rank::Curve(t) = rank(&sys) else { return None };
    let tangent = if t.dot(along) < 0.0 { -t } else { t };
    Some(MarchPoint { x, point: sys.a[0], tangent, partials: [sys.a[1], sys.a[2], sys.b[1], sys.b[2]] })
}

/// A point of a touching curve near x (the centres of a pair of patches), found by
/// Gauss–Newton on F = 0 staying inside `within`: `Ok(None)` when there is none there
/// (no contact, or an isolated touching point), an error when the surfaces coincide there.
pub fn find<A: Surface<3> + ?Sized, B: Surface<3> + ?Sized>(
    m: &Marcher<'_, A, B>,
    x: [f64; 4],
    within: &[Interval; 4],
) -> Result<Option<MarchPoint>> {
    let Some(x) = iterate(m, x, None, Some(within)) else { return Ok(None) };
    let sys = System::at(m, &x);
    if !touches(m, &sys) {
        return Ok(None);
    }
    match rank(&sys) {
        Rank::Isolated => Ok(None),
        Rank::Curve(_) => Ok(point(m, x, &Point::<3>::zeros())),
        Rank::Region => Err(coincidence(x[0], x[1])),
    }
}

/// The correction of one marching step: Gauss–Newton from x on F = 0 and (A − q)·T = 0,
/// or `x[k] = value` for `hold = Some((k, value))`; the touching point reached, or `None`.
pub fn correct<A: Surface<3> + ?Sized, B: Surface<3> + ?Sized>(
    m: &Marcher<'_, A, B>,
    x: [f64; 4],
    q: &Point<3>,
    t: &Point<3>,
    hold: Option<(usize, f64)>,
) -> Option<[f64; 4]> {
    let x = iterate(m, x, Some(Plane { q, t, hold }), None)?;
    touches(m, &System::at(m, &x)).then_some(x)
}

/// The fifth equation of a marching correction: (A − q)·T = 0, or a held parameter.
struct Plane<'p> {
    q: &'p Point<3>,
    t: &'p Point<3>,
    hold: Option<(usize, f64)>,
}

/// Gauss–Newton iterations on F = 0 with the marching constraint when given, clamping open
/// parameters to their domains and wrapping closed ones (at the end only when confined to
/// `within`, given before wrapping); `None` when an iterate leaves `within` or a step is
/// not finite.
fn iterate<A: Surface<3> + ?Sized, B: Surface<3> + ?Sized>(
    m: &Marcher<'_, A, B>,
    mut x: [f64; 4],
    constraint: Option<Plane<'_>>,
    within: Option<&[Interval; 4]>,
) -> Option<[f64; 4]> {
    let domains = m.domains();
    let wrap = |x: [f64; 4]| if within.is_some() { x } else { m.wrap(x) };
    x = wrap(x);
    let x = newton::iterate(cap::TOUCHING, x, |x| {
        let sys = System::at(m, x);
        let fifth = constraint.as_ref().map(|&Plane { q, t, hold }| match hold {
            Some((k, value)) => {
                let mut row = [0.0; 4];
                row[k] = 1.0;
                (row, x[k] - value)
            }
            None => ([sys.a[1].dot(t), sys.a[2].dot(t), 0.0, 0.0], (sys.a[0] - q).dot(t)),
        });
        let Some(d) = step(&sys, fifth) else {
            return Step::Fail;
        };
        let mut next = *x;
        let mut size = 0.0f64;
        for k in 0..4 {
            next[k] -= d[k];
            size = size.max(d[k].abs());
            if within.is_some_and(|w| !(next[k] >= w[k].start && next[k] <= w[k].end)) {
                return Step::Fail;
            }
            if !domains[k].1 {
                next[k] = domains[k].0.clamp(next[k]);
            }
        }
        let next = wrap(next);
        // Quadratic convergence: a step below 10⁻⁸ of the scale leaves an error of the
        // order of its square.
        Step::To(next, scaled_small(size, &next, QUADRATIC_STEP))
    })?;
    Some(m.wrap(x))
}
