//! B-functions: reference values (shared/reference/blending-splines.md §2.5, 40-digit
//! quadrature), closed forms, symmetry, end conditions, derivatives.

use splinekit::basis::BFunction;

fn eval(b: &BFunction, t: f64, k: usize) -> Vec<f64> {
    let mut out = vec![0.0; k + 1];
    b.eval(t, &mut out);
    out
}

#[test]
fn erbs_matches_the_reference_values() {
    let b = BFunction::erbs_default();
    let table = [
        (0.10, 0.0067909995294346, 0.28007833333687, 6.9155144033795, 30.5221777),
        (0.25, 0.1229672832773291, 1.18739103346403, 4.2218347856499, -24.3928232),
        (0.50, 0.5, 1.65713767973821, 0.0, -13.2571014),
        (0.75, 0.8770327167226709, 1.18739103346403, -4.2218347856499, -24.3928232),
    ];
    for (t, v, d1, d2, d3) in table {
        let o = eval(&b, t, 3);
        assert!((o[0] - v).abs() <= 2e-16, "B({t}) = {:.17} vs {v}", o[0]);
        assert!((o[1] - d1).abs() <= 1e-13 * d1.abs(), "B'({t}) = {:.15} vs {d1}", o[1]);
        assert!((o[2] - d2).abs() <= 1e-13 * d2.abs().max(1.0), "B''({t}) = {:.15} vs {d2}", o[2]);
        assert!((o[3] - d3).abs() <= 1e-6 * d3.abs(), "B'''({t}) = {:.10} vs {d3}", o[3]);
    }
    if let BFunction::Erbs(t) = &b {
        assert!((t.normaliser() - 0.603_450_161_218_938_1).abs() < 2e-16, "S = {:.18}", t.normaliser());
    }
}

#[test]
fn erbs_is_symmetric_flat_at_the_ends_and_shared() {
    let b = BFunction::erbs_default();
    for i in 0..=200 {
        let t = i as f64 / 200.0;
        let (x, y) = (b.value(t), b.value(1.0 - t));
        // Each value is within ~1.1e-16 and the sum rounds once more: 1.5 ulps of 1.
        assert!((x + y - 1.0).abs() <= 3.4e-16, "B({t}) + B(1−{t}) − 1 = {:e}", x + y - 1.0);
        if i > 0 {
            assert!(b.value(t) >= b.value(t - 0.005), "monotone");
        }
    }
    for (t, bound) in [(0.0, 0.0), (1.0, 0.0), (1e-3, 1e-70), (1.0 - 1e-3, 1e-70)] {
        // φ(10⁻³) ≈ e^{−249} ≈ 1e-108, and the k-th derivative grows like (4s²)^{−k}.
        let o = eval(&b, t, 5);
        for (k, v) in o.iter().enumerate().skip(1) {
            assert!(v.abs() <= bound, "B^({k})({t}) = {v}");
        }
    }
    assert_eq!(eval(&b, 0.0, 0)[0], 0.0);
    assert_eq!(eval(&b, 1.0, 0)[0], 1.0);
    // Same parameters share one table.
    let (BFunction::Erbs(a), BFunction::Erbs(c)) = (BFunction::erbs_default(), BFunction::erbs_default()) else {
        unreachable!()
    };
    assert!(std::sync::Arc::ptr_eq(&a, &c));
}

#[test]
fn erbs_derivatives_match_finite_differences_for_other_parameters() {
    for (alpha, beta, gamma, lambda) in [(1.0, 1.0, 1.0, 0.5), (1.5, 2.0, 1.0, 0.4), (1.0, 0.5, 2.0, 0.6)] {
        let b = BFunction::erbs(alpha, beta, gamma, lambda).unwrap();
        for &t in &[0.2, 0.35, 0.55, 0.8] {
            let o = eval(&b, t, 5);
            for k in 1..=5 {
                let h = 1e-5;
                let f = |x: f64| eval(&b, x, k - 1)[k - 1];
                let fd = (f(t - 2.0 * h) - f(t + 2.0 * h) + 8.0 * (f(t + h) - f(t - h))) / (12.0 * h);
                assert!(
                    (o[k] - fd).abs() < 1e-6 * o[k].abs().max(1.0),
                    "({alpha},{beta},{gamma},{lambda}) B^({k})({t}): {} vs {fd}",
                    o[k]
                );
            }
        }
        assert!((b.value(1.0) - 1.0).abs() < 1e-16 && b.value(0.0) == 0.0);
    }
    assert!(BFunction::erbs(0.0, 1.0, 1.0, 0.5).is_err());
    assert!(BFunction::erbs(1.0, 1.0, 1.0, 1.0).is_err());
}

#[test]
fn polynomial_trigonometric_and_other_b_functions() {
    let p1 = BFunction::polynomial(1).unwrap();
    let p2 = BFunction::polynomial(2).unwrap();
    let beta11 = BFunction::beta(1, 1).unwrap();
    let trig = BFunction::Trigonometric;
    let half = BFunction::HalfCosine;
    let rat = BFunction::Rational;
    for i in 0..=20 {
        let t = i as f64 / 20.0;
        let o = eval(&p1, t, 4);
        assert!((o[0] - (3.0 * t * t - 2.0 * t.powi(3))).abs() < 1e-15);
        assert!((o[1] - (6.0 * t - 6.0 * t * t)).abs() < 1e-14);
        assert!((o[2] - (6.0 - 12.0 * t)).abs() < 1e-13 && (o[3] + 12.0).abs() < 1e-12 && o[4] == 0.0);
        assert!((beta11.value(t) - o[0]).abs() < 1e-15);
        let q = eval(&p2, t, 1);
        // (the monomial form itself rounds to a few ulps of 15)
        assert!((q[0] - (6.0 * t.powi(5) - 15.0 * t.powi(4) + 10.0 * t.powi(3))).abs() < 1e-14);
        let tr = eval(&trig, t, 3);
        assert!((tr[0] - (t - (TAU * t).sin() / TAU)).abs() < 1e-16);
        assert!((tr[1] - (1.0 - (TAU * t).cos())).abs() < 1e-15);
        assert!((tr[2] - TAU * (TAU * t).sin()).abs() < 1e-13);
        assert!((tr[3] - TAU * TAU * (TAU * t).cos()).abs() < 1e-12);
        let hc = eval(&half, t, 2);
        assert!((hc[0] - (0.5 - 0.5 * (PI * t).cos())).abs() < 1e-16);
        assert!((hc[2] - 0.5 * PI * PI * (PI * t).cos()).abs() < 1e-14);
        let r = eval(&rat, t, 2);
        let d = (1.0 - t).powi(2) + t * t;
        assert!((r[0] - t * t / d).abs() < 1e-15);
        assert!((r[1] - 2.0 * t * (1.0 - t) / (d * d)).abs() < 1e-14);
        for b in [&p1, &p2, &trig, &half, &rat] {
            assert!((b.value(t) + b.value(1.0 - t) - 1.0).abs() < 1e-15, "symmetry");
        }
    }
    // Smoothness k: derivatives 1 … k vanish at both ends.
    let o = eval(&BFunction::polynomial(3).unwrap(), 0.0, 4);
    assert!(o[1] == 0.0 && o[2] == 0.0 && o[3] == 0.0 && o[4] != 0.0);
    assert!(BFunction::polynomial(0).is_err());
}

use std::f64::consts::{PI, TAU};

#[test]
fn erbs_derivatives_of_high_order_are_finite() {
    let b = BFunction::erbs_default();
    let o = eval(&b, 0.3, 24);
    assert!(o.iter().all(|v| v.is_finite()), "{o:?}");
    // Against the same derivative computed one order lower, then differenced.
    let h = 1e-6;
    let fd = (eval(&b, 0.3 + h, 20)[20] - eval(&b, 0.3 - h, 20)[20]) / (2.0 * h);
    assert!((o[21] - fd).abs() < 1e-5 * o[21].abs(), "{} vs {fd}", o[21]);
}

#[test]
fn two_curve_blends_follow_the_definition_and_join_smoothly() {
    use splinekit::Point;
    use splinekit::basis::Side;
    use splinekit::blend::{PlainBlend, TwoCurveBlend};
    use splinekit::curve::model::Circle;
    use splinekit::curve::{BezierCurve, Curve};
    let c1 = || -> Box<dyn Curve<3>> { Box::new(Circle::new(1.0).unwrap()) };
    let c2 = || -> Box<dyn Curve<3>> {
        Box::new(
            BezierCurve::new(vec![
                Point::<3>::new(0.0, 0.0, 0.0),
                Point::<3>::new(1.0, 2.0, 0.5),
                Point::<3>::new(2.0, 0.0, 1.0),
            ])
            .unwrap(),
        )
    };
    let x = 0.3;
    for (b, smooth) in
        [(BFunction::polynomial(1).unwrap(), 1), (BFunction::Trigonometric, 2), (BFunction::erbs_default(), 4)]
    {
        let blend = TwoCurveBlend::new(c1(), c2(), x, b.clone()).unwrap();
        let (a, s) = (c1(), c2());
        let a_at = |t: f64| a.point(TAU * t);
        for i in 0..=26 {
            let t = 1.3 * i as f64 / 26.0;
            let expected = if t < x {
                a_at(t)
            } else if t < 1.0 {
                a_at(t) + (s.point(t - x) - a_at(t)) * b.value((t - x) / (1.0 - x))
            } else {
                s.point(t - x)
            };
            assert!((blend.point(t) - expected).norm() < 1e-14, "t = {t}");
        }
        // Derivatives inside each piece against finite differences.
        for &t in &[0.15, 0.5, 0.8, 1.2] {
            let mut d = [Point::<3>::zeros(); 3];
            blend.eval(t, &mut d);
            let h = 1e-5;
            let fd1 = (blend.point(t + h) - blend.point(t - h)) / (2.0 * h);
            assert!((d[1] - fd1).norm() < 1e-6 * d[1].norm().max(1.0), "blend' at {t}");
        }
        // Continuity at the joins: the derivatives of orders 1 … smooth agree where the
        // blend starts (c₁ alone on the left) — the ends of c₂ are blended in with B = 0.
        let mut l = vec![Point::<3>::zeros(); smooth + 1];
        let mut r = vec![Point::<3>::zeros(); smooth + 1];
        blend.eval_side(x, Side::Left, &mut l);
        blend.eval_side(x, Side::Right, &mut r);
        for k in 0..=smooth {
            assert!((l[k] - r[k]).norm() < 1e-9 * l[k].norm().max(1.0), "order {k} at x");
        }
    }
    assert!(TwoCurveBlend::new(c1(), c2(), 1.0, BFunction::Linear).is_err());
    let plain = PlainBlend::new(c1(), c2(), BFunction::Linear).unwrap();
    assert!((plain.point(0.5) - (c1().point(std::f64::consts::PI) + c2().point(0.5)) * 0.5).norm() < 1e-15);
}

#[test]
fn erbs_fast_table_covers_most_of_the_interval_and_agrees_with_quadrature() {
    // Dense comparison of the fast path (B + 3 derivatives) with the exact path (asking for
    // 5 derivatives takes the exact path everywhere).
    for b in [BFunction::erbs_default(), BFunction::erbs(2.0, 1.5, 1.0, 0.4).unwrap()] {
        // Error measure: B absolute; B^{(k)} relative, with a floor of 1e-2 of its size
        // over [0, 1] (near its zeros only absolute accuracy means anything).
        let mut size = [0.0f64; 4];
        for i in 1..1000 {
            let mut e = [0.0; 6];
            b.eval(i as f64 / 1000.0, &mut e);
            for k in 0..4 {
                size[k] = size[k].max(e[k].abs());
            }
        }
        let mut worst = [0.0f64; 4];
        for i in 1..20000 {
            let t = i as f64 / 20000.0 + 1e-7;
            let mut fast = [0.0; 4];
            let mut exact = [0.0; 6];
            b.eval(t, &mut fast);
            b.eval(t, &mut exact);
            for k in 0..4 {
                let scale = if k == 0 { 1.0 } else { exact[k].abs().max(1e-2 * size[k]) };
                worst[k] = worst[k].max((fast[k] - exact[k]).abs() / scale);
            }
        }
        assert!(worst[0] <= 2.3e-16, "B: {worst:?}");
        assert!(worst[1..].iter().all(|&w| w < 1e-13), "derivatives: {worst:?}");
    }
}

#[test]
fn erbs_agrees_with_40_digit_quadrature_on_a_dense_grid() {
    // tests/data/erbs_reference.json, written by erbs_reference.py (mpmath).
    let data: serde_json::Value =
        serde_json::from_str(include_str!("data/erbs_reference.json")).expect("reference data parses");
    let b = BFunction::erbs_default();
    let mut worst = [0.0f64; 4];
    for row in data["rows"].as_array().unwrap() {
        let t = row[0].as_f64().unwrap();
        let want: Vec<f64> = (1..5).map(|k| row[k].as_str().unwrap().parse().unwrap()).collect();
        let mut got = [0.0; 4];
        b.eval(t, &mut got);
        worst[0] = worst[0].max((got[0] - want[0]).abs());
        for k in 1..4 {
            // Relative, with a floor where the derivative passes through zero.
            let scale = want[k].abs().max([0.0, 1e-3, 1e-2, 1e-1][k]);
            worst[k] = worst[k].max((got[k] - want[k]).abs() / scale);
        }
    }
    eprintln!(
        "ERBS vs 40-digit quadrature: |ΔB| {:.2e}, relative ΔB' {:.2e}, ΔB'' {:.2e}, ΔB''' {:.2e}",
        worst[0], worst[1], worst[2], worst[3]
    );
    assert!(worst[0] <= 2.3e-16, "{worst:?}");
    assert!(worst[1..].iter().all(|&w| w <= 1e-13), "{worst:?}");
}
