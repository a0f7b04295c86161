//! JSON → STEP → JSON is exact for B-spline and NURBS documents (curves and surfaces,
//! periodic ones included): every number comes back bit for bit.

use splinekit_scene::{SceneOrShape, ShapeDocument};
use splinekit_step::documents::{export_document, import_items};
use splinekit_step::part21::StepFile;
use splinekit_step::part21::writer::HeaderInfo;

fn round_trip(json: &str) -> ShapeDocument {
    let doc = SceneOrShape::from_json(json).unwrap();
    let (text, _) = export_document(&doc, "t", 1e-6, &HeaderInfo::default()).unwrap();
    let file = StepFile::from_bytes(text.into_bytes()).unwrap();
    let imported = import_items(&file).unwrap();
    assert!(imported.not_understood.is_empty(), "{:?}", imported.not_understood);
    assert_eq!(imported.items.len(), 1);
    imported.items[0].document.clone()
}

#[test]
fn spline_documents_come_back_exactly() {
    for json in [
        r#"{"type":"bspline","degree":3,"knots":[0,0,0,0,0.3,1.7,2,2,2,2],"control_points":[[0,0,1],[1,2,0.1],[2,-1,3],[3,1,0],[4,0,0.7],[5,2,2]]}"#,
        r#"{"type":"bspline","degree":3,"periodic":true,"knots":[0,1,2,3,4,5,6,7],"control_points":[[0,0,0],[1,0,0.1],[1,1,0.2],[0,1,0.3]]}"#,
        r#"{"type":"nurbs","degree":2,"knots":[0,0,0,0.25,0.25,0.5,0.5,0.75,0.75,1,1,1],"control_points":[[1,0,0],[1,1,0],[0,1,0],[-1,1,0],[-1,0,0],[-1,-1,0],[0,-1,0],[1,-1,0],[1,0,0]],"weights":[1,0.7071067811865476,1,0.7071067811865476,1,0.7071067811865476,1,0.7071067811865476,1]}"#,
        r#"{"type":"bspline_surface","degree_u":2,"degree_v":1,"knots_u":[0,0,0,1,1,1],"knots_v":[0,0,1,1],"control_points":[[[0,0,0],[0,1,0]],[[1,0,1],[1,1,1]],[[2,0,0],[2,1,0.3]]]}"#,
        r#"{"type":"nurbs_surface","degree_u":1,"degree_v":2,"periodic_v":true,"knots_u":[0,0,1,1],"knots_v":[0,1,2,3,4,5,6],"control_points":[[[0,0,0],[1,0,0],[0,1,0],[0.5,0.5,1]],[[0,0,1],[1,0,1],[0,1,1],[0.5,0.5,2]]],"weights":[[1,2,1,0.5],[1,1,3,1]]}"#,
    ] {
        let original = SceneOrShape::from_json(json).unwrap();
        let SceneOrShape::Shape(original) = original else { panic!() };
        assert_eq!(round_trip(json), original, "{json}");
    }
}

/// A sphere and a torus in a placement leave as SPHERICAL_SURFACE / TOROIDAL_SURFACE with
/// their AXIS2_PLACEMENT_3D and come back as the same `placed` documents (the reference
/// direction made orthogonal to the axis, as the placement reads it).
#[test]
fn placed_spheres_and_tori_come_back_placed() {
    for (json, ty) in [
        (
            r#"{"type":"placed","surface":{"type":"sphere","radius":1.5},"origin":[1,-2,0.5],"axis":[0,0.6,0.8],"ref_direction":[1,0,0]}"#,
            "SPHERICAL_SURFACE",
        ),
        (
            r#"{"type":"placed","surface":{"type":"torus","major_radius":3,"minor_radius":1},"origin":[0,1,2],"axis":[0,0,1],"ref_direction":[0,1,0]}"#,
            "TOROIDAL_SURFACE",
        ),
    ] {
        let doc = SceneOrShape::from_json(json).unwrap();
        let (text, _) = export_document(&doc, "t", 1e-6, &HeaderInfo::default()).unwrap();
        assert!(text.contains(&format!("={ty}(")), "{text}");
        let SceneOrShape::Shape(original) = doc else { panic!() };
        assert_eq!(round_trip(json), original, "{json}");
    }
}

/// A cone leaves as CONICAL_SURFACE (not the revolution of its generatrix) and comes back
/// as a surface on the same cone: every point of the imported document at a grid of its
/// parameters satisfies √(x² + y²) = r (1 − z/h), 0 ≤ z ≤ h, and the grid reaches the base
/// and the apex. (OpenCASCADE evaluates the exported entity at the document's parameters
/// in tests/step/ocp_judge.py.)
#[test]
fn cones_leave_as_conical_surfaces_on_the_same_cone() {
    let (r, h) = (1.5, 2.0);
    let json = format!(r#"{{"type":"cone","radius":{r},"height":{h}}}"#);
    let doc = SceneOrShape::from_json(&json).unwrap();
    let (text, _) = export_document(&doc, "t", 1e-6, &HeaderInfo::default()).unwrap();
    assert!(text.contains("=CONICAL_SURFACE("), "{text}");
    assert!(!text.contains("SURFACE_OF_REVOLUTION"), "{text}");
    let ShapeDocument::Surface(back) = round_trip(&json) else { panic!("not a surface") };
    let s = back.build_in::<3>().unwrap();
    let (du, dv) = (s.domain_u(), s.domain_v());
    let (mut lowest, mut highest) = (f64::INFINITY, f64::NEG_INFINITY);
    for i in 0..=20 {
        for j in 0..=20 {
            let p = s.point(du.lerp(i as f64 / 20.0), dv.lerp(j as f64 / 20.0));
            let off = (p[0].hypot(p[1]) - r * (1.0 - p[2] / h)).abs();
            assert!(off < 1e-12 && (-1e-12..=h + 1e-12).contains(&p[2]), "{p:?} is {off:e} off the cone");
            (lowest, highest) = (lowest.min(p[2]), highest.max(p[2]));
        }
    }
    assert!(lowest.abs() < 1e-12 && (highest - h).abs() < 1e-12, "z over [{lowest}, {highest}]");
}
