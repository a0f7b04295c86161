//! Times a blending surface over a triangulated sphere (the icosahedron split three times:
//! 642 vertex locals, 1280 triangles) built and meshed at about 10⁶ triangles on one core,
//! and a Delaunay triangulation of 10⁶ points.
//!
//! `cargo run --release -p splinekit-mesh --example triangle_blend_mesh`

use std::time::Instant;

use splinekit::Point;
use splinekit::basis::BFunction;
use splinekit::triangle::{TriangulatedSurface, TriangulationBlend};
use splinekit::triangulation::Delaunay;
use splinekit_mesh::MeshOptions;
use splinekit_mesh::triangle_atlas_mesh::uniform;

fn main() {
    let start = Instant::now();
    let sphere = TriangulatedSurface::icosphere(1.0, 3).expect("an icosphere");
    let blend = TriangulationBlend::new(&sphere, 2, BFunction::erbs_default()).expect("a blend");
    let built = start.elapsed().as_secs_f64();
    let atlas = blend.atlas();
    let start = Instant::now();
    let mesh = uniform(&atlas, 28, MeshOptions { uv: false }).expect("a mesh");
    let meshed = start.elapsed().as_secs_f64();
    let worst = mesh
        .positions
        .iter()
        .map(|p| ((p[0] * p[0] + p[1] * p[1] + p[2] * p[2]).sqrt() - 1.0).abs())
        .fold(0.0, f64::max);
    println!(
        "blend over {} vertices: built in {built:.3} s; {} triangles ({} vertices) in {meshed:.3} s ({:.0} ns a vertex); farthest vertex {worst:.2e} off the unit sphere",
        blend.vertex_count(),
        mesh.triangles.len(),
        mesh.positions.len(),
        meshed * 1e9 / mesh.positions.len() as f64
    );
    // 10⁶ points of a jittered grid.
    let mut state = 0x9e37_79b9_7f4a_7c15u64;
    let mut next = || {
        state ^= state << 13;
        state ^= state >> 7;
        state ^= state << 17;
        (state >> 11) as f64 / (1u64 << 53) as f64
    };
    let points: Vec<Point<2>> = (0..1_000_000)
        .map(|k| Point::<2>::new((k % 1000) as f64 + 0.8 * next(), (k / 1000) as f64 + 0.8 * next()))
        .collect();
    let start = Instant::now();
    let d = Delaunay::new(&points).expect("a triangulation");
    println!(
        "Delaunay of {} points: {} triangles in {:.3} s",
        points.len(),
        d.triangles().len(),
        start.elapsed().as_secs_f64()
    );
}
