//! The edges of issue 20 as users meet them on the command line: outputs that must
//! survive a failed write, degenerate shapes that must be named, limits that must agree,
//! scenes where one shape was expected.

use serde_json::{Value, json};
use std::path::Path;

mod common;
use common::{ScratchDir, run};

fn ok_json(args: &[&str], stdin: &str) -> Value {
    let o = run(args, stdin);
    assert_eq!(o.code, 0, "{args:?} failed: {}", o.stderr);
    serde_json::from_str(&o.stdout).unwrap_or_else(|e| panic!("{args:?}: {e} in {:?}", o.stdout))
}

/// Exit 2, nothing on standard output, one line on standard error naming `must_contain`.
fn assert_bad(args: &[&str], stdin: &str, must_contain: &str) -> String {
    let o = run(args, stdin);
    assert_eq!(o.code, 2, "{args:?}: exit {} (stderr {:?})", o.code, o.stderr);
    assert!(o.stdout.is_empty(), "{args:?}: printed {:?}", o.stdout);
    assert_eq!(o.stderr.lines().count(), 1, "{args:?}: stderr {:?}", o.stderr);
    assert!(!o.stderr.contains("panicked") && !o.stderr.contains("internal error"), "{:?}", o.stderr);
    assert!(o.stderr.contains(must_contain), "{args:?}: {:?} lacks {must_contain:?}", o.stderr);
    o.stderr
}

/// `tessellate` writes `doc` as each format of `exts` (exit 0), each file over `min_bytes`.
fn assert_tessellates(name: &str, doc: &str, exts: &[&str], min_bytes: u64) {
    let dir = ScratchDir::new(&format!("edges-{name}"));
    for ext in exts {
        let path = dir.join(format!("{name}.{ext}"));
        let o = run(&["tessellate", "-", "-o", path.to_str().unwrap()], doc);
        assert_eq!(o.code, 0, "{ext}: {}", o.stderr);
        assert!(std::fs::metadata(&path).unwrap().len() > min_bytes, "{ext}");
    }
}

fn names(dir: &Path) -> Vec<String> {
    let mut v: Vec<String> =
        std::fs::read_dir(dir).unwrap().map(|e| e.unwrap().file_name().to_string_lossy().into_owned()).collect();
    v.sort();
    v
}

/// A surface with no normal anywhere (every control point the same): `eval` fails after
/// it started writing the points.
const POINT_PATCH: &str = r#"{"type":"bezier_surface","control_points":[[[1,1,1],[1,1,1]],[[1,1,1],[1,1,1]]]}"#;

/// A write that fails part-way leaves the user's old file as it was (it used to be
/// truncated, then removed) and no temporary file beside it.
#[test]
fn a_failed_write_keeps_the_old_file() {
    let dir = ScratchDir::new("edges-old-file");
    let path = dir.join("result.json");
    std::fs::write(&path, "the user's old result\n").unwrap();
    let p = path.to_str().unwrap();
    assert_bad(&["eval", "-", "--at", "0.5:0.5", "-o", p], POINT_PATCH, "normals");
    assert_eq!(std::fs::read_to_string(&path).unwrap(), "the user's old result\n");
    assert_eq!(names(&dir), ["result.json"]);
    // A successful write replaces it whole.
    let o = run(&["eval", "-", "--at", "0.5", "-o", p], r#"{"type":"line","from":[0,0],"to":[2,4]}"#);
    assert_eq!((o.code, o.stdout.as_str()), (0, ""), "{}", o.stderr);
    let v: Value = serde_json::from_str(&std::fs::read_to_string(&path).unwrap()).unwrap();
    assert_eq!(v["points"], json!([[1.0, 2.0]]));
    assert_eq!(names(&dir), ["result.json"]);
}

/// Devices and symbolic links are written in place and never removed: a link to /dev/full
/// stays a link after the write fails (it used to be unlinked — and `-o /dev/full` run as
/// root removed the device node itself).
#[test]
fn a_failed_write_never_removes_a_device_or_a_link() {
    if !Path::new("/dev/full").exists() {
        return;
    }
    let dir = ScratchDir::new("edges-device");
    let link = dir.join("full.json");
    std::os::unix::fs::symlink("/dev/full", &link).unwrap();
    let doc = r#"{"type":"line","from":[0,0],"to":[2,4]}"#;
    assert_bad(&["eval", "-", "--samples", "2000", "-o", link.to_str().unwrap()], doc, "-o: cannot write");
    assert_eq!(std::fs::read_link(&link).unwrap(), Path::new("/dev/full"));
    assert_eq!(names(&dir), ["full.json"]);
    // (Never `-o /dev/full` itself here: should this regress, a test run as root would
    // remove the machine's device node. The link takes the same in-place path.)
    assert!(Path::new("/dev/full").exists(), "/dev/full was removed");
    // A link to a regular file is written through (the file changes, the link stays).
    let (file, link) = (dir.join("real.json"), dir.join("link.json"));
    std::fs::write(&file, "old").unwrap();
    std::os::unix::fs::symlink(&file, &link).unwrap();
    run(&["eval", "-", "--at", "0.5", "-o", link.to_str().unwrap()], doc);
    assert!(std::fs::symlink_metadata(&link).unwrap().file_type().is_symlink());
    let v: Value = serde_json::from_str(&std::fs::read_to_string(&file).unwrap()).unwrap();
    assert_eq!(v["points"], json!([[1.0, 2.0]]));
}

/// A B-spline surface of degree 5 in v (what CAD files carry): tessellated, exported and
/// given normals on a grid. The grid's row path used to overrun an 8-value array
/// ("range end index 10 out of range for slice of length 8").
#[test]
fn a_degree_five_surface_is_tessellated_and_has_grid_normals() {
    let row = |x: f64| (0..6).map(|j| json!([x, j as f64, ((x + j as f64) * 0.7).sin()])).collect::<Vec<_>>();
    let net: Vec<Value> = (0..4).map(|i| json!(row(i as f64))).collect();
    let knots_v = [0.0; 6].iter().chain([1.0; 6].iter()).copied().collect::<Vec<f64>>();
    let doc = json!({"type":"bspline_surface","degree_u":3,"degree_v":5,
        "knots_u":[0,0,0,0,1,1,1,1],"knots_v":knots_v,"control_points":net})
    .to_string();
    let v = ok_json(&["eval", "-", "--grid", "4,5", "--derivatives", "1"], &doc);
    assert_eq!(v["normals"].as_array().unwrap().len(), 20, "{v}");
    assert_tessellates("degree5", &doc, &["obj", "stl", "glb"], 1000);
}

/// A line through a sphere's poles meets it at the poles (OpenCASCADE gives them); it
/// used to end after "more than 400000 pairs of pieces".
#[test]
fn a_line_through_the_poles_meets_the_sphere_at_the_poles() {
    let dir = ScratchDir::new("edges-poles");
    let (line, sphere) = (dir.join("line.json"), dir.join("sphere.json"));
    std::fs::write(&line, r#"{"type":"line","from":[0,0,-3],"to":[0,0,3]}"#).unwrap();
    std::fs::write(&sphere, r#"{"type":"sphere","radius":2}"#).unwrap();
    let v = ok_json(&["intersect", line.to_str().unwrap(), sphere.to_str().unwrap()], "");
    let points = v["points"].as_array().unwrap();
    assert_eq!(points.len(), 2, "{v}");
    for (p, z) in points.iter().zip([-2.0, 2.0]) {
        let xyz: Vec<f64> = p["point"].as_array().unwrap().iter().map(|x| x.as_f64().unwrap()).collect();
        assert!(xyz[0].abs() < 1e-9 && xyz[1].abs() < 1e-9 && (xyz[2] - z).abs() < 1e-9, "{p}");
        assert_eq!(p["kind"], "crossing", "{p}");
    }
}

/// A horn torus (major radius = minor radius) is written as STL and glTF; its vertices
/// meeting at the centre used to refuse the whole mesh.
#[test]
fn a_horn_torus_is_written_as_stl() {
    let doc = r#"{"type":"torus","major_radius":1,"minor_radius":1}"#;
    assert_tessellates("horn", doc, &["stl", "glb"], 10_000);
}

/// Shapes with nothing to mesh say what is wrong instead of blaming `--density`.
#[test]
fn nothing_to_mesh_is_named() {
    let dir = ScratchDir::new("edges-nothing");
    let out = dir.join("m.obj");
    let o = out.to_str().unwrap();
    let covered = r#"{"type":"trimmed","surface":{"type":"plane"},
        "holes":[{"type":"catmull_rom","points":[[-0.5,-0.5],[1.5,-0.5],[1.5,1.5],[-0.5,1.5]],"closed":true}]}"#;
    let e = assert_bad(&["tessellate", "-", "-o", o], covered, "holes: the trim leaves nothing of the surface");
    assert!(!e.contains("--density"), "{e}");
    let e = assert_bad(&["tessellate", "-", "-o", o], POINT_PATCH, "the surface is the single point (1, 1, 1)");
    assert!(!e.contains("--density"), "{e}");
    assert_eq!(names(&dir), Vec::<String>::new(), "nothing written");
}

/// `offset` prints a scene when the offset has several pieces; `eval` answers per object:
/// `{"objects": [ANSWER, ...]}`, each ANSWER what the object alone gives.
#[test]
fn eval_answers_a_scene_per_object() {
    let scene = ok_json(&["offset", "-", "--distance", "-0.6"], r#"{"type":"ellipse","a":3,"b":1}"#);
    assert_eq!(scene["type"], "scene", "{scene}");
    let text = scene.to_string();
    let v = ok_json(&["eval", "-", "--samples", "100"], &text);
    let objects = v["objects"].as_array().unwrap();
    assert_eq!(objects.len(), 2, "{v}");
    for (i, answer) in objects.iter().enumerate() {
        let alone = ok_json(&["eval", "-", "--samples", "100"], &scene["objects"][i]["shape"].to_string());
        assert_eq!(answer, &alone, "object {i}");
        assert_eq!(answer["points"].as_array().unwrap().len(), 100);
    }
    // A scene of a curve and a surface: each takes the options that fit it, and an object
    // that cannot is named.
    let mixed = r#"{"type":"scene","objects":[{"shape":{"type":"circle"}},{"shape":{"type":"sphere"}}]}"#;
    assert_bad(&["eval", "-", "--samples", "3"], mixed, "objects[1].shape: --samples");
    // `intersect`, which combines two shapes, names the scene instead of "unknown shape type".
    let dir = ScratchDir::new("edges-scene");
    let path = dir.join("scene.json");
    std::fs::write(&path, &text).unwrap();
    let path = path.to_str().unwrap();
    assert_bad(&["intersect", path, path], "", "a scene of 2 objects");
}

/// The other commands that answer for one shape take a scene too: the queries (`project`,
/// `section`) answer `{"objects": [ANSWER, ...]}`, each ANSWER what the object alone gives;
/// the commands that make shapes (`offset`, `refine`) write the scene back with each
/// object's shape replaced, its style and the scene's background kept. An object a command
/// cannot take is named.
#[test]
fn one_shape_commands_answer_a_scene_per_object() {
    let curve = r#"{"type":"bspline","degree":2,"knots":[0,0,0,1,1,1],"control_points":[[0,0,0],[1,2,0],[2,0,0]]}"#;
    let scene = format!(
        r#"{{"type":"scene","objects":[{{"shape":{curve},"color":[1,0,0]}},{{"shape":{{"type":"sphere"}},"wireframe":true}}],"background":[0.5,0.5,0.5]}}"#
    );
    let alone = |args: &[&str], i: usize| {
        let shape: serde_json::Value = serde_json::from_str(&scene).unwrap();
        ok_json(args, &shape["objects"][i]["shape"].to_string())
    };

    let project = ["project", "-", "--point", "0.5,0.25,2"];
    let v = ok_json(&project, &scene);
    assert_eq!(v["objects"].as_array().unwrap().len(), 2, "{v}");
    for i in 0..2 {
        assert_eq!(v["objects"][i], alone(&project, i), "project, object {i}");
    }

    let offset = ["offset", "-", "--distance", "0.1"];
    let v = ok_json(&offset, &scene);
    assert_eq!(v["type"], "scene");
    assert_eq!(v["background"], serde_json::json!([0.5, 0.5, 0.5]));
    assert_eq!(v["objects"][0]["color"], serde_json::json!([1, 0, 0]));
    assert_eq!(v["objects"][1]["wireframe"], true);
    for i in 0..2 {
        assert_eq!(v["objects"][i]["shape"], alone(&offset, i), "offset, object {i}");
    }
    // An offset of several pieces gives as many objects, each with its object's style.
    let ellipse = r#"{"type":"scene","objects":[{"shape":{"type":"ellipse","a":3,"b":1},"color":[0,0,1]}]}"#;
    let v = ok_json(&["offset", "-", "--distance", "-0.6"], ellipse);
    let pieces = v["objects"].as_array().unwrap();
    assert_eq!(pieces.len(), 2, "{v}");
    assert!(pieces.iter().all(|o| o["color"] == serde_json::json!([0, 0, 1]) && o["shape"]["type"] == "bspline"));

    let spheres = r#"{"type":"scene","objects":[{"shape":{"type":"sphere"}},{"shape":{"type":"torus"}}]}"#;
    let section = ["section", "-", "--plane", "0,0,0/0,0,1"];
    let v = ok_json(&section, spheres);
    let counts: Vec<usize> =
        (0..2).map(|i| v["objects"][i]["sections"][0]["curves"].as_array().unwrap().len()).collect();
    assert_eq!(counts, [1, 2], "the sphere's equator; the torus's two circles: {v}");
    assert_bad(&section, &scene, "objects[0].shape: SURFACE: section cuts surfaces, this document is a curve");

    let curves = format!(r#"{{"type":"scene","objects":[{{"shape":{curve}}},{{"shape":{curve},"color":[0,1,0]}}]}}"#);
    let refine = ["refine", "-", "--elevate", "1"];
    let v = ok_json(&refine, &curves);
    for i in 0..2 {
        assert_eq!(v["objects"][i]["shape"]["degree"], 3, "{v}");
    }
    assert_eq!(v["objects"][1]["color"], serde_json::json!([0, 1, 0]));
    assert_bad(&refine, &scene, "objects[1].shape: type: refine works on");
}
