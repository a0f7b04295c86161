//! Meshes of triangle atlases: watertight where corners are shared, within the chord
//! tolerance of the surface (checked at points the mesher never sampled), no slivers.

use splinekit::Point;
use splinekit::basis::BFunction;
use splinekit::surface::Surface;
use std::sync::Arc;

use splinekit::triangle::{BezierTriangle, Triangle, TriangulatedSurface, TriangulationBlend};
use splinekit_mesh::triangle_atlas_mesh::{level_for, uniform, uniform_threads, within_tolerance};
use splinekit_mesh::{AdaptiveTolerance, MeshOptions, surface_mesh};

fn edge_uses(mesh: &splinekit_mesh::TriangleMesh) -> std::collections::HashMap<(u32, u32), usize> {
    let mut uses = std::collections::HashMap::new();
    for t in &mesh.triangles {
        for k in 0..3 {
            let (a, b) = (t[k], t[(k + 1) % 3]);
            *uses.entry((a.min(b), a.max(b))).or_insert(0) += 1;
        }
    }
    uses
}

#[test]
fn blend_over_a_sphere_meshes_closed_and_outward() {
    let m = TriangulatedSurface::icosphere(1.0, 1).unwrap();
    let b = TriangulationBlend::new(&m, 2, BFunction::erbs_default()).unwrap();
    let atlas = b.atlas();
    let mesh = uniform(&atlas, 4, MeshOptions { uv: false }).unwrap();
    // 80 triangles × 16; vertices: V − E + F = 2 with every edge used twice.
    assert_eq!(mesh.triangles.len(), 80 * 16);
    assert!(edge_uses(&mesh).values().all(|&u| u == 2));
    let e = edge_uses(&mesh).len();
    assert_eq!(mesh.positions.len() as i64 - e as i64 + mesh.triangles.len() as i64, 2);
    assert!(mesh.signed_volume() > 4.0, "{}", mesh.signed_volume());
}

#[test]
fn within_tolerance_at_unsampled_points_and_no_slivers() {
    let t = BezierTriangle::from_fn(3, |(i, j, k)| {
        Point::<3>::new(i as f64, j as f64, if i == 1 && j == 1 { 4.0 } else { 0.3 * k as f64 })
    })
    .unwrap();
    let atlas = splinekit::triangle::TriangleAtlas::single(Arc::new(t.clone()));
    for tol in [1e-1, 1e-2, 1e-3] {
        let level = level_for(&atlas, tol, 10_000_000).unwrap();
        let mesh = within_tolerance(&atlas, tol, 10_000_000, MeshOptions { uv: true }).unwrap();
        assert_eq!(mesh.triangles.len(), level * level);
        // The surface at the centre of each sub-triangle against the flat one through the
        // mesh's vertices (by their (u, v)), along the normal: within the tolerance.
        let mut worst = 0.0f64;
        for tri in &mesh.triangles {
            let uv = tri.map(|k| mesh.uvs[k as usize]);
            let (u, v) = ((uv[0][0] + uv[1][0] + uv[2][0]) / 3.0, (uv[0][1] + uv[1][1] + uv[2][1]) / 3.0);
            let flat = tri.iter().fold([0.0; 3], |acc, &k| {
                let p = mesh.positions[k as usize];
                [acc[0] + p[0] / 3.0, acc[1] + p[1] / 3.0, acc[2] + p[2] / 3.0]
            });
            let q = t.point(u, v, 1.0 - u - v);
            let n = t.normal(u, v, 1.0 - u - v).unwrap();
            worst = worst.max((q - Point::<3>::new(flat[0], flat[1], flat[2])).dot(&n).abs());
            // No slivers: every sub-triangle has the same area in (u, v).
            let area =
                ((uv[1][0] - uv[0][0]) * (uv[2][1] - uv[0][1]) - (uv[2][0] - uv[0][0]) * (uv[1][1] - uv[0][1])).abs();
            assert!((area * (level * level) as f64 - 1.0).abs() < 1e-9);
        }
        assert!(worst <= tol, "{worst} > {tol}");
    }
}

#[test]
fn the_surface_meshers_take_the_atlas() {
    let m = TriangulatedSurface::torus(3.0, 1.0, 12, 6).unwrap();
    let b = TriangulationBlend::new(&m, 2, BFunction::erbs_default()).unwrap();
    let atlas = b.atlas();
    assert!(atlas.triangle_atlas().is_some());
    let mesh = surface_mesh::adaptive(
        &atlas,
        (4, 4),
        AdaptiveTolerance { chord_height: 0.01, normal_angle: 0.5, max_depth: 8 },
        MeshOptions { uv: false },
    )
    .unwrap();
    assert!(edge_uses(&mesh).values().all(|&u| u == 2), "closed");
    let regular = surface_mesh::regular(&atlas, 32, 32, MeshOptions { uv: false }).unwrap();
    assert!(edge_uses(&regular).values().all(|&u| u == 2), "closed");
    // Vertices lie on the surface: the first triangle's corner is its vertex.
    let p = b.triangle(0).point(1.0, 0.0, 0.0);
    assert!(mesh.positions.iter().any(|q| (Point::<3>::new(q[0], q[1], q[2]) - p).norm() == 0.0));
}

/// Shared lattice points are decided on one thread and every point is evaluated once, so
/// the mesh made on several threads is the one-thread mesh bit for bit (positions, normals
/// summed over shared points, uvs and triangles), also when the threads outnumber the
/// triangles; and it is the blend itself at its lattice points.
#[test]
fn threads_make_the_same_mesh_bit_for_bit() {
    let m = TriangulatedSurface::icosphere(1.0, 1).unwrap();
    let b = TriangulationBlend::new(&m, 2, BFunction::erbs_default()).unwrap();
    let atlas = b.atlas();
    let one = uniform(&atlas, 5, MeshOptions { uv: true }).unwrap();
    for threads in [0, 2, 3, 7, 200] {
        let many = uniform_threads(&atlas, 5, MeshOptions { uv: true }, threads).unwrap();
        assert!(many == one, "{threads} threads");
    }
    // Vertex 0 is corner u of triangle 0, at the lattice's first point (i = n, j = 0).
    let t0 = &atlas.charts()[0];
    let p = t0.point(1.0, 0.0, 0.0);
    assert!(one.positions.iter().any(|q| (Point::<3>::new(q[0], q[1], q[2]) - p).norm() == 0.0));
    let tri = BezierTriangle::from_fn(2, |(i, j, _)| Point::<3>::new(i as f64, j as f64, (i * j) as f64)).unwrap();
    let single = splinekit::triangle::TriangleAtlas::single(Arc::new(tri) as Arc<dyn Triangle<3>>);
    let one = uniform(&single, 6, MeshOptions { uv: false }).unwrap();
    assert!(uniform_threads(&single, 6, MeshOptions { uv: false }, 4).unwrap() == one, "one triangle, four threads");
}
