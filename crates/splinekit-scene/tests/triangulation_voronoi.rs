//! A `triangulation` document's `local_pieces` style draws the Voronoi diagram of its
//! points (issue 36): one cell per point, its vertices below the surface at the lowest
//! height; checked against the definition, not the construction: every cell vertex is
//! nearest to its own site (no site is nearer) and equidistant from at least three sites
//! (a circumcentre), a bounded cell is a closed convex polygon around its site, and only
//! the points on the convex hull have unbounded cells.

use serde_json::json;
use splinekit_scene::surfaces::{SurfaceDocument, TriangulationDoc};
use splinekit_scene::{DocumentKind, SurfaceDecoration};

fn triangulation(points: &[[f64; 3]]) -> TriangulationDoc {
    match SurfaceDocument::from_value(json!({"type": "triangulation", "points": points})).unwrap() {
        SurfaceDocument::Triangulation(d) => d,
        other => panic!("{other:?}"),
    }
}

#[test]
fn the_local_pieces_of_a_triangulation_are_its_voronoi_cells() {
    let mut state = 0x2545_f491_4f6c_dd1du64;
    let mut next = move || {
        state ^= state << 13;
        state ^= state >> 7;
        state ^= state << 17;
        (state >> 11) as f64 / (1u64 << 53) as f64
    };
    let points: Vec<[f64; 3]> = (0..80)
        .map(|_| {
            let (x, y) = (4.0 * next() - 2.0, 3.0 * next() - 1.5);
            [x, y, 0.3 * x * y + 1.0]
        })
        .collect();
    let doc = triangulation(&points);
    let SurfaceDecoration::LocalPieces(pieces) = doc.decoration() else { panic!("local pieces") };
    let cells = pieces.local_pieces().unwrap();
    assert_eq!(cells.len(), points.len(), "one cell per point");
    assert!(pieces.local_origins().unwrap().1.is_empty(), "no handles");
    let floor = points.iter().map(|p| p[2]).fold(f64::INFINITY, f64::min);
    let dist = |v: &[f64; 3], p: &[f64; 3]| (v[0] - p[0]).hypot(v[1] - p[1]);
    let mut bounded = 0;
    for (i, (lines, site)) in cells.iter().enumerate() {
        assert_eq!(*site, points[i], "the cell's point is point {i}");
        let Some(line) = lines.first() else { continue };
        for v in line {
            assert_eq!(v[2], floor, "cells lie at the lowest height");
            let own = dist(v, &points[i]);
            let tol = 1e-9 * (1.0 + own);
            assert!(points.iter().all(|p| dist(v, p) >= own - tol), "cell {i}: a site nearer than its own at {v:?}");
            let equidistant = points.iter().filter(|p| (dist(v, p) - own).abs() <= tol).count();
            assert!(equidistant >= 3, "cell {i}: {v:?} is equidistant from {equidistant} sites");
        }
        if line.len() > 3 && line.first() == line.last() {
            bounded += 1;
            // Counter-clockwise and convex around the site: every edge has the site on its left.
            for w in line.windows(2) {
                let (a, b) = (w[0], w[1]);
                let cross = (b[0] - a[0]) * (site[1] - a[1]) - (b[1] - a[1]) * (site[0] - a[0]);
                assert!(cross > 0.0, "cell {i}: the site is not inside");
            }
        }
    }
    // Unbounded cells belong to the hull's points: a point is on the hull exactly when a
    // line through it has every other point on one side; count them directly.
    let on_hull = (0..points.len())
        .filter(|&i| {
            (0..720).any(|k| {
                let a = k as f64 * std::f64::consts::PI / 360.0;
                let (c, s) = (a.cos(), a.sin());
                let at = |p: &[f64; 3]| (p[0] - points[i][0]) * c + (p[1] - points[i][1]) * s;
                points.iter().enumerate().all(|(j, p)| j == i || at(p) < 0.0)
            })
        })
        .count();
    assert_eq!(bounded, points.len() - on_hull, "{bounded} bounded cells, {on_hull} points on the hull");
}
