//! Blending splines of Hermite data as documents (`"hermite"` in `blending_spline` and
//! `blending_spline_surface`): they build the kernel's spline, reproduce their data at every
//! knot to 1e-12, read back as themselves, take knot insertion and splitting as the
//! model-built ones do, and refuse bad data naming the field.

use serde_json::json;
use splinekit::Point;
use splinekit::basis::Side;
use splinekit::curve::Curve;
use splinekit::surface::{Direction, Surface};
use splinekit_scene::blending::{insert_knot_line, insert_local_curve, split_local_curve};
use splinekit_scene::curves::{BlendingSplineDoc, CurveDocument};
use splinekit_scene::surfaces::{BlendingSplineSurfaceDoc, SurfaceDocument};

fn curve(value: serde_json::Value) -> BlendingSplineDoc {
    match CurveDocument::from_value(value).unwrap() {
        CurveDocument::BlendingSpline(d) => d,
        other => panic!("{other:?}"),
    }
}

fn surface(value: serde_json::Value) -> BlendingSplineSurfaceDoc {
    match SurfaceDocument::from_value(value).unwrap() {
        SurfaceDocument::BlendingSplineSurface(d) => d,
        other => panic!("{other:?}"),
    }
}

fn curve_error(value: serde_json::Value) -> String {
    match CurveDocument::from_value(value) {
        Err(e) => e.to_string(),
        Ok(d) => d.build().err().map(|e| e.to_string()).unwrap_or_else(|| "built".into()),
    }
}

fn surface_error(value: serde_json::Value) -> String {
    match SurfaceDocument::from_value(value) {
        Err(e) => e.to_string(),
        Ok(d) => d.build().err().map(|e| e.to_string()).unwrap_or_else(|| "built".into()),
    }
}

/// Position, first and second derivatives of a planar curve at four knots (no formula behind them).
fn curve_json() -> serde_json::Value {
    json!({"type": "blending_spline", "knots": [0, 1, 2.5, 3],
        "hermite": [[[0, 0], [1, 1], [0, -2]], [[1, 1], [1, 0], [0.5, 0]], [[2, 0.5], [0, -1], [1, 1]], [[3, 0], [1, 0.2], [0, 0]]]})
}

fn points(v: &serde_json::Value) -> Vec<Point<2>> {
    v.as_array().unwrap().iter().map(|p| Point::<2>::new(p[0].as_f64().unwrap(), p[1].as_f64().unwrap())).collect()
}

#[test]
fn a_curve_of_hermite_data_reproduces_it_at_every_knot_and_reads_back() {
    let value = curve_json();
    let doc = curve(value.clone());
    let c = doc.curve::<2>().unwrap();
    let knots = [0.0, 1.0, 2.5, 3.0];
    for (k, t) in knots.iter().enumerate() {
        let want = points(&value["hermite"][k]);
        let mut got = [Point::<2>::zeros(); 3];
        c.eval_side(*t, Side::Right, &mut got);
        for j in 0..3 {
            assert!((got[j] - want[j]).norm() < 1e-12, "knot {k}, order {j}: {} vs {}", got[j], want[j]);
        }
    }
    let back = CurveDocument::BlendingSpline(doc.clone()).to_value();
    assert_eq!(curve(back), doc);
    // Closed: one more knot, local 0 again at its end.
    let mut closed = value.clone();
    closed["knots"] = json!([0, 1, 2.5, 3, 4]);
    closed["closed"] = json!(true);
    let c = curve(closed).curve::<2>().unwrap();
    let mut at_end = [Point::<2>::zeros(); 3];
    c.eval_side(4.0, Side::Left, &mut at_end);
    let want = points(&value["hermite"][0]);
    for j in 0..3 {
        assert!((at_end[j] - want[j]).norm() < 1e-12, "seam, order {j}");
    }
}

#[test]
fn inserting_and_splitting_keep_a_hermite_curve() {
    let doc = curve(curve_json());
    let before = doc.curve::<2>().unwrap();
    let (after, k) = insert_local_curve(&doc, 1.7).unwrap();
    assert_eq!(k, 2);
    assert!(after.local_curves.is_none(), "the data give the count");
    let data = after.hermite.as_ref().unwrap();
    assert_eq!((data.len(), after.knots.as_ref().unwrap()[2]), (5, 1.7));
    let c = after.curve::<2>().unwrap();
    // The new datum is the curve's own derivatives at 1.7; the data at the old knots stay.
    let mut want = [Point::<2>::zeros(); 3];
    before.eval(1.7, &mut want);
    assert_eq!(points(&serde_json::to_value(&data[2]).unwrap()), want.to_vec());
    for t in [0.0, 1.0, 1.7, 2.5, 3.0] {
        let (mut a, mut b) = ([Point::<2>::zeros(); 3], [Point::<2>::zeros(); 3]);
        c.eval(t, &mut a);
        before.eval(t, &mut b);
        for j in 0..3 {
            assert!((a[j] - b[j]).norm() < 1e-12, "insertion: at {t} order {j}");
        }
    }
    // A split copies the datum; the curve is the same everywhere.
    let split = split_local_curve(&doc, 1).unwrap();
    let data = split.hermite.as_ref().unwrap();
    assert_eq!((data.len(), &data[1]), (5, &data[2]));
    let c = split.curve::<2>().unwrap();
    for i in 0..=300 {
        let t = 3.0 * i as f64 / 300.0;
        assert!((c.point(t) - before.point(t)).norm() < 1e-12, "split at {t}");
    }
}

#[test]
fn bad_hermite_curves_are_refused_naming_the_field() {
    let with = |key: &str, v: serde_json::Value| {
        let mut d = curve_json();
        d[key] = v;
        d
    };
    let cases = [
        (with("model", json!({"type": "circle"})), "model: not with hermite data"),
        (with("local_curves", json!(4)), "local_curves: not with hermite data"),
        (with("knot_spacing", json!("uniform")), "knot_spacing: not with hermite data"),
        (json!({"type": "blending_spline", "hermite": [[[0, 0], [1, 0]]]}), "knots: missing"),
        (with("knots", json!([0, 1, 2])), "hermite: expected 3 entries"),
        (
            with("hermite", json!([[[0, 0], [1, 1]], [[1, 1]], [[0, 0], [1, 1]], [[0, 0], [1, 1]]])),
            "hermite[1]: expected 2 values",
        ),
        (
            with("hermite", json!([[[0, 0]], [[1, 1]], [[0, 0]], [[0, 0]]])),
            "hermite[0]: expected a position and 1 to 20 derivatives",
        ),
        (
            with("hermite", json!([[[0, 0], [1, 1]], [[1, 1, 0], [0, 0, 1]], [[0, 0], [1, 1]], [[0, 0], [1, 1]]])),
            "hermite[1]: expected points of dimension 2",
        ),
        (
            with("hermite", json!([[[0, 0], [1, 1]], [[1, 1], [0, 1e300]], [[0, 0], [1, 1]], [[0, 0], [1, 1]]])),
            "hermite[1][1][1]",
        ),
        (with("hermite", json!([])), "hermite: the list is empty"),
        (with("knots", json!([0, 2, 1, 3])), "knots[2]"),
    ];
    for (doc, want) in cases {
        let e = curve_error(doc.clone());
        assert!(e.contains(want), "{doc}: {e}");
    }
}

/// The bicubic partials of the hyperbolic paraboloid (u, v, u² − v²) at (u, v): rows i of ∂^{i,j}.
fn saddle(u: f64, v: f64) -> serde_json::Value {
    let zero = [0.0, 0.0, 0.0];
    json!([
        [[u, v, u * u - v * v], [0.0, 1.0, -2.0 * v], [0.0, 0.0, -2.0], zero],
        [[1.0, 0.0, 2.0 * u], zero, zero, zero],
        [[0.0, 0.0, 2.0], zero, zero, zero],
        [zero, zero, zero, zero],
    ])
}

#[test]
fn a_surface_of_hermite_data_is_the_surface_they_sample_and_takes_knot_lines() {
    let (ku, kv) = ([-1.0, 0.0, 0.5, 1.0], [-1.0, 0.2, 1.0]);
    let data: Vec<serde_json::Value> =
        ku.iter().map(|&u| json!(kv.iter().map(|&v| saddle(u, v)).collect::<Vec<_>>())).collect();
    let value = json!({"type": "blending_spline_surface", "knots_u": ku, "knots_v": kv, "hermite": data});
    let doc = surface(value.clone());
    assert_eq!(doc.counts().unwrap(), [4, 3]);
    let s = doc.surface::<3>().unwrap();
    // The data are of a quadratic: every bicubic patch is that quadratic, so the surface is too.
    for i in 0..=20 {
        for j in 0..=20 {
            let (u, v) = (-1.0 + 0.1 * i as f64, -1.0 + 0.1 * j as f64);
            let want = Point::<3>::new(u, v, u * u - v * v);
            assert!((s.point(u, v) - want).norm() < 1e-12, "({u}, {v})");
        }
    }
    assert_eq!(surface(SurfaceDocument::BlendingSplineSurface(doc.clone()).to_value()), doc);
    for (direction, t) in [(Direction::U, 0.25), (Direction::V, -0.5)] {
        let (after, k) = insert_knot_line(&doc, direction, t).unwrap();
        assert!(after.local_surfaces.is_none());
        let counts = after.counts().unwrap();
        assert_eq!(counts, if direction == Direction::U { [5, 3] } else { [4, 4] }, "{direction:?}");
        let s2 = after.surface::<3>().unwrap();
        let (u, v) = if direction == Direction::U { (t, 0.2) } else { (0.5, t) };
        let mut g = [Point::<3>::zeros(); 16];
        s2.eval_partials(u, v, 3, 3, &mut g);
        assert!((g[0] - Point::<3>::new(u, v, u * u - v * v)).norm() < 1e-12, "{direction:?} {k}");
        assert!((g[4 * 2] - Point::<3>::new(0.0, 0.0, 2.0)).norm() < 1e-12, "S_uu {direction:?}");
    }
}

#[test]
fn bad_hermite_surfaces_are_refused_naming_the_field() {
    let two = json!([[[0, 0, 0], [0, 1, 0]], [[1, 0, 0], [0, 0, 0]]]);
    let base = json!({"type": "blending_spline_surface", "knots_u": [0, 1], "knots_v": [0, 1], "hermite": [[two, two], [two, two]]});
    let with = |key: &str, v: serde_json::Value| {
        let mut d = base.clone();
        d[key] = v;
        d
    };
    assert_eq!(surface_error(base.clone()), "built");
    let cases = [
        (with("model", json!({"type": "torus"})), "model: not with hermite data"),
        (with("local_surfaces", json!([2, 2])), "local_surfaces: not with hermite data"),
        (with("local", json!({"type": "sub_surface"})), "local: not with hermite data"),
        (json!({"type": "blending_spline_surface", "knots_u": [0, 1], "hermite": [[two]]}), "knots_v: missing"),
        (with("knots_u", json!([0, 1, 2])), "hermite: expected 3×2 knot pairs"),
        (with("hermite", json!([[two, two], [two]])), "hermite[1]: expected 2 knot pairs"),
        (with("hermite", json!([[two, two], [two, [[[0, 0, 0], [0, 1, 0]]]]])), "hermite[1][1]: expected 2 rows"),
        (
            with("hermite", json!([[two, two], [two, [[[0, 0, 0]], [[1, 0, 0], [0, 0, 0]]]]])),
            "hermite[1][1][0]: expected 2 partials",
        ),
        (with("hermite", json!([[[[[0, 0, 0]]], two], [two, two]])), "hermite[0][0]: expected at least 2 × 2 partials"),
        (
            with("hermite", json!([[two, two], [two, [[[0, 0], [0, 1]], [[1, 0], [0, 0]]]]])),
            "hermite[1][1][0]: expected points of dimension 3",
        ),
        (json!({"type": "blending_spline_surface", "local_surfaces": [3, 3]}), "model: missing"),
        (json!({"type": "blending_spline_surface", "model": {"type": "torus"}}), "local_surfaces: missing"),
    ];
    for (doc, want) in cases {
        let e = surface_error(doc.clone());
        assert!(e.contains(want), "{doc}: {e}");
    }
}
