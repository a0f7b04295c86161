//! GMlib's constructions as documents: `curve_on_surface`, `bicubic_hermite`,
//! `hermite_curve_surface` and `loft` build from JSON, reproduce their data (the host
//! along the curve, the corner data, the boundary and cross-derivative curves, the
//! sections) to 1e-12, read back as themselves, give the exact form they promise, and
//! refuse bad data naming the field.

use serde_json::json;
use splinekit::Point;
use splinekit::curve::Curve;
use splinekit::surface::Surface;
use splinekit_scene::curves::CurveDocument;
use splinekit_scene::surfaces::{SurfaceDocument, SurfaceForm};

fn surface3(value: serde_json::Value) -> Box<dyn Surface<3>> {
    SurfaceDocument::from_value(value).unwrap().build_in::<3>().unwrap()
}

fn curve3(value: serde_json::Value) -> Box<dyn Curve<3>> {
    CurveDocument::from_value(value).unwrap().build_in::<3>().unwrap()
}

fn surface_error(value: serde_json::Value) -> String {
    match SurfaceDocument::from_value(value) {
        Err(e) => e.to_string(),
        Ok(d) => d.build().err().map(|e| e.to_string()).unwrap_or_else(|| "built".into()),
    }
}

fn curve_error(value: serde_json::Value) -> String {
    match CurveDocument::from_value(value) {
        Err(e) => e.to_string(),
        Ok(d) => d.build().err().map(|e| e.to_string()).unwrap_or_else(|| "built".into()),
    }
}

fn round_trips(value: serde_json::Value) {
    let doc = SurfaceDocument::from_value(value).unwrap();
    assert_eq!(SurfaceDocument::from_value(doc.to_value()).unwrap(), doc);
}

fn p3(v: &serde_json::Value) -> Point<3> {
    Point::<3>::new(v[0].as_f64().unwrap(), v[1].as_f64().unwrap(), v[2].as_f64().unwrap())
}

#[test]
fn a_curve_on_a_surface_document_is_the_host_along_the_curve() {
    let knot = curve3(json!({"type": "curve_on_surface",
        "curve": {"type": "bezier", "control_points": [[0.1, 0.2], [3, 1], [5, 6], [7, 2]]},
        "surface": {"type": "torus", "major_radius": 2, "minor_radius": 0.5}}));
    let torus = surface3(json!({"type": "torus", "major_radius": 2, "minor_radius": 0.5}));
    let gamma =
        CurveDocument::from_value(json!({"type": "bezier", "control_points": [[0.1, 0.2], [3, 1], [5, 6], [7, 2]]}))
            .unwrap()
            .build_in::<2>()
            .unwrap();
    for i in 0..=20 {
        let t = i as f64 / 20.0;
        let g = gamma.point(t);
        assert!((knot.point(t) - torus.point(g[0], g[1])).norm() < 1e-14);
        let mut d = [Point::<2>::zeros(); 2];
        gamma.eval(t, &mut d);
        let want = torus.partial(g[0], g[1], 1, 0) * d[1][0] + torus.partial(g[0], g[1], 0, 1) * d[1][1];
        assert!((knot.derivative(t, 1) - want).norm() < 1e-12 * want.norm().max(1.0));
    }
    let doc = CurveDocument::from_value(json!({"type": "curve_on_surface",
        "curve": {"type": "line", "from": [0, 0], "to": [1, 1]}, "surface": {"type": "plane"}}))
    .unwrap();
    assert_eq!(CurveDocument::from_value(doc.to_value()).unwrap(), doc);
    let e = curve_error(
        json!({"type": "curve_on_surface", "curve": {"type": "line", "from": [0, 0], "to": [2, 1]}, "surface": {"type": "plane"}}),
    );
    assert!(e.starts_with("curve: the curve's u runs over [0, 2], outside the surface's u-domain [0, 1]"), "{e}");
    let e = curve_error(json!({"type": "curve_on_surface", "curve": {"type": "circle"}, "surface": {"type": "plane"}}));
    assert!(e.starts_with("curve: a curve on a surface is a 2-D curve"), "{e}");
    let e = curve_error(
        json!({"type": "curve_on_surface", "curve": {"type": "line", "from": [0, 0], "to": [1, 1]}, "surface": {"type": "sphere", "radius": -1}}),
    );
    assert!(e.starts_with("surface: radius"), "{e}");
}

#[test]
fn a_bicubic_hermite_document_reproduces_its_corner_data_and_is_a_bezier_patch() {
    let data = json!([
        [
            [[[0, 0, 0], [0, 1, 0.3]], [[1, 0, -0.2], [0.5, 0.1, 1]]],
            [[[0, 1, 0.5], [0.2, 1, -0.4]], [[1, 0, 0.1], [0, 0, 2]]]
        ],
        [
            [[[1, 0, 0.2], [0, 1, 0.7]], [[1, 0.3, 0], [0, -1, 0.5]]],
            [[[1, 1, 1], [0, 1, 0]], [[1, 0, -1], [0.3, 0.3, 0.3]]]
        ]
    ]);
    let value = json!({"type": "bicubic_hermite", "hermite": data});
    let s = surface3(value.clone());
    for a in 0..2 {
        for b in 0..2 {
            let mut out = [Point::<3>::zeros(); 4];
            s.eval_partials(a as f64, b as f64, 1, 1, &mut out);
            for i in 0..2 {
                for j in 0..2 {
                    let want = p3(&data[a][b][i][j]);
                    assert!((out[i * 2 + j] - want).norm() < 1e-12, "∂^({i},{j}) at ({a}, {b})");
                }
            }
        }
    }
    round_trips(value.clone());
    let doc = SurfaceDocument::from_value(value).unwrap();
    match doc.exact_form().unwrap() {
        SurfaceForm::Spline(view) => {
            assert_eq!(view.degrees, (3, 3));
            assert!(view.knots.is_none());
            // The net's corners are the positions, its next points a third of the partials on.
            assert_eq!(view.control_points[3][0], vec![1.0, 0.0, 0.2]);
            let b10 = &view.control_points[1][0];
            assert!((b10[0] - 1.0 / 3.0).abs() < 1e-15 && (b10[2] + 0.2 / 3.0).abs() < 1e-15);
        }
        other => panic!("{other:?}"),
    }
    let mut bad = data.clone();
    bad[1][0] = json!([[[1, 0, 0.2], [0, 1, 0.7]]]);
    let e = surface_error(json!({"type": "bicubic_hermite", "hermite": bad}));
    assert!(e.starts_with("hermite[1][0]: expected 2 rows of partials"), "{e}");
    let mut bad = data.clone();
    bad[0][1][1][1] = json!([0, 0]);
    let e = surface_error(json!({"type": "bicubic_hermite", "hermite": bad}));
    assert_eq!(e, "hermite[0][1][1][1]: expected 3 coordinates, got 2");
    let e = surface_error(json!({"type": "bicubic_hermite", "hermite": [data[0]]}));
    assert!(e.starts_with("hermite: expected 2 rows of corners"), "{e}");
}

#[test]
fn a_hermite_curve_surface_document_interpolates_its_curves_and_checks_them() {
    let bottom = json!({"type": "bezier", "control_points": [[0, 0, 0], [1, -0.5, 0], [2, 0, 0]]});
    let top = json!({"type": "bezier", "control_points": [[0, 2, 0.5], [1, 2.5, 0.5], [2, 2, 0.5]]});
    let d0 = json!({"type": "bezier", "control_points": [[0, 1, 2], [0, 1, 3], [0, 1, 2]]});
    let d1 = json!({"type": "line", "from": [0, 2, 0], "to": [1, 2, -1]});
    let value = json!({"type": "hermite_curve_surface", "bottom": bottom, "top": top, "bottom_derivative": d0, "top_derivative": d1});
    let s = surface3(value.clone());
    let (cb, ct, c0, c1) = (curve3(bottom), curve3(top), curve3(d0), curve3(d1.clone()));
    for i in 0..=10 {
        let u = i as f64 / 10.0;
        let mut a = [Point::<3>::zeros(); 2];
        let mut b = [Point::<3>::zeros(); 2];
        s.eval_partials(u, 0.0, 0, 1, &mut a);
        s.eval_partials(u, 1.0, 0, 1, &mut b);
        assert!((a[0] - cb.point(u)).norm() < 1e-12 && (b[0] - ct.point(u)).norm() < 1e-12);
        assert!((a[1] - c0.point(u)).norm() < 1e-12 && (b[1] - c1.point(u)).norm() < 1e-12);
    }
    round_trips(value);
    let e =
        surface_error(json!({"type": "hermite_curve_surface", "bottom": {"type": "circle"}, "top": {"type": "circle"},
        "bottom_derivative": {"type": "circle"}, "top_derivative": d1}));
    assert!(e.starts_with("top_derivative: the curve's domain [0, 1] differs from bottom's [0, 6.28"), "{e}");
    let e =
        surface_error(json!({"type": "hermite_curve_surface", "bottom": {"type": "circle"}, "top": {"type": "circle"},
        "bottom_derivative": {"type": "circle"}, "top_derivative": {"type": "line", "from": [0, 0], "to": [1, 1]}}));
    assert!(e.starts_with("top_derivative: expected a curve of dimension 3 like bottom, got 2"), "{e}");
}

#[test]
fn loft_documents_interpolate_their_sections_across_as_asked() {
    let sections = json!([
        {"type": "bezier", "control_points": [[0, 0, 0], [1, 1, 0], [2, 0, 0]]},
        {"type": "bspline", "degree": 2, "knots": [0, 0, 0, 0.5, 1, 1, 1], "control_points": [[0, 0, 1], [0.5, -1, 1], [1.5, 1, 1.2], [2, 0, 1]]},
        {"type": "line", "from": [0, 0, 2], "to": [2, 0.5, 2]},
        {"type": "circle", "radius": 1}
    ]);
    let curves: Vec<Box<dyn Curve<3>>> = sections.as_array().unwrap().iter().map(|c| curve3(c.clone())).collect();
    for (cross, degree, params) in [
        ("bezier", None, json!("chord_length")),
        ("bspline", Some(2), json!("uniform")),
        ("bspline", None, json!([0, 1.5, 4])),
        ("bspline", Some(1), json!("centripetal")),
    ] {
        // A circle is closed, the others open: the last section is for the error below.
        let open = json!(sections.as_array().unwrap()[..3]);
        let mut value = json!({"type": "loft", "sections": open, "cross": cross, "parameters": params});
        if let Some(q) = degree {
            value["degree_v"] = json!(q);
        }
        round_trips(value.clone());
        let s = surface3(value);
        let dv = s.domain_v();
        let vs: Vec<f64> = match &params {
            serde_json::Value::Array(v) => v.iter().map(|x| x.as_f64().unwrap()).collect(),
            _ => vec![dv.start, f64::NAN, dv.end],
        };
        assert_eq!(dv.start, vs[0]);
        for (k, c) in curves.iter().take(3).enumerate() {
            if vs[k].is_nan() {
                continue;
            }
            let cd = c.domain();
            for i in 0..=10 {
                let u = i as f64 / 10.0;
                let want = c.point(cd.lerp(u));
                assert!((s.point(u, vs[k]) - want).norm() < 1e-12, "{cross} section {k} at {u}");
            }
        }
    }
    // Spline sections: the exact form is the B-spline loft, the same surface.
    let value = json!({"type": "loft", "sections": json!(sections.as_array().unwrap()[..2]), "cross": "bezier"});
    let doc = SurfaceDocument::from_value(value).unwrap();
    let s = doc.build_in::<3>().unwrap();
    match doc.exact_form().unwrap() {
        SurfaceForm::Spline(view) => {
            let (ku, kv) = view.knots.as_ref().unwrap();
            let net: Vec<Vec<Point<3>>> = view
                .control_points
                .iter()
                .map(|row| row.iter().map(|p| Point::<3>::from_column_slice(p)).collect())
                .collect();
            let spline =
                splinekit::surface::BSplineSurface::new(view.degrees, ku.to_vec(), kv.to_vec(), net, (false, false))
                    .unwrap();
            for (u, v) in [(0.1, 0.2), (0.5, 0.5), (0.9, 0.8)] {
                assert!((spline.point(u, v) - s.point(u, v)).norm() < 1e-12);
            }
        }
        other => panic!("{other:?}"),
    }
    // A line section has no spline view: approximated.
    let value = json!({"type": "loft", "sections": json!(sections.as_array().unwrap()[..3])});
    assert!(matches!(SurfaceDocument::from_value(value).unwrap().exact_form().unwrap(), SurfaceForm::Approximate));

    let e = surface_error(json!({"type": "loft", "sections": sections}));
    assert!(e.starts_with("sections[3]: the sections must be all closed or all open"), "{e}");
    let e = surface_error(json!({"type": "loft", "sections": json!(sections.as_array().unwrap()[..3]), "degree_v": 1}));
    assert!(e.starts_with("degree_v: a Bézier loft of 3 sections has degree 2 across"), "{e}");
    let e = surface_error(
        json!({"type": "loft", "sections": json!(sections.as_array().unwrap()[..3]), "cross": "bspline", "degree_v": 3}),
    );
    assert_eq!(e, "degree_v: must be between 1 and 2 for 3 sections, got 3");
    let e = surface_error(
        json!({"type": "loft", "sections": json!(sections.as_array().unwrap()[..2]), "parameters": "arc"}),
    );
    assert!(e.starts_with("parameters: expected \"chord_length\""), "{e}");
    let e = surface_error(
        json!({"type": "loft", "sections": json!(sections.as_array().unwrap()[..2]), "parameters": [1, 0]}),
    );
    assert!(e.starts_with("parameters[1]: parameters must increase strictly"), "{e}");
    let e = surface_error(json!({"type": "loft", "sections": [sections[0]]}));
    assert_eq!(e, "sections: expected at least 2 curves, got 1");
    let e = surface_error(json!({"type": "loft", "sections": [sections[0], sections[0]]}));
    assert!(e.starts_with("sections[1]: the section lies on sections[0]"), "{e}");
}
