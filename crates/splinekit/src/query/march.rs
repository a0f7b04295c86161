//! One step of marching along the intersection curve of two surfaces in 3-D.
//!
//! The state is x = (u_a, v_a, u_b, v_b) with S_a(u_a, v_a) = S_b(u_b, v_b). The curve's
//! tangent is T = N_a × N_b (normalised, oriented like the previous one). A step of length
//! h predicts the parameters by the least-squares solutions of J_a δ_a = h·T and
//! J_b δ_b = h·T (J = [S_u, S_v]), then corrects by Newton's method on the four equations
//! S_a − S_b = 0, (S_a − q)·T = 0 with q = P + h·T (the plane through the predicted point
//! normal to the tangent), or with a parameter held on the domain boundary the step crosses
//! (or runs along: a curve lying in a boundary is followed there).
//! The step is accepted when the tangent turns by θ with h·θ/8 ≤ `chord` (the sagitta of a
//! circular arc of chord h turning by θ) and θ ≤ [`MAX_TURN`]; otherwise it is halved,
//! at most [`MAX_HALVINGS`] times.

use crate::Interval;
use crate::Point;
use crate::query::newton::{self, NEGLIGIBLE_STEP, QUADRATIC_STEP, Step, cap, scaled_small};
pub use crate::query::surface_pair::{MarchPoint, Marcher};
use crate::query::touching;
use crate::surface::Surface;
use nalgebra::{Matrix2, Matrix4, Vector2, Vector4};

/// The largest angle (radians) the tangent may turn in one step.
pub const MAX_TURN: f64 = 0.2;

/// The largest move off a boundary, as a fraction of the step, of a curve that counts as
/// running along that boundary (a step at an angle of at most about 0.06° to it).
pub const ALONG_BOUNDARY: f64 = 1e-3;

/// How often one step may be halved before marching stops.
pub const MAX_HALVINGS: usize = 40;

/// Sine of the angle between the normals below which the surfaces count as tangent.
pub const TANGENT_NORMAL_SINE: f64 = 1e-8;

/// Which curve a march follows.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Contact {
    /// A crossing branch: the normals make an angle (tangent N_a × N_b).
    Crossing,
    /// A touching curve: the normals are parallel ([`crate::query::touching`]).
    Touching,
}

/// How a step ended.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum StepEnd {
    /// A point inside both domains, and the step length to try next.
    Inside(MarchPoint, f64),
    /// A point on a domain boundary: the branch leaves there.
    Boundary(MarchPoint),
    /// The normals became parallel (the surfaces touch).
    Tangential,
    /// No step length down to the halving limit was accepted.
    StepLimit,
}

/// S, S_u, S_v of both surfaces.
struct Frames {
    a: [Point<3>; 3],
    b: [Point<3>; 3],
}

impl<A: Surface<3> + ?Sized, B: Surface<3> + ?Sized> Marcher<'_, A, B> {
    fn frames(&self, x: &[f64; 4]) -> Frames {
        let (mut oa, mut ob) = ([Point::<3>::zeros(); 4], [Point::<3>::zeros(); 4]);
        self.a.eval_partials(x[0], x[1], 1, 1, &mut oa);
        self.b.eval_partials(x[2], x[3], 1, 1, &mut ob);
        Frames { a: [oa[0], oa[2], oa[1]], b: [ob[0], ob[2], ob[1]] }
    }

    /// The point at x with its unit tangent oriented along `along` (any sign when zero);
    /// `None` where the normals are parallel.
    pub fn point(&self, x: [f64; 4], along: &Point<3>) -> Option<MarchPoint> {
        Self::point_with(x, &self.frames(&x), along)
    }

    /// [`Marcher::point`] with the surfaces' frames at x already evaluated.
    fn point_with(x: [f64; 4], f: &Frames, along: &Point<3>) -> Option<MarchPoint> {
        let (na, nb) = (f.a[1].cross(&f.a[2]), f.b[1].cross(&f.b[2]));
        let t = na.cross(&nb);
        let scale = na.norm() * nb.norm();
        if t.norm().is_nan() || t.norm() <= TANGENT_NORMAL_SINE * scale {
            return None;
        }
        let t = t.normalize();
        let tangent = if t.dot(along) < 0.0 { -t } else { t };
        Some(MarchPoint { x, point: f.a[0], tangent, partials: [f.a[1], f.a[2], f.b[1], f.b[2]] })
    }

    /// Newton's method from x on S_a = S_b and the fourth equation: (S_a − q)·T = 0, or
    /// `x[k] = value` for `hold = Some((k, value))`. The parameters where the surfaces agree
    /// within the tolerance (with the frames there), or `None`. The iteration stops once a
    /// step is below 10⁻⁸ of the parameters' scale and the surfaces agree: Newton's
    /// quadratic convergence leaves an error of the order of the square of that step.
    fn correct(
        &self,
        x: [f64; 4],
        q: &Point<3>,
        t: &Point<3>,
        hold: Option<(usize, f64)>,
    ) -> Option<([f64; 4], Frames)> {
        let x = self.wrap(x);
        let mut f = self.frames(&x);
        let x = newton::iterate(cap::MARCH, x, |x| {
            let g = f.a[0] - f.b[0];
            let mut j = Matrix4::<f64>::zeros();
            for r in 0..3 {
                j[(r, 0)] = f.a[1][r];
                j[(r, 1)] = f.a[2][r];
                j[(r, 2)] = -f.b[1][r];
                j[(r, 3)] = -f.b[2][r];
            }
            let last = match hold {
                Some((k, value)) => {
                    j[(3, k)] = 1.0;
                    x[k] - value
                }
                None => {
                    j[(3, 0)] = t.dot(&f.a[1]);
                    j[(3, 1)] = t.dot(&f.a[2]);
                    (f.a[0] - q).dot(t)
                }
            };
            let Some(step) = j.lu().solve(&Vector4::new(g.x, g.y, g.z, last)) else {
                return Step::Fail;
            };
            let size = step.amax();
            if !size.is_finite() {
                return Step::Fail;
            }
            let next = self.wrap(std::array::from_fn(|k| x[k] - step[k]));
            f = self.frames(&next);
            let done = scaled_small(size, &next, NEGLIGIBLE_STEP)
                || (scaled_small(size, &next, QUADRATIC_STEP) && (f.a[0] - f.b[0]).norm() <= self.tolerance);
            Step::To(next, done)
        })?;
        ((f.a[0] - f.b[0]).norm() <= self.tolerance).then_some((x, f))
    }

    /// Newton's method with minimum-norm steps on S_a − S_b = 0 (three equations in four
    /// unknowns) from x, staying inside `within` (per parameter, before wrapping; open
    /// parameters are also clamped to their domains): the nearby point of the intersection
    /// curve, or `None` when the iteration leaves `within`, the Jacobian loses rank or the
    /// surfaces do not agree within the tolerance at the end.
    pub fn converge(&self, x: [f64; 4], within: &[Interval; 4]) -> Option<[f64; 4]> {
        let d = self.domains();
        let x = newton::iterate(cap::MARCH, x, |x| {
            let f = self.frames(x);
            let g = f.a[0] - f.b[0];
            let cols = [f.a[1], f.a[2], -f.b[1], -f.b[2]];
            let mut jjt = nalgebra::Matrix3::<f64>::zeros();
            for c in &cols {
                jjt += c * c.transpose();
            }
            let Some(y) = jjt.cholesky().map(|c| c.solve(&g)) else {
                return Step::Fail;
            };
            let mut next = *x;
            let mut size = 0.0f64;
            for k in 0..4 {
                let step = cols[k].dot(&y);
                size = size.max(step.abs());
                next[k] -= step;
                if !(next[k] >= within[k].start && next[k] <= within[k].end) {
                    return Step::Fail;
                }
                if !d[k].1 {
                    next[k] = d[k].0.clamp(next[k]);
                }
            }
            if !size.is_finite() {
                return Step::Fail;
            }
            Step::To(next, scaled_small(size, &next, NEGLIGIBLE_STEP))
        })?;
        let x = self.wrap(x);
        let f = self.frames(&x);
        ((f.a[0] - f.b[0]).norm() <= self.tolerance).then_some(x)
    }

    /// The parameter increments from `p` that move both surfaces by the vector `d` (least
    /// squares on the partials at `p`).
    fn predict(p: &MarchPoint, d: &Point<3>) -> Option<[f64; 4]> {
        let solve = |su: &Point<3>, sv: &Point<3>| -> Option<Vector2<f64>> {
            let m = Matrix2::new(su.dot(su), su.dot(sv), su.dot(sv), sv.dot(sv));
            m.lu().solve(&Vector2::new(su.dot(d), sv.dot(d)))
        };
        let [au, av, bu, bv] = &p.partials;
        let (da, db) = (solve(au, av)?, solve(bu, bv)?);
        let x = &p.x;
        Some([x[0] + da[0], x[1] + da[1], x[2] + db[0], x[3] + db[1]])
    }

    /// The first open parameter the predicted step leaves its domain by, as the fraction of
    /// the step that reaches the boundary and the (index, boundary value).
    fn exit(&self, from: &[f64; 4], to: &[f64; 4]) -> Option<(f64, usize, f64)> {
        let mut best: Option<(f64, usize, f64)> = None;
        for (k, (i, closed)) in self.domains().into_iter().enumerate() {
            if closed || (to[k] >= i.start && to[k] <= i.end) {
                continue;
            }
            let bound = if to[k] < i.start { i.start } else { i.end };
            let s = ((bound - from[k]) / (to[k] - from[k])).clamp(0.0, 1.0);
            if best.is_none_or(|b| s < b.0) {
                best = Some((s, k, bound));
            }
        }
        best
    }

    /// An open parameter the curve runs along the boundary of (p lies on that boundary and
    /// the predicted step moves off it by at most [`ALONG_BOUNDARY`] of its length, in
    /// 3-D): `to` is put back on the boundary, and the (index, boundary value) is held in
    /// the correction, so that a curve lying in a boundary (a sphere touching a cylinder
    /// along its rim) is followed along it instead of leaving at every step.
    fn along_boundary(&self, p: &MarchPoint, to: &mut [f64; 4], h: f64) -> Option<(usize, f64)> {
        for (k, (i, closed)) in self.domains().into_iter().enumerate() {
            let scale = 1e-12 * (1.0 + i.start.abs().max(i.end.abs()));
            let bound = if (p.x[k] - i.start).abs() <= scale {
                i.start
            } else if (p.x[k] - i.end).abs() <= scale {
                i.end
            } else {
                continue;
            };
            if closed || (to[k] >= i.start && to[k] <= i.end) {
                continue;
            }
            if (to[k] - bound).abs() * p.partials[k].norm() <= ALONG_BOUNDARY * h {
                to[k] = bound;
                return Some((k, bound));
            }
        }
        None
    }

    /// One step of length about h from `p` along a curve of the given contact (see the
    /// module documentation; touching curves are corrected by [`touching::correct`]). The next step
    /// length aims at 0.8 of the chord error and of [`MAX_TURN`] (the sagitta grows as the
    /// square of the step, the turn linearly), at most twice this one.
    pub fn step(&self, p: &MarchPoint, mut h: f64, contact: Contact) -> StepEnd {
        for _ in 0..MAX_HALVINGS {
            let Some(mut to) = Self::predict(p, &(p.tangent * h)) else { return StepEnd::StepLimit };
            let unwrapped = p.x;
            let along = self.along_boundary(p, &mut to, h);
            let exit = self.exit(&unwrapped, &to);
            let mut len = h;
            if let Some((s, _, _)) = exit {
                len = h * s;
                to = std::array::from_fn(|k| unwrapped[k] + (to[k] - unwrapped[k]) * s);
            }
            let q = p.point + p.tangent * len;
            let hold = exit.map(|(_, k, v)| (k, v)).or(along);
            let next = match contact {
                Contact::Crossing => {
                    let corrected = self.correct(to, &q, &p.tangent, hold);
                    let next = corrected.as_ref().and_then(|(x, f)| Self::point_with(*x, f, &p.tangent));
                    if next.is_none() && corrected.is_some() {
                        return StepEnd::Tangential;
                    }
                    next
                }
                Contact::Touching => {
                    touching::correct(self, to, &q, &p.tangent, hold).and_then(|x| touching::point(self, x, &p.tangent))
                }
            };
            let Some(next) = next else {
                h *= 0.5;
                continue;
            };
            let turn = 2.0 * ((next.tangent - p.tangent).norm() / 2.0).min(1.0).asin();
            let forward = (next.point - p.point).dot(&p.tangent) > 0.0 || len == 0.0;
            let sagitta = len * turn / 8.0;
            if turn > MAX_TURN || sagitta > self.chord || !forward {
                h *= 0.5;
                continue;
            }
            if exit.is_some() {
                return StepEnd::Boundary(next);
            }
            let by_chord = if sagitta > 0.0 { (0.8 * self.chord / sagitta).sqrt() } else { 2.0 };
            let by_turn = if turn > 0.0 { 0.8 * MAX_TURN / turn } else { 2.0 };
            let grow = (h * by_chord.min(by_turn).clamp(0.5, 2.0)).min(self.max_step);
            return StepEnd::Inside(next, grow);
        }
        StepEnd::StepLimit
    }
}
