//! Delaunay triangulations and Voronoi diagrams against exact arithmetic: points on an
//! integer grid (|x|, |y| < 2²⁰, exact in f64), so the orientation and in-circle
//! determinants are computed exactly in i128 here, independently of spade's adaptive
//! predicates. By Delaunay's lemma a triangulation of the convex hull is Delaunay iff every
//! interior edge is locally Delaunay (the vertex across it lies outside or on the
//! circumcircle), which is what the tests check edge by edge.

use std::collections::{HashMap, HashSet};

use splinekit::Point;
use splinekit::triangulation::Delaunay;

/// A small deterministic generator (xorshift64*).
struct Rng(u64);
impl Rng {
    fn next_u64(&mut self) -> u64 {
        self.0 ^= self.0 >> 12;
        self.0 ^= self.0 << 25;
        self.0 ^= self.0 >> 27;
        self.0.wrapping_mul(0x2545_f491_4f6c_dd1d)
    }
    /// An integer in [−2²⁰, 2²⁰).
    fn coordinate(&mut self) -> i64 {
        (self.next_u64() >> 43) as i64 - (1 << 20)
    }
}

fn grid_points(rng: &mut Rng, n: usize) -> Vec<Point<2>> {
    let mut seen = HashSet::new();
    let mut out = Vec::with_capacity(n);
    while out.len() < n {
        let (x, y) = (rng.coordinate(), rng.coordinate());
        if seen.insert((x, y)) {
            out.push(Point::<2>::new(x as f64, y as f64));
        }
    }
    out
}

fn exact(p: &Point<2>) -> (i128, i128) {
    assert!(p.x.fract() == 0.0 && p.y.fract() == 0.0 && p.x.abs() < 2f64.powi(21));
    (p.x as i128, p.y as i128)
}

/// Twice the signed area of (a, b, c), exactly: > 0 counter-clockwise.
fn orient(a: &Point<2>, b: &Point<2>, c: &Point<2>) -> i128 {
    let ((ax, ay), (bx, by), (cx, cy)) = (exact(a), exact(b), exact(c));
    (bx - ax) * (cy - ay) - (by - ay) * (cx - ax)
}

/// The in-circle determinant, exactly: > 0 iff d is strictly inside the circle through
/// the counter-clockwise a, b, c. Entries are < 2²² and 2⁴⁵ in size, products < 2⁹⁰.
fn incircle(a: &Point<2>, b: &Point<2>, c: &Point<2>, d: &Point<2>) -> i128 {
    let (dx, dy) = exact(d);
    let row = |p: &Point<2>| {
        let (x, y) = exact(p);
        let (x, y) = (x - dx, y - dy);
        (x, y, x * x + y * y)
    };
    let ((a1, a2, a3), (b1, b2, b3), (c1, c2, c3)) = (row(a), row(b), row(c));
    a1 * (b2 * c3 - b3 * c2) - a2 * (b1 * c3 - b3 * c1) + a3 * (b1 * c2 - b2 * c1)
}

/// Checks that every triangle is counter-clockwise and not degenerate, that triangles
/// and edges fit Euler's formula for a triangulated convex hull (T = 2n − 2 − h), and that
/// every interior edge that is not a constraint is locally Delaunay. Returns the number
/// of edges checked.
fn assert_delaunay(d: &Delaunay) -> usize {
    let (v, tris) = (d.vertices(), d.triangles());
    let constraints: HashSet<(usize, usize)> =
        d.constraint_edges().iter().map(|&[a, b]| (a.min(b), a.max(b))).collect();
    let mut across: HashMap<(usize, usize), Vec<(usize, usize)>> = HashMap::new();
    for (t, &[a, b, c]) in tris.iter().enumerate() {
        assert!(orient(&v[a], &v[b], &v[c]) > 0, "triangle {t} is not counter-clockwise");
        for (p, q, r) in [(a, b, c), (b, c, a), (c, a, b)] {
            across.entry((p.min(q), p.max(q))).or_default().push((t, r));
        }
    }
    let hull = d.convex_hull().len();
    assert_eq!(tris.len(), 2 * v.len() - 2 - hull, "Euler: T = 2n − 2 − h");
    let mut checked = 0;
    for (edge, sides) in &across {
        assert!(sides.len() <= 2, "edge {edge:?} in {} triangles", sides.len());
        if sides.len() == 2 && !constraints.contains(edge) {
            for (k, &(t, _)) in sides.iter().enumerate() {
                let [a, b, c] = tris[t];
                let other = sides[1 - k].1;
                assert!(
                    incircle(&v[a], &v[b], &v[c], &v[other]) <= 0,
                    "vertex {other} lies inside the circumcircle of triangle {t} ({a}, {b}, {c})"
                );
            }
            checked += 1;
        }
    }
    checked
}

#[test]
fn every_circumcircle_is_empty_on_a_hundred_thousand_random_points() {
    let mut rng = Rng(0x9e37_79b9_7f4a_7c15);
    let points = grid_points(&mut rng, 100_000);
    let d = Delaunay::new(&points).unwrap();
    assert_eq!(d.vertices(), points, "vertex i is points[i]");
    let checked = assert_delaunay(&d);
    assert!(checked > 290_000, "{checked} interior edges");
}

#[test]
fn incremental_insertion_matches_the_property() {
    let mut rng = Rng(5);
    let points = grid_points(&mut rng, 3000);
    let mut d = Delaunay::new(&points[..10]).unwrap();
    for p in &points[10..] {
        d.insert(*p).unwrap();
    }
    assert_eq!(d.num_vertices(), 3000);
    assert_delaunay(&d);
    // A point already there is not added twice.
    let n = d.num_vertices();
    d.insert(points[7]).unwrap();
    assert_eq!(d.num_vertices(), n);
}

#[test]
fn constraint_edges_stay_and_the_rest_is_delaunay() {
    let mut rng = Rng(11);
    let mut points = grid_points(&mut rng, 5000);
    // A closed square-ish polygon of 40 vertices and a diagonal-free zigzag inside it.
    let first = points.len();
    for k in 0..40 {
        let a = std::f64::consts::TAU * k as f64 / 40.0;
        points.push(Point::<2>::new((500_000.0 * a.cos()).round(), (500_000.0 * a.sin()).round()));
    }
    let mut d = Delaunay::new(&points).unwrap();
    let vertices = d.vertices();
    let index = |p: &Point<2>| vertices.iter().position(|q| q == p).unwrap();
    let ring: Vec<usize> = (first..first + 40).map(|i| index(&points[i])).collect();
    for k in 0..40 {
        d.add_constraint(ring[k], ring[(k + 1) % 40]).unwrap();
    }
    // Every polygon edge is an edge of the triangulation (or split by a vertex on it).
    let edges: HashSet<(usize, usize)> = d.edges().iter().map(|&[a, b]| (a.min(b), a.max(b))).collect();
    let on_ring = (0..40)
        .filter(|&k| edges.contains(&(ring[k].min(ring[(k + 1) % 40]), ring[k].max(ring[(k + 1) % 40]))))
        .count();
    assert!(on_ring >= 38, "{on_ring} of 40 polygon edges are edges");
    assert!(d.constraint_edges().len() >= 40);
    assert_delaunay(&d);
    // A segment crossing the polygon is refused, not a panic; bad numbers name the field.
    let inside = index(&points[(0..first).find(|&i| points[i].norm() < 200_000.0).unwrap()]);
    let outside = index(&points[(0..first).find(|&i| points[i].norm() > 800_000.0).unwrap()]);
    let e = d.add_constraint(inside, outside).unwrap_err().to_string();
    assert!(e.starts_with("constraint:") && e.contains("crosses"), "{e}");
    assert!(d.add_constraint(0, 10_000_000).is_err());
    // Given constraints: the same, and errors name the edge and the point.
    let n = points.len();
    let ring_edges: Vec<[usize; 2]> = (0..40).map(|k| [first + k, first + (k + 1) % 40]).collect();
    let c = Delaunay::with_constraints(&points, &ring_edges).unwrap();
    assert!(c.constraint_edges().len() >= 40);
    let mut bad = ring_edges.clone();
    bad.push([0, n + 5]);
    assert!(Delaunay::with_constraints(&points, &bad).unwrap_err().to_string().starts_with("edges[40]:"));
    let mut twice = points.clone();
    twice.push(points[3]);
    let e = Delaunay::new(&twice).unwrap_err().to_string();
    assert!(e.starts_with(&format!("points[{n}]")) && e.contains("repeats points[3]"), "{e}");
    assert!(d.add_constraint(3, 3).is_err());
}

#[test]
fn removing_vertices_keeps_the_others_and_the_property() {
    let mut rng = Rng(17);
    let points = grid_points(&mut rng, 10_000);
    let mut d = Delaunay::new(&points).unwrap();
    let mut removed = HashSet::new();
    for _ in 0..1000 {
        let i = (rng.next_u64() % d.num_vertices() as u64) as usize;
        let p = d.remove(i).unwrap();
        assert!(removed.insert((p.x as i64, p.y as i64)));
    }
    let left: HashSet<(i64, i64)> = d.vertices().iter().map(|p| (p.x as i64, p.y as i64)).collect();
    let want: HashSet<(i64, i64)> =
        points.iter().map(|p| (p.x as i64, p.y as i64)).filter(|p| !removed.contains(p)).collect();
    assert_eq!(left, want);
    assert_delaunay(&d);
    assert!(d.remove(1_000_000).is_err());
}

#[test]
fn voronoi_cells_are_the_nearest_site_regions() {
    let mut rng = Rng(23);
    let points = grid_points(&mut rng, 2000);
    let d = Delaunay::new(&points).unwrap();
    let (v, tris) = (d.vertices(), d.triangles());
    // Every Voronoi vertex is equidistant from its triangle's three sites.
    for (c, t) in d.circumcenters().iter().zip(&tris) {
        let r = [0, 1, 2].map(|k| (c - v[t[k]]).norm());
        assert!((r[0] - r[1]).abs() <= 1e-9 * r[0] && (r[0] - r[2]).abs() <= 1e-9 * r[0], "{r:?}");
    }
    let cells = d.voronoi_cells();
    assert_eq!(cells.len(), v.len());
    let hull: HashSet<usize> = d.convex_hull().into_iter().collect();
    for (i, cell) in cells.iter().enumerate() {
        assert_eq!(cell.site, v[i]);
        assert_eq!(cell.bounded, !hull.contains(&i), "site {i}");
    }
    // Random query points: the nearest site's bounded cell contains the point.
    let mut hits = 0;
    for _ in 0..300 {
        let q = Point::<2>::new(rng.coordinate() as f64 * 0.8, rng.coordinate() as f64 * 0.8);
        let nearest = (0..v.len()).min_by(|&a, &b| (v[a] - q).norm().total_cmp(&(v[b] - q).norm())).unwrap();
        let cell = &cells[nearest];
        if !cell.bounded {
            continue;
        }
        hits += 1;
        let n = cell.vertices.len();
        for k in 0..n {
            let (a, b) = (cell.vertices[k], cell.vertices[(k + 1) % n]);
            let side = (b - a).x * (q - a).y - (b - a).y * (q - a).x;
            assert!(side >= -1e-6 * (b - a).norm() * (q - a).norm(), "query outside its nearest site's cell");
        }
    }
    assert!(hits > 250);
}
