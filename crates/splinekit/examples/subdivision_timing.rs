//! Prints the time of one Catmull–Clark / Loop step on 10⁴ quads (2·10⁴ triangles), of a
//! step on 4·10⁴ quads (to show linear growth), of all limit frames and of exact limit
//! evaluations. Run with `cargo run --release -p splinekit --example subdivision_timing`.

use std::time::Instant;

use splinekit::Point;
use splinekit::subdivision::surface::{Cage, Scheme, SubdivisionSurface};

fn grid(n: u32, triangles: bool) -> Cage {
    let mut v = Vec::new();
    for j in 0..=n {
        for i in 0..=n {
            v.push(Point::<3>::new(i as f64, j as f64, ((i * 7 + j * 3) as f64).sin()));
        }
    }
    let id = |i: u32, j: u32| j * (n + 1) + i;
    let mut faces = Vec::new();
    for j in 0..n {
        for i in 0..n {
            let q = [id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)];
            if triangles {
                faces.push(vec![q[0], q[1], q[2]]);
                faces.push(vec![q[0], q[2], q[3]]);
            } else {
                faces.push(q.to_vec());
            }
        }
    }
    Cage::new(v, &faces)
}

fn time<T>(what: &str, reps: u32, mut f: impl FnMut() -> T) -> f64 {
    let _ = f();
    let t = Instant::now();
    for _ in 0..reps {
        std::hint::black_box(f());
    }
    let s = t.elapsed().as_secs_f64() / reps as f64;
    println!("{what}: {:.3} ms", s * 1e3);
    s
}

fn main() {
    let small = SubdivisionSurface::new(grid(100, false), Scheme::CatmullClark, false).unwrap();
    let big = SubdivisionSurface::new(grid(200, false), Scheme::CatmullClark, false).unwrap();
    let a = time("Catmull–Clark step, 10^4 quads (with adjacency of the result)", 20, || small.step().unwrap());
    let b = time("Catmull–Clark step, 4·10^4 quads", 5, || big.step().unwrap());
    println!("ratio {:.2} for 4× the faces (linear: 4)", b / a);
    let tri = SubdivisionSurface::new(grid(100, true), Scheme::Loop, false).unwrap();
    time("Loop step, 2·10^4 triangles", 20, || tri.step().unwrap());
    time("limit frames of all 10^4 vertices (Catmull–Clark)", 5, || small.limit_frames().unwrap());
    let s = SubdivisionSurface::new(Cage::cube(), Scheme::CatmullClark, false).unwrap();
    time("exact evaluation, regular face (B-spline patch)", 1000, || small.evaluate(5050, 0.3, 0.7).unwrap());
    time("exact evaluation, cube face at (0.3, 0.2) (valence-3 corners)", 1000, || s.evaluate(0, 0.3, 0.2).unwrap());
    time("exact evaluation, cube face at (1e-6, 2e-6) (~20 local steps)", 200, || s.evaluate(0, 1e-6, 2e-6).unwrap());
}
