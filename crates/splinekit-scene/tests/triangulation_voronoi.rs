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
    // The clipping box: the points' box grown by a tenth of its larger side each way.
    let (lo, hi) = (0..2).fold(([f64::INFINITY; 2], [f64::NEG_INFINITY; 2]), |(mut lo, mut hi), a| {
        points.iter().for_each(|p| (lo[a], hi[a]) = (lo[a].min(p[a]), hi[a].max(p[a])));
        (lo, hi)
    });
    let margin = 0.1 * (hi[0] - lo[0]).max(hi[1] - lo[1]);
    let on_box = |v: &[f64; 3]| {
        (0..2).any(|a| (v[a] - (lo[a] - margin)).abs() < 1e-12 || (v[a] - (hi[a] + margin)).abs() < 1e-12)
    };
    let mut closed = 0;
    let mut clipped = 0;
    for (i, (lines, site)) in cells.iter().enumerate() {
        assert_eq!(*site, points[i], "the cell's point is point {i}");
        for line in lines {
            assert!(line.len() >= 2, "cell {i}: a line of {} points", line.len());
            for v in line {
                assert_eq!(v[2], floor, "cells lie at the lowest height");
                assert!(
                    (0..2).all(|a| v[a] >= lo[a] - margin - 1e-12 && v[a] <= hi[a] + margin + 1e-12),
                    "inside the box"
                );
                let own = dist(v, &points[i]);
                let tol = 1e-9 * (1.0 + own);
                assert!(
                    points.iter().all(|p| dist(v, p) >= own - tol),
                    "cell {i}: a site nearer than its own at {v:?}"
                );
                // A circumcentre is equidistant from three sites; where a cell's edge was cut
                // by the box, the cut point is on the bisector of two.
                let equidistant = points.iter().filter(|p| (dist(v, p) - own).abs() <= tol).count();
                let need = if on_box(v) { 2 } else { 3 };
                clipped += usize::from(on_box(v));
                assert!(equidistant >= need, "cell {i}: {v:?} is equidistant from {equidistant} sites");
            }
            if line.len() > 3 && line.first() == line.last() {
                closed += 1;
                // Counter-clockwise and convex around the site: the site left of every edge.
                for w in line.windows(2) {
                    let (a, b) = (w[0], w[1]);
                    let cross = (b[0] - a[0]) * (site[1] - a[1]) - (b[1] - a[1]) * (site[0] - a[0]);
                    assert!(cross > 0.0, "cell {i}: the site is not inside");
                }
            }
        }
    }
    // Closed cells belong to points inside the hull: a point is on the hull exactly when a
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
    assert!(on_hull >= 3 && closed <= points.len() - on_hull, "{closed} closed cells, {on_hull} points on the hull");
    assert!(closed > points.len() / 2, "most cells are whole inside the box: {closed}");
    assert!(clipped > 0, "some far circumcentres were cut off");
}
