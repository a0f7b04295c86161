//! The Catmull–Clark limit surface as polynomial patches (for STEP export).
//!
//! Where a quad and its 1-ring are regular (every corner smooth of valence 4, or a regular
//! crease or boundary, see `regular_patch::catmull_clark_grid`), the limit surface on the
//! quad is the uniform bicubic B-spline patch of its 4×4 control grid G, written exactly as
//! a bicubic Bézier patch: per direction, b₀ = (G₀ + 4G₁ + G₂)/6, b₁ = (4G₁ + 2G₂)/6,
//! b₂ = (2G₁ + 4G₂)/6, b₃ = (G₁ + 4G₂ + G₃)/6 (the uniform cubic B-spline's Bézier
//! points on one knot span). Other faces (polygons, faces at an extraordinary vertex, at a
//! semi-sharp crease) are subdivided — face f's k-th corner becomes child face
//! `face_offsets[f] + k` — and their children tried again, down to `depth` steps; the
//! faces still irregular then (those touching an extraordinary vertex, of size about
//! 2^−depth) become bilinear patches through the limit points of their corners, which
//! meet their neighbours' edges at those points. [`LimitPatches::max_deviation`] measures
//! them: the largest distance between a stand-in's centre and the exact limit at its face's
//! centre.

use super::SubdivisionSurface;
use super::regular_patch::catmull_clark_grid;
use crate::Point;

/// Patches of a limit surface: exact bicubic Bézier patches (`[i][j]`, i along u) and
/// bilinear patches `[c₀, c₁, c₂, c₃]` (corners in face order) standing in for the
/// faces at extraordinary vertices.
#[derive(Debug, Default)]
pub struct LimitPatches {
    /// Exact bicubic Bézier patches.
    pub bicubic: Vec<[[Point<3>; 4]; 4]>,
    /// Bilinear patches through limit points.
    pub bilinear: Vec<[Point<3>; 4]>,
    /// The largest distance between a bilinear patch's centre and the limit surface at the
    /// centre of its face (0 without bilinear patches).
    pub max_deviation: f64,
}

/// The Bézier points of the uniform cubic B-spline of g on one span.
fn bezier_row(g: [Point<3>; 4]) -> [Point<3>; 4] {
    [
        (g[0] + g[1] * 4.0 + g[2]) / 6.0,
        (g[1] * 4.0 + g[2] * 2.0) / 6.0,
        (g[1] * 2.0 + g[2] * 4.0) / 6.0,
        (g[1] + g[2] * 4.0 + g[3]) / 6.0,
    ]
}

/// The bicubic Bézier patch of a 4×4 uniform B-spline grid.
pub fn bezier_patch(g: &[[Point<3>; 4]; 4]) -> [[Point<3>; 4]; 4] {
    // Along u for each j (columns[j][i]), then along v for each i.
    let columns: [[Point<3>; 4]; 4] = std::array::from_fn(|j| bezier_row([g[0][j], g[1][j], g[2][j], g[3][j]]));
    std::array::from_fn(|i| bezier_row([columns[0][i], columns[1][i], columns[2][i], columns[3][i]]))
}

/// The patches of a Catmull–Clark surface, irregular faces subdivided `depth` (≥ 1) times.
pub fn limit_patches(surface: &SubdivisionSurface, depth: usize) -> crate::Result<LimitPatches> {
    let mut out = LimitPatches::default();
    let mut s = surface.clone();
    let mut pending: Vec<u32> = (0..s.cage().face_count() as u32).collect();
    for level in 0..=depth {
        let mut next = Vec::new();
        for &f in &pending {
            let c = s.cage();
            if let Some(g) = catmull_clark_grid(c, s.topology(), f) {
                out.bicubic.push(bezier_patch(&g));
            } else if level < depth {
                next.extend(c.face_offsets[f as usize]..c.face_offsets[f as usize + 1]);
            } else {
                let face = c.face(f as usize);
                // Level ≥ 1: every face is a quad.
                let mut q = [Point::<3>::zeros(); 4];
                for (k, &v) in face.iter().take(4).enumerate() {
                    q[k] = s.limit_frame(v)?.position;
                }
                let centre = s.evaluate(f as usize, 0.5, 0.5)?.position;
                out.max_deviation = out.max_deviation.max(((q[0] + q[1] + q[2] + q[3]) / 4.0 - centre).norm());
                out.bilinear.push(q);
            }
        }
        if next.is_empty() {
            break;
        }
        pending = next;
        s = s.step()?;
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::subdivision::surface::{Cage, Scheme};

    fn bezier_at(b: &[[Point<3>; 4]; 4], u: f64, v: f64) -> Point<3> {
        let w = |t: f64| [(1.0 - t).powi(3), 3.0 * t * (1.0 - t).powi(2), 3.0 * t * t * (1.0 - t), t.powi(3)];
        let (wu, wv) = (w(u), w(v));
        let mut p = Point::<3>::zeros();
        for i in 0..4 {
            for j in 0..4 {
                p += b[i][j] * (wu[i] * wv[j]);
            }
        }
        p
    }

    /// A bumpy 6×6 grid: its 4 inner quads are regular, and the Bézier patches agree with
    /// exact evaluation; the cube (8 extraordinary vertices) gives 72 exact patches per
    /// level from level 2 on and 24 bilinear patches, whose corners are limit points.
    #[test]
    fn regular_patches_are_the_limit_surface() {
        let n = 6u32;
        let vs: Vec<Point<3>> = (0..n * n)
            .map(|k| {
                let (i, j) = (k % n, k / n);
                Point::<3>::new(i as f64, j as f64, ((i * 7 + j * 3) % 5) as f64 * 0.2)
            })
            .collect();
        let faces: Vec<Vec<u32>> = (0..n - 1)
            .flat_map(|j| (0..n - 1).map(move |i| vec![j * n + i, j * n + i + 1, (j + 1) * n + i + 1, (j + 1) * n + i]))
            .collect();
        let s = SubdivisionSurface::new(Cage::new(vs, &faces), Scheme::CatmullClark, false).unwrap();
        let c = s.cage();
        let mut regular = 0;
        for f in 0..c.face_count() {
            if let Some(g) = catmull_clark_grid(c, s.topology(), f as u32) {
                regular += 1;
                let b = bezier_patch(&g);
                for (u, v) in [(0.0, 0.0), (0.3, 0.7), (1.0, 0.5)] {
                    let e = s.evaluate(f, u, v).unwrap().position;
                    assert!((bezier_at(&b, u, v) - e).norm() < 1e-12, "face {f} at ({u}, {v})");
                }
            }
        }
        assert!(regular >= 9, "{regular} regular quads");

        let cube: Vec<Point<3>> = (0..8)
            .map(|k| Point::<3>::new([-1.0, 1.0][k & 1], [-1.0, 1.0][(k >> 1) & 1], [-1.0, 1.0][k >> 2]))
            .collect();
        let faces = vec![
            vec![0, 2, 3, 1],
            vec![4, 5, 7, 6],
            vec![0, 1, 5, 4],
            vec![2, 6, 7, 3],
            vec![0, 4, 6, 2],
            vec![1, 3, 7, 5],
        ];
        let s = SubdivisionSurface::new(Cage::new(cube, &faces), Scheme::CatmullClark, false).unwrap();
        let p = limit_patches(&s, 3).unwrap();
        assert_eq!((p.bicubic.len(), p.bilinear.len()), (2 * 72, 24));
        let corner = Point::<3>::new(0.5, 0.5, 0.5);
        assert!(p.bilinear.iter().any(|q| q.iter().any(|c| (c - corner).norm() < 1e-15)));
        // A bilinear patch's centre against the limit point at its face's centre (the
        // face point's limit one step on, vertex V + f of the next cage).
        let deviation = |depth: usize| {
            let s3 = s.subdivide(depth).unwrap();
            let s4 = s3.step().unwrap();
            let nv = s3.cage().vertices.len() as u32;
            let mut worst = 0.0f64;
            for f in 0..s3.cage().face_count() as u32 {
                if catmull_clark_grid(s3.cage(), s3.topology(), f).is_none() {
                    let q: Vec<Point<3>> =
                        s3.cage().face(f as usize).iter().map(|&v| s3.limit_frame(v).unwrap().position).collect();
                    let centre = (q[0] + q[1] + q[2] + q[3]) / 4.0;
                    worst = worst.max((centre - s4.limit_frame(nv + f).unwrap().position).norm());
                }
            }
            worst
        };
        let (d3, d4) = (deviation(3), deviation(4));
        assert!((p.max_deviation - d3).abs() < 1e-12, "{} vs {d3}", p.max_deviation);
        eprintln!("cube: bilinear patches within {d3:e} (3 levels), {d4:e} (4 levels) of the limit at their centres");
        // Quadratic in the patch size: a quarter per level or better (0.18 here, near λ² ≈ 0.17
        // of the valence-3 subdominant eigenvalue λ ≈ 0.41).
        assert!(d3 < 5e-3 && (0.1..0.3).contains(&(d4 / d3)), "{d3} {d4}");
        // Every bicubic patch lies between the cage's limit and the cage: |x| ≤ 1.
        assert!(p.bicubic.iter().flatten().flatten().all(|q| q.amax() <= 1.0));
    }
}
