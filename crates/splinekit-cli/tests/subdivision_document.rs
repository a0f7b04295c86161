//! The `subdivision_surface` shape document through the front ends (`eval`, `tessellate`,
//! `render`, glTF), each against the kernel's exact evaluation and limit masks.

mod common;
use common::{ScratchDir, run};

use serde_json::{Value, json};
use splinekit::Point;
use splinekit::subdivision::surface::{Cage, Crease, Scheme, SubdivisionSurface};

fn cube_doc() -> Value {
    json!({
        "type": "subdivision_surface",
        "vertices": [[-1,-1,-1],[1,-1,-1],[-1,1,-1],[1,1,-1],[-1,-1,1],[1,-1,1],[-1,1,1],[1,1,1]],
        "faces": [[0,2,3,1],[4,5,7,6],[0,1,5,4],[2,6,7,3],[0,4,6,2],[1,3,7,5]],
        "creases": [{"edge": [4, 5], "sharpness": 1.5}]
    })
}

/// The kernel's surface of a document's cage, built here from the JSON independently of
/// the document code.
fn kernel(doc: &Value, scheme: Scheme) -> SubdivisionSurface {
    let vertices: Vec<Point<3>> = doc["vertices"]
        .as_array()
        .unwrap()
        .iter()
        .map(|p| Point::<3>::new(p[0].as_f64().unwrap(), p[1].as_f64().unwrap(), p[2].as_f64().unwrap()))
        .collect();
    let faces: Vec<Vec<u32>> = doc["faces"]
        .as_array()
        .unwrap()
        .iter()
        .map(|f| f.as_array().unwrap().iter().map(|i| i.as_u64().unwrap() as u32).collect())
        .collect();
    let creases = doc["creases"]
        .as_array()
        .map(|c| {
            c.iter()
                .map(|k| Crease {
                    a: k["edge"][0].as_u64().unwrap() as u32,
                    b: k["edge"][1].as_u64().unwrap() as u32,
                    sharpness: k["sharpness"].as_f64().unwrap(),
                })
                .collect()
        })
        .unwrap_or_default();
    SubdivisionSurface::new(Cage::new(vertices, &faces).with_creases(creases), scheme, false).unwrap()
}

fn point(v: &Value) -> Point<3> {
    Point::<3>::new(v[0].as_f64().unwrap(), v[1].as_f64().unwrap(), v[2].as_f64().unwrap())
}

fn eval(doc: &Value, at: &str, derivatives: &str) -> Value {
    let o = run(&["eval", "-", "--at", at, "--derivatives", derivatives], &doc.to_string());
    assert_eq!(o.code, 0, "{}", o.stderr);
    serde_json::from_str(&o.stdout).unwrap()
}

/// `eval` of the document at (c + u, v) is the kernel's exact limit at (face c, u, v) of a
/// quad cage, bit for bit: position, normal and the five partials; and `subdivide-surface
/// --at c,u,v` on the same cage as OBJ gives the same numbers.
#[test]
fn eval_is_the_exact_limit_of_each_face() {
    let doc = cube_doc();
    let s = kernel(&doc, Scheme::CatmullClark);
    let params = [(0usize, 0.5, 0.5), (1, 0.25, 0.75), (2, 0.875, 0.125), (3, 0.0, 0.625), (5, 0.375, 0.5)];
    let at: Vec<String> = params.iter().map(|&(c, u, v)| format!("{}:{v}", c as f64 + u)).collect();
    let got = eval(&doc, &at.join(","), "2");
    for (n, &(c, u, v)) in params.iter().enumerate() {
        let e = s.evaluate(c, u, v).unwrap();
        let p = e.partials.unwrap();
        assert_eq!(point(&got["points"][n]), e.position, "face {c} at ({u}, {v})");
        // The command takes the normal from the partials: the same to rounding.
        assert!((point(&got["normals"][n]) - e.normal).norm() < 1e-15);
        for (key, want) in [("u", p.du), ("v", p.dv), ("uu", p.duu), ("uv", p.duv), ("vv", p.dvv)] {
            assert_eq!(point(&got["partials"][key][n]), want, "{key} on face {c} at ({u}, {v})");
        }
    }
    // The same cage through `subdivide-surface --at`.
    let mut obj = String::new();
    for p in doc["vertices"].as_array().unwrap() {
        obj += &format!("v {} {} {}\n", p[0], p[1], p[2]);
    }
    for f in doc["faces"].as_array().unwrap() {
        obj += "f";
        for i in f.as_array().unwrap() {
            obj += &format!(" {}", i.as_u64().unwrap() + 1);
        }
        obj += "\n";
    }
    obj += "t crease 2/1 4 5 1.5\n";
    let o = run(&["subdivide-surface", "-", "--scheme", "catmull-clark", "--at", "2,0.875,0.125"], &obj);
    assert_eq!(o.code, 0, "{}", o.stderr);
    let cli: Value = serde_json::from_str(&o.stdout).unwrap();
    assert_eq!(point(&cli[0]["position"]), point(&got["points"][2]));
    assert_eq!(point(&cli[0]["partials"]["du"]), point(&got["partials"]["u"][2]));
}

/// The cube's corner: the limit point (½, ½, ½)·sign and its normal along it, exact, from
/// `eval` at the corner of a chart; partials there do not exist and asking for them is refused.
#[test]
fn eval_at_an_extraordinary_vertex_gives_its_limit_point_and_normal() {
    let mut doc = cube_doc();
    doc.as_object_mut().unwrap().remove("creases");
    let got = eval(&doc, "0:0,1:1", "0");
    for n in 0..2 {
        let p = point(&got["points"][n]);
        let normal = point(&got["normals"][n]);
        assert!((p.abs() - Point::<3>::new(0.5, 0.5, 0.5)).norm() < 1e-15, "{p}");
        assert!((normal - p.normalize()).norm() < 1e-15, "{normal} at {p}");
    }
    let o = run(&["eval", "-", "--at", "0:0", "--derivatives", "1"], &doc.to_string());
    assert_eq!(o.code, 2);
    assert!(o.stderr.contains("extraordinary vertex"), "{}", o.stderr);
}

/// Loop triangles and Catmull–Clark pentagons: a triangle's chart is the unit square
/// collapsed onto it, (s, t) ↦ (s(1 − t), t), partials by the chain rule; an n-gon is n
/// charts, the quads of its first step. Each against the kernel, the chain rule also
/// against finite differences of the document's own points.
#[test]
fn triangles_and_polygons_map_as_documented() {
    // An octahedron under Loop.
    let tri = json!({
        "type": "subdivision_surface", "scheme": "loop",
        "vertices": [[1,0,0],[-1,0,0],[0,1,0],[0,-1,0],[0,0,1],[0,0,-1]],
        "faces": [[0,2,4],[2,1,4],[1,3,4],[3,0,4],[2,0,5],[1,2,5],[3,1,5],[0,3,5]]
    });
    let s = kernel(&tri, Scheme::Loop);
    let (c, u, v) = (3usize, 0.25, 0.5);
    let got = eval(&tri, &format!("{}:{v}", c as f64 + u), "2");
    let e = s.evaluate(c, u * (1.0 - v), v).unwrap();
    assert_eq!(point(&got["points"][0]), e.position);
    let p = e.partials.unwrap();
    let su = point(&got["partials"]["u"][0]);
    let sv = point(&got["partials"]["v"][0]);
    assert!((su - p.du * (1.0 - v)).norm() < 1e-15);
    assert!((sv - (p.dv - p.du * u)).norm() < 1e-15);
    // Finite differences of the document's points.
    let h = 1e-5;
    let pts = eval(
        &tri,
        &format!(
            "{}:{v},{}:{v},{}:{},{}:{}",
            c as f64 + u + h,
            c as f64 + u - h,
            c as f64 + u,
            v + h,
            c as f64 + u,
            v - h
        ),
        "0",
    );
    let fd_u = (point(&pts["points"][0]) - point(&pts["points"][1])) / (2.0 * h);
    let fd_v = (point(&pts["points"][2]) - point(&pts["points"][3])) / (2.0 * h);
    assert!((fd_u - su).norm() < 1e-8, "{fd_u} vs {su}");
    assert!((fd_v - sv).norm() < 1e-8, "{fd_v} vs {sv}");
    let suv = point(&got["partials"]["uv"][0]);
    let fd_uv = {
        let g = eval(&tri, &format!("{}:{},{}:{}", c as f64 + u, v + h, c as f64 + u, v - h), "1");
        (point(&g["partials"]["u"][0]) - point(&g["partials"]["u"][1])) / (2.0 * h)
    };
    assert!((fd_uv - suv).norm() < 1e-7, "{fd_uv} vs {suv}");

    // A pentagonal prism under Catmull–Clark: the pentagons are charts 0–4 and 5–9.
    let mut vertices = Vec::new();
    for z in [-1.0, 1.0] {
        for k in 0..5 {
            let a = std::f64::consts::TAU * k as f64 / 5.0;
            vertices.push(json!([a.cos(), a.sin(), z]));
        }
    }
    let mut faces = vec![json!([4, 3, 2, 1, 0]), json!([5, 6, 7, 8, 9])];
    for k in 0..5 {
        let m = (k + 1) % 5;
        faces.push(json!([k, m, m + 5, k + 5]));
    }
    let prism = json!({"type": "subdivision_surface", "vertices": vertices, "faces": faces});
    let s = kernel(&prism, Scheme::CatmullClark);
    let got = eval(&prism, "2.5:0.25,6.5:0.75,10.5:0.5", "1");
    assert_eq!(point(&got["points"][0]), s.evaluate_subface(0, 2, 0.5, 0.25).unwrap().position);
    assert_eq!(point(&got["points"][1]), s.evaluate_subface(1, 1, 0.5, 0.75).unwrap().position);
    assert_eq!(point(&got["points"][2]), s.evaluate(2, 0.5, 0.5).unwrap().position);
}

/// `tessellate --tolerance`: every vertex of the mesh is a limit point (the cube's eight
/// corners among them at (±½, ±½, ±½)), the limit normal with it, and the surface between is
/// within the tolerance: each triangle's centroid is no farther than the tolerance (plus the
/// flat triangle's own sag, bounded by the chord height measured at edge midpoints) from
/// the exact limit at that point's parameters, checked here on the finest face's centre.
#[test]
fn tessellate_puts_the_mesh_on_the_limit_within_the_tolerance() {
    let mut doc = cube_doc();
    doc.as_object_mut().unwrap().remove("creases");
    let dir = ScratchDir::new("subdoc-tess");
    for tolerance in [1e-2, 1e-3] {
        let out = dir.join("cube.obj");
        let o = run(
            &["tessellate", "-", "-o", out.to_str().unwrap(), "--tolerance", &tolerance.to_string()],
            &doc.to_string(),
        );
        assert_eq!(o.code, 0, "{}", o.stderr);
        let text = std::fs::read_to_string(&out).unwrap();
        let v: Vec<Point<3>> = text
            .lines()
            .filter(|l| l.starts_with("v "))
            .map(|l| {
                let x: Vec<f64> = l.split_whitespace().skip(1).map(|x| x.parse().unwrap()).collect();
                Point::<3>::new(x[0], x[1], x[2])
            })
            .collect();
        // The corners keep their place and lie at the valence-3 limit.
        for p in &v[..8] {
            assert!((p.abs() - Point::<3>::new(0.5, 0.5, 0.5)).norm() < 1e-15, "{p}");
        }
        // Every vertex is on the limit surface: the cube's limit lies within the sphere
        // through its corners and outside the inscribed one, and every vertex is the limit
        // point of a vertex of the subdivided cage (compared with the kernel's limit masks).
        let s = kernel(&doc, Scheme::CatmullClark);
        let steps = (0..8).find(|&k| s.subdivide(k).unwrap().cage().vertices.len() == v.len()).expect("a level");
        let level = s.subdivide(steps).unwrap();
        for (i, p) in v.iter().enumerate() {
            let want = level.limit_frame(i as u32).unwrap().position;
            assert!((p - want).norm() < 1e-12, "vertex {i}: {p} vs {want}");
        }
        // The deviation one step on, by exact evaluation at each face-centre of the mesh's
        // cage: the limit at the quad's centre against the mean of its corners' limits,
        // along the normal.
        let mut worst = 0.0f64;
        let cage = level.cage();
        for f in 0..cage.face_count() {
            let centre = cage.face(f).iter().fold(Point::<3>::zeros(), |a, &i| a + v[i as usize]) / 4.0;
            let e = level.evaluate(f, 0.5, 0.5).unwrap();
            worst = worst.max((e.position - centre).dot(&e.normal).abs());
        }
        assert!(worst <= tolerance, "tolerance {tolerance}: a face centre is {worst} off");
        // …and the level before does not meet it (the fewest steps).
        let coarse = s.subdivide(steps - 1).unwrap();
        let lim: Vec<Point<3>> = coarse.limit_frames().unwrap().iter().map(|f| f.position).collect();
        let mut coarse_worst = 0.0f64;
        for f in 0..coarse.cage().face_count() {
            let centre = coarse.cage().face(f).iter().fold(Point::<3>::zeros(), |a, &i| a + lim[i as usize]) / 4.0;
            let e = coarse.evaluate(f, 0.5, 0.5).unwrap();
            coarse_worst = coarse_worst.max((e.position - centre).dot(&e.normal).abs());
        }
        assert!(coarse_worst > tolerance, "tolerance {tolerance}: {} steps would do ({coarse_worst})", steps - 1);
    }
}

/// A cage from an OBJ file beside the document (with its crease tags) is the same surface
/// as the cage given inline; a missing file names the field and the path.
#[test]
fn a_cage_file_is_read_relative_to_the_document() {
    let dir = ScratchDir::new("subdoc-obj");
    let cage = std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/../../examples/meshes/creased_cube.obj"))
        .unwrap();
    std::fs::write(dir.join("creased.obj"), &cage).unwrap();
    let doc = dir.join("doc.json");
    std::fs::write(&doc, r#"{"type":"subdivision_surface","obj":"creased.obj"}"#).unwrap();
    let o = run(&["eval", doc.to_str().unwrap(), "--at", "0.5:0.5,3.25:0.75", "--derivatives", "1"], "");
    assert_eq!(o.code, 0, "{}", o.stderr);
    let from_file: Value = serde_json::from_str(&o.stdout).unwrap();
    let parsed = splinekit::subdivision::surface::read_obj_cage(&cage).unwrap();
    let s = SubdivisionSurface::new(
        Cage::new(parsed.vertices.iter().map(|p| Point::<3>::from(*p)).collect(), &parsed.faces)
            .with_creases(parsed.creases.clone()),
        Scheme::CatmullClark,
        false,
    )
    .unwrap();
    assert!(!parsed.creases.is_empty());
    assert_eq!(point(&from_file["points"][0]), s.evaluate(0, 0.5, 0.5).unwrap().position);
    assert_eq!(point(&from_file["points"][1]), s.evaluate(3, 0.25, 0.75).unwrap().position);

    std::fs::write(&doc, r#"{"type":"subdivision_surface","obj":"missing.obj"}"#).unwrap();
    let o = run(&["eval", doc.to_str().unwrap(), "--at", "0.5:0.5"], "");
    assert_eq!(o.code, 2);
    assert!(
        o.stderr.starts_with("error: obj: cannot read the cage file") && o.stderr.contains("missing.obj"),
        "{}",
        o.stderr
    );
}

/// Bad cages are refused with one line naming the field.
#[test]
fn bad_cages_name_the_field() {
    let tri = json!([[0, 0, 0], [1, 0, 0], [0, 1, 0]]);
    for (extra, field) in [
        (json!({"faces": [[0, 1, 7]]}), "faces[0]: vertex 7 does not exist (there are 3)"),
        (json!({"vertices": [[0, 0], [1, 0], [0, 1]]}), "vertices[0]: a cage's vertices are 3-D"),
        (json!({"faces": [[0, 1]]}), "faces[0]: a face needs 3 or more vertices"),
        (json!({"creases": [{"edge": [0, 1], "sharpness": -1}]}), "creases[0].sharpness"),
        (json!({"scheme": "doo-sabin"}), "scheme"),
    ] {
        let mut doc = json!({"type": "subdivision_surface", "vertices": tri, "faces": [[0, 1, 2]]});
        doc.as_object_mut().unwrap().extend(extra.as_object().unwrap().clone());
        let o = run(&["eval", "-", "--at", "0.5:0.5"], &doc.to_string());
        assert_eq!(o.code, 2, "{doc}");
        assert_eq!(o.stderr.lines().count(), 1);
        assert!(o.stderr.contains(field), "{} lacks {field}", o.stderr);
    }
}

/// glTF export and rendering of a document and of a scene holding it (with its cage drawn).
#[test]
fn gltf_and_render_take_the_document() {
    let dir = ScratchDir::new("subdoc-gltf");
    let glb = dir.join("cube.glb");
    let o = run(&["tessellate", "-", "-o", glb.to_str().unwrap(), "--density", "16"], &cube_doc().to_string());
    assert_eq!(o.code, 0, "{}", o.stderr);
    let bytes = std::fs::read(&glb).unwrap();
    assert_eq!(&bytes[..4], b"glTF");
    let scene = json!({"type": "scene", "objects": [{"shape": cube_doc(), "control_net": true}]});
    let png = dir.join("cube.png");
    let o = run(&["render", "-", "-o", png.to_str().unwrap(), "--size", "64x48"], &scene.to_string());
    assert_eq!(o.code, 0, "{}", o.stderr);
    assert_eq!(&std::fs::read(&png).unwrap()[1..4], b"PNG");
}
