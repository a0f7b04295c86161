//! Inserting local pieces into blending-spline documents: the document written back builds
//! exactly the shape the kernel's insertion makes (with moved, edited and animated pieces,
//! whose indices shift), reads back as itself, and only the documents that had an insertion
//! gain `knots`; documents without explicit knots read and write as before; bad knots are
//! refused with the field and the numbers.

use splinekit::curve::Curve;
use splinekit::surface::{Direction, Surface};
use splinekit_scene::blending::{BlendingSplineSurfaceDoc, insert_knot_line, insert_local_curve};
use splinekit_scene::{ShapeDocument, SurfaceDocument};

#[path = "common/edited_heart.rs"]
mod edited_heart;
use edited_heart::{HEART, curve_doc, curve_value};

fn surface_doc(json: &str) -> BlendingSplineSurfaceDoc {
    match ShapeDocument::from_json(json).unwrap() {
        ShapeDocument::Surface(SurfaceDocument::BlendingSplineSurface(d)) => d,
        _ => panic!("a blending-spline surface"),
    }
}

fn surface_value(d: &BlendingSplineSurfaceDoc) -> serde_json::Value {
    SurfaceDocument::BlendingSplineSurface(d.clone()).to_value()
}

#[test]
fn the_written_curve_document_builds_what_the_kernel_inserted() {
    let doc = curve_doc(HEART);
    let before = doc.curve::<3>().unwrap();
    // Between knots 4 and 5, and between 6 and 7 (the edited local is a neighbour).
    for frac in [4.3, 6.5] {
        let t = frac * std::f64::consts::TAU / 10.0;
        let mut kernel = before.clone();
        let k_kernel = kernel.insert_local(t).unwrap();
        let (after, k) = insert_local_curve(&doc, t).unwrap();
        assert_eq!(k, k_kernel);
        let built = after.curve::<3>().unwrap();
        assert_eq!(built.local_count(), 11);
        assert_eq!(after.knots.as_deref(), Some(kernel.knots().values()));
        for i in 0..=2000 {
            let s = built.domain().lerp(i as f64 / 2000.0);
            let (a, b) = (built.point(s), kernel.point(s));
            assert!((a - b).norm() < 1e-12, "t = {t}: at {s} the document gives {a}, the kernel {b}");
        }
        // Indices past the new local moved up by one; the new local has its points.
        let v = curve_value(&after);
        let shifted = |i: usize| if i >= k { i + 1 } else { i };
        assert!(v["transforms"].get(shifted(4).to_string()).is_some(), "{}", v["transforms"]);
        assert!(v["transforms"].get("1").is_some());
        assert_eq!(v["animation"][0]["local"], serde_json::json!(shifted(6)));
        let lcp = v["local_control_points"].as_object().unwrap();
        assert!(lcp.contains_key(&shifted(7).to_string()) && lcp.contains_key(&k.to_string()), "{lcp:?}");
        assert_eq!(lcp[&k.to_string()].as_array().map(Vec::len), Some(3));
        // It reads back as itself and is posed like the original (the animation follows).
        let back = curve_doc(&v.to_string());
        assert_eq!(back, after);
        let (mut posed_before, mut posed_after) = (doc.clone(), after.clone());
        posed_before.time = Some(0.3);
        posed_after.time = Some(0.3);
        let (pb, pa) = (posed_before.curve::<3>().unwrap(), posed_after.curve::<3>().unwrap());
        let far = (k as f64 + 3.0) * std::f64::consts::TAU / 10.0;
        assert!((pb.point(far % std::f64::consts::TAU) - pa.point(far % std::f64::consts::TAU)).norm() < 1e-9);
    }
}

#[test]
fn the_heart_example_gains_one_local_and_keeps_its_shape() {
    let text =
        std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/../../examples/scenes/heart_local_curves.json"))
            .unwrap();
    let scene: serde_json::Value = serde_json::from_str(&text).unwrap();
    let doc = curve_doc(&scene["objects"][0]["shape"].to_string());
    let before = doc.curve::<3>().unwrap();
    let (lo, hi) = (before.centre(2), before.centre(3));
    let (after, k) = insert_local_curve(&doc, 0.5 * (lo + hi)).unwrap();
    let c = after.curve::<3>().unwrap();
    assert_eq!((k, c.local_count()), (3, 11));
    let mut worst: f64 = 0.0;
    for i in 0..=2000 {
        let t = c.domain().lerp(i as f64 / 2000.0);
        let change = (c.point(t) - before.point(t)).norm();
        if t <= lo || t >= hi {
            assert!(change < 1e-12, "outside the split interval, {t} moved by {change}");
        }
        worst = worst.max(change);
    }
    // Quadratic locals 0.63 apart on a heart 33 across: within 1 % of its size.
    assert!(worst < 0.33, "{worst}");
}

#[test]
fn documents_without_explicit_knots_read_and_write_as_before() {
    let dir = concat!(env!("CARGO_MANIFEST_DIR"), "/../../examples/scenes");
    let mut seen = 0;
    for entry in std::fs::read_dir(dir).unwrap() {
        let path = entry.unwrap().path();
        let scene: serde_json::Value = serde_json::from_str(&std::fs::read_to_string(&path).unwrap()).unwrap();
        for object in scene["objects"].as_array().into_iter().flatten() {
            let shape = &object["shape"];
            if !matches!(shape["type"].as_str(), Some("blending_spline" | "blending_spline_surface")) {
                continue;
            }
            let written = match ShapeDocument::from_value(shape.clone()).unwrap() {
                ShapeDocument::Curve(c) => c.to_value(),
                ShapeDocument::Surface(s) => s.to_value(),
            };
            for field in ["knots", "knots_u", "knots_v"] {
                assert!(written.get(field).is_none(), "{}: {field} appeared", path.display());
            }
            let again = ShapeDocument::from_value(written.clone()).unwrap();
            let twice = match again {
                ShapeDocument::Curve(c) => c.to_value(),
                ShapeDocument::Surface(s) => s.to_value(),
            };
            assert_eq!(written, twice, "{}", path.display());
            seen += 1;
        }
    }
    assert!(seen >= 8, "{seen} blending splines in the examples");
}

/// The torus as in examples/scenes/blending_torus_local_patches.json's kind (bicubic
/// patches), with a moved, an edited and an animated patch.
const TORUS: &str = r#"{"type": "blending_spline_surface", "model": {"type": "torus"}, "local_surfaces": [8, 6],
    "transforms": {"3,2": {"translate": [0, 0, 0.6]}, "6,1": {"scale": 1.2}},
    "local_control_points": {"2,2": [[[2.2, 1.6, 1.4], [2.2, 1.6, 0.4], [2.6, 1.9, -0.3], [3.2, 2.3, -0.6]],
        [[2.5, 2.0, 1.4], [2.7, 2.0, 0.4], [3.1, 2.3, -0.3], [3.4, 2.6, -0.6]],
        [[2.3, 2.3, 1.4], [2.7, 2.5, 0.4], [3.0, 2.8, -0.3], [3.4, 3.0, -0.6]],
        [[1.8, 2.6, 1.4], [2.2, 2.9, 0.4], [2.6, 3.2, -0.3], [3.0, 3.5, -0.6]]]},
    "animation": [{"local": [5, 4], "motions": [{"pulse": {"amplitude": 0.3}}]}]}"#;

#[test]
fn the_written_surface_document_builds_what_the_kernel_inserted() {
    let doc = surface_doc(TORUS);
    let before = doc.surface::<3>().unwrap();
    for (direction, t, counts) in [(Direction::U, 2.0, [9, 6]), (Direction::V, 2.5, [8, 7])] {
        let mut kernel = before.clone();
        let k_kernel = kernel.insert_knot_line(direction, t).unwrap();
        let (after, k) = insert_knot_line(&doc, direction, t).unwrap();
        assert_eq!((k, after.local_surfaces), (k_kernel, Some(counts)));
        let built = after.surface::<3>().unwrap();
        for i in 0..=60 {
            for j in 0..=60 {
                let (u, v) = (built.domain_u().lerp(i as f64 / 60.0), built.domain_v().lerp(j as f64 / 60.0));
                let (a, b) = (built.point(u, v), kernel.point(u, v));
                assert!((a - b).norm() < 1e-12, "{direction:?}: at ({u}, {v}) {a} vs {b}");
            }
        }
        let v = surface_value(&after);
        let field = if direction == Direction::U { "knots_u" } else { "knots_v" };
        let other = if direction == Direction::U { "knots_v" } else { "knots_u" };
        let n = if direction == Direction::U { counts[0] } else { counts[1] };
        assert_eq!(v[field].as_array().map(Vec::len), Some(n + 1), "closed: one knot more than patches");
        assert!(v.get(other).is_none());
        let lcp = v["local_control_points"].as_object().unwrap();
        assert_eq!(lcp.len(), 1 + if direction == Direction::U { 6 } else { 8 }, "the edited patch and the new line");
        assert_eq!(surface_doc(&v.to_string()), after, "reads back as itself");
    }
}

#[test]
fn bad_knots_and_insertions_are_refused_with_the_field_and_numbers() {
    let err = |json: &str| match ShapeDocument::from_json(json) {
        Err(e) => e.to_string(),
        Ok(ShapeDocument::Curve(c)) => c.build().err().map(|e| e.to_string()).unwrap_or_default(),
        Ok(ShapeDocument::Surface(s)) => s.build().err().map(|e| e.to_string()).unwrap_or_default(),
    };
    let e = err(r#"{"type":"blending_spline","model":{"type":"heart"},"local_curves":3,"knots":[0,1,2,3]}"#);
    assert!(e.contains("knots") && e.contains("[0, 6.28") && e.contains("got [0, 3]"), "{e}");
    let e = err(
        r#"{"type":"blending_spline","model":{"type":"heart"},"local_curves":4,"knots":[0,1,2,6.283185307179586]}"#,
    );
    assert!(e.contains("local_curves") && e.contains("expected 3"), "{e}");
    let e = err(
        r#"{"type":"blending_spline","model":{"type":"heart"},"local_curves":3,"knots":[0,1,2,6.283185307179586],"knot_spacing":"chord_length"}"#,
    );
    assert!(e.contains("knot_spacing"), "{e}");
    let e = err(
        r#"{"type":"blending_spline_surface","model":{"type":"torus"},"local_surfaces":[3,4],"knots_u":[0,2,1,6.283185307179586]}"#,
    );
    assert!(e.contains("knots_u[2]"), "{e}");
    let e = err(
        r#"{"type":"blending_spline_surface","model":{"type":"torus"},"local_surfaces":[4,4],"knots_u":[0,1,2,6.283185307179586]}"#,
    );
    assert!(e.contains("local_surfaces[0]") && e.contains("expected 3"), "{e}");
    let explicit = curve_doc(
        r#"{"type":"blending_spline","knots":[0,1,2],"local_curves":[
            {"type":"line","from":[0,0],"to":[1,0]},{"type":"line","from":[0,1],"to":[1,1]},{"type":"line","from":[0,2],"to":[1,2]}]}"#,
    );
    assert_eq!(
        insert_local_curve(&explicit, 0.5).unwrap_err().to_string(),
        "local_curves: a local curve is inserted only into a blending spline built from a model (explicit local \
         curves are mapped onto their supports, and an insertion would stretch its neighbours)"
    );
    let e = insert_local_curve(&curve_doc(HEART), 9.0).unwrap_err().to_string();
    assert!(e.starts_with("t: ") && e.contains("got 9"), "{e}");
    let e = insert_knot_line(&surface_doc(TORUS), Direction::V, -1.0).unwrap_err().to_string();
    assert!(e.starts_with("v: ") && e.contains("got -1"), "{e}");
}
