//! Least-squares fitting and interpolation against scipy (reference values committed in
//! data/scipy_reference.json, made by data/make_scipy_reference.py) and invariants.

mod common;
use common::*;
use serde_json::Value;
use splinekit::Point;
use splinekit::curve::model::Circle;
use splinekit::curve::{BSplineCurve, Curve};
use splinekit::fit::{self, FitOptions, InterpolationOptions, KnotPlacement, Parametrization};

fn reference() -> Value {
    serde_json::from_str(include_str!("data/scipy_reference.json")).unwrap()
}

fn floats(v: &Value) -> Vec<f64> {
    v.as_array().unwrap().iter().map(|x| x.as_f64().unwrap()).collect()
}

fn points<const D: usize>(v: &Value) -> Vec<Point<D>> {
    v.as_array().unwrap().iter().map(|p| Point::<D>::from_iterator(floats(p))).collect()
}

fn check_lsq<const D: usize>(case: &Value) {
    let name = case["name"].as_str().unwrap();
    let k = case["degree"].as_u64().unwrap() as usize;
    let pts: Vec<Point<D>> = points(&case["points"]);
    let w = if case["weights"].is_null() { None } else { Some(floats(&case["weights"])) };
    let options = fit::FitWithKnotsOptions { weights: w, ..fit::FitWithKnotsOptions::new(k, floats(&case["knots"])) };
    let f = fit::fit_with_knots(&pts, &floats(&case["params"]), &options).unwrap();
    let expected: Vec<Point<D>> = points(&case["control_points"]);
    let scale = expected.iter().map(|p| p.norm()).fold(1.0, f64::max);
    let err = f.curve.control_points().iter().zip(&expected).map(|(a, b)| (a - b).norm()).fold(0.0, f64::max);
    assert!(
        err < 1e-10 * scale,
        "{name}: control points differ from scipy by {err} (condition estimate {:.3e})",
        f.condition_estimate
    );
}

#[test]
fn least_squares_agrees_with_scipy_make_lsq_spline() {
    let r = reference();
    for case in r["lsq"].as_array().unwrap() {
        match case["points"][0].as_array().unwrap().len() {
            2 => check_lsq::<2>(case),
            3 => check_lsq::<3>(case),
            d => panic!("dimension {d}"),
        }
    }
}

#[test]
fn interpolation_agrees_with_scipy_make_interp_spline() {
    let r = reference();
    for case in r["interp"].as_array().unwrap() {
        let k = case["degree"].as_u64().unwrap() as usize;
        let pts: Vec<Point<2>> = points(&case["points"]);
        let params = floats(&case["params"]);
        // Same knots and parameters: the least-squares solve of a square system interpolates.
        let f = fit::fit_with_knots(&pts, &params, &fit::FitWithKnotsOptions::new(k, floats(&case["knots"]))).unwrap();
        let expected: Vec<Point<2>> = points(&case["control_points"]);
        for (a, b) in f.curve.control_points().iter().zip(&expected) {
            assert!((a - b).norm() < 1e-10 * (1.0 + b.norm()), "degree {k}: {a} vs {b}");
        }
        assert!(f.max_error < 1e-12);
    }
}

#[test]
fn evaluation_agrees_with_scipy_bspline() {
    let r = reference();
    for case in r["eval"].as_array().unwrap() {
        let k = case["degree"].as_u64().unwrap() as usize;
        let c = BSplineCurve::<3>::new(k, floats(&case["knots"]), points(&case["control_points"])).unwrap();
        for (t, ders) in floats(&case["params"]).iter().zip(case["derivatives"].as_array().unwrap()) {
            let expected: Vec<Point<3>> = points(ders);
            let mut out = vec![Point::<3>::zeros(); expected.len()];
            c.eval(*t, &mut out);
            for (d, (a, b)) in out.iter().zip(&expected).enumerate() {
                assert!((a - b).norm() < 1e-12 * (1.0 + b.norm()), "degree {k}, order {d} at {t}: {a} vs {b}");
            }
        }
    }
}

#[test]
fn fitting_reproduces_polynomials_of_the_spline_degree_exactly() {
    // Any cubic polynomial curve lies in the spline space, so LSQ returns it exactly.
    let pts: Vec<Point<2>> = (0..50)
        .map(|i| {
            let t = i as f64 / 49.0;
            p2(1.0 + 2.0 * t - 3.0 * t * t + t * t * t, 0.5 - t * t * t)
        })
        .collect();
    let mut opts = FitOptions::new(3, 9);
    opts.params = Parametrization::Uniform;
    opts.knots = KnotPlacement::Uniform;
    let f = fit::fit(&pts, &opts).unwrap();
    assert!(f.max_error < 1e-13, "max error {}", f.max_error);
}

#[test]
fn fitting_a_circle_converges_and_closed_fits_are_periodic() {
    let circle = Circle::new(2.0).unwrap();
    let mut last = f64::INFINITY;
    for n in [8, 16, 32] {
        let mut opts = FitOptions::new(3, n);
        opts.closed = true;
        opts.knots = KnotPlacement::Uniform;
        let f = fit::fit_curve(&circle, 400, &opts).unwrap();
        assert!(f.curve.is_closed());
        // Radius error, measured on the fitted curve.
        let err = (0..1000).map(|i| (f.curve.point(i as f64 / 1000.0).norm() - 2.0).abs()).fold(0.0, f64::max);
        assert!(err < last / 10.0, "n = {n}: radius error {err} did not fall by 10× (was {last})");
        last = err;
    }
    assert!(last < 1e-5, "32 control points: radius error {last}");
}

#[test]
fn fixed_ends_and_weights() {
    let pts: Vec<Point<2>> = (0..40)
        .map(|i| {
            let t = i as f64 / 39.0;
            p2(t, (6.0 * t).sin() + 0.05 * ((i * 7919) % 13) as f64 / 13.0)
        })
        .collect();
    let mut opts = FitOptions::new(3, 8);
    opts.interpolate_ends = true;
    let f = fit::fit(&pts, &opts).unwrap();
    assert!((f.curve.point(0.0) - pts[0]).norm() < 1e-15);
    assert!((f.curve.point(1.0) - pts[39]).norm() < 1e-15);
    // A huge weight on one sample pulls the curve onto it.
    let mut w = vec![1.0; 40];
    w[20] = 1e6;
    opts.interpolate_ends = false;
    opts.weights = Some(w);
    let g = fit::fit(&pts, &opts).unwrap();
    assert!((g.curve.point(g.params[20]) - pts[20]).norm() < 1e-6);
}

#[test]
fn underdetermined_fits_are_refused() {
    let pts: Vec<Point<2>> = (0..5).map(|i| p2(i as f64, 0.0)).collect();
    let e = fit::fit(&pts, &FitOptions::new(3, 9)).unwrap_err().to_string();
    assert!(e.contains("control_points") && e.contains("9"), "{e}");
    // Data only on half the domain: control points beyond it are undetermined.
    let params: Vec<f64> = (0..30).map(|i| i as f64 / 60.0).collect();
    let pts: Vec<Point<2>> = params.iter().map(|&t| p2(t, t * t)).collect();
    let knots = vec![0., 0., 0., 0., 0.2, 0.4, 0.6, 0.8, 1., 1., 1., 1.];
    let e = fit::fit_with_knots(&pts, &params, &fit::FitWithKnotsOptions::new(3, knots)).unwrap_err().to_string();
    assert!(e.contains("control point") && e.contains("not determined"), "{e}");
}

#[test]
fn interpolation_passes_through_the_points() {
    let pts: Vec<Point<3>> = (0..12)
        .map(|i| {
            let a = i as f64 * 0.6;
            p3(a.cos(), a.sin(), 0.1 * i as f64 + (i % 3) as f64 * 0.05)
        })
        .collect();
    for p in 1..=5 {
        for params in [Parametrization::Uniform, Parametrization::ChordLength, Parametrization::Centripetal] {
            let mut o = InterpolationOptions::new(p);
            o.params = params;
            let r = fit::interpolate(&pts, &o).unwrap();
            for (t, q) in r.params.iter().zip(&pts) {
                assert!((r.curve.point(*t) - q).norm() < 1e-12, "degree {p} {params:?}");
            }
            o.closed = true;
            let r = fit::interpolate(&pts, &o).unwrap();
            assert!(r.curve.is_closed());
            for (t, q) in r.params.iter().zip(&pts) {
                assert!((r.curve.point(*t) - q).norm() < 1e-12, "closed degree {p} {params:?}");
            }
        }
    }
    let mut o = InterpolationOptions::new(3);
    o.end_derivatives = Some((p3(1.0, 0.0, 0.0), p3(0.0, -2.0, 1.0)));
    let r = fit::interpolate(&pts, &o).unwrap();
    assert!((r.curve.derivative(0.0, 1) - p3(1.0, 0.0, 0.0)).norm() < 1e-11);
    assert!((r.curve.derivative(1.0, 1) - p3(0.0, -2.0, 1.0)).norm() < 1e-11);
    for (t, q) in r.params.iter().zip(&pts) {
        assert!((r.curve.point(*t) - q).norm() < 1e-12);
    }
}
