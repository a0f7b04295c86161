//! Surfaces interpolating heights over a triangulation, z = f(x, y) with f(v_i) = z_i at every
//! vertex: piecewise linear, or C¹ from vertex gradients by the Clough–Tocher split. Both are
//! piecewise polynomial, so each piece is returned as an exact [`BezierTriangle`] in ℝ³
//! (x and y linear, z the interpolant), ready for a [`TriangleAtlas`](crate::triangle::TriangleAtlas).
//!
//! **Linear**: on triangle (a, b, c), f = λ_a z_a + λ_b z_b + λ_c z_c (degree 1).
//!
//! **Clough–Tocher** (Farin, *CAGD* §20.3; Lai & Schumaker §6.2): each triangle V₁V₂V₃ is
//! split at its centroid C into three micro-triangles (V_i, V_j, C), each a cubic Bézier
//! triangle. With g_i the gradient at V_i, the ordinates of the micro-triangle (V_i, V_j, C)
//! (indices (α_i, α_j, α_C)) are
//!
//! * b₃₀₀ = z_i, b₂₁₀ = z_i + g_i·(V_j − V_i)/3, b₂₀₁ = a_i = z_i + g_i·(C − V_i)/3
//!   (and symmetrically at V_j): f and ∇f at the vertices;
//! * b₁₁₁ = e_ij = (b₂₁₀ + b₁₂₀)/2 + (N_i + N_j)/6 + (d·τ)/L (b₁₂₀ − b₂₁₀), where d = C − M
//!   (M the edge's midpoint), τ the unit edge direction, L its length and N_i = (d·n)(g_i·n)
//!   for the unit normal n of the edge: this makes the cross-boundary derivative ∂f/∂n
//!   linear along the edge, interpolating g_i·n and g_j·n, so that both triangles sharing the
//!   edge have the same ∂f/∂n there (C¹ across every edge of the triangulation);
//! * b₁₀₂ = q_i = (a_i + e_ij + e_ki)/3 and b₀₀₃ = S = (q₁ + q₂ + q₃)/3: the C¹ conditions
//!   across the three inner edges V_iC (V_k = 3C − V_i − V_j has barycentric coordinates
//!   (−1, −1, 3) in (V_i, V_j, C)).
//!
//! The result is C¹ everywhere and reproduces quadratic polynomials when given their
//! gradients. Without gradients (no vertex normals), g_i is the least-squares plane
//! through z_i and the neighbours of vertex i: minimises Σ_j (z_j − z_i − g·(v_j − v_i))².

use crate::Point;
use crate::error::{Error, Result};
use crate::triangle::BezierTriangle;
use crate::triangulation::Delaunay;

/// How heights are interpolated over the triangles.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum HeightInterpolant {
    /// Piecewise linear (C⁰).
    Linear,
    /// Clough–Tocher's cubic split (C¹), from vertex gradients.
    CloughTocher,
}

/// The interpolant's pieces: cubic or linear Bézier triangles in ℝ³ and, for each, the vertex
/// numbers at its corners u, v, w (the triangulation's, then n + t for the centroid of
/// triangle t of a Clough–Tocher split).
#[derive(Debug, Clone)]
pub struct HeightPieces {
    /// The Bézier triangles.
    pub triangles: Vec<BezierTriangle<3>>,
    /// Their corners' vertex numbers.
    pub corners: Vec<[u32; 3]>,
}

/// The gradient ∇f = (−n_x/n_z, −n_y/n_z) of the height field whose normal is `n`.
pub fn gradient_of_normal(field: &str, n: &Point<3>) -> Result<[f64; 2]> {
    let len = n.norm();
    if !(len.is_finite() && len > 0.0) || n.z.abs() <= 1e-9 * len {
        return Err(Error::invalid(
            field,
            format!("a height field's normal must point up or down (n_z ≠ 0), got {:?}", n.as_slice()),
        ));
    }
    Ok([-n.x / n.z, -n.y / n.z])
}

/// Gradients estimated at every vertex by the least-squares plane through its neighbours
/// (see the module documentation); a vertex whose neighbours are collinear with it gets the
/// gradient along their line.
pub fn estimate_gradients(d: &Delaunay, heights: &[f64]) -> Vec<[f64; 2]> {
    let v = d.vertices();
    let mut neighbours: Vec<Vec<usize>> = vec![Vec::new(); v.len()];
    for [a, b] in d.edges() {
        neighbours[a].push(b);
        neighbours[b].push(a);
    }
    (0..v.len())
        .map(|i| {
            let (mut sxx, mut sxy, mut syy, mut sxz, mut syz) = (0.0, 0.0, 0.0, 0.0, 0.0);
            for &j in &neighbours[i] {
                let (dx, dy, dz) = (v[j].x - v[i].x, v[j].y - v[i].y, heights[j] - heights[i]);
                sxx += dx * dx;
                sxy += dx * dy;
                syy += dy * dy;
                sxz += dx * dz;
                syz += dy * dz;
            }
            let det = sxx * syy - sxy * sxy;
            if det.abs() > 1e-12 * (sxx * syy).max(f64::MIN_POSITIVE) {
                [(syy * sxz - sxy * syz) / det, (sxx * syz - sxy * sxz) / det]
            } else if sxx + syy > 0.0 {
                // Collinear: the slope along the line.
                let s = (sxz + syz) / (sxx + syy);
                [s, s]
            } else {
                [0.0, 0.0]
            }
        })
        .collect()
}

/// The pieces of the interpolant of `heights` (one per vertex) over `d`; Clough–Tocher takes
/// `gradients` (one per vertex; estimated when `None`).
///
/// # Errors
///
/// `heights` or `gradients` of the wrong length or not finite, naming them.
///
/// # Examples
///
/// ```
/// use splinekit::Point;
/// use splinekit::triangle::Triangle;
/// use splinekit::triangulation::{Delaunay, HeightInterpolant, height_pieces};
/// // f = x² + y² with its gradients: Clough–Tocher reproduces quadratics.
/// let pts: Vec<Point<2>> = [(0.0, 0.0), (1.0, 0.0), (0.0, 1.0), (1.0, 1.0), (0.4, 0.6)]
///     .iter().map(|&(x, y)| Point::<2>::new(x, y)).collect();
/// let d = Delaunay::new(&pts).unwrap();
/// let z: Vec<f64> = pts.iter().map(|p| p.x * p.x + p.y * p.y).collect();
/// let g: Vec<[f64; 2]> = pts.iter().map(|p| [2.0 * p.x, 2.0 * p.y]).collect();
/// let pieces = height_pieces(&d, &z, Some(&g), HeightInterpolant::CloughTocher).unwrap();
/// let q = pieces.triangles[4].point(0.2, 0.3, 0.5);
/// assert!((q.z - (q.x * q.x + q.y * q.y)).abs() < 1e-14);
/// ```
pub fn height_pieces(
    d: &Delaunay,
    heights: &[f64],
    gradients: Option<&[[f64; 2]]>,
    kind: HeightInterpolant,
) -> Result<HeightPieces> {
    let n = d.num_vertices();
    if heights.len() != n {
        return Err(Error::count("heights", format!("{n} values, one per point"), heights.len()));
    }
    if let Some((i, z)) = heights.iter().enumerate().find(|(_, z)| !z.is_finite()) {
        return Err(Error::invalid(format!("heights[{i}]"), format!("is not finite ({z})")));
    }
    let tris = d.triangles();
    if tris.is_empty() {
        return Err(Error::invalid("points", format!("{n} points make no triangle (they are collinear or too few)")));
    }
    let v = d.vertices();
    let p3 = |i: usize| Point::<3>::new(v[i].x, v[i].y, heights[i]);
    let mut pieces = HeightPieces { triangles: Vec::new(), corners: Vec::new() };
    match kind {
        HeightInterpolant::Linear => {
            for t in &tris {
                pieces.triangles.push(BezierTriangle::new(vec![p3(t[0]), p3(t[1]), p3(t[2])])?);
                pieces.corners.push(t.map(|i| i as u32));
            }
        }
        HeightInterpolant::CloughTocher => {
            let estimated;
            let g = match gradients {
                Some(g) => {
                    if g.len() != n {
                        return Err(Error::count("normals", format!("{n} vectors, one per point"), g.len()));
                    }
                    if let Some(i) = g.iter().position(|g| !(g[0].is_finite() && g[1].is_finite())) {
                        return Err(Error::invalid(format!("normals[{i}]"), "gives a gradient that is not finite"));
                    }
                    g
                }
                None => {
                    estimated = estimate_gradients(d, heights);
                    &estimated[..]
                }
            };
            for (ti, t) in tris.iter().enumerate() {
                let micro = clough_tocher(t.map(|i| (v[i], heights[i], g[i])));
                for (k, m) in micro.into_iter().enumerate() {
                    pieces.triangles.push(m);
                    pieces.corners.push([t[k] as u32, t[(k + 1) % 3] as u32, (n + ti) as u32]);
                }
            }
        }
    }
    Ok(pieces)
}

/// The three cubic micro-triangles (V₀, V₁, C), (V₁, V₂, C), (V₂, V₀, C) of one triangle
/// given (position, height, gradient) at its corners (see the module documentation).
fn clough_tocher(c: [(Point<2>, f64, [f64; 2]); 3]) -> [BezierTriangle<3>; 3] {
    let centre = (c[0].0 + c[1].0 + c[2].0) / 3.0;
    let dot = |g: [f64; 2], d: Point<2>| g[0] * d.x + g[1] * d.y;
    // b_ij: the edge point next to V_i towards V_j; a_i: towards C.
    let b = |i: usize, j: usize| c[i].1 + dot(c[i].2, c[j].0 - c[i].0) / 3.0;
    let a = |i: usize| c[i].1 + dot(c[i].2, centre - c[i].0) / 3.0;
    let e = |i: usize, j: usize| {
        let (vi, vj) = (c[i].0, c[j].0);
        let edge = vj - vi;
        let len = edge.norm();
        let tau = edge / len;
        let normal = Point::<2>::new(-tau.y, tau.x);
        let d = centre - (vi + vj) / 2.0;
        let dn = d.dot(&normal);
        let (ni, nj) = (dn * dot(c[i].2, normal), dn * dot(c[j].2, normal));
        (b(i, j) + b(j, i)) / 2.0 + (ni + nj) / 6.0 + d.dot(&tau) / len * (b(j, i) - b(i, j))
    };
    let es = [e(0, 1), e(1, 2), e(2, 0)];
    // q_i on the inner edge V_iC: (a_i + e of the two edges at V_i)/3.
    let q = |i: usize| (a(i) + es[i] + es[(i + 2) % 3]) / 3.0;
    let qs = [q(0), q(1), q(2)];
    let s = (qs[0] + qs[1] + qs[2]) / 3.0;
    std::array::from_fn(|k| {
        let (i, j) = (k, (k + 1) % 3);
        let z = |ai: usize, aj: usize, ac: usize| -> f64 {
            match (ai, aj, ac) {
                (3, 0, 0) => c[i].1,
                (0, 3, 0) => c[j].1,
                (0, 0, 3) => s,
                (2, 1, 0) => b(i, j),
                (1, 2, 0) => b(j, i),
                (2, 0, 1) => a(i),
                (0, 2, 1) => a(j),
                (1, 1, 1) => es[k],
                (1, 0, 2) => qs[i],
                (0, 1, 2) => qs[j],
                _ => unreachable!("cubic indices"),
            }
        };
        BezierTriangle::from_fn(3, |(ai, aj, ac)| {
            let xy = (c[i].0 * ai as f64 + c[j].0 * aj as f64 + centre * ac as f64) / 3.0;
            Point::<3>::new(xy.x, xy.y, z(ai, aj, ac))
        })
        .expect("a cubic net of finite points")
    })
}
