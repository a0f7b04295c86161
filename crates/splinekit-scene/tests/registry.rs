//! The registry of document kinds: every kind's example document is valid, survives the
//! trip through JSON, builds in its dimension and evaluates; the messages list every kind;
//! nested documents report errors by their full path.

use serde_json::{Value, json};
use splinekit::Point;
use splinekit::curve::Curve;
use splinekit::surface::Surface;
use splinekit_scene::{CurveDocument, Curves, Decoration, DimensionVisitor, ShapeDocument, SurfaceDocument, Surfaces};

/// The position at the start, middle and end of a curve's domain.
struct CurveSamples;

impl DimensionVisitor<Curves> for CurveSamples {
    type Output = Vec<f64>;
    fn visit<const D: usize>(self, c: &dyn Curve<D>) -> Vec<f64> {
        let dom = c.domain();
        [0.0, 0.5, 1.0].iter().flat_map(|&s| c.point(dom.lerp(s)).iter().copied().collect::<Vec<_>>()).collect()
    }
}

/// The position at the corners and centre of a surface's domain.
struct SurfaceSamples;

impl DimensionVisitor<Surfaces> for SurfaceSamples {
    type Output = Vec<f64>;
    fn visit<const D: usize>(self, s: &dyn Surface<D>) -> Vec<f64> {
        let (du, dv) = (s.domain_u(), s.domain_v());
        let mut out = Vec::new();
        for (a, b) in [(0.0, 0.0), (1.0, 0.0), (0.5, 0.5), (0.0, 1.0), (1.0, 1.0)] {
            let mut p = [Point::<D>::zeros(); 1];
            s.eval_partials(du.lerp(a), dv.lerp(b), 0, 0, &mut p);
            out.extend(p[0].iter());
        }
        out
    }
}

/// Checks every kind of a family (`$Doc`, parsed back as the `ShapeDocument` variant
/// `$Shape`): the examples follow the registry's list of types, each writes its `type`,
/// parses back through `ShapeDocument::parse` as that family to an equal document, builds
/// in its dimension and evaluates to finite samples (`$samples`).
macro_rules! check_every_kind {
    ($Doc:ident, $Shape:ident, $samples:expr) => {
        let examples = $Doc::examples();
        assert_eq!(examples.iter().map($Doc::type_name).collect::<Vec<_>>(), $Doc::TYPES);
        for doc in examples {
            let name = doc.type_name();
            let value = doc.to_value();
            assert_eq!(value["type"], json!(name));
            let ShapeDocument::$Shape(back) = ShapeDocument::parse(&value).unwrap_or_else(|e| panic!("{name}: {e}"))
            else {
                panic!("{name} parsed as a shape of the other family");
            };
            assert_eq!(back, doc, "{name} round trip");
            let shape = doc.build().unwrap_or_else(|e| panic!("{name}: {e}"));
            assert_eq!(shape.dimension(), doc.dimension().unwrap());
            let samples = shape.visit($samples);
            assert!(samples.iter().all(|x| x.is_finite()), "{name}: {samples:?}");
        }
    };
}

#[test]
fn every_curve_kind_has_an_example_that_round_trips_builds_and_evaluates() {
    check_every_kind!(CurveDocument, Curve, CurveSamples);
}

#[test]
fn every_surface_kind_has_an_example_that_round_trips_builds_and_evaluates() {
    check_every_kind!(SurfaceDocument, Surface, SurfaceSamples);
}

#[test]
fn the_unknown_type_message_lists_every_kind() {
    let err = ShapeDocument::parse(&json!({"type": "nope"})).unwrap_err().to_string();
    let names: Vec<&str> = CurveDocument::examples()
        .iter()
        .map(CurveDocument::type_name)
        .chain(SurfaceDocument::examples().iter().map(SurfaceDocument::type_name))
        .collect();
    let listed = err.split_once('(').unwrap().1.trim_end_matches(')');
    let listed: Vec<&str> = listed.split("; ").flat_map(|part| part.split_once(": ").unwrap().1.split(", ")).collect();
    assert_eq!(listed, names, "{err}");
    let err = CurveDocument::parse(&json!({"type": "nope"})).unwrap_err().to_string();
    for name in CurveDocument::TYPES {
        assert!(err.contains(&format!(" {name},")) || err.ends_with(&format!(" {name})")), "{name} in {err}");
    }
}

fn shape_error(doc: Value) -> String {
    let shape = ShapeDocument::parse(&doc);
    match shape {
        Err(e) => e.to_string(),
        Ok(ShapeDocument::Curve(c)) => c.build().err().expect("an error").to_string(),
        Ok(ShapeDocument::Surface(s)) => s.build().err().expect("an error").to_string(),
    }
}

#[test]
fn errors_in_nested_documents_name_the_full_path() {
    let line = json!({"type": "line", "from": [0, 0], "to": [1, 0]});
    let cases = [
        (
            json!({"type": "blend", "first": line, "second": {"type": "bezier", "control_points": [[0, 0], [1, "a"]]}, "overlap": 0.5}),
            "second.control_points[1][1]: invalid type: string \"a\", expected f64",
        ),
        (json!({"type": "blend", "first": 3, "second": line, "overlap": 0.5}), "first: expected a JSON object"),
        (
            json!({"type": "trimmed", "surface": {"type": "plane"}, "holes": [{"type": "catmull_rom", "points": [[0, 0], [1, 0], [1, 1]], "closed": true}, {"type": "zzz"}]}),
            "holes[1].type: unknown curve type \"zzz\"",
        ),
        (
            json!({"type": "trimmed", "surface": {"type": "circle"}}),
            "surface.type: expected a surface type, got \"circle\"",
        ),
        (
            json!({"type": "revolution", "curve": {"type": "blend", "first": line, "second": {"type": "line", "from": [0], "to": ["x"]}, "overlap": 0.5}}),
            "curve.second.to[0]: invalid type: string \"x\", expected f64",
        ),
        (
            json!({"type": "blending_spline", "model": {"type": "circle"}, "local_curves": 4, "transforms": {"x": {}}}),
            "transforms.x: keys must be local-curve indices",
        ),
        (
            json!({"type": "blending_spline", "model": {"type": "circle"}, "local_curves": 4, "transforms": 3}),
            "transforms: expected a list or an object, got a number",
        ),
        (
            json!({"type": "blending_spline_surface", "model": {"type": "torus"}, "local_surfaces": [4, 4], "transforms": "all"}),
            "transforms: expected a list of rows or an object, got a string",
        ),
        (
            json!({"type": "blending_spline_surface", "model": {"type": "torus"}, "local_surfaces": [4, 4], "transforms": {"1": {}}}),
            "transforms.1: keys must be patch indices \"k,l\"",
        ),
        (
            json!({"type": "blending_spline", "model": {"type": "circle"}, "local_curves": 4, "transforms": [{}, {"scale": "big"}]}),
            "transforms[1].scale: invalid type: string \"big\", expected f64",
        ),
        (
            json!({"type": "blending_spline_surface", "model": {"type": "torus"}, "local_surfaces": [4, 4], "transforms": [[{}], [{}, {"turn": 1}]]}),
            "transforms[1][1].turn: unknown field `turn`",
        ),
        (
            json!({"type": "blending_spline", "model": {"type": "circle"}, "local_curves": 4, "animation": [{"local": "one", "motions": []}]}),
            "animation[0].local: invalid type: string \"one\"",
        ),
        (
            json!({"type": "blending_spline", "knots": [0, 1], "local_curves": [line, {"type": "bezier", "control_points": [[0, 0, 0]]}]}),
            "local_curves[1]: expected a curve of dimension 2 like local_curves[0], got 3",
        ),
        (
            json!({"type": "blending_spline", "model": {"type": "circle"}, "local_curves": [line]}),
            "local_curves: with a model, expected a count of local curves, got an array",
        ),
        (
            json!({"type": "blending_spline", "knots": [0, 1], "local_curves": 2.5}),
            "local_curves: with explicit knots, expected a list of curves, got a number",
        ),
        (
            json!({"type": "coons", "bottom": line, "top": line, "left": line, "right": line, "blend": "quintic"}),
            "blend: expected \"linear\" or \"cubic\", got \"quintic\"",
        ),
        (
            json!({"type": "blend", "first": line, "second": line, "overlap": 0.5, "bfunction": {"type": "x"}}),
            "bfunction.type: unknown B-function \"x\"",
        ),
    ];
    for (doc, expected) in cases {
        let err = shape_error(doc.clone());
        assert!(err.starts_with(expected), "{doc}\n  got:      {err}\n  expected: {expected}…");
    }
}

#[test]
fn the_example_shape_documents_survive_the_trip_through_json() {
    let dir = format!("{}/../../examples/shapes", env!("CARGO_MANIFEST_DIR"));
    for entry in std::fs::read_dir(dir).unwrap() {
        let path = entry.unwrap().path();
        let doc = ShapeDocument::from_json(&std::fs::read_to_string(&path).unwrap()).unwrap();
        let value = match &doc {
            ShapeDocument::Curve(c) => c.to_value(),
            ShapeDocument::Surface(s) => s.to_value(),
        };
        assert_eq!(ShapeDocument::parse(&value).unwrap(), doc, "{}", path.display());
    }
}

#[test]
fn posing_reaches_animations_nested_in_other_documents() {
    let animated = json!({"type": "blending_spline", "model": {"type": "circle"}, "local_curves": 4,
        "animation": [{"local": 1, "motions": [{"oscillate": {"direction": [0, 0, 1], "amplitude": 1}}]}]});
    let doc = json!({"type": "extrusion", "curve": {"type": "blend", "overlap": 0.5,
        "first": {"type": "line", "from": [0, 0, 0], "to": [1, 0, 0]}, "second": animated}, "direction": [0, 0, 1]});
    let ShapeDocument::Surface(rest) = ShapeDocument::parse(&doc).unwrap() else { panic!("a surface") };
    let mut posed = rest.clone();
    posed.set_time(0.25);
    let (a, b) = (rest.build().unwrap().visit(SurfaceSamples), posed.build().unwrap().visit(SurfaceSamples));
    assert!(a.iter().zip(&b).any(|(x, y)| (x - y).abs() > 0.1), "the pose moved nothing: {a:?} {b:?}");
}

#[test]
fn decorations_are_the_documents_own_points_and_pieces() {
    for doc in CurveDocument::examples() {
        match (&doc, doc.decoration()) {
            (CurveDocument::Bezier(d), Decoration::ControlPolygon { points, closed, .. }) => {
                assert!(points == d.control_points.as_slice() && !closed)
            }
            (CurveDocument::CatmullRom(d), Decoration::ControlPolygon { points, closed, .. }) => {
                assert!(points == d.points.as_slice() && closed == d.closed)
            }
            (CurveDocument::BlendingSpline(d), Decoration::LocalCurves(e)) => assert!(std::ptr::eq(d, e)),
            (CurveDocument::Circle(_) | CurveDocument::Blend(_), decoration) => {
                assert!(matches!(decoration, Decoration::None))
            }
            _ => {}
        }
    }
    for doc in SurfaceDocument::examples() {
        match (&doc, doc.decoration()) {
            (SurfaceDocument::NurbsSurface(d), Decoration::ControlNet(net)) => {
                assert!(net == d.control_points.as_slice())
            }
            (SurfaceDocument::BlendingSplineSurface(d), Decoration::LocalPatches(e)) => assert!(std::ptr::eq(d, e)),
            (SurfaceDocument::Torus(_) | SurfaceDocument::Trimmed(_), decoration) => {
                assert!(matches!(decoration, Decoration::None))
            }
            (doc, decoration) => assert!(
                !matches!(doc, SurfaceDocument::NurbsSurface(_) | SurfaceDocument::BlendingSplineSurface(_)),
                "{}: {decoration:?}",
                doc.type_name()
            ),
        }
    }
}
