//! Issue 36's timings in one run:
//! - a cubic Bézier triangle's point (de Casteljau and the Bernstein form) against the same
//!   surface as its exact degenerate bicubic tensor patch, ns a point (criterion's
//!   `cargo bench -p splinekit --bench triangles` measures the same more carefully);
//! - a blending surface over a triangulated torus of 10³ vertices (40 × 25, every local
//!   fitted to the PN triangles), built, then meshed at about 10⁶ triangles on one core and
//!   on every core (the meshes are compared bit for bit), with how far the mesh's vertices
//!   are from the torus;
//! - the Delaunay triangulation of 10⁶ random points in a square.
//!
//! `cargo run --release -p splinekit-mesh --example triangle_blend_mesh`

use std::hint::black_box;
use std::time::Instant;

use splinekit::Point;
use splinekit::basis::BFunction;
use splinekit::surface::Surface;
use splinekit::triangle::{BezierTriangle, Triangle, TriangulatedSurface, TriangulationBlend};
use splinekit::triangulation::Delaunay;
use splinekit_mesh::MeshOptions;
use splinekit_mesh::triangle_atlas_mesh::uniform_threads;

/// Best of five runs of `f`, in seconds.
fn best(mut f: impl FnMut()) -> f64 {
    (0..5)
        .map(|_| {
            let start = Instant::now();
            f();
            start.elapsed().as_secs_f64()
        })
        .fold(f64::INFINITY, f64::min)
}

fn main() {
    let mut state = 0x9e37_79b9_7f4a_7c15u64;
    let mut next = move || {
        state ^= state << 13;
        state ^= state >> 7;
        state ^= state << 17;
        (state >> 11) as f64 / (1u64 << 53) as f64
    };

    // A cubic Bézier triangle point, and the tensor path.
    let t = BezierTriangle::from_fn(3, |(i, j, k)| {
        Point::<3>::new(i as f64 + 0.1 * (j * k) as f64, j as f64 - 0.2 * i as f64, (i * j + k) as f64 * 0.3)
    })
    .expect("a cubic");
    let patch = t.to_tensor_patch();
    let st: Vec<(f64, f64)> = (0..1 << 16).map(|_| (next(), next())).collect();
    let uvw: Vec<[f64; 3]> = st.iter().map(|&(s, q)| splinekit::triangle::degenerate_patch_parameters(s, q)).collect();
    let n = st.len() as f64;
    let casteljau = best(|| {
        black_box(uvw.iter().fold(Point::<3>::zeros(), |acc, p| acc + t.point(black_box(p[0]), p[1], p[2])));
    });
    let bernstein = best(|| {
        black_box(uvw.iter().fold(Point::<3>::zeros(), |acc, p| acc + t.point_bernstein(black_box(p[0]), p[1], p[2])));
    });
    let tensor = best(|| {
        black_box(st.iter().fold(Point::<3>::zeros(), |acc, &(s, q)| acc + patch.point(black_box(s), q)));
    });
    let worst = st
        .iter()
        .zip(&uvw)
        .map(|(&(s, q), p)| (patch.point(s, q) - t.point(p[0], p[1], p[2])).norm())
        .fold(0.0, f64::max);
    println!(
        "cubic Bézier triangle point: de Casteljau {:.1} ns, Bernstein form {:.1} ns; its bicubic tensor patch {:.1} ns (largest difference {worst:.1e})",
        casteljau * 1e9 / n,
        bernstein * 1e9 / n,
        tensor * 1e9 / n
    );

    // The blend over a torus of 10³ vertices, meshed at about 10⁶ triangles.
    let (major, minor) = (3.0, 1.0);
    let start = Instant::now();
    let torus = TriangulatedSurface::torus(major, minor, 40, 25).expect("a torus");
    let blend = TriangulationBlend::new(&torus, 2, BFunction::erbs_default()).expect("a blend");
    let built = start.elapsed().as_secs_f64();
    let atlas = blend.atlas();
    let level = 23;
    let cores = std::thread::available_parallelism().map_or(1, |c| c.get());
    let mut one = None;
    let mut timed = Vec::new();
    for threads in [1, cores] {
        let start = Instant::now();
        let mesh = uniform_threads(&atlas, level, MeshOptions { uv: false }, threads).expect("a mesh");
        timed.push((threads, start.elapsed().as_secs_f64()));
        match &one {
            None => one = Some(mesh),
            Some(m) => assert!(*m == mesh, "the same mesh on {threads} threads"),
        }
    }
    let mesh = one.expect("meshed");
    let off = mesh.positions.iter().map(|p| ((p[0].hypot(p[1]) - major).hypot(p[2]) - minor).abs()).fold(0.0, f64::max);
    println!(
        "blend over {} vertices ({} triangles): built in {built:.3} s; meshed at level {level}: {} triangles, {} vertices, farthest vertex {off:.2e} from the torus",
        blend.vertex_count(),
        blend.triangles().len(),
        mesh.triangles.len(),
        mesh.positions.len(),
    );
    for (threads, s) in timed {
        println!("  on {threads} thread(s): {s:.3} s ({:.0} ns a vertex)", s * 1e9 / mesh.positions.len() as f64);
    }
    // 10⁶ random points in a square.
    let points: Vec<Point<2>> = (0..1_000_000).map(|_| Point::<2>::new(next(), next())).collect();
    let start = Instant::now();
    let d = Delaunay::new(&points).expect("a triangulation");
    println!(
        "Delaunay of {} random points: {} triangles in {:.3} s",
        points.len(),
        d.triangles().len(),
        start.elapsed().as_secs_f64()
    );
}
