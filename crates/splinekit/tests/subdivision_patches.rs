//! The Catmull–Clark limit as Bézier patches with local refinement at extraordinary
//! vertices (`bezier_patches`), against independent truth: the whole-surface refinement it
//! replaces, exact evaluation on the globally subdivided cage, and the subdominant
//! eigenvalue of the vertex valence.

mod common;

use splinekit::Point;
use splinekit::subdivision::surface::bezier_patches::{
    LimitPatches, MAX_DEPTH, Refinement, bezier_patch, limit_patches, limit_patches_within, refine_patches,
};
use splinekit::subdivision::surface::regular_patch::catmull_clark_grid;
use splinekit::subdivision::surface::{Cage, Scheme, SubdivisionSurface, read_obj_cage};

fn p(x: f64, y: f64, z: f64) -> Point<3> {
    Point::<3>::new(x, y, z)
}

fn obj(name: &str) -> SubdivisionSurface {
    let path = format!("{}/../../examples/meshes/{name}", env!("CARGO_MANIFEST_DIR"));
    let c = read_obj_cage(&std::fs::read_to_string(path).unwrap()).unwrap();
    let cage = Cage::new(c.vertices.iter().map(|v| p(v[0], v[1], v[2])).collect(), &c.faces).with_creases(c.creases);
    SubdivisionSurface::new(cage, Scheme::CatmullClark, false).unwrap()
}

/// The icosahedron (twelve vertices of valence 5; after one step every triangle is three
/// quads, each with a valence-5 and a valence-3 corner).
fn icosahedron() -> SubdivisionSurface {
    SubdivisionSurface::new(common::cages::icosahedron(), Scheme::CatmullClark, false).unwrap()
}

/// The Catmull–Clark subdominant eigenvalue at a smooth vertex of valence n.
fn lambda(n: usize) -> f64 {
    let c = (2.0 * std::f64::consts::PI / n as f64).cos();
    5.0 / 16.0 + (c + (std::f64::consts::PI / n as f64).cos() * (2.0 * (9.0 + c)).sqrt()) / 16.0
}

/// The patches by refining the WHOLE surface each level (the method local refinement
/// replaces): level-l faces of `s.subdivide(l)` that are regular, children of irregular
/// ones, and at the last level the irregular faces as bilinear patches through limit
/// points, with their deviation on the 9 × 9 grid by exact evaluation on that cage.
fn whole_surface_patches(s: &SubdivisionSurface, depth: usize) -> LimitPatches {
    let mut out = LimitPatches::default();
    let mut level_surface = s.clone();
    let mut pending: Vec<u32> = (0..s.cage().face_count() as u32).collect();
    for level in 0..=depth {
        let (c, t) = (level_surface.cage(), level_surface.topology());
        let mut next = Vec::new();
        for &f in &pending {
            if let Some(g) = catmull_clark_grid(c, t, f) {
                out.bicubic.push(bezier_patch(&g));
            } else if level < depth {
                next.extend(c.face_offsets[f as usize]..c.face_offsets[f as usize + 1]);
            } else {
                let q: Vec<Point<3>> =
                    c.face(f as usize).iter().map(|&v| level_surface.limit_frame(v).unwrap().position).collect();
                for i in 0..9 {
                    for j in 0..9 {
                        let (u, v) = (i as f64 / 8.0, j as f64 / 8.0);
                        let b = q[0] * ((1.0 - u) * (1.0 - v))
                            + q[1] * (u * (1.0 - v))
                            + q[2] * (u * v)
                            + q[3] * ((1.0 - u) * v);
                        let e = level_surface.evaluate(f as usize, u, v).unwrap().position;
                        out.max_deviation = out.max_deviation.max((b - e).norm());
                    }
                }
                out.bilinear.push([q[0], q[1], q[2], q[3]]);
                out.levels.push(level);
            }
        }
        if next.is_empty() {
            break;
        }
        pending = next;
        level_surface = level_surface.step().unwrap();
    }
    out
}

fn same_patches<const N: usize, const M: usize>(a: &[[[Point<3>; N]; M]], b: &[[[Point<3>; N]; M]], what: &str) {
    assert_eq!(a.len(), b.len(), "{what}: counts");
    // Each patch of one list is one of the other (to rounding).
    for x in a {
        let near = b.iter().any(|y| x.iter().flatten().zip(y.iter().flatten()).all(|(p, q)| (p - q).norm() < 1e-12));
        assert!(near, "{what}: a patch of one list is not in the other");
    }
}

/// Local refinement gives exactly the patches of whole-surface refinement (cube, creased
/// cube with its sharp ring and semi-sharp edge, icosahedron), and the same deviation.
#[test]
fn local_refinement_is_whole_surface_refinement() {
    for (name, s, depth) in
        [("cube", obj("cube.obj"), 4), ("creased cube", obj("creased_cube.obj"), 4), ("icosahedron", icosahedron(), 3)]
    {
        let local = limit_patches(&s, depth).unwrap();
        let whole = whole_surface_patches(&s, depth);
        same_patches(&local.bicubic, &whole.bicubic, name);
        let wrap = |q: &[[Point<3>; 4]]| q.iter().map(|x| [*x]).collect::<Vec<[[Point<3>; 4]; 1]>>();
        same_patches(&wrap(&local.bilinear), &wrap(&whole.bilinear), name);
        assert!(
            (local.max_deviation - whole.max_deviation).abs() <= 1e-12 * whole.max_deviation,
            "{name}: {} vs {}",
            local.max_deviation,
            whole.max_deviation
        );
        assert!(local.levels.iter().all(|&l| l == depth));
    }
}

/// The cube: 24 stand-ins at every depth and 3 × 24 exact patches more per level, up to 30
/// levels; the creased cube the same (16 stand-ins, 48 more exact patches a level) once its
/// semi-sharp edge (sharpness 2.5) has decayed, after 3 levels.
#[test]
fn patch_counts_grow_linearly_with_depth() {
    let cube = obj("cube.obj");
    for depth in [1, 2, 5, 12, 20, MAX_DEPTH] {
        let p = limit_patches(&cube, depth).unwrap();
        assert_eq!((p.bicubic.len(), p.bilinear.len(), p.depth()), (72 * (depth - 1), 24, depth));
    }
    let creased = obj("creased_cube.obj");
    let counts: Vec<(usize, usize)> = (3..=8)
        .map(|d| {
            let p = limit_patches(&creased, d).unwrap();
            (p.bicubic.len(), p.bilinear.len())
        })
        .collect();
    for w in counts.windows(2) {
        assert_eq!((w[1].0 - w[0].0, w[1].1), (3 * w[0].1, 16), "{counts:?}");
    }
}

/// At depth 25 every stand-in corner is a corner of an exact neighbouring patch, or a
/// smooth extraordinary vertex that is the same point in each of its stand-ins (to
/// rounding): the deep patches still meet.
#[test]
fn deep_stand_ins_meet_their_neighbours() {
    let p = limit_patches(&obj("creased_cube.obj"), 25).unwrap();
    let corners: Vec<Point<3>> = p.bicubic.iter().flat_map(|b| [b[0][0], b[3][0], b[3][3], b[0][3]]).collect();
    let nearest = |c: &Point<3>, among: &mut dyn Iterator<Item = Point<3>>| {
        among.map(|x| (x - c).norm()).fold(f64::INFINITY, f64::min)
    };
    let mut at_vertices = 0;
    for (k, q) in p.bilinear.iter().enumerate() {
        for c in q {
            let exact = nearest(c, &mut corners.iter().copied());
            if exact > 1e-13 {
                at_vertices += 1;
                let others = p.bilinear.iter().enumerate().filter(|&(j, _)| j != k).flat_map(|(_, q)| *q);
                let d = nearest(c, &mut others.into_iter());
                assert!(d < 1e-13, "a stand-in corner is {exact} from every exact patch and {d} from other stand-ins");
            }
        }
    }
    // 16 stand-ins: 12 at the bottom's four smooth valence-3 corners, whose vertex only
    // stand-ins share, and 4 on the top face at its crease corners, whose limit point the
    // exact patches of the sides also have.
    assert_eq!((p.bilinear.len(), at_vertices), (16, 12));
}

/// The gap the stand-ins leave: along each stand-in edge shared with an exact patch (same
/// end points), the largest distance between the straight edge and the patch's cubic edge
/// at 65 parameters is at most the measured deviation (plus 1 %, what the 9 × 9 samples
/// may miss): the cube at depth 12, the default tolerance's depth.
#[test]
fn stand_in_gaps_are_within_the_deviation() {
    let p = limit_patches(&obj("cube.obj"), 12).unwrap();
    let bezier = |b: [Point<3>; 4], t: f64| {
        let s = 1.0 - t;
        b[0] * (s * s * s) + b[1] * (3.0 * s * s * t) + b[2] * (3.0 * s * t * t) + b[3] * (t * t * t)
    };
    // The four boundary curves of each bicubic patch, as Bézier polygons.
    let curves: Vec<[Point<3>; 4]> = p
        .bicubic
        .iter()
        .flat_map(|b| {
            [
                [b[0][0], b[1][0], b[2][0], b[3][0]],
                [b[3][0], b[3][1], b[3][2], b[3][3]],
                [b[3][3], b[2][3], b[1][3], b[0][3]],
                [b[0][3], b[0][2], b[0][1], b[0][0]],
            ]
        })
        .collect();
    let (mut shared, mut gap) = (0, 0.0f64);
    for q in &p.bilinear {
        for k in 0..4 {
            let (a, b) = (q[k], q[(k + 1) % 4]);
            for c in &curves {
                let forward = (c[0] - a).norm() < 1e-12 && (c[3] - b).norm() < 1e-12;
                let backward = (c[0] - b).norm() < 1e-12 && (c[3] - a).norm() < 1e-12;
                if forward || backward {
                    shared += 1;
                    for i in 0..=64 {
                        let t = i as f64 / 64.0;
                        let line = a * (1.0 - t) + b * t;
                        gap = gap.max((line - bezier(*c, if forward { t } else { 1.0 - t })).norm());
                    }
                }
            }
        }
    }
    // Two edges of each of the 24 stand-ins border its exact siblings.
    assert_eq!(shared, 48);
    assert!(gap > 0.0 && gap <= 1.01 * p.max_deviation, "gap {gap}, deviation {}", p.max_deviation);
}

/// The deviation falls by the subdominant eigenvalue λ of the extraordinary vertex a level
/// (the limit is c + λᴸ·(characteristic map) + … on the level-L face, and the bilinear
/// stand-in does not reproduce the characteristic map): λ(3) ≈ 0.410 on the cube, λ(5) ≈
/// 0.550 (the slowest) on the icosahedron.
#[test]
fn deviation_decays_by_the_subdominant_eigenvalue() {
    for (name, s, n, levels) in [("cube", obj("cube.obj"), 3, 6..13), ("icosahedron", icosahedron(), 5, 8..13)] {
        let d: Vec<f64> = levels.clone().map(|l| limit_patches(&s, l).unwrap().max_deviation).collect();
        for w in d.windows(2) {
            let r = w[1] / w[0];
            assert!((r / lambda(n) - 1.0).abs() < 0.02, "{name}: ratio {r}, λ({n}) = {}", lambda(n));
        }
    }
    assert!((lambda(3) - 0.4101).abs() < 1e-4 && (lambda(5) - 0.5500).abs() < 1e-3);
}

/// With a tolerance each irregular face stops at the fewest levels whose stand-in meets it:
/// the creased cube's faces stop at different levels, the deviation is within the
/// tolerance, and one level less everywhere does not meet it.
#[test]
fn a_tolerance_takes_the_fewest_levels() {
    let s = obj("creased_cube.obj");
    let size = 2.0 * 3f64.sqrt();
    for relative in [1e-6, 1e-8] {
        let t = relative * size;
        let clock = std::time::Instant::now();
        let p = limit_patches_within(&s, t).unwrap();
        let took = clock.elapsed();
        assert!(p.max_deviation <= t && p.max_deviation > 0.0);
        let depth = p.depth();
        assert!(limit_patches(&s, depth - 1).unwrap().max_deviation > t, "{relative}: depth {depth}");
        assert!(p.levels.iter().any(|&l| l < depth), "{relative}: every face at level {depth}");
        // Fewer patches than refining every irregular face to the deepest level.
        assert!(p.bicubic.len() < limit_patches(&s, depth).unwrap().bicubic.len());
        eprintln!(
            "creased cube within {relative:e}: depth {depth}, {} + {} patches in {took:?}",
            p.bicubic.len(),
            p.bilinear.len()
        );
    }
    // Beyond what 30 levels reach: the deepest stand-ins, short of the tolerance.
    let p = refine_patches(&s, Refinement::Tolerance { tolerance: 1e-15, max_depth: MAX_DEPTH }).unwrap();
    assert!(p.max_deviation > 1e-15 && p.depth() == MAX_DEPTH);
}

/// Bad requests name the field and the number.
#[test]
fn bad_requests_are_refused() {
    let s = obj("cube.obj");
    for (r, field) in [
        (Refinement::Depth(0), "depth"),
        (Refinement::Depth(MAX_DEPTH + 1), "depth"),
        (Refinement::Tolerance { tolerance: 0.0, max_depth: 10 }, "tolerance"),
        (Refinement::Tolerance { tolerance: f64::NAN, max_depth: 10 }, "tolerance"),
    ] {
        let e = refine_patches(&s, r).unwrap_err().to_string();
        assert!(e.contains(field), "{e}");
    }
    // The bilinear scheme's limit is its faces, exactly.
    let c = s.cage();
    let p = limit_patches(&SubdivisionSurface::new(c.clone(), Scheme::Bilinear, false).unwrap(), 3).unwrap();
    assert_eq!((p.bilinear.len(), p.max_deviation, p.depth()), (6, 0.0, 0));
    assert!((0..6).all(|f| c.face(f).iter().zip(&p.bilinear[f]).all(|(&v, q)| c.vertices[v as usize] == *q)));
}
