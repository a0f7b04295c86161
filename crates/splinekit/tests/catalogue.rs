//! The catalogue of model surfaces and curves (GMlib's, written from their published
//! formulas): each kind against its closed form written here independently at
//! pseudo-random parameters, its implicit equation or curvature identity where the
//! literature gives one, its partials of orders up to 3 in each parameter against central
//! differences of the exact partial one order lower, and its seams where it is closed.

mod common;
use common::*;
use splinekit::Point;
use splinekit::surface::Surface;
use splinekit::surface::model::*;
use std::f64::consts::TAU;

/// `n` pseudo-random pairs in (0, 1)² (a fixed linear congruential sequence).
fn unit_pairs(n: usize) -> Vec<(f64, f64)> {
    let mut state = 0x2545_f491_4f6c_dd1du64;
    let mut next = move || {
        state = state.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
        (state >> 11) as f64 / (1u64 << 53) as f64
    };
    (0..n).map(|_| (next(), next())).collect()
}

/// `n` pseudo-random parameters inside the surface's domain, 2 % away from its edges.
fn params<S: Surface<3> + ?Sized>(s: &S, n: usize) -> Vec<(f64, f64)> {
    let (du, dv) = (s.domain_u(), s.domain_v());
    unit_pairs(n).into_iter().map(|(a, b)| (du.lerp(0.02 + 0.96 * a), dv.lerp(0.02 + 0.96 * b))).collect()
}

/// ∂^{i+j} by the fourth-order central difference of the exact (i−1, j) or (i, j−1) partial.
fn fd<S: Surface<3> + ?Sized>(s: &S, u: f64, v: f64, i: usize, j: usize, h: f64) -> Point<3> {
    let f = |du: f64, dv: f64| if i > 0 { s.partial(u + du, v, i - 1, j) } else { s.partial(u, v + dv, i, j - 1) };
    let (e1, e2) = if i > 0 { ((h, 0.0), (2.0 * h, 0.0)) } else { ((0.0, h), (0.0, 2.0 * h)) };
    (f(-e2.0, -e2.1) - f(e2.0, e2.1) + (f(e1.0, e1.1) - f(-e1.0, -e1.1)) * 8.0) / (12.0 * h)
}

/// Every partial of order ≤ 3 in u and in v at pseudo-random parameters against [`fd`],
/// and the positions against `formula`, written independently.
fn check_surface<S: Surface<3> + ?Sized>(s: &S, name: &str, formula: impl Fn(f64, f64) -> Point<3>) {
    let h = 1e-4 * s.domain_u().length().min(s.domain_v().length());
    for (u, v) in params(s, 24) {
        let mut out = [Point::<3>::zeros(); 16];
        s.eval_partials(u, v, 3, 3, &mut out);
        let want = formula(u, v);
        assert!((out[0] - want).norm() <= 1e-12 * want.norm().max(1.0), "{name} at ({u}, {v}): {} vs {want}", out[0]);
        for i in 0..=3 {
            for j in 0..=3 {
                if i + j == 0 {
                    continue;
                }
                let f = fd(s, u, v, i, j, h);
                let scale = out[i * 4 + j].norm().max(out[0].norm()).max(1.0);
                assert!(
                    (out[i * 4 + j] - f).norm() < 1e-6 * scale,
                    "{name}: ∂({i},{j}) at ({u}, {v}): {} vs {f}",
                    out[i * 4 + j]
                );
            }
        }
    }
    // Closed directions: the partials at both ends agree (a period of the formula).
    let (du, dv) = (s.domain_u(), s.domain_v());
    for t in [0.1, 0.37, 0.8] {
        let mut a = [Point::<3>::zeros(); 9];
        let mut b = [Point::<3>::zeros(); 9];
        let ends = [
            (s.is_closed_u(), (du.start, dv.lerp(t)), (du.end - 1e-13 * du.length(), dv.lerp(t))),
            (s.is_closed_v(), (du.lerp(t), dv.start), (du.lerp(t), dv.end - 1e-13 * dv.length())),
        ];
        for (closed, (u0, v0), (u1, v1)) in ends {
            if closed {
                s.eval_partials(u0, v0, 2, 2, &mut a);
                s.eval_partials(u1, v1, 2, 2, &mut b);
                for (p, q) in a.iter().zip(&b) {
                    assert!((p - q).norm() < 1e-9 * p.norm().max(1.0), "{name}: seam at t = {t}: {p} vs {q}");
                }
            }
        }
    }
}

#[test]
fn the_figure_8_klein_bottle_is_gmlibs_bottle_8() {
    // GMlib's "bottle 8" is the figure-8 immersion that `klein_bottle` already is:
    // a = R + cos(u/2) sin v − sin(u/2) sin 2v, (a cos u, a sin u, sin(u/2) sin v + cos(u/2) sin 2v).
    let k = KleinBottle::new(2.5).unwrap();
    check_surface(&k, "klein_bottle", |u, v| {
        let a = 2.5 + (u / 2.0).cos() * v.sin() - (u / 2.0).sin() * (2.0 * v).sin();
        p3(a * u.cos(), a * u.sin(), (u / 2.0).sin() * v.sin() + (u / 2.0).cos() * (2.0 * v).sin())
    });
    // The u-ends meet with a flip: S(2π, v) = S(0, 2π − v).
    for (_, v) in params(&k, 8) {
        assert!((k.point(TAU, v) - k.point(0.0, TAU - v)).norm() < 1e-12);
    }
}

#[test]
fn the_asteroidal_sphere_is_the_sphere_cubed_and_lies_on_the_3d_astroid() {
    let (a, b, c) = (1.2, 0.9, 1.5);
    let s = AsteroidalSphere::new(a, b, c).unwrap();
    check_surface(&s, "asteroidal_sphere", |u, v| {
        p3((a * u.cos() * v.cos()).powi(3), (b * u.sin() * v.cos()).powi(3), (c * v.sin()).powi(3))
    });
    for (u, v) in params(&s, 32) {
        let p = s.point(u, v);
        let astroid = p.x.abs().cbrt().powi(2) / (a * a)
            + p.y.abs().cbrt().powi(2) / (b * b)
            + p.z.abs().cbrt().powi(2) / (c * c);
        assert!((astroid - 1.0).abs() < 1e-12, "|x|^(2/3)/a² + … = {astroid} at ({u}, {v})");
    }
    assert!(AsteroidalSphere::new(0.0, 1.0, 1.0).is_err() && AsteroidalSphere::new(1.0, f64::NAN, 1.0).is_err());
}

#[test]
fn bent_horns_match_bourkes_formula() {
    let phi = TAU / 3.0;
    let s = BentHorns::new(0.5).unwrap();
    check_surface(&s, "bent_horns", |u, v| {
        p3(
            (2.0 + u.cos()) * (v / 3.0 - v.sin()),
            (2.0 + (u - phi).cos()) * (v.cos() - 1.0),
            (2.0 + (u + phi).cos()) * (v.cos() - 1.0),
        ) * 0.5
    });
    // The horns meet in a point at v = 0, whatever u.
    assert!(s.point(0.3, 0.0).norm() < 1e-15 && s.point(-2.0, 0.0).norm() < 1e-15);
    assert!(BentHorns::new(-1.0).is_err() && BentHorns::new(f64::INFINITY).is_err());
}

#[test]
fn the_bohemian_dome_is_a_circle_moved_along_an_ellipse_and_lies_on_its_quartic() {
    let (a, b, c) = (1.0, 0.8, 0.6);
    let s = BohemianDome::new(a, b, c).unwrap();
    check_surface(&s, "bohemian_dome", |u, v| p3(a * u.cos(), a * u.sin() + b * v.cos(), c * v.sin()));
    for (u, v) in params(&s, 32) {
        let p = s.point(u, v);
        let w = b * b * (1.0 - p.z * p.z / (c * c));
        let quartic = (p.x * p.x + p.y * p.y + w - a * a).powi(2) - 4.0 * p.y * p.y * w;
        assert!(quartic.abs() < 1e-12, "quartic = {quartic} at ({u}, {v})");
    }
    assert!(BohemianDome::new(1.0, 0.0, 1.0).is_err() && BohemianDome::new(1.0, 1.0, -2.0).is_err());
}

/// Apéry's sextic of Boy's surface.
fn apery(x: f64, y: f64, z: f64) -> f64 {
    let (r2, q) = (std::f64::consts::SQRT_2, x * x + y * y);
    64.0 * (1.0 - z).powi(3) * z.powi(3) - 48.0 * (1.0 - z).powi(2) * z * z * (3.0 * q + 2.0 * z * z)
        + 12.0
            * (1.0 - z)
            * z
            * (27.0 * q * q - 24.0 * z * z * q + 36.0 * r2 * y * z * (y * y - 3.0 * x * x) + 4.0 * z.powi(4))
        + (9.0 * q - 2.0 * z * z)
            * (-81.0 * q * q - 72.0 * z * z * q + 108.0 * r2 * x * z * (x * x - 3.0 * y * y) + 4.0 * z.powi(4))
}

#[test]
fn boys_surface_lies_on_aperys_sextic_and_its_u_ends_meet_flipped() {
    let r2 = std::f64::consts::SQRT_2;
    let s = BoySurface::new(1.0).unwrap();
    check_surface(&s, "boy_surface", |u, v| {
        let d = 2.0 - r2 * (3.0 * u).sin() * (2.0 * v).sin();
        let c2 = v.cos() * v.cos();
        p3(
            (r2 * c2 * (2.0 * u).cos() + u.cos() * (2.0 * v).sin()) / d,
            (r2 * c2 * (2.0 * u).sin() - u.sin() * (2.0 * v).sin()) / d,
            3.0 * c2 / d,
        )
    });
    for (u, v) in params(&s, 32) {
        let p = s.point(u, v) * (2.0 / 3.0);
        // The sextic's terms are of size up to ~10³ here.
        assert!(apery(p.x, p.y, p.z).abs() < 1e-10, "Apéry's sextic = {} at ({u}, {v})", apery(p.x, p.y, p.z));
    }
    let h = std::f64::consts::FRAC_PI_2;
    for t in [0.3, 1.2, 2.9] {
        assert!((s.point(h, t) - s.point(-h, std::f64::consts::PI - t)).norm() < 1e-12, "u-ends at v = {t}");
    }
    // Scaling scales; a bad scale is refused.
    let big = BoySurface::new(2.5).unwrap();
    assert!((big.partial(0.4, 1.1, 1, 2) - s.partial(0.4, 1.1, 1, 2) * 2.5).norm() < 1e-12);
    assert!(BoySurface::new(0.0).is_err());
}

#[test]
fn the_cross_cap_is_the_sphere_under_a_quadratic_map_and_lies_on_its_quartic() {
    let s = CrossCap::new(1.0).unwrap();
    check_surface(&s, "cross_cap", |u, v| {
        // p = (cos u sin v, sin u sin v, cos v) ↦ (p₂p₃, 2p₁p₂, p₁² − p₂²).
        let p = p3(u.cos() * v.sin(), u.sin() * v.sin(), v.cos());
        p3(p.y * p.z, 2.0 * p.x * p.y, p.x * p.x - p.y * p.y)
    });
    for (u, v) in params(&s, 32) {
        let p = s.point(u, v);
        let quartic = 4.0 * p.x * p.x * (p.norm_squared() + p.z) + p.y * p.y * (p.y * p.y + p.z * p.z - 1.0);
        assert!(quartic.abs() < 1e-13, "quartic = {quartic} at ({u}, {v})");
    }
    let twice = CrossCap::new(2.0).unwrap();
    assert!((twice.point(1.0, 0.7) - s.point(1.0, 0.7) * 2.0).norm() < 1e-15);
    assert!(CrossCap::new(f64::NAN).is_err());
}

#[test]
fn dinis_surface_has_constant_gaussian_curvature() {
    let (a, b) = (1.0, 0.2);
    let s = DiniSurface::new(a, b).unwrap();
    check_surface(&s, "dini_surface", |u, v| {
        p3(a * u.cos() * v.sin(), a * u.sin() * v.sin(), a * (v.cos() + (v / 2.0).tan().ln()) + b * u)
    });
    let other = DiniSurface::new(1.5, -0.4).unwrap();
    for (surface, a, b) in [(&s, a, b), (&other, 1.5, -0.4)] {
        for (u, v) in params(surface, 32) {
            let k = surface.curvatures(u, v).unwrap().gaussian;
            assert!((k + 1.0 / (a * a + b * b)).abs() < 1e-10, "K = {k} at ({u}, {v})");
        }
    }
    assert!(DiniSurface::new(0.0, 0.2).is_err() && DiniSurface::new(1.0, f64::NAN).is_err());
}

#[test]
fn the_eight_surface_turns_a_figure_eight_and_lies_on_its_quartic() {
    let s = EightSurface::new(1.0).unwrap();
    check_surface(&s, "eight_surface", |u, v| p3(u.cos() * (2.0 * v).sin(), u.sin() * (2.0 * v).sin(), v.sin()));
    for (u, v) in params(&s, 32) {
        let p = s.point(u, v);
        let quartic = p.x * p.x + p.y * p.y - 4.0 * p.z * p.z * (1.0 - p.z * p.z);
        assert!(quartic.abs() < 1e-14, "x² + y² − 4z²(1 − z²) = {quartic} at ({u}, {v})");
    }
    assert!(EightSurface::new(-1.0).is_err());
}

#[test]
fn the_inside_out_torus_is_an_elliptic_torus_through_its_axis() {
    let (a, b, c) = (1.0, 2.0, 1.5);
    let s = InsideOutTorus::new(a, b, c).unwrap();
    check_surface(&s, "inside_out_torus", |u, v| {
        p3((a + b * v.cos()) * u.cos(), (a + b * v.cos()) * u.sin(), c * v.sin())
    });
    for (u, v) in params(&s, 32) {
        let p = s.point(u, v);
        let rho = (p.x * p.x + p.y * p.y).sqrt();
        let e = |r: f64| (r - a).powi(2) / (b * b) + p.z * p.z / (c * c) - 1.0;
        assert!((e(rho) * e(-rho)).abs() < 1e-12, "not on the torus at ({u}, {v})");
    }
    // With b > a the tube crosses the axis: the inner equator is on the far side.
    assert!((s.point(0.0, std::f64::consts::PI) - p3(a - b, 0.0, 0.0)).norm() < 1e-15);
    assert!(InsideOutTorus::new(1.0, 0.0, 1.0).is_err() && InsideOutTorus::new(1.0, 1.0, f64::INFINITY).is_err());
}

#[test]
fn kuens_surface_has_constant_gaussian_curvature_minus_one() {
    let s = KuenSurface::new(1.0).unwrap();
    check_surface(&s, "kuen_surface", |u, v| {
        let d = 1.0 + u * u * v.sin() * v.sin();
        p3(
            2.0 * (u.cos() + u * u.sin()) * v.sin() / d,
            2.0 * (u.sin() - u * u.cos()) * v.sin() / d,
            (v / 2.0).tan().ln() + 2.0 * v.cos() / d,
        )
    });
    for (u, v) in params(&s, 48) {
        let k = s.curvatures(u, v).unwrap().gaussian;
        assert!((k + 1.0).abs() < 1e-9, "K = {k} at ({u}, {v})");
    }
    // Scaled by r, K = −1/r².
    let r = KuenSurface::new(2.0).unwrap();
    assert!((r.curvatures(0.7, 1.3).unwrap().gaussian + 0.25).abs() < 1e-10);
    assert!(KuenSurface::new(0.0).is_err());
}

#[test]
fn the_sine_surface_matches_its_formula() {
    let s = SineSurface::new(1.5).unwrap();
    check_surface(&s, "sine_surface", |u, v| p3(u.sin(), v.sin(), (u + v).sin()) * 1.5);
    assert!(SineSurface::new(0.0).is_err());
}

#[test]
fn the_slippers_surface_matches_bourkes_formula() {
    let phi = TAU / 3.0;
    let s = SlippersSurface::new(1.0).unwrap();
    check_surface(&s, "slippers_surface", |u, v| {
        p3(
            (2.0 + u.cos()) * v.cos().powi(3) * v.sin(),
            (2.0 + (u + phi).cos()) * (v + phi).cos().powi(2) * (v + phi).sin().powi(2),
            -(2.0 + (u - phi).cos()) * (phi - v).cos().powi(2) * (phi - v).sin().powi(3),
        )
    });
    assert!(SlippersSurface::new(-0.5).is_err());
}

#[test]
fn steiners_roman_surface_lies_on_steiners_quartic() {
    let r = 1.3;
    let s = RomanSurface::new(r).unwrap();
    check_surface(&s, "roman_surface", |u, v| {
        let p = p3(u.cos() * v.cos(), u.sin() * v.cos(), v.sin());
        p3(p.x * p.z, p.y * p.z, p.x * p.y) * (r * r)
    });
    for (u, v) in params(&s, 32) {
        let p = s.point(u, v);
        let quartic = p.x * p.x * p.y * p.y + p.y * p.y * p.z * p.z + p.z * p.z * p.x * p.x - r * r * p.x * p.y * p.z;
        assert!(quartic.abs() < 1e-14, "quartic = {quartic} at ({u}, {v})");
    }
    assert!(RomanSurface::new(0.0).is_err());
}

#[test]
fn the_swallowtail_is_where_the_quartic_has_a_double_root() {
    let s = Swallowtail::new(1.0).unwrap();
    check_surface(&s, "swallowtail", |u, v| p3(u * v * v + 3.0 * v.powi(4), -2.0 * u * v - 4.0 * v.powi(3), u));
    for (u, v) in params(&s, 32) {
        // t⁴ + z t² + y t + x and its derivative vanish at t = v.
        let p = s.point(u, v);
        let (q, dq) = (v.powi(4) + p.z * v * v + p.y * v + p.x, 4.0 * v.powi(3) + 2.0 * p.z * v + p.y);
        assert!(q.abs() < 1e-13 && dq.abs() < 1e-13, "q = {q}, q′ = {dq} at ({u}, {v})");
    }
    assert!(Swallowtail::new(f64::NEG_INFINITY).is_err());
}

#[test]
fn the_trianguloid_trefoil_matches_bourkes_formula() {
    let phi = TAU / 3.0;
    let s = TrianguloidTrefoil::new(1.0).unwrap();
    check_surface(&s, "trianguloid_trefoil", |u, v| {
        p3(
            2.0 * (3.0 * u).sin() / (2.0 + v.cos()),
            2.0 * (u.sin() + 2.0 * (2.0 * u).sin()) / (2.0 + (v + phi).cos()),
            (u.cos() - 2.0 * (2.0 * u).cos()) * (2.0 + v.cos()) * (2.0 + (v + phi).cos()) / 4.0,
        )
    });
    assert!(TrianguloidTrefoil::new(0.0).is_err());
}

#[test]
fn the_whitney_umbrella_lies_on_x2_equals_y2_z() {
    let s = WhitneyUmbrella::new(1.0).unwrap();
    check_surface(&s, "whitney_umbrella", |u, v| p3(u * v, u, v * v));
    let scaled = WhitneyUmbrella::new(2.0).unwrap();
    for (u, v) in params(&s, 32) {
        let p = s.point(u, v);
        assert!((p.x * p.x - p.y * p.y * p.z).abs() < 1e-15, "x² − y²z at ({u}, {v})");
        let q = scaled.point(u, v);
        assert!((2.0 * q.x * q.x - q.y * q.y * q.z).abs() < 1e-14, "r x² − y²z at ({u}, {v})");
    }
    assert!(WhitneyUmbrella::new(0.0).is_err());
}

/// The curve's derivatives of orders 1 … 4 at pseudo-random parameters against the
/// central difference, of step h, of the exact order below.
fn check_curve(c: &dyn splinekit::curve::Curve<3>, name: &str, h: f64) {
    let dom = c.domain();
    for (a, _) in unit_pairs(16) {
        let t = dom.lerp(0.02 + 0.96 * a);
        let mut out = [Point::<3>::zeros(); 5];
        c.eval(t, &mut out);
        for k in 1..=4 {
            let f = finite_difference(c, t, k, h);
            let scale = out[k].norm().max(out[k - 1].norm()).max(1.0);
            assert!((out[k] - f).norm() < 2e-6 * scale, "{name}: order {k} at {t}: {} vs {f}", out[k]);
        }
    }
}

#[test]
fn the_logarithmic_spiral_keeps_its_angle_and_has_its_closed_form_length() {
    use splinekit::curve::model::LogarithmicSpiral;
    use splinekit::curve::{Curve, CurveArcLength};
    let (a, b) = (0.5, 0.15);
    let c = LogarithmicSpiral::new(a, b, 3.0).unwrap();
    check_curve(&c, "logarithmic_spiral", 1e-4);
    assert_eq!((c.domain().start, c.domain().end), (0.0, 6.0 * std::f64::consts::PI));
    let cot_psi = b;
    for (s, _) in unit_pairs(24) {
        let t = c.domain().lerp(s);
        let r = a * (b * t).exp();
        assert!((c.point(t) - p3(r * t.cos(), r * t.sin(), 0.0)).norm() < 1e-13 * r.max(1.0));
        // The angle ψ between the radius and the tangent: cot ψ = b.
        let (p, d) = (c.point(t), c.derivative(t, 1));
        let cos = p.dot(&d) / (p.norm() * d.norm());
        assert!((cos / (1.0 - cos * cos).sqrt() - cot_psi).abs() < 1e-12, "cot ψ at {t}");
        assert!((c.curvature(t) - 1.0 / (r * (1.0 + b * b).sqrt())).abs() < 1e-12 / r, "κ at {t}");
    }
    let end = c.domain().end;
    let length = a * (1.0 + b * b).sqrt() * ((b * end).exp() - 1.0) / b;
    assert!((c.length(1e-12) - length).abs() < 1e-9 * length, "{} vs {length}", c.length(1e-12));
    // b = 0 is the circle; an overflowing growth and bad fields are refused.
    let circle = LogarithmicSpiral::new(2.0, 0.0, 1.0).unwrap();
    assert!((circle.length(1e-12) - 4.0 * std::f64::consts::PI).abs() < 1e-10);
    assert!(LogarithmicSpiral::new(1.0, 1e3, 1e3).is_err());
    assert!(LogarithmicSpiral::new(0.0, 0.1, 1.0).is_err() && LogarithmicSpiral::new(1.0, f64::NAN, 1.0).is_err());
    assert!(LogarithmicSpiral::new(1.0, 0.1, 0.0).is_err());
}

#[test]
fn the_chrysanthemum_curve_matches_its_polar_formula() {
    use splinekit::curve::Curve;
    use splinekit::curve::model::Chrysanthemum;
    let c = Chrysanthemum::new(0.5).unwrap();
    // sin⁸ of an angle turning at up to 34 rad per unit t has harmonics up to 272: a step of
    // 10⁻⁵ keeps the difference's h⁴ f⁽⁷⁾/30 below its tolerance.
    check_curve(&c, "chrysanthemum", 1e-5);
    assert_eq!((c.domain().start, c.domain().end), (0.0, 21.0 * std::f64::consts::PI));
    for (s, _) in unit_pairs(200) {
        let t = c.domain().lerp(s);
        let r = 5.0 * (1.0 + (11.0 * t / 5.0).sin())
            - 4.0 * (17.0 * t / 3.0).sin().powi(4) * (2.0 * (3.0 * t).cos() - 28.0 * t).sin().powi(8);
        assert!((c.point(t) - p3(r * t.cos(), r * t.sin(), 0.0) * 0.5).norm() < 1e-12, "at {t}");
    }
    assert!(!c.is_closed() && Chrysanthemum::new(0.0).is_err());
}
