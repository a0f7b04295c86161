//! Curve–surface (and surface–surface) intersections against closed forms: every reported
//! point lies on both shapes, and every root of an independent one-variable equation is
//! found.

mod common;
use common::*;
use splinekit::Point;
use splinekit::basis::Side;
use splinekit::curve::model::Line;
use splinekit::curve::{Curve, Interval};
use splinekit::query::{IntersectionKind, intersect_curve_surface};
use splinekit::surface::Surface;
use splinekit::surface::model::{Cylinder, Sphere};

/// A helix about the x axis: (a·t − l, r cos t, r sin t), t ∈ [0, 6π].
struct XHelix {
    a: f64,
    l: f64,
    r: f64,
}

impl Curve<3> for XHelix {
    fn domain(&self) -> Interval {
        Interval::new(0.0, 6.0 * std::f64::consts::PI)
    }
    fn eval_side(&self, t: f64, _side: Side, out: &mut [Point<3>]) {
        for (k, o) in out.iter_mut().enumerate() {
            let x = match k {
                0 => self.a * t - self.l,
                1 => self.a,
                _ => 0.0,
            };
            // The k-th derivative of cos t is cos(t + kπ/2).
            let phase = t + k as f64 * std::f64::consts::FRAC_PI_2;
            *o = p3(x, self.r * phase.cos(), self.r * phase.sin());
        }
    }
}

/// Roots of g on [a, b] by sampling and bisection.
fn roots(g: impl Fn(f64) -> f64, a: f64, b: f64, n: usize) -> Vec<f64> {
    let mut out = Vec::new();
    for i in 0..n {
        let (mut lo, mut hi) = (a + (b - a) * i as f64 / n as f64, a + (b - a) * (i + 1) as f64 / n as f64);
        if g(lo).signum() == g(hi).signum() {
            continue;
        }
        for _ in 0..200 {
            let m = 0.5 * (lo + hi);
            if g(m).signum() == g(lo).signum() { lo = m } else { hi = m }
        }
        out.push(0.5 * (lo + hi));
    }
    out
}

#[test]
fn lines_pierce_a_sphere_where_the_quadratic_says() {
    let sphere = Sphere::new(1.5).unwrap();
    for k in 0..12 {
        let f = k as f64;
        let from = p3(-3.0 + 0.1 * f, -2.0 + 0.3 * (f * 1.7).sin(), 0.2 * f - 1.0);
        let to = p3(2.5, 2.0 * (f * 0.9).cos(), 1.0 - 0.15 * f);
        let line = Line::new(from, to).unwrap();
        let d = to - from;
        // |from + t d|² = r²: a t² + b t + c = 0.
        let (a, b, c) = (d.dot(&d), 2.0 * from.dot(&d), from.dot(&from) - 2.25);
        let disc = b * b - 4.0 * a * c;
        let expected: Vec<f64> = if disc > 0.0 {
            [(-b - disc.sqrt()) / (2.0 * a), (-b + disc.sqrt()) / (2.0 * a)]
                .into_iter()
                .filter(|t| (0.0..=1.0).contains(t))
                .collect()
        } else {
            vec![]
        };
        let found = intersect_curve_surface(&line, &sphere, 1e-9).unwrap();
        assert_eq!(found.len(), expected.len(), "line {k}: {found:?} vs {expected:?}");
        for (p, t) in found.iter().zip(&expected) {
            assert!((p.t - t).abs() < 1e-12, "line {k}: t {} vs {t}", p.t);
            assert!((line.point(p.t) - sphere.point(p.u, p.v)).norm() < 1e-9);
            assert_eq!(p.kind, IntersectionKind::Crossing);
        }
    }
}

#[test]
fn a_helix_about_x_crosses_a_cylinder_about_z_at_every_root() {
    let (rho, h) = (0.9, 2.0);
    let cylinder = Cylinder::new(rho, h).unwrap();
    let helix = XHelix { a: 0.05, l: 0.47, r: 1.0 };
    let found = intersect_curve_surface(&helix, &cylinder, 1e-9).unwrap();
    // On the cylinder's side: x² + y² = ρ² with 0 ≤ z ≤ h.
    let g = |t: f64| {
        let p = helix.point(t);
        p.x * p.x + p.y * p.y - rho * rho
    };
    let expected: Vec<f64> = roots(g, 0.0, 6.0 * std::f64::consts::PI, 4000)
        .into_iter()
        .filter(|&t| (0.0..=h).contains(&helix.point(t).z))
        .collect();
    assert!(expected.len() >= 4, "the test needs crossings: {expected:?}");
    assert_eq!(found.len(), expected.len(), "{found:?} vs {expected:?}");
    for (p, t) in found.iter().zip(&expected) {
        assert!((p.t - t).abs() < 1e-10, "t {} vs {t}", p.t);
        assert!((helix.point(p.t) - cylinder.point(p.u, p.v)).norm() < 1e-9);
    }
}
