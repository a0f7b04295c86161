//! Subdivision surfaces against independent truth: B-spline patches, closed-form limit
//! points of the cube and the icosahedron, crease curves, finite differences and the
//! subdominant eigenvalue.

mod common;

use splinekit::Point;
use splinekit::curve::{BSplineCurve, Curve};
use splinekit::subdivision::surface::{
    BoundaryRule, Cage, Crease, Scheme, SubdivisionSurface, Topology, catmull_clark::catmull_clark_step, local,
};
use splinekit::surface::{BSplineSurface, Surface};

fn p(x: f64, y: f64, z: f64) -> Point<3> {
    Point::<3>::new(x, y, z)
}

/// An (n+1)×(n+1) grid of vertices z = h(i, j) over [0, n]², quads counter-clockwise from +z.
fn grid(n: u32, h: impl Fn(u32, u32) -> f64) -> Cage {
    let mut v = Vec::new();
    for j in 0..=n {
        for i in 0..=n {
            v.push(p(i as f64, j as f64, h(i, j)));
        }
    }
    let id = |i: u32, j: u32| j * (n + 1) + i;
    let mut faces = Vec::new();
    for j in 0..n {
        for i in 0..n {
            faces.push(vec![id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)]);
        }
    }
    Cage::new(v, &faces)
}

/// The infinitely sharp creases along row `row` of an n × n grid's vertices (ids
/// row·(n + 1) + i, as [`grid`] numbers them).
fn sharp_row(n: u32, row: u32) -> Vec<Crease> {
    (0..n).map(|i| Crease { a: row * (n + 1) + i, b: row * (n + 1) + i + 1, sharpness: f64::INFINITY }).collect()
}

/// [`grid`]`(n, bumpy)` with infinitely sharp creases along row `row`.
fn grid_with_sharp_row(n: u32, row: u32) -> Cage {
    let mut cage = grid(n, bumpy);
    cage.creases = sharp_row(n, row);
    cage
}

fn bumpy(i: u32, j: u32) -> f64 {
    ((i * 7 + j * 3) as f64).sin() + 0.3 * ((i * j) as f64).cos()
}

fn close(a: Point<3>, b: Point<3>, tol: f64, what: &str) {
    assert!((a - b).norm() <= tol, "{what}: {a:?} vs {b:?} (|Δ| = {:e})", (a - b).norm());
}

/// On a regular grid the Catmull–Clark limit of a face is the uniform bicubic B-spline
/// patch of the 4×4 points around it (knots −3..4, span [0, 1]), built with splinekit's own
/// B-spline surface: position and all partials to 1e-14 (relative to the data's size 1).
#[test]
fn regular_quads_are_the_bicubic_bspline_patch() {
    let cage = grid(6, bumpy);
    let s = SubdivisionSurface::new(cage.clone(), Scheme::CatmullClark, false).unwrap();
    let face = 2 * 6 + 3; // face (3, 2): corners (3,2), (4,2), (4,3), (3,3)
    let net: Vec<Vec<Point<3>>> =
        (0..4).map(|a| (0..4).map(|b| cage.vertices[((2 + b - 1) * 7 + (3 + a - 1)) as usize]).collect()).collect();
    let knots: Vec<f64> = (-3..=4).map(f64::from).collect();
    let b = BSplineSurface::new((3, 3), knots.clone(), knots, net, (false, false)).unwrap();
    for &(u, v) in &[(0.0, 0.0), (0.3, 0.7), (0.5, 0.5), (1.0, 0.25), (0.9, 1.0), (0.123, 0.456)] {
        let e = s.evaluate(face, u, v).unwrap();
        let d = e.partials.unwrap();
        close(e.position, b.point(u, v), 1e-14, "position");
        close(d.du, b.partial(u, v, 1, 0), 1e-14, "du");
        close(d.dv, b.partial(u, v, 0, 1), 1e-14, "dv");
        close(d.duu, b.partial(u, v, 2, 0), 1e-13, "duu");
        close(d.duv, b.partial(u, v, 1, 1), 1e-13, "duv");
        close(d.dvv, b.partial(u, v, 0, 2), 1e-13, "dvv");
    }
}

/// Cube closed forms. Corner (valence 3): the mask (n²v + 4Σeᵢ + Σdᵢ)/(n(n + 5)) with
/// n = 3 gives x = (9·1 + 4(−1 + 1 + 1) + (−1 − 1 + 1))/24 = 12/24, so (½, ½, ½).
/// Face centre: after one step the face point f = (0, 0, 1) has valence 4, edge
/// neighbours (¾, 0, ¾) and its turns, diagonal neighbours the vertex points (5/9)(±1, ±1, 1);
/// its limit (16f + 4Σe + Σd)/36 has z = (16 + 12 + 20/9)/36 = 68/81. Normals by symmetry.
#[test]
fn cube_limit_points_and_normals_in_closed_form() {
    let s = SubdivisionSurface::new(Cage::cube(), Scheme::CatmullClark, false).unwrap();
    let f = s.limit_frame(7).unwrap();
    close(f.position, p(0.5, 0.5, 0.5), 1e-15, "corner limit");
    close(f.normal, p(1.0, 1.0, 1.0) / 3f64.sqrt(), 1e-15, "corner normal");
    // Face 1 is z = +1 (4, 5, 7, 6).
    let c = s.evaluate(1, 0.5, 0.5).unwrap();
    close(c.position, p(0.0, 0.0, 68.0 / 81.0), 1e-15, "face centre");
    close(c.normal, p(0.0, 0.0, 1.0), 1e-15, "face-centre normal");
    let corner = s.evaluate(1, 0.0, 0.0).unwrap();
    close(corner.position, p(-0.5, -0.5, 0.5), 1e-15, "corner by evaluation");
    assert!(corner.partials.is_none(), "no partials at an extraordinary vertex");
    // Seven global steps: the 0.5000012 and 0.83954, near but not at the limit.
    let k = s.subdivide(5).unwrap();
    assert!((k.cage().vertices[7] - p(0.5, 0.5, 0.5)).norm() > 1e-6);
}

/// Icosahedron (valence 5 everywhere, circumradius 1) under Loop: the neighbours of v sum
/// to √5·v (each has v·e = 1/√5), so the mask (ωv + Σeᵢ)/(ω + 5) with ω = 3/(8β₅) puts
/// the limit at (ω + √5)/(ω + 5)·v, with the normal v.
#[test]
fn icosahedron_loop_limit_in_closed_form() {
    let cage = common::cages::icosahedron();
    let v = cage.vertices.clone();
    let s = SubdivisionSurface::new(cage, Scheme::Loop, false).unwrap();
    let c = 0.375 + 0.25 * (std::f64::consts::TAU / 5.0).cos();
    let beta = (0.625 - c * c) / 5.0;
    let omega = 3.0 / (8.0 * beta);
    let r = (omega + 5f64.sqrt()) / (omega + 5.0);
    for (i, x) in v.iter().enumerate() {
        let f = s.limit_frame(i as u32).unwrap();
        close(f.position, x * r, 1e-15, "limit point");
        close(f.normal, *x, 1e-14, "normal");
    }
    // Exact evaluation at a face's corner and centre: the centre lies on the sphere? No —
    // but it is symmetric: along the face's centroid direction.
    let e = s.evaluate(0, 1.0 / 3.0, 1.0 / 3.0).unwrap();
    let centroid = (v[0] + v[11] + v[5]) / 3.0;
    assert!(e.position.normalize().cross(&centroid.normalize()).norm() < 1e-13);
    close(e.normal, centroid.normalize(), 1e-13, "centre normal");
    close(s.evaluate(0, 0.0, 0.0).unwrap().position, v[0] * r, 1e-15, "corner by evaluation");
}

/// Partials by central differences (h = 1e-4 for first partials, 1e-5 on the first
/// partials for second ones: errors O(h²)) near and away from extraordinary vertices, for
/// Catmull–Clark on the cube (valence 3) and Loop on the fan-triangulated cube (valences
/// 3 to 6).
#[test]
fn partials_match_finite_differences() {
    let cases = [
        SubdivisionSurface::new(Cage::cube(), Scheme::CatmullClark, false).unwrap(),
        SubdivisionSurface::new(Cage::cube(), Scheme::Loop, true).unwrap(),
    ];
    for s in &cases {
        // Points off every dyadic line u, v, u + v = k/2ʲ: the patches join C² (not C³), so a
        // central difference straddling a join is only O(h).
        for &(u, v) in &[(0.31, 0.17), (0.01, 0.02), (0.2, 0.6), (0.43, 0.06)] {
            let h = 1e-4;
            let at = |u: f64, v: f64| s.evaluate(0, u, v).unwrap();
            let e = at(u, v);
            let d = e.partials.unwrap();
            let fu = (at(u + h, v).position - at(u - h, v).position) / (2.0 * h);
            let fv = (at(u, v + h).position - at(u, v - h).position) / (2.0 * h);
            close(d.du, fu, 1e-6, "du");
            close(d.dv, fv, 1e-6, "dv");
            let h = 1e-5;
            let fuu = (at(u + h, v).partials.unwrap().du - at(u - h, v).partials.unwrap().du) / (2.0 * h);
            let fuv = (at(u, v + h).partials.unwrap().du - at(u, v - h).partials.unwrap().du) / (2.0 * h);
            let fvv = (at(u, v + h).partials.unwrap().dv - at(u, v - h).partials.unwrap().dv) / (2.0 * h);
            let scale = 1.0 + d.duu.norm().max(d.dvv.norm());
            close(d.duu, fuu, 1e-6 * scale, &format!("duu at ({u}, {v})"));
            close(d.duv, fuv, 1e-6 * scale, &format!("duv at ({u}, {v})"));
            close(d.dvv, fvv, 1e-6 * scale, &format!("dvv at ({u}, {v})"));
        }
    }
}

/// The patch path and the mask path agree: the point (3/8, 3/8) of a cube face is, after
/// three steps, the face point of level-2 face 2 (child at corner 2 of level-1 face 0), a
/// regular vertex whose limit mask gives its limit; local evaluation reaches it through a
/// regular bicubic patch instead.
#[test]
fn exact_evaluation_agrees_with_global_subdivision_and_masks() {
    let s = SubdivisionSurface::new(Cage::cube(), Scheme::CatmullClark, false).unwrap();
    let l2 = s.subdivide(2).unwrap();
    let l3 = l2.step().unwrap();
    let vertex = (l2.cage().vertices.len() + 2) as u32;
    let by_mask = l3.limit_frame(vertex).unwrap();
    let by_eval = s.evaluate(0, 0.375, 0.375).unwrap();
    close(by_eval.position, by_mask.position, 1e-14, "limit point");
    close(by_eval.normal, by_mask.normal, 1e-13, "normal");
}

/// Near an extraordinary vertex of valence n the ring of level-k neighbours shrinks
/// towards the limit point like λⁿᵏ, λ = (5 + cos(2π/n) + cos(π/n)√(18 + 2cos(2π/n)))/16
/// the subdominant eigenvalue of Catmull–Clark: the ratio of successive distances tends
/// to λ.
#[test]
fn rings_converge_at_the_subdominant_eigenvalue() {
    for n in [3usize, 5, 6] {
        // A fan of n quads around vertex 0, lifted so the limit is not flat.
        let mut v = vec![p(0.0, 0.0, 0.3)];
        for i in 0..2 * n {
            let a = std::f64::consts::PI * i as f64 / n as f64;
            let r = if i % 2 == 0 { 1.0 } else { 1.6 };
            v.push(p(r * a.cos(), r * a.sin(), 0.2 * (i as f64).sin()));
        }
        let faces: Vec<Vec<u32>> =
            (0..n as u32).map(|i| vec![0, 2 * i + 1, 2 * i + 2, (2 * i + 2) % (2 * n as u32) + 1]).collect();
        let s = SubdivisionSurface::new(Cage::new(v, &faces), Scheme::CatmullClark, false).unwrap();
        let limit = s.limit_frame(0).unwrap().position;
        let theta = std::f64::consts::TAU / n as f64;
        let lambda = (5.0 + theta.cos() + (theta / 2.0).cos() * (18.0 + 2.0 * theta.cos()).sqrt()) / 16.0;
        let mut cage = s.cage().clone();
        let mut dist = Vec::new();
        for _ in 0..14 {
            let t = Topology::new(&cage).unwrap();
            let ring: f64 = t.vertex_edges(0).iter().map(|&(_, w)| (cage.vertices[w as usize] - limit).norm()).sum();
            dist.push(ring);
            let (star, _) = local::sub_cage(&cage, &t, &local::star_faces(&t, 0));
            let st = Topology::new(&star).unwrap();
            cage = catmull_clark_step(&star, &st);
        }
        let ratio = dist[13] / dist[12];
        assert!((ratio - lambda).abs() < 2e-3, "n = {n}: ratio {ratio}, λ = {lambda}");
        // And the limit mask is the limit: the centre itself converges.
        assert!((cage.vertices[0] - limit).norm() < 1e-6);
    }
}

/// An infinitely sharp crease along a row of a grid: on either side, the limit along the
/// crease is the uniform cubic B-spline curve of the crease vertices (built with
/// splinekit's B-spline curve), so the surface is only C⁰ across it.
#[test]
fn infinitely_sharp_crease_limit_is_the_cubic_bspline_of_its_vertices() {
    let (n, row) = (8u32, 4u32);
    let cage = grid_with_sharp_row(n, row);
    let s = SubdivisionSurface::new(cage.clone(), Scheme::CatmullClark, false).unwrap();
    let pts: Vec<Point<3>> = (0..=n).map(|i| cage.vertices[(row * (n + 1) + i) as usize]).collect();
    let knots: Vec<f64> = (-3..=(n as i32 + 1)).map(f64::from).collect();
    // Uniform cubic on the inner crease vertices 2..6 (spans away from the grid's corners).
    let curve = BSplineCurve::new(3, knots[..pts.len() + 4].to_vec(), pts.clone()).unwrap();
    for i in 3..5u32 {
        for &t in &[0.0, 0.25, 0.6, 1.0] {
            // With knots j − 3 the span [i − 1, i] runs between crease vertices i and i + 1.
            let below = s.evaluate(((row - 1) * n + i) as usize, t, 1.0).unwrap();
            let above = s.evaluate((row * n + i) as usize, t, 0.0).unwrap();
            let c = curve.point(i as f64 - 1.0 + t);
            close(below.position, c, 1e-14, "below");
            close(above.position, c, 1e-14, "above");
        }
    }
    // Without the crease the two sides join smoothly; with it the tangents across differ.
    let below = s.evaluate(((row - 1) * n + 3) as usize, 0.5, 1.0).unwrap();
    let above = s.evaluate((row * n + 3) as usize, 0.5, 0.0).unwrap();
    assert!((below.normal - above.normal).norm() > 1e-3);
}

/// Semi-sharp rules by hand (DeRose–Kass–Truong, OpenSubdiv uniform decay): a vertex with
/// two crease edges of sharpness 1 moves by (e₀ + 6v + e₁)/8 once, and the child edges
/// are smooth; sharpness ½ blends the crease and smooth points half and half.
#[test]
fn semi_sharp_creases_follow_the_published_rules() {
    let n = 4u32;
    let base = grid(n, bumpy);
    let row = 2u32;
    let mid = row * (n + 1) + 2;
    let (e0, e1) = (mid - 1, mid + 1);
    let smooth = SubdivisionSurface::new(base.clone(), Scheme::CatmullClark, false).unwrap().step().unwrap();
    for s in [1.0, 0.5, 2.5] {
        let cage = base
            .clone()
            .with_creases(vec![Crease { a: e0, b: mid, sharpness: s }, Crease { a: mid, b: e1, sharpness: s }]);
        let sub = SubdivisionSurface::new(cage.clone(), Scheme::CatmullClark, false).unwrap().step().unwrap();
        let v = cage.vertices[mid as usize];
        let crease = (cage.vertices[e0 as usize] + v * 6.0 + cage.vertices[e1 as usize]) / 8.0;
        let w = s.min(1.0);
        close(
            sub.cage().vertices[mid as usize],
            crease * w + smooth.cage().vertices[mid as usize] * (1.0 - w),
            1e-15,
            "vertex",
        );
        let child: Vec<f64> = sub.cage().creases.iter().map(|c| c.sharpness).collect();
        let expected = (s - 1.0f64).max(0.0);
        assert!(child.iter().all(|&c| c == expected) && child.len() == if expected > 0.0 { 4 } else { 0 });
    }
    // Three sharp edges make a corner: the vertex stays.
    let corner = base.clone().with_creases(vec![
        Crease { a: e0, b: mid, sharpness: 3.0 },
        Crease { a: mid, b: e1, sharpness: 3.0 },
        Crease { a: mid, b: mid + n + 1, sharpness: 3.0 },
    ]);
    let sub = SubdivisionSurface::new(corner.clone(), Scheme::CatmullClark, false).unwrap().step().unwrap();
    assert_eq!(sub.cage().vertices[mid as usize], corner.vertices[mid as usize]);
    // Exact evaluation through semi-sharp edges: the limit at the crease vertex equals
    // the limit of the once-subdivided cage (the first step is the only non-smooth one
    // for sharpness 1).
    let one = base
        .clone()
        .with_creases(vec![Crease { a: e0, b: mid, sharpness: 1.0 }, Crease { a: mid, b: e1, sharpness: 1.0 }]);
    let s0 = SubdivisionSurface::new(one, Scheme::CatmullClark, false).unwrap();
    let s1 = s0.step().unwrap();
    close(s0.limit_frame(mid).unwrap().position, s1.limit_frame(mid).unwrap().position, 1e-15, "semi-sharp limit");
    // (face, u, v) at the crease vertex is the corner (1, 1) of face (1, 1).
    let e = s0.evaluate((n + 1) as usize, 1.0, 1.0).unwrap();
    close(e.position, s1.limit_frame(mid).unwrap().position, 1e-14, "semi-sharp evaluation");
}

/// Boundaries: with "edge only" the boundary limit curve of a grid is the cubic B-spline of
/// the boundary vertices; with "edge and corner" the cage's corners are interpolated.
#[test]
fn boundary_rules() {
    let n = 6u32;
    let cage = grid(n, bumpy);
    let s = SubdivisionSurface::new(cage.clone(), Scheme::CatmullClark, false).unwrap();
    let pts: Vec<Point<3>> = (0..=n).map(|i| cage.vertices[i as usize]).collect();
    let knots: Vec<f64> = (-3..=(n as i32 + 1)).map(f64::from).collect();
    let curve = BSplineCurve::new(3, knots[..pts.len() + 4].to_vec(), pts).unwrap();
    for i in 2..4u32 {
        let e = s.evaluate(i as usize, 0.3, 0.0).unwrap();
        close(e.position, curve.point(i as f64 - 1.0 + 0.3), 1e-14, "boundary curve");
        // And the B-spline with phantom points is exact off the boundary too: compare with
        // the limit of one more step.
        let s1 = s.step().unwrap();
        let f = s1.limit_frame(cage.vertices.len() as u32 + i).unwrap(); // face point of face i
        close(s.evaluate(i as usize, 0.5, 0.5).unwrap().position, f.position, 1e-14, "face point");
    }
    let corners =
        SubdivisionSurface::new(cage.clone().with_boundary(BoundaryRule::EdgeAndCorner), Scheme::CatmullClark, false)
            .unwrap();
    close(corners.limit_frame(0).unwrap().position, cage.vertices[0], 0.0, "corner interpolated");
    close(corners.evaluate(0, 0.0, 0.0).unwrap().position, cage.vertices[0], 1e-15, "corner by evaluation");
    let edge_only = s.limit_frame(0).unwrap().position;
    assert!((edge_only - cage.vertices[0]).norm() > 1e-3, "edge-only corners are smoothed");
}

/// The Loop box-spline patch: partition of unity, C² joins across an edge between two
/// regular triangles, and agreement with the vertex limit masks after two steps.
#[test]
fn loop_regular_patches_are_c2_box_splines() {
    // A triangulated bumpy grid: quads split along one diagonal give valence 6 inside.
    let q = grid(8, bumpy);
    let mut faces = Vec::new();
    for f in 0..q.face_count() {
        let c = q.face(f);
        faces.push(vec![c[0], c[1], c[2]]);
        faces.push(vec![c[0], c[2], c[3]]);
    }
    let cage = Cage::new(q.vertices.clone(), &faces);
    let s = SubdivisionSurface::new(cage, Scheme::Loop, false).unwrap();
    let w = splinekit::subdivision::surface::box_spline::loop_basis(0.2, 0.3);
    assert!((w[0].iter().sum::<f64>() - 1.0).abs() < 1e-14);
    for d in 1..6 {
        assert!(w[d].iter().sum::<f64>().abs() < 1e-12);
    }
    // Quad (3, 3) → triangles 2·27 = 54 (c0, c1, c2) and 55 (c0, c2, c3), sharing c0–c2.
    // On 54, (u, v) runs c0→c1, c0→c2; on 55, c0→c2, c0→c3. The shared edge: 54 at
    // (0, t)... 54's edge c0→c2 is v = t, u = 0... it is (u, v) = (0, t) on 54 and (t, 0)
    // on 55, and the directions map as ∂v(54) = ∂u(55) along the edge.
    for &t in &[0.2, 0.5, 0.8] {
        let a = s.evaluate(54, 0.0, t).unwrap();
        let b = s.evaluate(55, t, 0.0).unwrap();
        close(a.position, b.position, 1e-14, "C⁰");
        let (da, db) = (a.partials.unwrap(), b.partials.unwrap());
        close(da.dv, db.du, 1e-13, "C¹ along");
        close(da.dvv, db.duu, 1e-12, "C² along");
        // Across: x(54) = c0 + u(c1 − c0) + v(c2 − c0), x(55) = c0 + u'(c2 − c0) + v'(c3 − c0);
        // with c3 − c0 = (c2 − c0) − (c1 − c0) on the lattice, u = −v', v = u' + v'.
        // So ∂v' = −∂u + ∂v on 54's side.
        close(db.dv, -da.du + da.dv, 1e-13, "C¹ across");
        close(db.dvv, da.duu - 2.0 * da.duv + da.dvv, 1e-11, "C² across");
    }
    // Corner of a regular face: the patch equals the limit mask there.
    let f = s.limit_frame(q.face(27)[0]).unwrap();
    close(s.evaluate(54, 0.0, 0.0).unwrap().position, f.position, 1e-14, "mask");
}

#[test]
fn loop_refuses_polygons_unless_triangulating() {
    let err = SubdivisionSurface::new(Cage::cube(), Scheme::Loop, false).unwrap_err().to_string();
    assert!(err.contains("faces[0]") && err.contains("4 vertices") && err.contains("triangulation"), "{err}");
    assert!(SubdivisionSurface::new(Cage::cube(), Scheme::Loop, true).is_ok());
}

#[test]
fn bad_cages_are_refused_with_the_field() {
    let mut c = Cage::cube();
    c.creases = vec![Crease { a: 0, b: 7, sharpness: 1.0 }];
    let e = SubdivisionSurface::new(c, Scheme::CatmullClark, false).unwrap_err().to_string();
    assert!(e.contains("creases[0]") && e.contains("0–7"), "{e}");
    let bad = Cage::new(vec![p(0.0, 0.0, 0.0); 3], &[vec![0, 1, 2], vec![0, 1, 2]]);
    assert!(SubdivisionSurface::new(bad, Scheme::CatmullClark, false).is_err());
    let s = SubdivisionSurface::new(Cage::cube(), Scheme::CatmullClark, false).unwrap();
    assert!(s.evaluate(9, 0.5, 0.5).unwrap_err().to_string().contains("9 does not exist"));
    assert!(s.evaluate(0, 1.5, 0.5).unwrap_err().to_string().contains("outside"));
}

/// Linear time: a step on 10⁴ quads makes 4·10⁴ quads, vertex i staying vertex i.
#[test]
fn a_step_keeps_vertex_order_and_counts() {
    let s = SubdivisionSurface::new(grid(100, bumpy), Scheme::CatmullClark, false).unwrap();
    let t = s.step().unwrap();
    assert_eq!(t.cage().face_count(), 40_000);
    assert_eq!(t.cage().vertices.len(), 201 * 201);
    // Bilinear keeps the vertices themselves.
    let b = SubdivisionSurface::new(Cage::cube(), Scheme::Bilinear, false).unwrap();
    let b1 = b.step().unwrap();
    assert_eq!(&b1.cage().vertices[..8], &b.cage().vertices[..]);
    close(b.evaluate(1, 0.5, 0.5).unwrap().position, p(0.0, 0.0, 1.0), 1e-15, "bilinear centre");
}

/// Loop along a boundary: the limit curve of an open triangulated grid's border is the
/// uniform cubic B-spline of its boundary vertices (the crease rules (1, 6, 1)/8 and
/// midpoints are cubic B-spline subdivision), and points just inside converge to it.
#[test]
fn loop_boundary_limit_is_the_cubic_bspline_of_the_border() {
    let n = 6u32;
    let q = triangulated_grid(n);
    let s = SubdivisionSurface::new(q.clone(), Scheme::Loop, false).unwrap();
    let pts: Vec<Point<3>> = (0..=n).map(|i| q.vertices[i as usize]).collect();
    let knots: Vec<f64> = (-3..=(n as i32 + 1)).map(f64::from).collect();
    let curve = BSplineCurve::new(3, knots[..pts.len() + 4].to_vec(), pts).unwrap();
    for i in 2..4u32 {
        // Triangle 2i = (c0, c1, c2) of quad (i, 0): its edge c0→c1 (v = 0) is the border.
        for &t in &[0.3, 0.5] {
            let e = s.evaluate(2 * i as usize, t, 0.0).unwrap();
            close(e.position, curve.point(i as f64 - 1.0 + t), 1e-14, "boundary point");
            let inside = s.evaluate(2 * i as usize, t, 1e-9).unwrap();
            assert!((inside.position - e.position).norm() < 1e-7);
            assert!(inside.normal.dot(&e.normal) > 0.999, "{:?} vs {:?}", inside.normal, e.normal);
        }
    }
}

/// At a vertex on an infinitely sharp crease each side has its own tangent plane: the
/// evaluation at the vertex from a face on either side gives that side's normal, the one
/// its own regular patch gives a little way off the vertex along the crease.
#[test]
fn crease_vertex_normals_belong_to_their_side() {
    let (n, row) = (8u32, 4u32);
    let cage = grid_with_sharp_row(n, row);
    // The crease vertices are regular crease vertices, so the phantom-point patches give
    // the exact normal at the vertex on each side; the sector masks must agree.
    let s = SubdivisionSurface::new(cage, Scheme::CatmullClark, false).unwrap();
    let v = row * (n + 1) + 4;
    let t = s.topology();
    let frames = s.limit_frames().unwrap();
    let corners = s.limit_corner_normals(&frames);
    let below = s.evaluate(((row - 1) * n + 4) as usize, 0.0, 1.0).unwrap(); // corner c3 of the face below
    let above = s.evaluate((row * n + 4) as usize, 0.0, 0.0).unwrap(); // corner c0 of the face above
    assert!((below.normal - above.normal).norm() > 1e-3);
    for (h, nrm) in corners.iter().enumerate() {
        if t.origin(h as u32) == v {
            let f = t.he_face[h];
            let expected = if f < row * n { below.normal } else { above.normal };
            close(*nrm, expected, 1e-13, "sector normal");
        }
    }
}

/// The triangulated grid of `grid(n, bumpy)`: each quad (c₀, c₁, c₂, c₃) cut along c₀c₂,
/// a regular lattice whose border vertices have valence 4 (corners 2 and 3).
fn triangulated_grid(n: u32) -> Cage {
    let q = grid(n, bumpy);
    let mut faces = Vec::new();
    for f in 0..q.face_count() {
        let c = q.face(f);
        faces.push(vec![c[0], c[1], c[2]]);
        faces.push(vec![c[0], c[2], c[3]]);
    }
    Cage::new(q.vertices.clone(), &faces)
}

/// The level-`levels` vertices inside level-0 triangle f, with their (u, v): child k of a
/// triangle (a, b, c) is (a, e_ab, e_ca), (e_ab, b, e_bc), (e_ca, e_bc, c), (e_bc, e_ca, e_ab)
/// in that order (loop_step's numbering), face 4f + k of the next level.
fn loop_vertices_in(fine: &Cage, levels: u32, f: usize) -> Vec<(u32, (f64, f64))> {
    fn walk(fine: &Cage, levels: u32, f: usize, corners: [(f64, f64); 3], out: &mut Vec<(u32, (f64, f64))>) {
        if levels == 0 {
            for (k, &c) in fine.face(f).iter().enumerate() {
                out.push((c, corners[k]));
            }
            return;
        }
        let mid = |a: (f64, f64), b: (f64, f64)| ((a.0 + b.0) / 2.0, (a.1 + b.1) / 2.0);
        let [a, b, c] = corners;
        let (ab, bc, ca) = (mid(a, b), mid(b, c), mid(c, a));
        for (k, child) in [[a, ab, ca], [ab, b, bc], [ca, bc, c], [bc, ca, ab]].into_iter().enumerate() {
            walk(fine, levels - 1, 4 * f + k, child, out);
        }
    }
    let mut out = Vec::new();
    walk(fine, levels, f, [(0.0, 0.0), (1.0, 0.0), (0.0, 1.0)], &mut out);
    out
}

/// Loop triangles along a border or an infinitely sharp crease are box-spline patches of
/// their points with phantom points beyond the crease (regular_patch.rs). Independent
/// truth: two global Loop steps with the crease rules, then the limit mask at every
/// level-2 vertex inside every triangle, against `evaluate` at that vertex's (u, v). The
/// border and crease triangles now carry partials, checked against finite differences
/// right up to the crease (one-sided across it).
#[test]
fn loop_border_and_crease_triangles_are_exact_patches_with_partials() {
    let n = 6u32;
    let plain = triangulated_grid(n);
    let mut creased = plain.clone();
    let row = 3u32;
    creased.creases = sharp_row(n, row);
    for (name, cage) in [("border", plain), ("crease", creased)] {
        let s = SubdivisionSurface::new(cage, Scheme::Loop, false).unwrap();
        let fine = s.subdivide(2).unwrap();
        let mut with_partials = 0;
        for f in 0..s.cage().face_count() {
            for (vertex, (u, v)) in loop_vertices_in(fine.cage(), 2, f) {
                let by_mask = fine.limit_frame(vertex).unwrap();
                let by_eval = s.evaluate(f, u, v).unwrap();
                close(by_eval.position, by_mask.position, 1e-13, &format!("{name}: face {f} at ({u}, {v})"));
                // A vertex on the interior crease has a tangent plane on each side; the
                // vertex mask gives one of them (the sector masks are tested elsewhere).
                let on_crease = fine
                    .topology()
                    .vertex_edges(vertex)
                    .iter()
                    .any(|&(e, _)| fine.topology().sharpness[e as usize] > 0.0);
                if !on_crease {
                    close(by_eval.normal, by_mask.normal, 1e-12, &format!("{name}: normal, face {f} at ({u}, {v})"));
                }
            }
        }
        // Triangle 2i + 1 = (c₀, c₂, c₃) of quad (i, j) has its edge c₂ → c₃ (u + v = 1 … the
        // edge from (1, 0) to (0, 1)) on row j + 1; triangle 2i of quad (i, j) has c₀ → c₁
        // (v = 0) on row j. Take the triangles whose v = 0 edge lies on the border (j = 0)
        // or on the crease row from above (j = row), away from the grid's corners.
        for j in [0, row] {
            for i in 2..4u32 {
                let f = (2 * (j * n + i)) as usize;
                let at = |u: f64, v: f64| s.evaluate(f, u, v).unwrap();
                for &(u, v) in &[(0.3, 0.0), (0.02, 0.0), (0.41, 0.02), (0.2, 0.37)] {
                    let e = at(u, v);
                    let d = e.partials.unwrap_or_else(|| panic!("{name}: no partials on face {f} at ({u}, {v})"));
                    with_partials += 1;
                    let h = 1e-5;
                    let fu = (at(u + h, v).position - at(u - h, v).position) / (2.0 * h);
                    // One-sided second-order difference in v: the face ends at v = 0.
                    let fv = (at(u, v + h).position * 4.0 - at(u, v + 2.0 * h).position - e.position * 3.0) / (2.0 * h);
                    close(d.du, fu, 1e-6, &format!("{name}: du at ({u}, {v})"));
                    close(d.dv, fv, 1e-5, &format!("{name}: dv at ({u}, {v})"));
                    let fuu = (at(u + h, v).partials.unwrap().du - at(u - h, v).partials.unwrap().du) / (2.0 * h);
                    let fvv = (at(u, v + h).partials.unwrap().dv * 4.0
                        - at(u, v + 2.0 * h).partials.unwrap().dv
                        - d.dv * 3.0)
                        / (2.0 * h);
                    let scale = 1.0 + d.duu.norm().max(d.dvv.norm());
                    close(d.duu, fuu, 1e-5 * scale, &format!("{name}: duu at ({u}, {v})"));
                    close(d.dvv, fvv, 1e-5 * scale, &format!("{name}: dvv at ({u}, {v})"));
                    let nrm = d.du.cross(&d.dv).normalize();
                    close(e.normal, nrm, 1e-14, "normal from the partials");
                }
                // The crease vertex c₀ itself (valence 4 on its side) has partials too,
                // the limits of those beside it.
                let corner = at(0.0, 0.0).partials.unwrap_or_else(|| panic!("{name}: no partials at a crease vertex"));
                let beside = at(1e-9, 0.0).partials.unwrap();
                close(corner.du, beside.du, 1e-7, "du at the crease vertex");
                close(corner.dv, beside.dv, 1e-7, "dv at the crease vertex");
            }
        }
        assert_eq!(with_partials, 16);
    }
}
