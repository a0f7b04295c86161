//! The Dupin cyclide's exact biquadratic NURBS form against independent truth: every point
//! lies on the quartic (x² + y² + z² − μ² + b²)² = 4 (a x − c μ)² + 4 b² y², and the point
//! at parameters (s, t) is the closed-form parametrisation's at the angles the nine-point
//! NURBS circle has at s and t (exactly the parameter at the quarter points), for ring,
//! spindle and horn cyclides; bad parameters are refused by name.

use std::f64::consts::{FRAC_PI_2, FRAC_PI_4, PI};

use splinekit::surface::Surface;
use splinekit::surface::model::dupin_cyclide;

/// The closed-form parametrisation at angles (θ, ψ).
fn closed_form(a: f64, c: f64, mu: f64, theta: f64, psi: f64) -> [f64; 3] {
    let b2 = a * a - c * c;
    let b = b2.sqrt();
    let (ct, st, cp, sp) = (theta.cos(), theta.sin(), psi.cos(), psi.sin());
    let d = a - c * ct * cp;
    [(mu * (c - a * ct * cp) + b2 * ct) / d, b * st * (a - mu * cp) / d, b * sp * (c * ct - mu) / d]
}

/// The angle of the nine-point NURBS circle at parameter s, in closed form rather than
/// from its control points: on quarter k (s = (k + τ)·π/2, τ ∈ [0, 1]) the circle is the
/// rational quadratic arc of half-angle α = π/4 (end weights 1, middle weight cos α), and
/// such an arc's half-angle tangent, measured from the arc's middle, is linear in its
/// parameter: tan(β/2) = tan(α/2)·(2τ − 1) (the arc is a projective image of the line,
/// odd about τ = ½, from −α at τ = 0 to α at τ = 1). So θ = kπ/2 + π/4 + 2 atan(tan(π/8)(2τ − 1)).
fn circle_angle(s: f64) -> f64 {
    let k = (s / FRAC_PI_2).floor().clamp(0.0, 3.0);
    let tau = s / FRAC_PI_2 - k;
    k * FRAC_PI_2 + FRAC_PI_4 + 2.0 * ((PI / 8.0).tan() * (2.0 * tau - 1.0)).atan()
}

const CYCLIDES: [(f64, f64, f64); 3] = [(3.0, 1.0, 2.0), (3.0, 1.0, 0.5), (3.0, 2.0, 3.0)];

#[test]
fn every_point_lies_on_the_quartic() {
    for (a, c, mu) in CYCLIDES {
        let s = dupin_cyclide(a, c, mu).unwrap();
        let b2 = a * a - c * c;
        for i in 0..=24 {
            for j in 0..=24 {
                let (u, v) = (2.0 * PI * i as f64 / 24.0, 2.0 * PI * j as f64 / 24.0);
                let p = s.point(u, v);
                let (x, y, z) = (p[0], p[1], p[2]);
                let lhs = (x * x + y * y + z * z - mu * mu + b2).powi(2);
                let rhs = 4.0 * (a * x - c * mu).powi(2) + 4.0 * b2 * y * y;
                assert!((lhs - rhs).abs() <= 1e-12 * lhs.max(1.0), "({a}, {c}, {mu}) at ({u}, {v}): {lhs} ≠ {rhs}");
            }
        }
    }
}

#[test]
fn the_nurbs_is_the_closed_form_at_the_circles_angles() {
    for (a, c, mu) in CYCLIDES {
        let s = dupin_cyclide(a, c, mu).unwrap();
        let (du, dv) = (s.domain_u(), s.domain_v());
        assert_eq!((du.start, du.end, dv.start, dv.end), (0.0, 2.0 * PI, 0.0, 2.0 * PI));
        for i in 0..=20 {
            for j in 0..=20 {
                let (u, v) = (du.lerp(i as f64 / 20.0), dv.lerp(j as f64 / 20.0));
                let p = s.point(u, v);
                let q = closed_form(a, c, mu, circle_angle(u), circle_angle(v));
                let d = ((p[0] - q[0]).powi(2) + (p[1] - q[1]).powi(2) + (p[2] - q[2]).powi(2)).sqrt();
                assert!(d < 1e-13 * a, "({a}, {c}, {mu}) at ({u}, {v}): {p:?} ≠ {q:?}");
            }
        }
        // At the quarter points the parameters are the angles.
        for k in 0..4 {
            for l in 0..4 {
                let (u, v) = (k as f64 * FRAC_PI_2, l as f64 * FRAC_PI_2);
                let (p, q) = (s.point(u, v), closed_form(a, c, mu, u, v));
                assert!((0..3).all(|m| (p[m] - q[m]).abs() < 1e-14 * a), "{p:?} ≠ {q:?}");
            }
        }
    }
}

#[test]
fn it_closes_in_both_directions_and_has_normals_on_the_ring() {
    let s = dupin_cyclide(3.0, 1.0, 2.0).unwrap();
    for t in [0.3, 1.7, 4.0] {
        assert!((s.point(0.0, t) - s.point(2.0 * PI, t)).norm() < 1e-14);
        assert!((s.point(t, 0.0) - s.point(t, 2.0 * PI)).norm() < 1e-14);
    }
    for (u, v) in [(0.4, 0.9), (2.0, 5.0), (PI, PI)] {
        let n = s.normal(u, v).expect("a ring cyclide is regular");
        // The normal is the quartic's gradient's direction.
        let p = s.point(u, v);
        let (a, c, mu, b2) = (3.0, 1.0, 2.0, 8.0);
        let r = p[0] * p[0] + p[1] * p[1] + p[2] * p[2] - mu * mu + b2;
        let g = [4.0 * r * p[0] - 8.0 * a * (a * p[0] - c * mu), 4.0 * r * p[1] - 8.0 * b2 * p[1], 4.0 * r * p[2]];
        let gn = (g[0] * g[0] + g[1] * g[1] + g[2] * g[2]).sqrt();
        let cos = (n[0] * g[0] + n[1] * g[1] + n[2] * g[2]) / gn;
        assert!(cos.abs() > 1.0 - 1e-10, "normal {n:?} against the gradient {g:?}");
    }
}

#[test]
fn bad_parameters_are_refused_by_name() {
    for ((a, c, mu), field) in [
        ((1.0, 1.0, 0.5), "a"),
        ((1.0, 2.0, 0.5), "a"),
        ((3.0, -1.0, 0.5), "c"),
        ((f64::NAN, 1.0, 0.5), "a"),
        ((3.0, 1.0, f64::INFINITY), "mu"),
    ] {
        let e = dupin_cyclide(a, c, mu).unwrap_err().to_string();
        assert!(e.starts_with(&format!("{field}:")), "({a}, {c}, {mu}): {e}");
    }
}
