//! The triangle family in STEP (issue 36): a Bézier triangle, polynomial or rational,
//! leaves as its degenerate tensor patch of degree (n, n) and comes back (read by the
//! importer) as a surface that is the textbook Bernstein sum Σ n!/(i! j! k!) uⁱ vʲ wᵏ P_ijk
//! (weighted for rational ones) at (u, v, w) = (s(1 − t), s t, 1 − s) to 1e-14; a
//! Clough–Tocher triangulation leaves as one exact item per cubic piece; a blending
//! triangulation as one item per triangle within the tolerance.

use splinekit::Point;
use splinekit::surface::Surface;
use splinekit_scene::{SceneOrShape, ShapeDocument};
use splinekit_step::documents::{export_document, import_items};
use splinekit_step::part21::StepFile;
use splinekit_step::part21::writer::HeaderInfo;

fn factorial(n: usize) -> f64 {
    (1..=n).map(|k| k as f64).product()
}

/// The Bernstein sum of a net in storage order (b_n00 first, rows of falling i, each by
/// falling j), with weights.
fn bernstein(points: &[[f64; 3]], weights: &[f64], u: f64, v: f64, w: f64) -> Point<3> {
    let n = (0..).find(|n| (n + 1) * (n + 2) / 2 == points.len()).unwrap();
    let (mut num, mut den, mut at) = (Point::<3>::zeros(), 0.0, 0);
    for i in (0..=n).rev() {
        for j in (0..=n - i).rev() {
            let k = n - i - j;
            let b = factorial(n) / (factorial(i) * factorial(j) * factorial(k))
                * u.powi(i as i32)
                * v.powi(j as i32)
                * w.powi(k as i32)
                * weights[at];
            num += Point::<3>::from(points[at]) * b;
            den += b;
            at += 1;
        }
    }
    num / den
}

fn export(json: &str, tolerance: f64) -> (String, Vec<splinekit_step::documents::Exported>) {
    export_document(&SceneOrShape::from_json(json).unwrap(), "t", tolerance, &HeaderInfo::default()).unwrap()
}

#[test]
fn bezier_triangles_come_back_as_their_bernstein_sum() {
    let mut state = 0x5851_f42d_4c95_7f2du64;
    let mut next = move || {
        state ^= state << 13;
        state ^= state >> 7;
        state ^= state << 17;
        (state >> 11) as f64 / (1u64 << 53) as f64
    };
    let mut worst = 0.0f64;
    for n in [1, 2, 3, 4] {
        for rational in [false, true] {
            let len = (n + 1) * (n + 2) / 2;
            let points: Vec<[f64; 3]> = (0..len).map(|_| [4.0 * next() - 2.0, 4.0 * next() - 2.0, next()]).collect();
            let weights: Vec<f64> = (0..len).map(|_| if rational { 0.5 + 1.5 * next() } else { 1.0 }).collect();
            let mut doc = serde_json::json!({"type": "bezier_triangle", "control_points": points});
            if rational {
                doc["weights"] = serde_json::json!(weights);
            }
            let (text, exported) = export(&doc.to_string(), 1e-6);
            assert_eq!(exported.len(), 1);
            assert_eq!(exported[0].max_deviation, 0.0, "exact");
            assert!(text.contains("B_SPLINE_SURFACE_WITH_KNOTS"));
            assert_eq!(text.contains("RATIONAL_B_SPLINE_SURFACE"), rational, "degree {n}");
            let file = StepFile::from_bytes(text.into_bytes()).unwrap();
            let imported = import_items(&file).unwrap();
            assert!(imported.not_understood.is_empty(), "{:?}", imported.not_understood);
            let ShapeDocument::Surface(s) = &imported.items[0].document else { panic!("a surface") };
            let s = s.build_in::<3>().unwrap();
            for a in 0..=10 {
                for b in 0..=10 {
                    let (p, q) = (a as f64 / 10.0, b as f64 / 10.0);
                    let want = bernstein(&points, &weights, p * (1.0 - q), p * q, 1.0 - p);
                    let d = (s.point(p, q) - want).norm();
                    worst = worst.max(d / want.norm().max(1.0));
                    assert!(d <= 1e-14 * want.norm().max(1.0), "degree {n}, rational {rational}, ({p}, {q}): {d:e}");
                }
            }
        }
    }
    eprintln!("Bézier triangles through STEP: largest relative difference {worst:e}");
}

#[test]
fn triangulations_leave_one_item_per_piece() {
    let ct = r#"{"type": "triangulation", "points": [[0,0,1],[2,0,0],[1.2,1.5,0.3],[-1,1.7,0.2],[-2,0,0],[-1,-1.7,-0.2],[1,-1.7,0.1]], "interpolant": "clough_tocher"}"#;
    let (_, exported) = export(ct, 1e-6);
    // Six triangles around the centre, three cubic pieces each, every one exact.
    assert_eq!(exported.len(), 18);
    assert!(exported.iter().all(|e| e.max_deviation == 0.0));
    let blend = r#"{"type": "blending_triangulation", "mesh": {"type": "icosphere", "radius": 1, "subdivisions": 0}}"#;
    let (_, exported) = export(blend, 1e-2);
    assert_eq!(exported.len(), 20, "one item per triangle of the icosahedron");
    assert!(
        exported.iter().all(|e| e.max_deviation <= e.tolerance),
        "{:?}",
        exported.iter().map(|e| e.max_deviation).collect::<Vec<_>>()
    );
}
