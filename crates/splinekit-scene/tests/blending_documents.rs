//! Blending-spline documents: the example animations in `examples/shapes/` are the kernel's
//! presets, posed at any time; transforms, explicit locals and errors.

use splinekit::Point;
use splinekit::blend::presets;
use splinekit::curve::Curve;
use splinekit::surface::Surface;
use splinekit_scene::{CurveDocument, ShapeDocument, SurfaceDocument};

fn example(name: &str) -> ShapeDocument {
    let path = format!("{}/../../examples/shapes/{name}.json", env!("CARGO_MANIFEST_DIR"));
    ShapeDocument::from_json(&std::fs::read_to_string(path).unwrap()).unwrap()
}

#[test]
fn the_beating_heart_document_is_the_preset_at_every_time() {
    let (mut preset, tracks) = presets::beating_heart().unwrap();
    let rest = preset.transforms();
    for time in [0.0, 0.1, 0.25, 0.6, 1.37] {
        preset.animate(&rest, &tracks, time).unwrap();
        let mut doc = example("beating_heart");
        doc.set_time(time);
        let ShapeDocument::Curve(CurveDocument::BlendingSpline(d)) = doc else { panic!("a blending spline") };
        let built = d.curve::<3>().unwrap();
        for i in 0..=50 {
            let t = std::f64::consts::TAU * i as f64 / 50.0;
            assert!((built.point(t) - preset.point(t)).norm() < 1e-12, "time {time}, t = {t}");
        }
    }
    // At a quarter beat the right side has moved out along x and the tip down.
    preset.animate(&rest, &tracks, 0.25).unwrap();
    assert!((preset.point(std::f64::consts::PI) - Point::<3>::new(0.0, -18.5, 0.0)).norm() < 1e-12);
}

#[test]
fn the_animated_surface_documents_are_the_presets() {
    type Preset = fn() -> splinekit::Result<(
        splinekit::blend::BlendingSplineSurface<3>,
        Vec<splinekit::blend::Track<(usize, usize)>>,
    )>;
    let cases: [(&str, Preset); 3] = [
        ("animated_plane", presets::animated_plane),
        ("animated_cylinder", presets::animated_cylinder),
        ("animated_torus", presets::animated_torus),
    ];
    for (name, preset) in cases {
        let (mut s, tracks) = preset().unwrap();
        let rest = s.transforms();
        for time in [0.0, 0.2, 0.25, 0.9] {
            s.animate(&rest, &tracks, time).unwrap();
            let mut doc = example(name);
            doc.set_time(time);
            let ShapeDocument::Surface(SurfaceDocument::BlendingSplineSurface(d)) = doc else { panic!("{name}") };
            let built = d.surface::<3>().unwrap();
            let (du, dv) = (s.domain_u(), s.domain_v());
            for i in 0..=12 {
                for j in 0..=12 {
                    let (u, v) = (du.lerp(i as f64 / 12.0), dv.lerp(j as f64 / 12.0));
                    assert!((built.point(u, v) - s.point(u, v)).norm() < 1e-12, "{name} at time {time}");
                }
            }
        }
    }
}

#[test]
fn surface_transforms_by_rows_or_by_pair_and_explicit_locals() {
    let by_pair = ShapeDocument::from_json(
        r#"{"type":"blending_spline_surface","model":{"type":"torus"},"local_surfaces":[4,4],
            "transforms":{"1,2":{"translate":[0,0,1]}}}"#,
    )
    .unwrap();
    let empty = "{}";
    let rows: Vec<String> = (0..4)
        .map(|k| {
            let cells: Vec<&str> =
                (0..4).map(|l| if (k, l) == (1, 2) { r#"{"translate":[0,0,1]}"# } else { empty }).collect();
            format!("[{}]", cells.join(","))
        })
        .collect();
    let by_rows = ShapeDocument::from_json(&format!(
        r#"{{"type":"blending_spline_surface","model":{{"type":"torus"}},"local_surfaces":[4,4],"transforms":[{}]}}"#,
        rows.join(",")
    ))
    .unwrap();
    let (ShapeDocument::Surface(a), ShapeDocument::Surface(b)) = (by_pair, by_rows) else { panic!() };
    let (a, b) = (a.build_in::<3>().unwrap(), b.build_in::<3>().unwrap());
    for (u, v) in [(1.6, 3.1), (0.2, 0.3), (4.0, 5.0)] {
        assert_eq!(a.point(u, v), b.point(u, v));
    }

    let explicit = ShapeDocument::from_json(
        r#"{"type":"blending_spline","knots":[0,1,2],"local_curves":[
              {"type":"line","from":[-1,0],"to":[1,0]},
              {"type":"bezier","control_points":[[0,0],[1,2],[2,0]]},
              {"type":"line","from":[1,0],"to":[3,0]}]}"#,
    )
    .unwrap();
    let ShapeDocument::Curve(c) = explicit else { panic!() };
    let c = c.build_in::<2>().unwrap();
    assert!((c.point(1.0) - Point::<2>::new(1.0, 1.0)).norm() < 1e-15);

    for (doc, field) in [
        (r#"{"type":"blending_spline","knots":[0,1],"local_curves":3}"#, "local_curves"),
        (r#"{"type":"blending_spline","local_curves":3}"#, "model"),
        (r#"{"type":"blending_spline","model":{"type":"heart"},"local_curves":[]}"#, "local_curves"),
        (r#"{"type":"blending_spline_surface","model":{"type":"torus"},"local_surfaces":[4]}"#, "local_surfaces"),
        (
            r#"{"type":"blending_spline_surface","model":{"type":"torus"},"local_surfaces":[4,4],"transforms":{"a":{}}}"#,
            "transforms.a",
        ),
        (
            r#"{"type":"blending_spline_surface","model":{"type":"torus"},"local_surfaces":[4,4],"local":{"type":"bezier","degree":[3]}}"#,
            "local",
        ),
    ] {
        let err = ShapeDocument::from_json(doc).and_then(|d| match d {
            ShapeDocument::Curve(c) => c.build().map(|_| ()),
            ShapeDocument::Surface(s) => s.build().map(|_| ()),
        });
        let msg = err.err().unwrap_or_else(|| panic!("{doc} was accepted")).to_string();
        assert!(msg.starts_with(field), "{doc}: {msg}");
    }
}

#[test]
fn a_rotation_pivot_is_a_world_point_on_the_axis() {
    // Rotating local 0 of a circle (origin (1, 0, 0)) by π about the z axis through the
    // world origin sends its interpolation point to (−1, 0, 0): the curve passes there at t = 0.
    let doc = |pivot: &str| {
        ShapeDocument::from_json(&format!(
            r#"{{"type":"blending_spline","model":{{"type":"circle"}},"local_curves":8,
                "transforms":{{"0":{{"rotate":{{"axis":[0,0,1],"angle":3.141592653589793{pivot}}}}}}}}}"#
        ))
        .unwrap()
    };
    let ShapeDocument::Curve(c) = doc(r#","pivot":[0,0,0]"#) else { panic!() };
    let p = c.build_in::<3>().unwrap().point(0.0);
    assert!((p - Point::<3>::new(-1.0, 0.0, 0.0)).norm() < 1e-12, "{p}");
    // Without a pivot the local turns about its own origin, which stays put.
    let ShapeDocument::Curve(c) = doc("") else { panic!() };
    let p = c.build_in::<3>().unwrap().point(0.0);
    assert!((p - Point::<3>::new(1.0, 0.0, 0.0)).norm() < 1e-12, "{p}");
}

#[test]
fn local_indices_read_alike_in_transforms_and_local_control_points() {
    // Both fields read a local's key with one parser: blanks around the index are allowed
    // in each (transforms refused " 3" before, while local_control_points took it).
    let read = |transform: &str, points: &str| {
        ShapeDocument::from_json(&format!(
            r#"{{"type": "blending_spline", "model": {{"type": "heart"}}, "local_curves": 10,
                "transforms": {{"{transform}": {{"scale": 1.5}}}},
                "local_control_points": {{"{points}": [[0, 0, 0], [1, 0, 0], [2, 1, 0], [3, 0, 0]]}}}}"#
        ))
    };
    let plain = read("3", "3").unwrap();
    for key in [" 3", "3 ", " 3 "] {
        assert_eq!(read(key, key).unwrap(), plain, "{key:?}");
    }
    for key in ["x", "3,1", "-3"] {
        let e = read(key, "3").unwrap_err().to_string();
        assert_eq!(e, format!("transforms.{key}: keys must be local-curve indices"));
        let e = read("3", key).unwrap_err().to_string();
        assert_eq!(e, format!("local_control_points.{key}: keys must be local-curve indices (\"3\")"));
    }
}
