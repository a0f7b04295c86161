//! `convert --report`: every STEP item is reported beside samples of the shape it was
//! written from, also where one object leaves several items (a surface of triangles leaves
//! one per triangle; its neighbours must not lend it their points).

use serde_json::Value;

mod common;
use common::{ScratchDir, run};

/// The largest distance of `points` from the plane through three of them far apart.
fn off_plane(points: &[[f64; 3]]) -> f64 {
    let sub = |a: [f64; 3], b: [f64; 3]| [a[0] - b[0], a[1] - b[1], a[2] - b[2]];
    let dot = |a: [f64; 3], b: [f64; 3]| a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
    let cross =
        |a: [f64; 3], b: [f64; 3]| [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];
    let p0 = points[0];
    let p1 = *points
        .iter()
        .max_by(|a, b| dot(sub(**a, p0), sub(**a, p0)).total_cmp(&dot(sub(**b, p0), sub(**b, p0))))
        .unwrap();
    let (n, area) = points
        .iter()
        .map(|q| {
            let n = cross(sub(p1, p0), sub(*q, p0));
            (n, dot(n, n))
        })
        .max_by(|a, b| a.1.total_cmp(&b.1))
        .unwrap();
    let n = n.map(|x| x / area.sqrt());
    points.iter().map(|q| dot(sub(*q, p0), n).abs()).fold(0.0, f64::max)
}

#[test]
fn each_triangle_item_is_reported_with_its_own_triangle() {
    // z = x² + y² at five points: four linear triangles of four different planes, after a
    // curve, so that items and objects are not one to one.
    let doc = r#"{"type": "scene", "objects": [
        {"shape": {"type": "bezier", "control_points": [[0, 0, 2], [1, 0, 2], [1, 1, 2]]}},
        {"shape": {"type": "triangulation",
                   "points": [[0, 0, 0], [1, 0, 1], [0, 1, 1], [1, 1, 2], [0.5, 0.5, 0.5]]}}]}"#;
    let dir = ScratchDir::new("convert-report-triangles");
    let (input, step, report) = (dir.join("in.json"), dir.join("out.step"), dir.join("report.json"));
    std::fs::write(&input, doc).unwrap();
    let o = run(
        &["convert", input.to_str().unwrap(), "-o", step.to_str().unwrap(), "--report", report.to_str().unwrap()],
        "",
    );
    assert_eq!(o.code, 0, "{}", o.stderr);
    assert!(o.stdout.is_empty(), "{}", o.stdout);
    let report: Value = serde_json::from_str(&std::fs::read_to_string(&report).unwrap()).unwrap();
    let items = report["items"].as_array().unwrap();
    let names: Vec<&str> = items.iter().map(|i| i["name"].as_str().unwrap()).collect();
    assert_eq!(names.len(), 5, "{names:?}");
    assert_eq!(items[0]["kind"], "curve");
    assert!(names[1..].iter().enumerate().all(|(c, n)| n.ends_with(&format!("triangle {c}"))), "{names:?}");
    // Every item's name is an item of the file.
    let text = std::fs::read_to_string(&step).unwrap();
    assert!(names.iter().all(|n| text.contains(&format!("'{n}'"))), "{names:?}");
    let mut planes = Vec::new();
    for item in &items[1..] {
        let points: Vec<[f64; 3]> = serde_json::from_value(item["points"].clone()).unwrap();
        assert_eq!(points.len(), 144);
        // A linear triangle: all its samples on one plane (a neighbour's would not be).
        assert!(off_plane(&points) < 1e-12, "{}: {:e} off its plane", item["name"], off_plane(&points));
        // The triangle is linear in its barycentric coordinates (s(1 − t), s t, 1 − s) at
        // (u, v) = (c + s, t): every sample is that combination of its three corners
        // (those at (s, t) = (1, 0), (1, 1), (0, ·)), which lie on z = x² + y².
        let params: Vec<[f64; 2]> = serde_json::from_value(item["params"].clone()).unwrap();
        let c = params[0][0].floor();
        let at = |s: f64, t: f64| points[params.iter().position(|p| p[0] - c == s && p[1] == t).unwrap()];
        let corners = [at(1.0, 0.0), at(1.0, 1.0), at(0.0, 0.0)];
        for k in corners {
            assert!((k[2] - (k[0] * k[0] + k[1] * k[1])).abs() < 1e-12, "{}: corner {k:?}", item["name"]);
        }
        for (p, q) in params.iter().zip(&points) {
            let (s, t) = (p[0] - c, p[1]);
            let l = [s * (1.0 - t), s * t, 1.0 - s];
            let expected: [f64; 3] = std::array::from_fn(|k| (0..3).map(|m| l[m] * corners[m][k]).sum());
            let error = (0..3).map(|k| (q[k] - expected[k]).abs()).fold(0.0, f64::max);
            assert!(error < 1e-12, "{}: at {p:?} {q:?}, the corners give {expected:?}", item["name"]);
        }
        let centroid = points.iter().fold([0.0; 3], |s, p| [s[0] + p[0], s[1] + p[1], s[2] + p[2]]);
        planes.push(centroid.map(|x| x / points.len() as f64));
    }
    // Four different triangles (their sample centroids apart).
    for (i, a) in planes.iter().enumerate() {
        for b in &planes[i + 1..] {
            assert!((0..3).map(|k| (a[k] - b[k]).abs()).fold(0.0, f64::max) > 0.05, "{planes:?}");
        }
    }
}
