//! `trimmed` documents leave as STEP faces (bounds, edges, pcurves) and come back as
//! `trimmed` documents with the same surface and loops; loop orientation and refusals.
//! OpenCASCADE's verdict on the same files (validity, area, inside/outside) is in
//! tests/step/face_checks.py.

use splinekit_scene::{CurveDocument, SceneOrShape, ShapeDocument, SurfaceDocument};
use splinekit_step::documents::{export_document, import_items};
use splinekit_step::part21::StepFile;
use splinekit_step::part21::writer::HeaderInfo;

const SURFACE: &str = r#"{"type":"bspline_surface","degree_u":2,"degree_v":1,"knots_u":[0,0,0,1,1,1],"knots_v":[0,0,1,1],"control_points":[[[0,0,0],[0,1,0]],[[1,0,1],[1,1,1]],[[2,0,0],[2,1,0.3]]]}"#;
const HOLE: &str = r#"{"type":"nurbs","degree":2,"knots":[0,0,0,0.25,0.25,0.5,0.5,0.75,0.75,1,1,1],"control_points":[[0.7,0.5],[0.7,0.7],[0.5,0.7],[0.3,0.7],[0.3,0.5],[0.3,0.3],[0.5,0.3],[0.7,0.3],[0.7,0.5]],"weights":[1,0.7071067811865476,1,0.7071067811865476,1,0.7071067811865476,1,0.7071067811865476,1]}"#;
const OUTER_CLOCKWISE: &str = r#"{"type":"bspline","degree":1,"knots":[0,0,1,2,3,4,4],"control_points":[[0.1,0.1],[0.1,0.9],[0.9,0.9],[0.9,0.1],[0.1,0.1]]}"#;

fn trimmed(outer: Option<&str>, holes: &[&str]) -> String {
    let outer = outer.map_or(String::new(), |o| format!(r#","outer":{o}"#));
    format!(r#"{{"type":"trimmed","surface":{SURFACE}{outer},"holes":[{}]}}"#, holes.join(","))
}

fn export(json: &str) -> String {
    let doc = SceneOrShape::from_json(json).unwrap();
    export_document(&doc, "t", 1e-6, &HeaderInfo::default()).unwrap().0
}

fn import(text: String) -> ShapeDocument {
    let imported = import_items(&StepFile::from_bytes(text.into_bytes()).unwrap()).unwrap();
    assert!(imported.not_understood.is_empty(), "{:?}", imported.not_understood);
    assert_eq!(imported.items.len(), 1);
    imported.items[0].document.clone()
}

fn points(c: &CurveDocument) -> Vec<Vec<f64>> {
    match c {
        CurveDocument::Bspline(b) => b.control_points.clone(),
        CurveDocument::Nurbs(n) => n.control_points.clone(),
        other => panic!("a loop comes back as a spline, got {other:?}"),
    }
}

/// The lines of the file holding `entity`.
fn lines_with<'a>(text: &'a str, entity: &str) -> Vec<&'a str> {
    text.lines().filter(|l| l.contains(&format!("={entity}("))).collect()
}

#[test]
fn a_trimmed_spline_surface_comes_back_trimmed_with_its_loops() {
    let json = trimmed(Some(OUTER_CLOCKWISE), &[HOLE]);
    let back = import(export(&json));
    let ShapeDocument::Surface(SurfaceDocument::Trimmed(t)) = back else { panic!("not trimmed: {back:?}") };
    let ShapeDocument::Surface(SurfaceDocument::Trimmed(original)) = SceneOrShape::from_json(&json)
        .map(|d| match d {
            SceneOrShape::Shape(s) => s,
            SceneOrShape::Scene(_) => unreachable!(),
        })
        .unwrap()
    else {
        unreachable!()
    };
    assert_eq!(t.surface, original.surface);
    // A bound whose flag is F is read back reversed (the reader turns every loop so that
    // the material lies on its left): the clockwise outer loop comes back counter-clockwise,
    // the counter-clockwise hole clockwise, each the same points (and weights) backwards.
    let backwards = |mut v: Vec<Vec<f64>>| {
        v.reverse();
        v
    };
    assert_eq!(points(t.outer.as_ref().unwrap()), backwards(points(original.outer.as_ref().unwrap())));
    assert_eq!(t.holes.len(), 1);
    let CurveDocument::Nurbs(hole) = &t.holes[0] else { panic!("{:?}", t.holes[0]) };
    let CurveDocument::Nurbs(was) = &original.holes[0] else { unreachable!() };
    let mut weights = was.weights.clone();
    weights.reverse();
    assert_eq!(
        (&hole.control_points, &hole.weights, hole.degree),
        (&backwards(was.control_points.clone()), &weights, was.degree)
    );
}

#[test]
fn bounds_carry_the_orientation_that_puts_the_material_on_the_left() {
    let text = export(&trimmed(Some(OUTER_CLOCKWISE), &[HOLE]));
    // Outer written clockwise: flag F. The hole (counter-clockwise) likewise F.
    assert_eq!(lines_with(&text, "FACE_OUTER_BOUND").len(), 1);
    assert!(lines_with(&text, "FACE_OUTER_BOUND")[0].ends_with(",.F.);"), "{text}");
    assert!(lines_with(&text, "FACE_BOUND")[0].ends_with(",.F.);"));
    // Without an outer loop: the domain's rectangle, counter-clockwise (T), four edges
    // between four vertices, plus the hole's closed edge on a vertex of its own.
    let text = export(&trimmed(None, &[HOLE]));
    assert!(lines_with(&text, "FACE_OUTER_BOUND")[0].ends_with(",.T.);"));
    assert_eq!(lines_with(&text, "EDGE_CURVE").len(), 5);
    assert_eq!(lines_with(&text, "VERTEX_POINT").len(), 5);
    assert_eq!(lines_with(&text, "ADVANCED_FACE").len(), 1);
    assert_eq!(lines_with(&text, "MANIFOLD_SURFACE_SHAPE_REPRESENTATION").len(), 1);
    // No geometric set when every item is a face.
    assert!(lines_with(&text, "GEOMETRIC_SET").is_empty());
}

/// Closed surfaces without an outer loop leave bounded by their natural bounds, as CAD
/// systems write whole surfaces: seams (`SEAM_CURVE`, one edge used both ways) where the
/// domain closes, no edge where a side is one point. (OpenCASCADE finds these faces valid
/// with the closed-form areas: tests/step/shapes/natural_bounds.json.)
#[test]
fn closed_surfaces_without_an_outer_loop_are_bounded_by_seams() {
    // (surface, edge curves, seam curves, oriented edges, vertices)
    for (surface, edges, seams, uses, vertices) in [
        // bottom circle, seam, top circle; the seam used up and down
        (r#"{"type":"cylinder"}"#, 3, 1, 4, 2),
        // one meridian between the poles, used up and down; the poles have no edge
        (r#"{"type":"sphere"}"#, 1, 1, 2, 2),
        // two seams on one vertex, each used both ways
        (r#"{"type":"torus"}"#, 2, 2, 4, 1),
        // the base circle and the seam up to the apex and back
        (r#"{"type":"cone","radius":1,"height":2}"#, 2, 1, 3, 2),
    ] {
        let text = export(&format!(r#"{{"type":"trimmed","surface":{surface}}}"#));
        let count = |entity: &str| lines_with(&text, entity).len();
        assert_eq!(
            (count("EDGE_CURVE"), count("SEAM_CURVE"), count("ORIENTED_EDGE"), count("VERTEX_POINT")),
            (edges, seams, uses, vertices),
            "{surface}"
        );
        // A seam's two uses: the same edge forwards and backwards.
        let seam_edges: Vec<&str> = lines_with(&text, "ORIENTED_EDGE");
        let forwards = seam_edges.iter().filter(|l| l.ends_with(",.T.);")).count();
        assert_eq!(forwards, edges, "{surface}: every edge used forwards once");
    }
}
