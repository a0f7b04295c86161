//! The command line as users and scripts see it (CONTRACT.md §2–3).

use serde_json::{Value, json};

mod common;
use common::{ScratchDir, run};

fn ok_json(args: &[&str], stdin: &str) -> Value {
    let o = run(args, stdin);
    assert_eq!(o.code, 0, "{args:?} failed: {}", o.stderr);
    serde_json::from_str(&o.stdout).unwrap()
}

fn floats(v: &Value) -> Vec<f64> {
    v.as_array().unwrap().iter().map(|x| x.as_f64().unwrap()).collect()
}

fn assert_bad(args: &[&str], stdin: &str, must_contain: &str) {
    let o = run(args, stdin);
    assert_eq!(o.code, 2, "{args:?} with {stdin:?}: exit {} (stderr {:?})", o.code, o.stderr);
    assert!(o.stdout.is_empty(), "{args:?}: printed {:?}", o.stdout);
    assert_eq!(o.stderr.lines().count(), 1, "{args:?}: stderr {:?}", o.stderr);
    assert!(o.stderr.starts_with("error: "), "{:?}", o.stderr);
    assert!(!o.stderr.contains("panicked"), "{:?}", o.stderr);
    assert!(o.stderr.contains(must_contain), "{args:?} with {stdin:?}: {:?} lacks {must_contain:?}", o.stderr);
}

/// Writes `text` to the file `name` in `dir`, returning its path.
fn write_in(dir: &std::path::Path, name: &str, text: &str) -> String {
    let p = dir.join(name);
    std::fs::write(&p, text).unwrap();
    p.to_str().unwrap().to_string()
}

/// [`assert_bad`] for each (input, expected text) of a table, all with the same arguments.
fn assert_all_bad(args: &[&str], cases: &[(&str, &str)]) {
    for (stdin, must_contain) in cases {
        assert_bad(args, stdin, must_contain);
    }
}

/// [`assert_bad`] for each (arguments, input, expected text) of a table.
fn assert_each_bad(cases: &[(&[&str], &str, &str)]) {
    for (args, stdin, must_contain) in cases {
        assert_bad(args, stdin, must_contain);
    }
}

#[test]
fn eval_prints_params_points_and_derivatives() {
    let doc = r#"{"type":"bezier","control_points":[[0,0],[1,2],[2,0]]}"#;
    let v = ok_json(&["eval", "-", "--at", "0,0.5,1", "--derivatives", "2"], doc);
    assert_eq!(v["params"], json!([0.0, 0.5, 1.0]));
    assert_eq!(v["points"], json!([[0.0, 0.0], [1.0, 1.0], [2.0, 0.0]]));
    assert_eq!(v["derivatives"][1], json!([[2.0, 0.0], [0.0, -8.0]]));
    let v = ok_json(&["eval", "-", "--samples", "5"], doc);
    assert_eq!(floats(&v["params"]), vec![0.0, 0.25, 0.5, 0.75, 1.0]);
    assert_eq!(v["derivatives"], json!([[], [], [], [], []]));
}

#[test]
fn eval_bspline_matches_the_seed_example() {
    // The seed's cubic B-spline with 8 control points and knots 0,0,0,0,1,2,3,4,5,5,5,5.
    let doc = json!({"type":"bspline","degree":3,"knots":[0,0,0,0,1,2,3,4,5,5,5,5],
        "control_points":[[0,0],[1,2],[2,-1],[3,1],[4,0],[5,2],[6,-1],[7,0]]});
    let v = ok_json(&["eval", "-", "--at", "0,2.5,5", "--derivatives", "1"], &doc.to_string());
    assert_eq!(v["points"][0], json!([0.0, 0.0]));
    assert_eq!(v["points"][2], json!([7.0, 0.0]));
    // At t = 2.5 (middle of the uniform span [2,3]): (P2 + 23 P3 + 23 P4 + P5)/48.
    let p = floats(&v["points"][1]);
    let x = (2.0 + 23.0 * 3.0 + 23.0 * 4.0 + 5.0) / 48.0;
    let y = (-1.0 + 23.0 * 1.0 + 23.0 * 0.0 + 2.0) / 48.0;
    assert!((p[0] - x).abs() < 1e-15 && (p[1] - y).abs() < 1e-15, "{p:?}");
}

#[test]
fn model_curves_follow_the_contract_formulas() {
    let v = ok_json(&["eval", "-", "--at", "1.0"], r#"{"type":"heart"}"#);
    let p = floats(&v["points"][0]);
    let t: f64 = 1.0;
    assert!((p[0] - 16.0 * t.sin().powi(3)).abs() < 1e-13);
    assert!((p[1] - (13.0 * t.cos() - 5.0 * (2.0 * t).cos() - 2.0 * (3.0 * t).cos() - (4.0 * t).cos())).abs() < 1e-13);
    let v = ok_json(&["eval", "-", "--at", "0.3"], r#"{"type":"rose","radius":2,"n":3}"#);
    let p = floats(&v["points"][0]);
    assert!((p[2] - 2.0 * (0.9f64).sin()).abs() < 1e-15);
    // Closed curves wrap parameters around.
    let v = ok_json(&["eval", "-", "--at", "-1.0"], r#"{"type":"circle","radius":2}"#);
    let p = floats(&v["points"][0]);
    assert!((p[0] - 2.0 * (1.0f64).cos()).abs() < 1e-14 && (p[1] + 2.0 * (1.0f64).sin()).abs() < 1e-14);
}

#[test]
fn fit_with_uniform_params_and_knots_then_eval_round_trip() {
    let csv: String = (0..50)
        .map(|i| {
            let t = i as f64 / 49.0;
            format!("{},{}\n", (std::f64::consts::TAU * t).cos(), (std::f64::consts::TAU * t).sin())
        })
        .collect();
    let doc = ok_json(
        &["fit", "-", "--degree", "3", "--control-points", "10", "--params", "uniform", "--knots", "uniform"],
        &csv,
    );
    assert_eq!(doc["type"], "bspline");
    let knots = floats(&doc["knots"]);
    assert_eq!(knots.len(), 14);
    for (i, k) in knots[3..11].iter().enumerate() {
        assert!((k - i as f64 / 7.0).abs() < 1e-15);
    }
    let v = ok_json(&["eval", "-", "--samples", "50"], &doc.to_string());
    for p in v["points"].as_array().unwrap() {
        let p = floats(p);
        assert!((p[0].hypot(p[1]) - 1.0).abs() < 2e-3);
    }
    // JSON input and closed fits.
    let json_pts: Value = (0..40)
        .map(|i| {
            let a = i as f64 * std::f64::consts::TAU / 40.0;
            json!([a.cos(), a.sin(), 0.5])
        })
        .collect::<Vec<_>>()
        .into();
    let doc = ok_json(&["fit", "-", "--degree", "3", "--control-points", "12", "--closed"], &json_pts.to_string());
    assert_eq!(doc["periodic"], json!(true));
    let v = ok_json(&["eval", "-", "--at", "0,1", "--derivatives", "2"], &doc.to_string());
    assert_eq!(v["points"][0], v["points"][1]);
}

#[test]
fn fit_a_model_curve_by_sampling_it() {
    let doc = ok_json(
        &["fit", "-", "--degree", "3", "--control-points", "16", "--closed", "--samples", "300"],
        r#"{"type":"circle","radius":2}"#,
    );
    assert_eq!(doc["periodic"], json!(true));
    let v = ok_json(&["eval", "-", "--samples", "101"], &doc.to_string());
    for p in v["points"].as_array().unwrap() {
        let p = floats(p);
        assert!((p[0].hypot(p[1]) - 2.0).abs() < 1e-4, "{p:?}");
    }
    assert_bad(
        &["fit", "-", "--degree", "3", "--control-points", "16", "--samples", "1"],
        r#"{"type":"circle"}"#,
        "--samples",
    );
}

#[test]
fn interpolate_refine_and_subdivide() {
    let pts = "0 0\n1 2\n2 -1\n3 1\n4 0\n";
    let doc = ok_json(&["interpolate", "-", "--degree", "3", "--params", "uniform"], pts);
    let v = ok_json(&["eval", "-", "--at", "0,0.25,0.5,0.75,1"], &doc.to_string());
    let expected = [[0.0, 0.0], [1.0, 2.0], [2.0, -1.0], [3.0, 1.0], [4.0, 0.0]];
    for (p, e) in v["points"].as_array().unwrap().iter().zip(expected) {
        let p = floats(p);
        assert!((p[0] - e[0]).abs() < 1e-12 && (p[1] - e[1]).abs() < 1e-12);
    }
    let before = ok_json(&["eval", "-", "--samples", "33"], &doc.to_string());
    for args in [vec!["refine", "-", "--insert", "0.1,0.6,0.6"], vec!["refine", "-", "--elevate", "2"]] {
        let refined = ok_json(&args, &doc.to_string());
        let after = ok_json(&["eval", "-", "--samples", "33"], &refined.to_string());
        for (a, b) in before["points"].as_array().unwrap().iter().zip(after["points"].as_array().unwrap()) {
            let (a, b) = (floats(a), floats(b));
            assert!((a[0] - b[0]).abs() < 1e-12 && (a[1] - b[1]).abs() < 1e-12, "{args:?}");
        }
    }
    let inserted = ok_json(&["refine", "-", "--insert", "0.3"], &doc.to_string());
    let removed = ok_json(&["refine", "-", "--remove", "0.3"], &inserted.to_string());
    assert_eq!(floats(&removed["knots"]), floats(&doc["knots"]));
    let square = "[[0,0],[1,0],[1,1],[0,1]]";
    let s = ok_json(
        &["subdivide", "-", "--scheme", "lane_riesenfeld", "--degree", "3", "--steps", "3", "--closed"],
        square,
    );
    assert_eq!(s.as_array().unwrap().len(), 32);
    let s = ok_json(&["subdivide", "-", "--scheme", "chaikin", "--steps", "1"], square);
    assert_eq!(s, json!([[0.25, 0.0], [0.75, 0.0], [1.0, 0.25], [1.0, 0.75], [0.75, 1.0], [0.25, 1.0]]));
    let s = ok_json(&["subdivide", "-", "--scheme", "four_point", "--steps", "2", "--closed"], square);
    assert_eq!(s.as_array().unwrap().len(), 16);
}

#[test]
fn output_to_a_file() {
    let dir = ScratchDir::new("cli-test");
    let path = dir.join("out.json");
    let o =
        run(&["eval", "-", "--at", "0.5", "-o", path.to_str().unwrap()], r#"{"type":"line","from":[0,0],"to":[2,4]}"#);
    assert_eq!(o.code, 0);
    assert!(o.stdout.is_empty());
    let v: Value = serde_json::from_str(&std::fs::read_to_string(&path).unwrap()).unwrap();
    assert_eq!(v["points"], json!([[1.0, 2.0]]));
}

#[test]
fn bad_input_gives_exit_2_and_one_line_naming_the_field() {
    let eval = ["eval", "-", "--at", "0.5"];
    let cases: &[(&str, &str)] = &[
        (
            r#"{"type":"bspline","degree":3,"knots":[0,0,0,0,1,2,3,4,5,5,5],"control_points":[[0,0],[1,0],[2,0],[3,0],[4,0],[5,0],[6,0],[7,0]]}"#,
            "knots: expected 12 values for 8 control points of degree 3, got 11",
        ),
        (r#"{"type":"nope"}"#, "type: unknown shape type \"nope\""),
        ("{", "invalid JSON"),
        ("", "invalid JSON"),
        (r#"{"control_points":[[0,0]]}"#, "type: missing"),
        (r#"{"type":"bezier","control_points":[[0,0],[1,"a"]]}"#, "control_points[1][1]"),
        (r#"{"type":"bezier","control_points":[[0,0],[1,1,1]]}"#, "control_points[1]: expected 2 coordinates"),
        (r#"{"type":"bezier","control_points":[]}"#, "control_points: expected at least 1 point"),
        (r#"{"type":"bezier","control_points":[[0,0]],"colour":1}"#, "unknown field `colour`"),
        (r#"{"type":"bspline","degree":100000,"knots":[0,1],"control_points":[[0,0]]}"#, "degree 100000"),
        (r#"{"type":"bspline","degree":-1,"knots":[0,1],"control_points":[[0,0]]}"#, "degree"),
        (r#"{"type":"bspline","degree":1,"knots":[0,1,0.5,2],"control_points":[[0,0],[1,1]]}"#, "non-decreasing"),
        (r#"{"type":"bspline","degree":1,"knots":[0,1,1,2],"control_points":[[0,0],[1,1]]}"#, "domain"),
        (
            r#"{"type":"nurbs","degree":1,"knots":[0,0,1,1],"control_points":[[0,0],[1,1]],"weights":[1,-2]}"#,
            "weights: weight 1 is -2",
        ),
        (
            r#"{"type":"nurbs","degree":1,"knots":[0,0,1,1],"control_points":[[0,0],[1,1]],"weights":[1]}"#,
            "weights: expected 2 values",
        ),
        (r#"{"type":"circle","radius":0}"#, "radius"),
        (r#"{"type":"hermite","points":[[0,0],[1,1]],"tangents":[[1,0]]}"#, "tangents"),
        (r#"{"type":"catmull_rom","points":[[0,0],[1,1]],"alpha":2}"#, "alpha"),
        (r#"{"type":"bezier","control_points":[[0,0],[1,1e400]]}"#, "out of range"),
        (r#"{"type":"bezier","control_points":[[0,0],[1,NaN]]}"#, "invalid JSON"),
        (r#"{"type":"bezier","control_points":[[1,2,3,4,5],[1,2,3,4,5]]}"#, "dimension 5"),
        ("[[0,0]]", "expected a JSON object"),
    ];
    assert_all_bad(&eval, cases);
    let circle = r#"{"type":"circle"}"#;
    assert_each_bad(&[
        (&["eval", "-", "--samples", "1000000000"], circle, "--samples: 1000000000 is more than the limit"),
        (&["eval", "-", "--at", "abc"], circle, "--at: 'abc' is not a number"),
        (&["eval", "-", "--at", "nan"], circle, "--at"),
        (&["eval", "-", "--at", "2"], r#"{"type":"line","from":[0],"to":[1]}"#, "outside the domain"),
        (&["eval", "-", "--samples", "3", "--derivatives", "100000"], circle, "--derivatives"),
        (&["eval", "-", "--samples", "-3"], circle, "--samples"),
        (&["eval", "missing.json", "--at", "0"], circle, "cannot read 'missing.json'"),
        (&["eval", "-"], circle, "--at"),
        (&["frobnicate"], "", "frobnicate"),
        (
            &["fit", "-", "--degree", "3", "--control-points", "10"],
            "0,0\n1,1\n2,0\n",
            "--control-points: 10 control points need at least 10 data points, got 3",
        ),
        (&["fit", "-", "--degree", "100000", "--control-points", "10"], "0,0\n1,1\n", "--degree"),
        (&["fit", "-", "--degree", "3", "--control-points", "4"], "0,0\n1,x\n", "line 2: 'x' is not a number"),
        (&["fit", "-", "--degree", "3", "--control-points", "4"], "[[0,0],[1]]", "points[1]: expected 2 coordinates"),
        (&["fit", "-", "--degree", "3", "--control-points", "4"], "", "no points"),
        (&["fit", "-", "--degree", "2", "--control-points", "3"], "0,0\n0,0\n0,0\n1,1\n", "coincide"),
        (&["interpolate", "-", "--degree", "3"], "0,0\n1,1\n", "at least 4 points"),
        (&["refine", "-", "--insert", "0.5"], circle, "refine works on"),
        (
            &["refine", "-", "--insert", "7"],
            r#"{"type":"bezier","control_points":[[0,0],[1,1],[2,0]]}"#,
            "outside the domain",
        ),
        (&["refine", "-"], r#"{"type":"bezier","control_points":[[0,0],[1,1]]}"#, "--insert"),
        (
            &["subdivide", "-", "--scheme", "lane_riesenfeld", "--steps", "60", "--closed"],
            "[[0,0],[1,0],[1,1]]",
            "--steps",
        ),
        (
            &["subdivide", "-", "--scheme", "chaikin", "--degree", "3", "--steps", "1"],
            "[[0,0],[1,0],[1,1]]",
            "--degree",
        ),
    ]);
}

#[test]
fn every_example_in_docs_format_md_is_a_valid_document() {
    let text = include_str!("../../../docs/format.md");
    let mut count = 0;
    for block in text.split("```json\n").skip(1) {
        let doc = block.split("```").next().unwrap();
        if doc.trim_start().starts_with("{\"params\"") {
            continue;
        }
        // A subdivision limit's grid meets extraordinary vertices, where it has no partials.
        let v = if doc.contains("\"subdivision_surface\"") {
            ok_json(&["eval", "-", "--grid", "5,1"], doc)
        } else {
            // Evaluated as a curve; a surface (whatever its kind) says so and is evaluated
            // on a grid.
            let o = run(&["eval", "-", "--samples", "5", "--derivatives", "1"], doc);
            if o.code == 2 && o.stderr.contains("surfaces take") {
                ok_json(&["eval", "-", "--grid", "5,1", "--derivatives", "1"], doc)
            } else {
                assert_eq!(o.code, 0, "{doc}: {}", o.stderr);
                serde_json::from_str(&o.stdout).unwrap()
            }
        };
        assert_eq!(v["points"].as_array().unwrap().len(), 5, "{doc}");
        count += 1;
    }
    assert!(count >= 19, "only {count} examples found");
}

#[test]
fn tessellate_writes_svg_and_obj_polylines() {
    let dir = ScratchDir::new("tessellate");
    let svg = dir.join("heart.svg");
    let o = run(&["tessellate", "-", "-o", svg.to_str().unwrap(), "--tolerance", "0.01"], r#"{"type":"heart"}"#);
    assert_eq!(o.code, 0, "{}", o.stderr);
    let text = std::fs::read_to_string(&svg).unwrap();
    assert!(text.starts_with("<svg") && text.contains("<path d=\"M"));
    let obj = dir.join("line.obj");
    let o = run(
        &["tessellate", "-", "-o", obj.to_str().unwrap(), "--density", "4"],
        r#"{"type":"line","from":[0,0,0],"to":[4,0,0]}"#,
    );
    assert_eq!(o.code, 0, "{}", o.stderr);
    let text = std::fs::read_to_string(&obj).unwrap();
    assert_eq!(text.lines().filter(|l| l.starts_with("v ")).count(), 5);
    assert!(text.contains("v 1 0 0") && text.contains("l 1 2 3 4 5"), "{text}");
    assert_bad(&["tessellate", "-", "-o", "x.stl"], r#"{"type":"heart"}"#, "-o");
    assert_bad(
        &["tessellate", "-", "-o", dir.join("a.svg").to_str().unwrap(), "--tolerance", "-1"],
        r#"{"type":"heart"}"#,
        "tolerance",
    );
}

#[test]
fn gallery_writes_every_figure_and_an_index() {
    let dir = ScratchDir::new("gallery");
    let o = run(&["gallery", "-o", dir.to_str().unwrap()], "");
    assert_eq!(o.code, 0, "{}", o.stderr);
    let index = std::fs::read_to_string(dir.join("index.html")).unwrap();
    let pictures: Vec<&str> = index.split("<img src=\"").skip(1).map(|s| s.split('"').next().unwrap()).collect();
    // The catalogue: one picture of every model kind's example, named after its type, and
    // the sheet of all of them.
    let (catalogue, figures): (Vec<&str>, Vec<&str>) = pictures.iter().partition(|f| f.starts_with("catalogue/"));
    let models: Vec<&str> = splinekit_scene::SurfaceDocument::examples()
        .iter()
        .filter(|d| d.blending_model())
        .map(|d| d.type_name())
        .chain(splinekit_scene::CurveDocument::examples().iter().filter(|d| d.blending_model()).map(|d| d.type_name()))
        .collect();
    assert_eq!(catalogue, models.iter().map(|m| format!("catalogue/{m}.png")).collect::<Vec<_>>());
    assert!(models.len() >= 39 && models.contains(&"boy_surface") && models.contains(&"chrysanthemum"));
    for f in &catalogue {
        let img = splinekit_render::Image::from_png(&std::fs::read(dir.join(f)).unwrap()).unwrap();
        assert!(img.coverage() > 0.002 && img.coverage() < 0.95, "{f}: {} of the picture is drawn", img.coverage());
    }
    let sheet = splinekit_render::Image::from_png(&std::fs::read(dir.join("catalogue/all.png")).unwrap()).unwrap();
    assert_eq!((sheet.width, sheet.height), (6 * 240, models.len().div_ceil(6) as u32 * 180));
    assert!(figures.len() >= 40, "{figures:?}");
    let (mut png, mut gif) = (0, 0);
    for f in &figures {
        let bytes = std::fs::read(dir.join(f)).unwrap();
        if f.ends_with(".svg") {
            assert!(String::from_utf8(bytes).unwrap().contains("<path d=\"M"), "{f} draws nothing");
        } else if f.ends_with(".png") {
            let img = splinekit_render::Image::from_png(&bytes).unwrap();
            let cov = img.coverage();
            assert!(cov > 0.005 && cov < 0.95, "{f}: {cov} of the picture is drawn");
            png += 1;
        } else {
            assert!(bytes.starts_with(b"GIF89a") && bytes.len() > 10_000, "{f}");
            gif += 1;
        }
    }
    assert!(png >= 18 && gif >= 4, "{png} PNG, {gif} GIF");
    let links: Vec<&str> = index
        .split("<a href=\"")
        .skip(1)
        .map(|s| s.split('"').next().unwrap())
        .filter(|l| *l != "catalogue/all.png")
        .collect();
    let (gltf, others): (Vec<&str>, Vec<&str>) = links.iter().partition(|l| l.ends_with(".glb"));
    let (step, pictures): (Vec<&str>, Vec<&str>) = others.iter().partition(|l| l.ends_with(".step"));
    assert_eq!(gltf.len(), png + gif);
    // Every glb shows in a 3-D view (tools/browser/gallery_test.mjs tests it in Chromium):
    // a figure with its model script, models/NAME.js, carrying the glb in base64, and a
    // link to the picture, which is the view's poster.
    assert_eq!(index.matches("<figure data-view=\"").count(), gltf.len());
    assert_eq!(pictures.len(), gltf.len(), "{pictures:?}");
    for l in gltf {
        let glb = std::fs::read(dir.join(l)).unwrap();
        assert!(glb.starts_with(b"glTF"), "{l}");
        let stem = l.strip_suffix(".glb").unwrap();
        assert!(index.contains(&format!("&quot;src&quot;:&quot;models/{stem}.js&quot;")), "{stem}");
        let model = std::fs::read_to_string(dir.join(format!("models/{stem}.js"))).unwrap();
        let base64 = model.strip_prefix(&format!("splinekitGallery.addModel(\"{stem}\", \"")).unwrap();
        let base64 = base64.strip_suffix("\");\n").unwrap();
        assert_eq!(base64.len(), glb.len().div_ceil(3) * 4, "{stem}");
        assert!(base64.bytes().all(|b| b.is_ascii_alphanumeric() || b"+/=".contains(&b)), "{stem}");
    }
    for script in ["vendor/three-gltf-orbit.min.js", "viewer.js"] {
        assert!(index.contains(&format!("<script src=\"{script}\"></script>")), "{script}");
        assert!(std::fs::metadata(dir.join(script)).unwrap().len() > 5000, "{script}");
    }
    assert!(std::fs::read_to_string(dir.join("vendor/three-LICENSE")).unwrap().contains("MIT License"));
    // The exact figures (B-spline polygon, Bézier surface, NURBS torus, …) offer STEP files.
    assert!(step.len() >= 3, "{step:?}");
    for l in step {
        assert!(l.ends_with(".step") && std::fs::read(dir.join(l)).unwrap().starts_with(b"ISO-10303-21;"), "{l}");
    }
}

#[test]
fn tessellate_writes_surface_meshes_and_render_and_animate_write_pictures() {
    let dir = ScratchDir::new("meshes");
    let torus = r#"{"type":"torus"}"#;
    for ext in ["obj", "stl", "stla", "ply", "gltf", "glb"] {
        let out = dir.join(format!("torus.{ext}"));
        let o = run(&["tessellate", "-", "-o", out.to_str().unwrap(), "--density", "8"], torus);
        assert_eq!(o.code, 0, "{ext}: {}", o.stderr);
        let bytes = std::fs::read(&out).unwrap();
        let head = String::from_utf8_lossy(&bytes[..bytes.len().min(80)]).to_string();
        match ext {
            "obj" => assert_eq!(String::from_utf8(bytes).unwrap().lines().filter(|l| l.starts_with("f ")).count(), 128),
            "stl" => assert_eq!(bytes.len(), 84 + 50 * 128),
            "stla" => assert!(head.starts_with("solid torus")),
            "ply" => assert!(head.contains("element vertex 81")),
            "gltf" => assert!(head.starts_with("{\"asset\"")),
            _ => assert!(bytes.starts_with(b"glTF")),
        }
    }
    // A scene with an animation: one node per object, the frames as morph targets.
    let scene =
        std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/../../examples/scenes/beating_heart.json"))
            .unwrap();
    let glb = dir.join("heart.glb");
    let o = run(&["tessellate", "-", "-o", glb.to_str().unwrap()], &scene);
    assert_eq!(o.code, 0, "{}", o.stderr);
    let bytes = std::fs::read(&glb).unwrap();
    let json_len = u32::from_le_bytes([bytes[12], bytes[13], bytes[14], bytes[15]]) as usize;
    let doc: serde_json::Value = serde_json::from_slice(&bytes[20..20 + json_len]).unwrap();
    assert_eq!(doc["nodes"].as_array().unwrap().len(), 2);
    assert_eq!(doc["animations"].as_array().unwrap().len(), 2, "both curves keep their vertex count");
    assert_eq!(doc["meshes"][1]["primitives"][0]["targets"].as_array().unwrap().len(), 20);
    assert_bad(&["tessellate", "-", "-o", dir.join("h.stl").to_str().unwrap()], &scene, "objects[0]: a curve (heart)");
    let adaptive = dir.join("adaptive.obj");
    let o = run(&["tessellate", "-", "-o", adaptive.to_str().unwrap(), "--tolerance", "0.01"], torus);
    assert_eq!(o.code, 0, "{}", o.stderr);
    assert_bad(&["tessellate", "-", "-o", dir.join("t.svg").to_str().unwrap()], torus, "-o");
    assert_bad(&["tessellate", "-", "-o", dir.join("t.obj").to_str().unwrap(), "--density", "0"], torus, "--density");

    let png = dir.join("torus.png");
    let o = run(&["render", "-", "-o", png.to_str().unwrap(), "--size", "160x120"], torus);
    assert_eq!(o.code, 0, "{}", o.stderr);
    let img = splinekit_render::Image::from_png(&std::fs::read(&png).unwrap()).unwrap();
    assert_eq!((img.width, img.height), (160, 120));
    assert!(img.coverage() > 0.2);
    assert_each_bad(&[
        (&["render", "-", "-o", png.to_str().unwrap(), "--size", "0x5"], torus, "--size"),
        (&["render", "-", "-o", dir.join("x.jpg").to_str().unwrap()], torus, "-o"),
        (&["render", "-", "-o", png.to_str().unwrap()], r#"{"type":"scene","objects":[]}"#, "objects"),
        (
            &["render", "-", "-o", png.to_str().unwrap()],
            r#"{"type":"scene","objects":[{"shape":{"type":"torus"},"colour":[1,0,0]}]}"#,
            "colour",
        ),
    ]);

    let heart =
        std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/../../examples/shapes/beating_heart.json"))
            .unwrap();
    let gif = dir.join("heart.gif");
    let o =
        run(&["animate", "-", "-o", gif.to_str().unwrap(), "--frames", "4", "--fps", "8", "--size", "96x96"], &heart);
    assert_eq!(o.code, 0, "{}", o.stderr);
    let bytes = std::fs::read(&gif).unwrap();
    assert!(bytes.starts_with(b"GIF89a"));
    // Four image descriptors (0x2C after a graphic control extension block).
    assert_eq!(bytes.windows(2).filter(|w| w == &[0x00, 0x2C]).count(), 4);
    assert_bad(&["animate", "-", "-o", gif.to_str().unwrap(), "--fps", "0"], &heart, "--fps");
}

/// The triangles of a binary STL file, their corners as the bits of their f32 coordinates.
fn stl_triangles(bytes: &[u8]) -> Vec<[[u32; 3]; 3]> {
    let count = u32::from_le_bytes(bytes[80..84].try_into().unwrap()) as usize;
    assert_eq!(bytes.len(), 84 + 50 * count);
    let word = |at: usize| u32::from_le_bytes(bytes[at..at + 4].try_into().unwrap());
    (0..count)
        .map(|t| std::array::from_fn(|c| std::array::from_fn(|k| word(84 + 50 * t + 12 * (c + 1) + 4 * k))))
        .collect()
}

/// Edges of a triangle soup used other than once in each direction (an edge on the
/// boundary, a fold, a flipped triangle): none for a closed, consistently oriented mesh.
fn unpaired_edges(triangles: &[[[u32; 3]; 3]]) -> usize {
    let mut directed = std::collections::HashMap::new();
    for t in triangles {
        for k in 0..3 {
            *directed.entry((t[k], t[(k + 1) % 3])).or_insert(0) += 1;
        }
    }
    directed.iter().filter(|&(&(a, b), &n)| n != 1 || directed.get(&(b, a)) != Some(&1)).count()
}

#[test]
fn tessellate_writes_scenes_in_every_mesh_format() {
    let dir = ScratchDir::new("scene-meshes");
    let example = |name: &str| -> Value {
        let path = format!("{}/../../examples/scenes/{name}.json", env!("CARGO_MANIFEST_DIR"));
        serde_json::from_str(&std::fs::read_to_string(path).unwrap()).unwrap()
    };
    // The wireframed blending torus of the examples, a sphere inside its hole, the heart
    // curve of another example and a hidden surface.
    let mut objects = example("torus_before")["objects"].as_array().unwrap().clone();
    objects.push(json!({"shape": {"type": "sphere", "radius": 0.5}, "density": 24}));
    let surfaces = json!({"type": "scene", "objects": objects.clone()}).to_string();
    objects.push(example("heart_transformed")["objects"][0].clone());
    objects.push(json!({"shape": {"type": "plane"}, "hidden": true}));
    let all = json!({"type": "scene", "objects": objects}).to_string();
    let out = |name: &str| dir.join(name).to_str().unwrap().to_string();

    let o = run(&["tessellate", "-", "-o", &out("all.obj")], &all);
    assert_eq!(o.code, 0, "{}", o.stderr);
    let obj = std::fs::read_to_string(out("all.obj")).unwrap();
    let groups: Vec<&str> = obj.lines().filter(|l| l.starts_with("o ")).collect();
    assert_eq!(groups, ["o blending_spline_surface_0", "o sphere_1", "o heart_2"], "one group per visible object");
    assert_eq!(obj.lines().filter(|l| l.starts_with("g ")).count(), 3);
    assert!(obj.lines().filter(|l| l.starts_with("l ")).count() > 1, "the wireframe and the heart as lines");

    assert_bad(&["tessellate", "-", "-o", &out("all.stl")], &all, "objects[2]: a curve (heart), which STL cannot hold");
    assert!(!dir.join("all.stl").exists());
    let o = run(&["tessellate", "-", "-o", &out("all.ply")], &all);
    assert_eq!(o.code, 0, "{}", o.stderr);
    let ply = std::fs::read_to_string(out("all.ply")).unwrap();
    assert!(ply.contains("element edge "), "curves as edges");
    let mesh = splinekit_mesh::export::ply::read_ply(&ply).unwrap();
    // The torus's 64 × 64 cells, the sphere's 24 × 24 (a fan of 24 at each pole).
    assert_eq!(mesh.triangles.len(), 2 * 64 * 64 + 2 * 24 * 23, "one mesh of both surfaces");

    // STL: one mesh, closed where the surfaces are (a torus, a sphere), also as ASCII.
    let o = run(&["tessellate", "-", "-o", &out("surfaces.stl")], &surfaces);
    assert_eq!(o.code, 0, "{}", o.stderr);
    let triangles = stl_triangles(&std::fs::read(out("surfaces.stl")).unwrap());
    assert_eq!(triangles.len(), 2 * 64 * 64 + 2 * 24 * 23);
    assert_eq!(unpaired_edges(&triangles), 0, "the torus and the sphere are closed");
    let o = run(&["tessellate", "-", "-o", &out("surfaces.stla")], &surfaces);
    assert_eq!(o.code, 0, "{}", o.stderr);
    let stla = std::fs::read_to_string(out("surfaces.stla")).unwrap();
    assert_eq!(stla.matches("facet normal").count(), triangles.len());
    assert_bad(
        &["tessellate", "-", "-o", &out("s.svg")],
        &surfaces,
        "-o: scenes are written as .obj, .stl, .stla, .ply",
    );
}

/// An STL file read back as one mesh, its corners welded where their coordinates are the
/// same bits ([`splinekit_mesh::brep_mesh::open_edges`] welds by position).
fn stl_mesh(bytes: &[u8]) -> splinekit_mesh::TriangleMesh {
    let triangles = splinekit_mesh::export::stl::read_stl(bytes).unwrap();
    let mut mesh = splinekit_mesh::TriangleMesh::default();
    for (k, (_, corners)) in triangles.iter().enumerate() {
        mesh.positions.extend(corners.iter().map(|c| c.map(f64::from)));
        mesh.triangles.push([0, 1, 2].map(|i| 3 * k as u32 + i));
    }
    mesh
}

#[test]
fn a_scene_of_the_examples_closed_surfaces_is_written_as_a_closed_stl() {
    let dir = ScratchDir::new("scene-stl");
    let examples = format!("{}/../../examples/scenes", env!("CARGO_MANIFEST_DIR"));
    let objects = |name: &str| -> Vec<Value> {
        let text = std::fs::read_to_string(format!("{examples}/{name}.json")).unwrap();
        serde_json::from_str::<Value>(&text).unwrap()["objects"].as_array().unwrap().clone()
    };
    // The closed, orientable surfaces of the examples (blending, NURBS and trigonometric
    // tori, a sweep, two subdivision surfaces, a blending spline over a triangulated
    // sphere), with their drawing aids (a wireframe, control nets, a colour map), in one
    // scene: 63 824 triangles at the examples' densities.
    let closed = [
        "torus_before",
        "nurbs_torus",
        "torus_gaussian_curvature",
        "sweep_trefoil",
        "subdivision_surfaces",
        "blending_sphere_moved",
    ];
    let all: Vec<Value> = closed.iter().flat_map(|name| objects(name)).collect();
    let scene = json!({"type": "scene", "objects": all}).to_string();
    for ext in ["stl", "stla"] {
        let path = dir.join(format!("closed.{ext}"));
        let o = run(&["tessellate", "-", "-o", path.to_str().unwrap()], &scene);
        assert_eq!(o.code, 0, "{}", o.stderr);
        let mesh = stl_mesh(&std::fs::read(&path).unwrap());
        assert!(mesh.triangles.len() > 10_000, "{} triangles", mesh.triangles.len());
        assert_eq!(splinekit_mesh::brep_mesh::open_edges(&mesh), 0, "{ext}: every edge used once each way");
    }
    // An open surface beside them shows its border.
    let mut with_plane: Vec<Value> = objects("torus_before");
    with_plane.extend(objects("plane_before"));
    let path = dir.join("open.stl");
    let scene = json!({"type": "scene", "objects": with_plane}).to_string();
    let o = run(&["tessellate", "-", "-o", path.to_str().unwrap()], &scene);
    assert_eq!(o.code, 0, "{}", o.stderr);
    assert!(splinekit_mesh::brep_mesh::open_edges(&stl_mesh(&std::fs::read(&path).unwrap())) > 0);
}

#[test]
fn eval_surfaces_prints_partials_and_unit_normals() {
    let v = ok_json(&["eval", "-", "--at", "0.3:0.2,1:-0.5", "--derivatives", "2"], r#"{"type":"sphere","radius":2}"#);
    let keys: Vec<&String> = v["partials"].as_object().unwrap().keys().collect();
    assert_eq!(keys, ["u", "v", "uu", "uv", "vv"]);
    for (i, (u, w)) in [(0.3f64, 0.2f64), (1.0, -0.5)].iter().enumerate() {
        let p = floats(&v["points"][i]);
        let expected = [2.0 * u.cos() * w.cos(), 2.0 * u.sin() * w.cos(), 2.0 * w.sin()];
        for c in 0..3 {
            assert!((p[c] - expected[c]).abs() < 1e-15);
        }
        let n = floats(&v["normals"][i]);
        assert!((n[0] * n[0] + n[1] * n[1] + n[2] * n[2] - 1.0).abs() < 1e-15);
        // Outward normal of the sphere is the position direction.
        assert!((n[0] - expected[0] / 2.0).abs() < 1e-15);
        let suv = floats(&v["partials"]["uv"][i]);
        assert!((suv[0] - 2.0 * u.sin() * w.sin()).abs() < 1e-15);
    }
    // Poles have a limit normal.
    let v = ok_json(&["eval", "-", "--at", "0:1.5707963267948966"], r#"{"type":"sphere"}"#);
    assert!((floats(&v["normals"][0])[2] - 1.0).abs() < 1e-12);
    // Grids run u slowest and include both ends.
    let v = ok_json(
        &["eval", "-", "--grid", "3,2"],
        r#"{"type":"plane","origin":[1,0,0],"u_axis":[2,0,0],"v_axis":[0,3,0]}"#,
    );
    assert_eq!(v["params"], json!([[0.0, 0.0], [0.0, 1.0], [0.5, 0.0], [0.5, 1.0], [1.0, 0.0], [1.0, 1.0]]));
    assert_eq!(v["points"][3], json!([2.0, 3.0, 0.0]));
    let net = json!({"type":"bspline_surface","degree_u":2,"degree_v":1,"knots_u":[0,0,0,1,1,1],"knots_v":[0,0,1,1],
        "control_points":[[[0,0,0],[0,1,0]],[[1,0,1],[1,1,1]],[[2,0,0],[2,1,0]]]});
    let v = ok_json(&["eval", "-", "--at", "0.5:0.5", "--derivatives", "1"], &net.to_string());
    assert_eq!(v["points"][0], json!([1.0, 0.5, 0.5]));
    assert_eq!(v["partials"]["u"][0], json!([2.0, 0.0, 0.0]));
    let v2 = ok_json(
        &["eval", "-", "--at", "0.5:0.5"],
        r#"{"type":"bezier_surface","control_points":[[[0,0],[0,1]],[[1,0],[1,1]]]}"#,
    );
    assert_eq!(v2["points"][0], json!([0.5, 0.5]));
    assert!(v2.get("normals").is_none(), "2-D surfaces have no normals");
}

#[test]
fn bad_surface_input_names_the_field() {
    let at = ["eval", "-", "--at", "0.5:0.5"];
    assert_each_bad(&[
        (
            &at,
            r#"{"type":"bspline_surface","degree_u":1,"degree_v":1,"knots_u":[0,0,1,1],"knots_v":[0,0,1],"control_points":[[[0,0,0],[0,1,0]],[[1,0,0],[1,1,1]]]}"#,
            "knots_v: expected 4 values",
        ),
        (&at, r#"{"type":"bezier_surface","control_points":[[[0,0,0],[0,1,0]],[[1,0,0]]]}"#, "control_points[1]"),
        (&at, r#"{"type":"bezier_surface","control_points":[[[0,0,0],[0,1,0]],[[1,0,0],[1,1]]]}"#, "control_points[1]"),
        (&at, r#"{"type":"bezier_surface","control_points":[]}"#, "control_points"),
        (
            &at,
            r#"{"type":"nurbs_surface","degree_u":1,"degree_v":1,"knots_u":[0,0,1,1],"knots_v":[0,0,1,1],"control_points":[[[0,0,0],[0,1,0]],[[1,0,0],[1,1,1]]],"weights":[[1,1],[1,0]]}"#,
            "weights[1]",
        ),
        (
            &at,
            r#"{"type":"nurbs_surface","degree_u":1,"degree_v":1,"knots_u":[0,0,1,1],"knots_v":[0,0,1,1],"control_points":[[[0,0,0],[0,1,0]],[[1,0,0],[1,1,1]]],"weights":[[1,1]]}"#,
            "weights",
        ),
        (&at, r#"{"type":"torus","minor_radius":-1}"#, "minor_radius"),
        (&at, r#"{"type":"sphere","colour":"red"}"#, "unknown field `colour`"),
        (&["eval", "-", "--at", "0.5"], r#"{"type":"sphere"}"#, "U:V"),
        (&["eval", "-", "--at", "0:9"], r#"{"type":"sphere"}"#, "outside the domain"),
        (&["eval", "-", "--grid", "100000,100000"], r#"{"type":"sphere"}"#, "--grid"),
        (&["eval", "-", "--grid", "0,3"], r#"{"type":"sphere"}"#, "--grid"),
        (&["eval", "-", "--samples", "3"], r#"{"type":"sphere"}"#, "--samples"),
        (&["eval", "-", "--grid", "3,3"], r#"{"type":"circle"}"#, "--grid"),
        (&["eval", "-", "--at", "0.5:0.5"], r#"{"type":"circle"}"#, "--at"),
        (&["refine", "-", "--elevate", "1"], r#"{"type":"sphere"}"#, "refine"),
    ]);
}

#[test]
fn derived_surface_documents() {
    let rev = r#"{"type":"revolution","curve":{"type":"line","from":[1,0,0],"to":[1,0,2]}}"#;
    let v = ok_json(&["eval", "-", "--at", "1.0:0.5"], rev);
    let p = floats(&v["points"][0]);
    assert!((p[0] - 1f64.cos()).abs() < 1e-15 && (p[1] - 1f64.sin()).abs() < 1e-15 && (p[2] - 1.0).abs() < 1e-15);
    let ext = r#"{"type":"extrusion","curve":{"type":"circle"},"direction":[0,0,3]}"#;
    let v = ok_json(&["eval", "-", "--at", "0:0.5"], ext);
    assert_eq!(v["points"][0], json!([1.0, 0.0, 1.5]));
    let ruled = r#"{"type":"ruled","first":{"type":"line","from":[0,0],"to":[2,0]},"second":{"type":"line","from":[0,1],"to":[2,3]}}"#;
    let v = ok_json(&["eval", "-", "--at", "0.5:0.5"], ruled);
    assert_eq!(v["points"][0], json!([1.0, 1.0]));
    assert_all_bad(
        &["eval", "-", "--at", "0:0"],
        &[
            (r#"{"type":"revolution","curve":{"type":"bezier","control_points":[[0,0],[1,1]]}}"#, "curve"),
            (r#"{"type":"revolution","curve":{"type":"line","from":[1,0,0],"to":[1,0,2]},"axis":[0,0,0]}"#, "axis"),
            (r#"{"type":"extrusion","curve":{"type":"circle"},"direction":[0,1]}"#, "direction"),
            (
                r#"{"type":"ruled","first":{"type":"circle"},"second":{"type":"nope"}}"#,
                "second.type: unknown curve type",
            ),
            (
                r#"{"type":"coons","bottom":{"type":"line","from":[0,0,0],"to":[1,0,0]},"top":{"type":"line","from":[0,1,0],"to":[1,1,0]},"left":{"type":"line","from":[0,0,0],"to":[0,1,0]},"right":{"type":"line","from":[1,0.5,0],"to":[1,1,0]}}"#,
                "corners",
            ),
            (
                r#"{"type":"coons","bottom":{"type":"line","from":[0,0,0],"to":[1,0,0]},"top":{"type":"line","from":[0,1,0],"to":[1,1,0]},"left":{"type":"line","from":[0,0,0],"to":[0,1,0]},"right":{"type":"line","from":[1,0,0],"to":[1,1,0]},"blend":"quintic"}"#,
                "blend",
            ),
        ],
    );
}

#[test]
fn trimmed_surface_documents_report_containment() {
    let doc = r#"{"type":"trimmed","surface":{"type":"plane"},"holes":[{"type":"catmull_rom","points":[[0.4,0.4],[0.6,0.4],[0.6,0.6],[0.4,0.6]],"closed":true}]}"#;
    let v = ok_json(&["eval", "-", "--at", "0.5:0.5,0.1:0.1"], doc);
    assert_eq!(v["inside"], json!([false, true]));
    assert_eq!(v["points"][1], json!([0.1, 0.1, 0.0]));
    let v = ok_json(&["eval", "-", "--at", "0.5:0.5"], r#"{"type":"plane"}"#);
    assert!(v.get("inside").is_none());
    assert_all_bad(
        &["eval", "-", "--at", "0:0"],
        &[
            (
                r#"{"type":"trimmed","surface":{"type":"plane"},"outer":{"type":"line","from":[0,0],"to":[1,1]}}"#,
                "outer: a trimming loop must be closed",
            ),
            (
                r#"{"type":"trimmed","surface":{"type":"plane"},"outer":{"type":"circle"}}"#,
                "outer: a trimming loop must be a 2-D curve",
            ),
            (r#"{"type":"trimmed","surface":{"type":"circle"}}"#, "surface.type: expected a surface type"),
        ],
    );
}

#[test]
fn bfunction_and_blend_documents() {
    let v = ok_json(
        &["eval", "-", "--at", "0.25", "--derivatives", "2"],
        r#"{"type":"bfunction","bfunction":{"type":"erbs"}}"#,
    );
    assert!((floats(&v["points"][0])[0] - 0.1229672832773291).abs() <= 2e-16);
    assert!((floats(&v["derivatives"][0][1])[0] - 4.2218347856499).abs() < 1e-12);
    let v = ok_json(
        &["eval", "-", "--at", "0.5"],
        r#"{"type":"bfunction","bfunction":{"type":"polynomial","smoothness":2}}"#,
    );
    assert_eq!(v["points"][0], json!([0.5]));
    let blend = r#"{"type":"blend","first":{"type":"line","from":[0,0],"to":[1,0]},"second":{"type":"line","from":[0.5,0],"to":[1.5,1]},"overlap":0.5}"#;
    let v = ok_json(&["eval", "-", "--at", "0,0.75,1.5"], blend);
    // At t = 0.75: c1 = (0.75, 0), c2(0.25) = (0.75, 0.25), B(0.5) = 0.5.
    assert_eq!(v["points"], json!([[0.0, 0.0], [0.75, 0.125], [1.5, 1.0]]));
    assert_all_bad(
        &["eval", "-", "--at", "0.5"],
        &[
            (r#"{"type":"bfunction","bfunction":{"type":"erbs","lambda":2}}"#, "bfunction: lambda"),
            (r#"{"type":"bfunction","bfunction":{"type":"spline"}}"#, "bfunction.type"),
            (r#"{"type":"bfunction","bfunction":{"type":"polynomial","smoothness":0}}"#, "smoothness"),
            (r#"{"type":"blend","first":{"type":"circle"},"second":{"type":"circle"},"overlap":1.5}"#, "overlap"),
            (
                r#"{"type":"blend","first":{"type":"circle"},"second":{"type":"line","from":[0,0],"to":[1,1]},"overlap":0.5}"#,
                "second: expected a curve of dimension 3",
            ),
        ],
    );
}

#[test]
fn blending_spline_documents() {
    let doc = r#"{"type":"blending_spline","model":{"type":"heart"},"local_curves":10,"local":{"type":"bezier","degree":3},"bfunction":{"type":"erbs"}}"#;
    // ERBS + cubic Bézier locals: position and first 3 derivatives of the model at every knot.
    let knots: Vec<String> = (0..10).map(|k| format!("{}", std::f64::consts::TAU * k as f64 / 10.0)).collect();
    let v = ok_json(&["eval", "-", "--at", &knots.join(","), "--derivatives", "3"], doc);
    let m = ok_json(&["eval", "-", "--at", &knots.join(","), "--derivatives", "3"], r#"{"type":"heart"}"#);
    for i in 0..10 {
        let (a, b) = (floats(&v["points"][i]), floats(&m["points"][i]));
        assert!((0..3).all(|c| (a[c] - b[c]).abs() < 1e-12), "knot {i}");
        for k in 0..3 {
            let (a, b) = (floats(&v["derivatives"][i][k]), floats(&m["derivatives"][i][k]));
            assert!((0..3).all(|c| (a[c] - b[c]).abs() < 1e-9 * (1.0 + b[c].abs())), "knot {i} derivative {}", k + 1);
        }
    }
    // A transform moves its local's knot exactly.
    let moved = r#"{"type":"blending_spline","model":{"type":"heart"},"local_curves":10,"transforms":{"0":{"translate":[0,2,0]}}}"#;
    let v = ok_json(&["eval", "-", "--at", "0"], moved);
    assert!((floats(&v["points"][0])[1] - 7.0).abs() < 1e-12);
    assert_all_bad(
        &["eval", "-", "--at", "0"],
        &[
            (
                r#"{"type":"blending_spline","model":{"type":"heart"},"local_curves":10,"transforms":{"12":{"scale":2}}}"#,
                "local curve 12 does not exist",
            ),
            (r#"{"type":"blending_spline","model":{"type":"heart"},"local_curves":1}"#, "local_curves"),
            (
                r#"{"type":"blending_spline","model":{"type":"heart"},"local_curves":5,"local":{"type":"spline"}}"#,
                "local",
            ),
            (
                r#"{"type":"blending_spline","model":{"type":"heart"},"local_curves":5,"transforms":[{"rotate":{"angle":1}}]}"#,
                "transforms[0].rotate.axis",
            ),
            (r#"{"type":"blending_spline","model":{"type":"nope"},"local_curves":5}"#, "model.type"),
        ],
    );
}

#[test]
fn eval_time_poses_the_example_animations() {
    let heart =
        std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/../../examples/shapes/beating_heart.json"))
            .unwrap();
    let rest = ok_json(&["eval", "-", "--at", "3.141592653589793"], &heart);
    let beat = ok_json(&["eval", "-", "--at", "3.141592653589793", "--time", "0.25"], &heart);
    let y = |v: &Value| v["points"][0][1].as_f64().unwrap();
    assert!((y(&rest) + 17.0).abs() < 1e-12 && (y(&beat) + 18.5).abs() < 1e-12, "{rest} {beat}");
    let period = ok_json(&["eval", "-", "--at", "3.141592653589793", "--time", "1.25"], &heart);
    assert!((y(&period) - y(&beat)).abs() < 1e-12);
    assert_bad(&["eval", "-", "--at", "1", "--time", "soon"], &heart, "--time");
    assert_bad(&["eval", "-", "--at", "1", "--time", "inf"], &heart, "--time");

    let torus =
        std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/../../examples/shapes/animated_torus.json"))
            .unwrap();
    let v = ok_json(&["eval", "-", "--at", "0:0", "--time", "0.25", "--derivatives", "1"], &torus);
    assert!((v["points"][0][0].as_f64().unwrap() - 4.6).abs() < 1e-12, "{v}");
    let n = floats(&v["normals"][0]);
    assert!((n.iter().map(|x| x * x).sum::<f64>() - 1.0).abs() < 1e-12);
}

#[test]
fn view_refuses_bad_arguments_and_explains_a_missing_display() {
    let torus = r#"{"type":"torus"}"#;
    assert_each_bad(&[
        (&["view", "-", "--frames", "0"], torus, "--frames"),
        (&["view", "-", "--screenshot", "x.jpg"], torus, "--screenshot"),
        (&["view", "-"], r#"{"type":"scene","objects":[]}"#, "objects"),
    ]);
}

#[test]
fn subdivide_surface_writes_meshes_and_refuses_bad_ones() {
    let dir = ScratchDir::new("subdivision");
    let cube = std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/../../examples/meshes/cube.obj")).unwrap();
    let obj = dir.join("cc.obj");
    let o = run(
        &["subdivide-surface", "-", "--scheme", "catmull-clark", "--steps", "2", "-o", obj.to_str().unwrap()],
        &cube,
    );
    assert_eq!(o.code, 0, "{}", o.stderr);
    let text = std::fs::read_to_string(&obj).unwrap();
    assert_eq!(text.lines().filter(|l| l.starts_with("f ")).count(), 96);
    assert_eq!(text.lines().filter(|l| l.starts_with("v ")).count(), 98);
    let stl = dir.join("ds.stl");
    let o =
        run(&["subdivide-surface", "-", "--scheme", "doo-sabin", "--steps", "1", "-o", stl.to_str().unwrap()], &cube);
    assert_eq!(o.code, 0, "{}", o.stderr);
    // 6 quads + 12 quads + 8 triangles, fanned: 2·18 + 8 triangles.
    assert_eq!(std::fs::read(&stl).unwrap().len(), 84 + 50 * 44);
    let flipped = cube.replace("f 5 6 8 7", "f 7 8 6 5");
    assert_bad(
        &["subdivide-surface", "-", "--scheme", "catmull-clark", "-o", obj.to_str().unwrap()],
        &flipped,
        "oriented",
    );
    assert_bad(
        &["subdivide-surface", "-", "--scheme", "catmull-clark", "-o", obj.to_str().unwrap()],
        "v 0 0 0\nf 1 2 3\n",
        "line 2",
    );
    // Loop takes triangles: the cube's quads are refused unless --triangulate.
    assert_bad(&["subdivide-surface", "-", "--scheme", "loop", "-o", obj.to_str().unwrap()], &cube, "triangulation");
    assert_bad(&["subdivide-surface", "-", "--scheme", "spline", "-o", obj.to_str().unwrap()], &cube, "scheme");
}

#[test]
fn project_finds_nearest_points_and_every_minimum() {
    let circle = r#"{"type":"nurbs","degree":2,"knots":[0,0,0,0.25,0.25,0.5,0.5,0.75,0.75,1,1,1],
        "control_points":[[1,0],[1,1],[0,1],[-1,1],[-1,0],[-1,-1],[0,-1],[1,-1],[1,0]],
        "weights":[1,0.7071067811865476,1,0.7071067811865476,1,0.7071067811865476,1,0.7071067811865476,1]}"#;
    let v = ok_json(&["project", "-", "--point", "3,4"], circle);
    let p = floats(&v["nearest"]["point"]);
    assert!((p[0] - 0.6).abs() < 1e-14 && (p[1] - 0.8).abs() < 1e-14, "{v}");
    assert!((v["nearest"]["distance"].as_f64().unwrap() - 4.0).abs() < 1e-14);
    // From inside, off centre, the nearest point (1, 0) is the only local minimum; this
    // circle is stored as an open curve, so it is reported at both ends of the domain.
    let v = ok_json(&["project", "-", "--point", "0.5,0", "--all"], circle);
    let ts: Vec<f64> = v["minima"].as_array().unwrap().iter().map(|m| m["t"].as_f64().unwrap()).collect();
    assert_eq!(ts, vec![0.0, 1.0], "{v}");
    let sphere = r#"{"type":"sphere","radius":2}"#;
    let v = ok_json(&["project", "-", "--point", "0,0,5"], sphere);
    assert!((v["nearest"]["distance"].as_f64().unwrap() - 3.0).abs() < 1e-12, "{v}");
    // The centre of the sphere: every point is nearest, reported once.
    let v = ok_json(&["project", "-", "--point", "0,0,0", "--all"], sphere);
    assert_eq!(v["minima"].as_array().unwrap().len(), 1, "{v}");
    assert_bad(&["project", "-", "--point", "1,2"], sphere, "--point: the shape is 3-D");
    assert_bad(&["project", "-", "--point", "1,2,3", "--accuracy", "-1"], sphere, "--accuracy");
}

#[test]
fn intersect_reports_crossings_tangents_overlaps_and_self_intersections() {
    let dir = ScratchDir::new("intersect");
    let write = |name: &str, text: &str| write_in(&dir, name, text);
    let circle = r#"{"type":"nurbs","degree":2,"knots":[0,0,0,0.25,0.25,0.5,0.5,0.75,0.75,1,1,1],
        "control_points":[[1,0],[1,1],[0,1],[-1,1],[-1,0],[-1,-1],[0,-1],[1,-1],[1,0]],
        "weights":[1,0.7071067811865476,1,0.7071067811865476,1,0.7071067811865476,1,0.7071067811865476,1]}"#;
    let a = write("circle.json", circle);
    let line =
        write("line.json", r#"{"type":"bspline","degree":1,"knots":[0,0,1,1],"control_points":[[-2,0.5],[2,0.5]]}"#);
    let v = ok_json(&["intersect", &a, &line], "");
    let points = v["points"].as_array().unwrap();
    assert_eq!(points.len(), 2, "{v}");
    for p in points {
        assert_eq!(p["kind"], "crossing");
        let xy = floats(&p["point"]);
        assert!((xy[0].abs() - 0.75f64.sqrt()).abs() < 1e-12 && (xy[1] - 0.5).abs() < 1e-12, "{v}");
    }
    assert_eq!(v["overlaps"], json!([]));
    let top = write("top.json", r#"{"type":"bspline","degree":1,"knots":[0,0,1,1],"control_points":[[-2,1],[2,1]]}"#);
    let v = ok_json(&["intersect", &a, &top], "");
    assert_eq!(v["points"].as_array().unwrap().len(), 1, "{v}");
    assert_eq!(v["points"][0]["kind"], "tangent");
    let v = ok_json(&["intersect", &a, &a], "");
    assert_eq!(v["overlaps"].as_array().unwrap().len(), 1, "{v}");
    let looped = write("loop.json", r#"{"type":"bezier","control_points":[[0,0],[3,2],[-1,2],[2,0]]}"#);
    let v = ok_json(&["intersect", &looped], "");
    assert_eq!(v["points"].as_array().unwrap().len(), 1, "{v}");
    let sphere = write("sphere.json", r#"{"type":"sphere","radius":1}"#);
    assert_bad(&["intersect", &a, &sphere], "", "A: a curve and a surface intersect in 3-D only, this shape is 2-D");
    let helix = write("helix.json", r#"{"type":"helix"}"#);
    assert_bad(&["intersect", &a, &helix], "", "B: the curves must have the same dimension");
    assert_bad(&["intersect", &a, &line, "--tolerance", "0"], "", "--tolerance");
}

#[test]
fn intersect_and_section_cut_surfaces() {
    let dir = ScratchDir::new("intersect-surfaces");
    let write = |name: &str, text: &str| write_in(&dir, name, text);
    let sphere = write("sphere.json", r#"{"type":"sphere","radius":2}"#);
    let line = write("line.json", r#"{"type":"line","from":[-3,0.5,0.3],"to":[3,0.5,0.3]}"#);
    for args in [[&line, &sphere], [&sphere, &line]] {
        let v = ok_json(&["intersect", args[0], args[1]], "");
        let points = v["points"].as_array().unwrap();
        assert_eq!(points.len(), 2, "{v}");
        for p in points {
            let x = floats(&p["point"]);
            assert!((x[0].abs() - 3.66f64.sqrt()).abs() < 1e-12 && floats(&p["params"]).len() == 3, "{v}");
        }
    }
    let torus = write("torus.json", r#"{"type":"torus"}"#);
    let cylinder = write("cylinder.json", r#"{"type":"cylinder","radius":3,"height":2}"#);
    let v = ok_json(&["intersect", &torus, &cylinder], "");
    let curves = v["curves"].as_array().unwrap();
    assert_eq!(curves.len(), 1, "{v}");
    assert_eq!(curves[0]["closed"], true);
    assert_eq!(curves[0]["tangent"], false);
    for p in curves[0]["points"].as_array().unwrap() {
        let x = floats(p);
        assert!(((x[0] * x[0] + x[1] * x[1]).sqrt() - 3.0).abs() < 1e-9 && (x[2] - 1.0).abs() < 1e-9, "{p}");
    }
    // A unit sphere in a unit cylinder: they touch along the equator, one tangent loop.
    let unit = write("unit.json", r#"{"type":"sphere","radius":1}"#);
    let around = write(
        "around.json",
        r#"{"type":"revolution","curve":{"type":"line","from":[1,0,-1],"to":[1,0,1]},"axis":[0,0,1]}"#,
    );
    let v = ok_json(&["intersect", &unit, &around], "");
    let curves = v["curves"].as_array().unwrap();
    assert_eq!(curves.len(), 1, "{v}");
    assert_eq!((&curves[0]["tangent"], &curves[0]["closed"]), (&true.into(), &true.into()), "{v}");
    for p in curves[0]["points"].as_array().unwrap() {
        let x = floats(p);
        assert!(((x[0] * x[0] + x[1] * x[1]).sqrt() - 1.0).abs() < 1e-9 && x[2].abs() < 1e-9, "{p}");
    }
    let v = ok_json(&["section", &sphere, "--plane", "0,0,1/0,0,1"], "");
    let curves = v["sections"][0]["curves"].as_array().unwrap();
    assert_eq!(curves.len(), 1, "{v}");
    for p in curves[0]["points"].as_array().unwrap() {
        let x = floats(p);
        assert!(((x[0] * x[0] + x[1] * x[1]).sqrt() - 3f64.sqrt()).abs() < 1e-9 && (x[2] - 1.0).abs() < 1e-9);
    }
    assert_each_bad(&[
        (&["section", &sphere, "--plane", "0,0,1/0,0,0"], "", "--plane: the normal must be"),
        (&["section", &sphere, "--plane", "0,0,1"], "", "--plane"),
        (&["section", &sphere, "--plane", "0,0,0/0,0,1", "--levels", "0"], "", "--levels"),
        (&["section", &line, "--plane", "0,0,0/0,0,1"], "", "SURFACE"),
        (&["intersect", &torus, &cylinder, "--chord", "0"], "", "--chord"),
    ]);
}

#[test]
fn offset_prints_bspline_documents_and_a_scene_of_pieces() {
    // A circle of radius 2 at distance 0.5: one closed B-spline on the circle of radius 2.5.
    let v = ok_json(&["offset", "-", "--distance", "0.5", "--tolerance", "1e-8"], r#"{"type":"circle","radius":2}"#);
    assert_eq!(v["type"], "bspline", "{v}");
    assert_eq!(v["periodic"], true, "{v}");
    let text = v.to_string();
    let e = ok_json(&["eval", "-", "--samples", "50"], &text);
    for p in e["points"].as_array().unwrap() {
        assert!((floats(p).iter().map(|x| x * x).sum::<f64>().sqrt() - 2.5).abs() < 1e-8, "{p}");
    }
    // An ellipse's inner offset past its smallest radius of curvature: two trimmed pieces.
    let v = ok_json(&["offset", "-", "--distance", "-0.6"], r#"{"type":"ellipse","a":3,"b":1}"#);
    assert_eq!(v["type"], "scene", "{v}");
    assert_eq!(v["objects"].as_array().unwrap().len(), 2, "{v}");
    // A sphere's offset is a B-spline surface on the sphere of radius 2.5.
    let v = ok_json(&["offset", "-", "--distance", "0.5", "--tolerance", "1e-4"], r#"{"type":"sphere","radius":2}"#);
    assert_eq!(v["type"], "bspline_surface", "{v}");
    let e = ok_json(&["eval", "-", "--grid", "7,7"], &v.to_string());
    for p in e["points"].as_array().unwrap() {
        assert!((floats(p).iter().map(|x| x * x).sum::<f64>().sqrt() - 2.5).abs() < 1e-4, "{p}");
    }
    let circle = r#"{"type":"circle","radius":2}"#;
    assert_each_bad(&[
        (&["offset", "-", "--distance", "nan"], circle, "--distance"),
        (&["offset", "-", "--distance", "1", "--tolerance", "0"], circle, "--tolerance"),
        (&["offset", "-", "--distance", "1", "--normal", "0,0"], circle, "--normal"),
        (&["offset", "-", "--distance", "0.1"], r#"{"type":"cone"}"#, "apex"),
        (&["offset", "-", "--distance", "0.1", "--normal", "1,0,0"], r#"{"type":"sphere"}"#, "--normal"),
    ]);
}

#[test]
fn eval_samples_at_equal_arc_length() {
    // The quarter points of an ellipse by length are its vertices, by symmetry.
    let v = ok_json(&["eval", "-", "--samples", "5", "--arc-length"], r#"{"type":"ellipse","a":2,"b":1}"#);
    let ts = floats(&v["params"]);
    for (t, k) in ts.iter().zip(0..) {
        assert!((t - k as f64 * std::f64::consts::FRAC_PI_2).abs() < 1e-9, "{ts:?}");
    }
    assert_bad(&["eval", "-", "--grid", "3,3", "--arc-length"], r#"{"type":"sphere"}"#, "--samples");
}

/// `local_control_points` reach every command: at knot c₃ the curve is local 3 alone, the
/// edited quadratic Bézier at its midpoint, (P₀ + 2P₁ + P₂)/4; bad entries end with one line
/// naming the field and the numbers.
#[test]
fn edited_local_control_points_are_honoured_and_checked_by_the_commands() {
    let doc = r#"{"type":"blending_spline","model":{"type":"heart"},"local_curves":10,
        "local":{"type":"bezier","degree":2},"local_control_points":{"3":[[10,0,0],[14,-4,2],[12,-8,0]]}}"#;
    let c3 = 3.0 * std::f64::consts::TAU / 10.0;
    let v = ok_json(&["eval", "-", "--at", &format!("{c3:?}")], doc);
    let p = floats(&v["points"][0]);
    let expected = [(10.0 + 28.0 + 12.0) / 4.0, (0.0 - 8.0 - 8.0) / 4.0, 4.0 / 4.0];
    for (a, b) in p.iter().zip(expected) {
        assert!((a - b).abs() < 1e-12, "{p:?} vs {expected:?}");
    }
    let dir = ScratchDir::new("lcp");
    let obj = dir.join("heart.obj");
    let o = run(&["tessellate", "-", "-o", obj.to_str().unwrap()], doc);
    assert_eq!(o.code, 0, "{}", o.stderr);
    let png = dir.join("never.png");
    let bad = doc.replace("[[10,0,0],[14,-4,2],[12,-8,0]]", "[[10,0,0],[14,-4],[12,-8,0]]");
    assert_bad(&["eval", "-", "--samples", "4"], &bad, "local_control_points.3[1]: expected 3 coordinates, got 2");
    let bad = doc.replace("\"3\":", "\"10\":");
    assert_bad(
        &["eval", "-", "--samples", "4"],
        &bad,
        "local_control_points.10: local curve 10 does not exist (there are 10)",
    );
    let bad = doc.replace("\"bezier\",\"degree\":2", "\"bezier\",\"degree\":3");
    assert_bad(
        &["render", "-", "-o", png.to_str().unwrap()],
        &bad,
        "local_control_points.3: expected 4 control points for a Bézier local of degree 3, got 3",
    );
    assert!(!png.exists(), "nothing written for a bad document");
}
