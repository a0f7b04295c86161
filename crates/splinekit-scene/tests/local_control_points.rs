//! `local_control_points` of blending splines: edited Bézier locals (curves) and patches
//! (surfaces) in their rest frames. Checked against what the format says independently of
//! the kernel: at knot c_k the blend is local k alone, so the curve there is the edited
//! Bézier at its interpolation point (de Casteljau here), moved by the local's transform;
//! nothing outside the local's support changes; the fitted values given back reproduce the
//! curve bit for bit; bad entries are refused with the field and the numbers.

use std::f64::consts::TAU;

use splinekit::Point;
use splinekit::curve::Curve;
use splinekit::surface::Surface;
use splinekit_scene::blending::{BlendingSplineDoc, BlendingSplineSurfaceDoc};
use splinekit_scene::{CurveDocument, ShapeDocument, SurfaceDocument};

fn heart(extra: &str) -> BlendingSplineDoc {
    let json = format!(
        r#"{{"type":"blending_spline","model":{{"type":"heart"}},"local_curves":10,
            "local":{{"type":"bezier","degree":3}}{extra}}}"#
    );
    match ShapeDocument::from_json(&json).unwrap() {
        ShapeDocument::Curve(CurveDocument::BlendingSpline(d)) => d,
        _ => panic!("a blending spline"),
    }
}

fn torus(extra: &str) -> BlendingSplineSurfaceDoc {
    let json = format!(
        r#"{{"type":"blending_spline_surface","model":{{"type":"torus"}},"local_surfaces":[6,4],
            "local":{{"type":"bezier","degree":[3,2]}}{extra}}}"#
    );
    match ShapeDocument::from_json(&json).unwrap() {
        ShapeDocument::Surface(SurfaceDocument::BlendingSplineSurface(d)) => d,
        _ => panic!("a blending-spline surface"),
    }
}

/// De Casteljau at u.
fn casteljau(points: &[Point<3>], u: f64) -> Point<3> {
    let mut p = points.to_vec();
    for r in 1..p.len() {
        for i in 0..p.len() - r {
            p[i] = p[i] * (1.0 - u) + p[i + 1] * u;
        }
    }
    p[0]
}

fn json_points(points: &[Point<3>]) -> String {
    let list: Vec<String> = points.iter().map(|p| format!("[{:?},{:?},{:?}]", p.x, p.y, p.z)).collect();
    format!("[{}]", list.join(","))
}

#[test]
fn the_fitted_points_given_back_reproduce_the_curve_bit_for_bit() {
    let plain = heart("").curve::<3>().unwrap();
    let fitted = plain.local_bezier_points(3).unwrap().to_vec();
    let doc = heart(&format!(
        r#","local_control_points":{{"3":{}}},"transforms":{{"3":{{"scale":1.3}}}}"#,
        json_points(&fitted)
    ));
    let again = heart(r#","transforms":{"3":{"scale":1.3}}"#).curve::<3>().unwrap();
    let edited = doc.curve::<3>().unwrap();
    let mut a = [Point::<3>::zeros(); 3];
    let mut b = [Point::<3>::zeros(); 3];
    for i in 0..=2000 {
        let t = TAU * i as f64 / 2000.0;
        again.eval(t, &mut a);
        edited.eval(t, &mut b);
        assert_eq!(a, b, "t = {t}");
    }
    // And through JSON text: written, read back, the same document and curve.
    let text = serde_json::to_string(&CurveDocument::BlendingSpline(doc.clone()).to_value()).unwrap();
    assert!(text.contains(r#""local_control_points":{"3":[["#), "{text}");
    let ShapeDocument::Curve(CurveDocument::BlendingSpline(back)) = ShapeDocument::from_json(&text).unwrap() else {
        panic!()
    };
    assert_eq!(back, doc);
    assert_eq!(back.curve::<3>().unwrap().point(1.9), edited.point(1.9));
}

#[test]
fn an_edited_local_changes_the_curve_inside_its_support_only() {
    let plain = heart("").curve::<3>().unwrap();
    let mut p = plain.local_bezier_points(3).unwrap().to_vec();
    p[1] += Point::<3>::new(0.8, -0.5, 0.3);
    p[3] += Point::<3>::new(-0.4, 0.2, 0.0);
    let translate = Point::<3>::new(0.25, 0.5, -1.0);
    let extra = format!(
        r#","local_control_points":{{"3":{}}},"transforms":{{"3":{{"translate":[0.25,0.5,-1],"rotate":{{"axis":[0,0,1],"angle":0.4}}}}}}"#,
        json_points(&p)
    );
    let moved_only = heart(r#","transforms":{"3":{"translate":[0.25,0.5,-1],"rotate":{"axis":[0,0,1],"angle":0.4}}}"#)
        .curve::<3>()
        .unwrap();
    let edited = heart(&extra).curve::<3>().unwrap();
    let (c2, c3, c4) = (TAU * 0.2, TAU * 0.3, TAU * 0.4);
    let mut changed = 0;
    for i in 0..=2000 {
        let t = TAU * i as f64 / 2000.0;
        let (a, b) = (moved_only.point(t), edited.point(t));
        if t <= c2 || t >= c4 {
            assert_eq!(a, b, "t = {t} is outside local 3's support");
        } else if a != b {
            changed += 1;
        }
    }
    assert!(changed > 300, "only {changed} samples inside the support changed");
    // At c₃ the curve is local 3 alone: the edited Bézier at its midpoint (the support is
    // [c₂, c₄]), moved by the transform about the origin o (the heart's point at c₃).
    let heart_model = splinekit::curve::model::Heart::new(1.0).unwrap();
    let o = heart_model.point(c3);
    let turn = nalgebra::Rotation3::from_axis_angle(&nalgebra::Vector3::z_axis(), 0.4);
    let expected = o + translate + turn * (casteljau(&p, 0.5) - o);
    assert!((edited.point(c3) - expected).norm() < 1e-12, "{} vs {expected}", edited.point(c3));
    // The kernel reports the world control points the same way.
    let world = edited.local_bezier_world_points(3).unwrap();
    assert!((world[1] - (o + translate + turn * (p[1] - o))).norm() < 1e-12);
}

#[test]
fn an_edited_patch_changes_the_surface_inside_its_support_only() {
    let plain = torus("").surface::<3>().unwrap();
    let (fitted, (du, dv)) = plain.bezier_rest_net(2, 1).unwrap();
    assert_eq!((du, dv), (3, 2));
    let rows = |net: &[Point<3>]| -> String {
        let rows: Vec<String> = net.chunks(dv + 1).map(json_points).collect();
        format!("[{}]", rows.join(","))
    };
    let same = torus(&format!(r#","local_control_points":{{"2,1":{}}}"#, rows(fitted))).surface::<3>().unwrap();
    let mut net = fitted.to_vec();
    net[5] += Point::<3>::new(0.0, 0.0, 0.7);
    let edited = torus(&format!(r#","local_control_points":{{"2,1":{}}}"#, rows(&net))).surface::<3>().unwrap();
    let (ku, kv) = plain.knots();
    let (su, sv) = (ku.support(2), kv.support(1));
    let mut changed = 0;
    for i in 0..=60 {
        for j in 0..=40 {
            let (u, v) = (TAU * i as f64 / 60.0, TAU * j as f64 / 40.0);
            assert_eq!(plain.point(u, v), same.point(u, v), "({u}, {v})");
            let inside = u > su.start && u < su.end && v > sv.start && v < sv.end;
            if !inside {
                assert_eq!(plain.point(u, v), edited.point(u, v), "({u}, {v}) is outside patch [2, 1]");
            } else if plain.point(u, v) != edited.point(u, v) {
                changed += 1;
            }
        }
    }
    assert!(changed > 50, "only {changed} samples inside the support changed");
    // At the knot pair the surface is patch (2, 1) alone: its tensor Bézier at (½, ½).
    let columns: Vec<Point<3>> = net.chunks(dv + 1).map(|row| casteljau(row, 0.5)).collect();
    let at = edited.point(ku.centre(2), kv.centre(1));
    assert!((at - casteljau(&columns, 0.5)).norm() < 1e-12, "{at}");
}

#[test]
fn bad_entries_are_refused_by_field_and_numbers() {
    let build = |json: &str| -> String {
        let built = ShapeDocument::from_json(json).and_then(|d| match d {
            ShapeDocument::Curve(c) => c.build().map(|_| ()),
            ShapeDocument::Surface(s) => s.build().map(|_| ()),
        });
        built.err().unwrap_or_else(|| panic!("{json} was accepted")).to_string()
    };
    let heart = |lcp: &str, local: &str| {
        format!(
            r#"{{"type":"blending_spline","model":{{"type":"heart"}},"local_curves":10,"local":{local},"local_control_points":{lcp}}}"#
        )
    };
    let cubic = r#"{"type":"bezier","degree":3}"#;
    for (lcp, local, expected) in [
        (
            r#"{"3":[[0,0,0],[1,0,0]]}"#,
            cubic,
            "local_control_points.3: expected 4 control points for a Bézier local of degree 3, got 2",
        ),
        (r#"{"3":[[0,0,0],[1,0],[0,0,0],[0,0,0]]}"#, cubic, "local_control_points.3[1]: expected 3 coordinates, got 2"),
        (
            r#"{"12":[[0,0,0],[0,0,0],[0,0,0],[0,0,0]]}"#,
            cubic,
            "local_control_points.12: local curve 12 does not exist (there are 10)",
        ),
        (r#"{"x":[]}"#, cubic, "local_control_points.x: keys must be local-curve indices"),
        (r#"[1]"#, cubic, "local_control_points: expected an object keyed by local-curve index, got an array"),
        (r#"{"3":[[0,0,0],[0,0,1e300],[0,0,0],[0,0,0]]}"#, cubic, "local_control_points.3[1][2]: 1e300 is beyond"),
        (
            r#"{"3":[[0,0,0],[0,0,0],[0,0,0]]}"#,
            r#"{"type":"sub_curve"}"#,
            "local_control_points: only for Bézier locals made from a model",
        ),
    ] {
        let msg = build(&heart(lcp, local));
        assert!(msg.starts_with(expected), "{lcp}: {msg}");
        assert!(!msg.contains('\n'), "{msg}");
    }
    let explicit = r#"{"type":"blending_spline","knots":[0,1],"local_curves":[{"type":"line","from":[0,0],"to":[1,0]},
        {"type":"line","from":[0,1],"to":[1,1]}],"local_control_points":{"0":[[0,0],[1,0]]}}"#;
    assert!(build(explicit).starts_with("local_control_points: only for Bézier locals made from a model (\"local\": {\"type\": \"bezier\"}), not explicit local curves"), "{}", build(explicit));
    let torus = |lcp: &str| {
        format!(
            r#"{{"type":"blending_spline_surface","model":{{"type":"torus"}},"local_surfaces":[6,4],"local_control_points":{lcp}}}"#
        )
    };
    let row = "[[0,0,0],[0,0,0],[0,0,0],[0,0,0]]";
    for (lcp, expected) in [
        (
            format!(r#"{{"2,1":[{row},{row},{row}]}}"#),
            "local_control_points.2,1: expected 4 rows (d_u + 1 for degrees [3, 3]), got 3",
        ),
        (
            format!(r#"{{"2,1":[{row},{row},[[0,0,0]],{row}]}}"#),
            "local_control_points.2,1[2]: expected 4 points (d_v + 1 for degrees [3, 3]), got 1",
        ),
        (
            format!(r#"{{"6,1":[{row},{row},{row},{row}]}}"#),
            "local_control_points.6,1: patch [6, 1] does not exist (there are 6×4)",
        ),
        (r#"{"2":[]}"#.to_string(), "local_control_points.2: keys must be patch indices \"k,l\""),
    ] {
        let msg = build(&torus(&lcp));
        assert!(msg.starts_with(expected), "{lcp}: {msg}");
    }
    let sub = r#"{"type":"blending_spline_surface","model":{"type":"torus"},"local_surfaces":[6,4],"local":{"type":"sub_surface"},"local_control_points":{"0,0":[]}}"#;
    assert!(build(sub).starts_with("local_control_points: only for Bézier locals made from a model"), "{}", build(sub));
}
