//! Curves on surfaces (GMlib's `PSurfCurve`): points against direct evaluation of the host
//! at the curve's (u, v), derivatives of every order against closed forms (lines on a
//! torus, a circle on a paraboloid, any curve on a plane) and against central differences
//! of the exact derivative one order lower (a Bézier curve on Dini's surface and on a
//! B-spline surface), and the refusal of curves that leave an open direction's domain.

use splinekit::Point;
use splinekit::basis::Side;
use splinekit::curve::model::Line;
use splinekit::curve::{BezierCurve, Curve};
use splinekit::surface::model::{DiniSurface, Plane, Torus};
use splinekit::surface::{BSplineSurface, CurveOnSurface, Surface};
use splinekit::{Interval, Result};
use std::f64::consts::TAU;

fn derivatives<C: Curve<3> + ?Sized>(c: &C, t: f64, k: usize) -> Vec<Point<3>> {
    let mut out = vec![Point::<3>::zeros(); k + 1];
    c.eval(t, &mut out);
    out
}

fn binomial(n: usize, k: usize) -> f64 {
    (0..k).fold(1.0, |acc, i| acc * (n - i) as f64 / (i + 1) as f64)
}

#[test]
fn a_line_on_the_torus_is_the_torus_knot_with_every_derivative_in_closed_form() -> Result<()> {
    let torus = Torus::new(3.0, 1.0)?;
    let (a, b) = (Point::<2>::new(0.2, -0.4), Point::<2>::new(0.2 + 2.0 * TAU, -0.4 + 3.0 * TAU));
    let knot = CurveOnSurface::new(Line::new(a, b)?, torus.clone())?;
    let (alpha, beta) = (b[0] - a[0], b[1] - a[1]);
    let k = 7;
    for i in 0..=40 {
        let t = i as f64 / 40.0;
        let (u, v) = (a[0] + alpha * t, a[1] + beta * t);
        let got = derivatives(&knot, t, k);
        assert!((got[0] - torus.point(u, v)).norm() < 1e-14, "position at {t}");
        // c^{(n)} = Σ_m C(n, m) α^m β^{n−m} ∂^{m, n−m}S (the host's Taylor series along the line).
        let mut host = vec![Point::<3>::zeros(); (k + 1) * (k + 1)];
        torus.eval_partials(u, v, k, k, &mut host);
        for n in 1..=k {
            let want: Point<3> = (0..=n)
                .map(|m| {
                    host[m * (k + 1) + n - m] * (binomial(n, m) * alpha.powi(m as i32) * beta.powi((n - m) as i32))
                })
                .sum();
            let err = (got[n] - want).norm();
            assert!(err < 1e-12 * want.norm().max(1.0), "order {n} at {t}: {} vs {want}", got[n]);
        }
    }
    Ok(())
}

/// The paraboloid (u, v, u² + v²).
struct Paraboloid;
impl Surface<3> for Paraboloid {
    fn domain_u(&self) -> Interval {
        Interval::new(-2.0, 2.0)
    }
    fn domain_v(&self) -> Interval {
        Interval::new(-2.0, 2.0)
    }
    fn eval_partials(&self, u: f64, v: f64, du: usize, dv: usize, out: &mut [Point<3>]) {
        for i in 0..=du {
            for j in 0..=dv {
                out[i * (dv + 1) + j] = match (i, j) {
                    (0, 0) => Point::<3>::new(u, v, u * u + v * v),
                    (1, 0) => Point::<3>::new(1.0, 0.0, 2.0 * u),
                    (0, 1) => Point::<3>::new(0.0, 1.0, 2.0 * v),
                    (2, 0) | (0, 2) => Point::<3>::new(0.0, 0.0, 2.0),
                    _ => Point::<3>::zeros(),
                };
            }
        }
    }
}

/// The circle (x₀ + r cos t, y₀ + r sin t) in the parameter plane, every derivative exact.
struct ParamCircle(f64, f64, f64);
impl Curve<2> for ParamCircle {
    fn domain(&self) -> Interval {
        Interval::new(0.0, TAU)
    }
    fn is_closed(&self) -> bool {
        true
    }
    fn eval_side(&self, t: f64, _side: Side, out: &mut [Point<2>]) {
        for (k, o) in out.iter_mut().enumerate() {
            let phase = t + k as f64 * std::f64::consts::FRAC_PI_2;
            *o = Point::<2>::new(self.2 * phase.cos(), self.2 * phase.sin());
        }
        out[0] += Point::<2>::new(self.0, self.1);
    }
}

#[test]
fn a_circle_about_the_paraboloids_axis_is_a_horizontal_circle() -> Result<()> {
    let r = 1.3;
    let c = CurveOnSurface::new(ParamCircle(0.0, 0.0, r), Paraboloid)?;
    assert!(c.is_closed());
    for i in 0..20 {
        let t = i as f64 * 0.31;
        let got = derivatives(&c, t, 6);
        for (k, g) in got.iter().enumerate() {
            let phase = t + k as f64 * std::f64::consts::FRAC_PI_2;
            let z = if k == 0 { r * r } else { 0.0 };
            let want = Point::<3>::new(r * phase.cos(), r * phase.sin(), z);
            assert!((g - want).norm() < 1e-13, "order {k} at {t}: {g} vs {want}");
        }
    }
    // Off the axis the height is (x₀ + r cos t)² + (y₀ + r sin t)², whose derivatives are
    // those of 2r(x₀ cos t + y₀ sin t) (the rest is constant).
    let (x0, y0) = (0.3, -0.2);
    let c = CurveOnSurface::new(ParamCircle(x0, y0, 0.9), Paraboloid)?;
    for i in 0..20 {
        let t = i as f64 * 0.31;
        let got = derivatives(&c, t, 6);
        for (k, g) in got.iter().enumerate().skip(1) {
            let phase = t + k as f64 * std::f64::consts::FRAC_PI_2;
            let want = 2.0 * 0.9 * (x0 * phase.cos() + y0 * phase.sin());
            assert!((g[2] - want).abs() < 1e-13, "z order {k} at {t}: {} vs {want}", g[2]);
        }
    }
    Ok(())
}

#[test]
fn on_a_plane_the_derivatives_are_the_lifted_curves() -> Result<()> {
    let (o, a, b) = (Point::<3>::new(1.0, 2.0, 3.0), Point::<3>::new(1.0, 0.0, 1.0), Point::<3>::new(0.0, 2.0, -1.0));
    let plane = Plane::new(o, a, b)?;
    let gamma = BezierCurve::new(vec![
        Point::<2>::new(0.1, 0.1),
        Point::<2>::new(0.9, 0.0),
        Point::<2>::new(0.2, 0.8),
        Point::<2>::new(0.7, 0.9),
        Point::<2>::new(0.95, 0.4),
    ])?;
    let c = CurveOnSurface::new(gamma.clone(), plane)?;
    for i in 0..=10 {
        let t = i as f64 / 10.0;
        let mut g = [Point::<2>::zeros(); 6];
        gamma.eval(t, &mut g);
        let got = derivatives(&c, t, 5);
        for k in 0..=5 {
            let want = if k == 0 { o } else { Point::<3>::zeros() } + a * g[k][0] + b * g[k][1];
            assert!((got[k] - want).norm() < 1e-13, "order {k} at {t}");
        }
    }
    Ok(())
}

/// c^{(k)} by the fourth-order central difference of the exact c^{(k−1)}.
fn fd<C: Curve<3> + ?Sized>(c: &C, t: f64, k: usize, h: f64) -> Point<3> {
    let f = |x: f64| c.derivative(x, k - 1);
    (f(t - 2.0 * h) - f(t + 2.0 * h) + (f(t + h) - f(t - h)) * 8.0) / (12.0 * h)
}

fn check_against_differences<C: Curve<3>>(c: &C, name: &str) {
    let d = c.domain();
    for i in 1..20 {
        let t = d.lerp(0.05 + 0.9 * i as f64 / 20.0);
        for k in 1..=4 {
            let (got, want) = (c.derivative(t, k), fd(c, t, k, 1e-3 * d.length()));
            assert!((got - want).norm() < 2e-6 * want.norm().max(1.0), "{name}: order {k} at {t}: {got} vs {want}");
        }
    }
}

#[test]
fn derivatives_agree_with_central_differences_on_curved_hosts() -> Result<()> {
    let dini = DiniSurface::new(1.0, 0.2)?;
    let (du, dv) = (dini.domain_u(), dini.domain_v());
    let p = |a: f64, b: f64| Point::<2>::new(du.lerp(a), dv.lerp(b));
    let gamma = BezierCurve::new(vec![p(0.1, 0.2), p(0.5, 0.9), p(0.8, 0.1), p(0.9, 0.7)])?;
    let on_dini = CurveOnSurface::new(gamma.clone(), dini.clone())?;
    for i in 0..=10 {
        let t = i as f64 / 10.0;
        let g = gamma.point(t);
        assert!((on_dini.point(t) - dini.point(g[0], g[1])).norm() < 1e-14);
    }
    check_against_differences(&on_dini, "Dini");

    let q = |x: f64, y: f64, z: f64| Point::<3>::new(x, y, z);
    let net = vec![
        vec![q(0.0, 0.0, 0.0), q(0.0, 1.0, 0.5), q(0.0, 2.0, 0.0), q(0.0, 3.0, 0.3)],
        vec![q(1.0, 0.0, 1.0), q(1.0, 1.0, -1.0), q(1.0, 2.0, 2.0), q(1.0, 3.0, 0.0)],
        vec![q(2.0, 0.0, 0.0), q(2.0, 1.0, 1.5), q(2.0, 2.0, -0.5), q(2.0, 3.0, 1.0)],
        vec![q(3.0, 0.0, 0.5), q(3.0, 1.0, 0.0), q(3.0, 2.0, 1.0), q(3.0, 3.0, 0.0)],
    ];
    let k = vec![0.0, 0.0, 0.0, 0.0, 1.0, 1.0, 1.0, 1.0];
    let patch = BSplineSurface::new((3, 3), k.clone(), k, net, (false, false))?;
    let gamma = BezierCurve::new(vec![
        Point::<2>::new(0.0, 0.1),
        Point::<2>::new(0.4, 1.0),
        Point::<2>::new(0.9, 0.0),
        Point::<2>::new(1.0, 0.8),
    ])?;
    let on_patch = CurveOnSurface::new(gamma, patch)?;
    check_against_differences(&on_patch, "bicubic patch");
    // A bicubic patch along a cubic is a polynomial of degree 18: the 19th derivative vanishes.
    let high = derivatives(&on_patch, 0.37, 19);
    assert!(high[19].norm() < 1e-6 * high[18].norm().max(1.0), "{}", high[19]);
    Ok(())
}

#[test]
fn a_curve_leaving_an_open_direction_is_refused_naming_the_field() -> Result<()> {
    let line = Line::new(Point::<2>::new(-0.5, 0.5), Point::<2>::new(1.0, 0.5))?;
    let plane = Plane::new(Point::<3>::zeros(), Point::<3>::x(), Point::<3>::y())?;
    let err = CurveOnSurface::new(line, plane).err().expect("refused");
    assert!(matches!(&err, splinekit::Error::Invalid { field, .. } if field == "curve"), "{err}");
    assert!(err.to_string().contains("outside the surface's u-domain"), "{err}");
    // A closed direction wraps: the same line on the torus is fine.
    let line = Line::new(Point::<2>::new(-0.5, 0.5), Point::<2>::new(9.0, 0.5))?;
    let torus = Torus::new(3.0, 1.0)?;
    let c = CurveOnSurface::new(line, torus.clone())?;
    assert!((c.point(0.0) - torus.point(-0.5 + TAU, 0.5)).norm() < 1e-14);
    Ok(())
}
