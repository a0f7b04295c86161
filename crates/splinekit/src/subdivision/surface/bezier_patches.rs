//! The Catmull–Clark and Loop limit surfaces as polynomial patches (for STEP export).
//!
//! Loop works the same way with triangles: a regular triangle (three smooth interior
//! corners of valence 6) is its quartic box-spline patch written exactly as a Bézier
//! patch of degree (4, 4) with one collapsed edge ([`super::loop_bezier`]); an irregular
//! one has four children (one step of its 1-ring, [`super::loop_scheme::loop_step`]), of
//! which only those at an extraordinary vertex, a crease or a boundary stay irregular; its
//! stand-in is the flat triangle through the limit points of its corners, the bilinear
//! patch (c₀, c₁, c₂, c₂), measured in the atlas chart (s, t) ↦ (u, v) = (s(1 − t), t).
//! Loop boundaries and infinitely sharp creases never become regular box-spline patches,
//! so their faces are stand-ins at every level; the deviation there falls by about ¼ a
//! level (the crease curve is a cubic B-spline approximated by chords).
//!
//! Catmull–Clark:
//! Where a quad and its 1-ring are regular (every corner smooth of valence 4, or a regular
//! crease or boundary, see `regular_patch::catmull_clark_grid`), the limit surface on the
//! quad is the uniform bicubic B-spline patch of its 4×4 control grid G, written exactly as
//! a bicubic Bézier patch: per direction, b₀ = (G₀ + 4G₁ + G₂)/6, b₁ = (4G₁ + 2G₂)/6,
//! b₂ = (2G₁ + 4G₂)/6, b₃ = (G₁ + 4G₂ + G₃)/6 (the uniform cubic B-spline's Bézier
//! points on one knot span).
//!
//! Other faces (polygons, faces at an extraordinary vertex, at a semi-sharp crease) are
//! refined **locally**, as exact evaluation does ([`super::limit_eval`]): the face's 1-ring
//! is cut out ([`super::local::sub_cage`]) and subdivided once, which gives the right 1-ring
//! of each of its children (an n-gon's n quads), and each child is tried again. A quad at
//! one extraordinary vertex has four children of which only the one at that vertex stays
//! irregular; the other three are exact bicubic patches. So each level costs a constant
//! per irregular face (a 1-ring of about ten faces), not the 4× of subdividing the whole
//! surface, and 20 or 30 levels are cheap: the cube at depth d gives 72(d − 1) bicubic
//! patches and 24 stand-ins. A semi-sharp crease of sharpness s is smooth after ⌈s⌉ levels,
//! and its faces regular then unless an extraordinary vertex is near.
//!
//! The faces still irregular when refinement stops (at level ≥ 1, so quads) become
//! bilinear stand-ins through the limit points of their corners (limit masks), which meet
//! their neighbours' edges at those points. Each stand-in B is measured against the exact
//! limit S of its face (at each sample, the face's child of the next level containing it:
//! that child's bicubic patch where it is regular, else [`super::SubdivisionSurface::evaluate`]
//! on the local cage) on a
//! 9 × 9 grid of (u, v) ∈ {0, ⅛, …, 1}², edges included (the corners are limit points and
//! agree by construction): the deviation is max |B(u, v) − S(u, v)|, the distance between
//! points of the same parameters, an upper bound on both the distance from B(u, v) to the
//! surface and the gap along a shared edge at the samples. The largest deviation lies on
//! the edges away from the extraordinary vertex; on the cube the 9 × 9 grid finds it within
//! 0.6 % of a 33 × 33 grid's (a 5 × 5 grid within 2.7 %). Refinement stops at a
//! fixed level ([`Refinement::Depth`]) or, per face, at the fewest levels whose stand-in
//! is within a tolerance ([`Refinement::Tolerance`]). Near an extraordinary vertex of
//! subdominant eigenvalue λ the limit is c + λᴸ·(its characteristic map) + o(λᴸ) on the
//! level-L face, so the deviation falls by about λ a level where the characteristic map is
//! not bilinear on the face (λ ≈ 0.41 at valence 3, 0.55 at valence 5), and by about λ² at
//! its centre. Local cages are moved to the origin at each level so that their shrinking
//! differences keep their relative precision.

use super::catmull_clark::catmull_clark_step;
use super::limit_eval::{quad_child, triangle_child};
use super::local::{one_ring_faces, sub_cage};
use super::loop_bezier::{QuarticNet, loop_bezier_patch, quartic_at};
use super::loop_scheme::loop_step;
use super::regular_patch::{catmull_clark_grid, cubic_bspline_basis};
use super::topology::Topology;
use super::{Scheme, SubdivisionSurface};
use crate::{Error, Point, Result};

/// Most levels of local refinement (the faces at an extraordinary vertex are then
/// 2⁻³⁰ of their cage face in parameter).
pub const MAX_DEPTH: usize = 30;

/// The (u, v) samples of a stand-in's deviation: the 9 × 9 grid without its corners.
const SAMPLES: usize = 9;

/// Patches of a limit surface: exact bicubic Bézier patches (`[i][j]`, i along u) and
/// bilinear patches `[c₀, c₁, c₂, c₃]` (corners in face order) standing in for the
/// faces at extraordinary vertices.
#[derive(Debug, Default)]
pub struct LimitPatches {
    /// Exact bicubic Bézier patches (Catmull–Clark).
    pub bicubic: Vec<[[Point<3>; 4]; 4]>,
    /// Exact Bézier patches of degree (4, 4) (Loop, `[i][j]` with i along s), each a
    /// regular triangle in the atlas chart, its edge t = 1 collapsed onto the corner c₂
    /// (see [`super::loop_bezier`]).
    pub quartic: Vec<QuarticNet>,
    /// Bilinear patches through limit points (the faces themselves for the bilinear scheme).
    pub bilinear: Vec<[Point<3>; 4]>,
    /// The level of each bilinear patch (its face is 2⁻ˡᵉᵛᵉˡ of a cage face).
    pub levels: Vec<usize>,
    /// The largest distance between a bilinear patch and the limit surface at the same
    /// parameters over the sample grid (0 without bilinear patches).
    pub max_deviation: f64,
}

impl LimitPatches {
    /// The deepest level of a bilinear patch (0 without them).
    pub fn depth(&self) -> usize {
        self.levels.iter().copied().max().unwrap_or(0)
    }
}

/// When local refinement of an irregular face stops.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Refinement {
    /// Stand-ins at exactly this level (1 to [`MAX_DEPTH`]).
    Depth(usize),
    /// Per face, the fewest levels (1 to `max_depth` ≤ [`MAX_DEPTH`]) whose stand-in is
    /// within `tolerance` (absolute, > 0) of the limit at the samples; faces that do not
    /// meet it by `max_depth` stop there (see [`LimitPatches::max_deviation`]).
    Tolerance {
        /// The largest deviation allowed.
        tolerance: f64,
        /// The deepest level.
        max_depth: usize,
    },
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

/// The patches of a Catmull–Clark or Loop surface, irregular faces refined locally `depth`
/// (1 to [`MAX_DEPTH`]) times.
pub fn limit_patches(surface: &SubdivisionSurface, depth: usize) -> Result<LimitPatches> {
    refine_patches(surface, Refinement::Depth(depth))
}

/// The patches of a Catmull–Clark or Loop surface, each irregular face refined locally until its
/// stand-in is within `tolerance` of the limit (at most [`MAX_DEPTH`] levels).
pub fn limit_patches_within(surface: &SubdivisionSurface, tolerance: f64) -> Result<LimitPatches> {
    refine_patches(surface, Refinement::Tolerance { tolerance, max_depth: MAX_DEPTH })
}

/// The patches of a Catmull–Clark or Loop surface under `refinement` (the bilinear
/// scheme: its exact bilinear faces, whatever the refinement).
pub fn refine_patches(surface: &SubdivisionSurface, refinement: Refinement) -> Result<LimitPatches> {
    let max_depth = match refinement {
        Refinement::Depth(d) => d,
        Refinement::Tolerance { tolerance, max_depth } => {
            if !(tolerance > 0.0 && tolerance.is_finite()) {
                return Err(Error::invalid("tolerance", format!("must be finite and > 0, got {tolerance}")));
            }
            max_depth
        }
    };
    if !(1..=MAX_DEPTH).contains(&max_depth) {
        return Err(Error::invalid("depth", format!("must be 1 to {MAX_DEPTH} levels, got {max_depth}")));
    }
    if surface.scheme() == Scheme::Bilinear {
        return Ok(bilinear_faces(surface));
    }
    let mut out = LimitPatches::default();
    let zero = Point::<3>::zeros();
    for f in 0..surface.cage().face_count() as u32 {
        refine_face(surface, f, 0, zero, refinement, max_depth, &mut out)?;
    }
    Ok(out)
}

/// The bilinear scheme's limit, exactly: each quad is the bilinear patch of its corners,
/// each n-gon (n ≠ 4) the n quads of one step (corner, edge midpoint, centroid, edge
/// midpoint), all in [`LimitPatches::bilinear`] at level 0 with deviation 0.
fn bilinear_faces(surface: &SubdivisionSurface) -> LimitPatches {
    let (cage, mut out) = (surface.cage(), LimitPatches::default());
    for f in 0..cage.face_count() {
        let c: Vec<Point<3>> = cage.face(f).iter().map(|&v| cage.vertices[v as usize]).collect();
        let n = c.len();
        if n == 4 {
            out.bilinear.push([c[0], c[1], c[2], c[3]]);
        } else {
            let centroid = c.iter().fold(Point::<3>::zeros(), |a, p| a + p) / n as f64;
            for k in 0..n {
                let (prev, next) = (c[(k + n - 1) % n], c[(k + 1) % n]);
                out.bilinear.push([c[k], (c[k] + next) * 0.5, centroid, (prev + c[k]) * 0.5]);
            }
        }
    }
    out.levels = vec![0; out.bilinear.len()];
    out
}

/// Pushes the exact patch of `face` (moved by `offset`) if it is regular.
fn push_exact(s: &SubdivisionSurface, face: u32, offset: Point<3>, out: &mut LimitPatches) -> bool {
    let (cage, topo) = (s.cage(), s.topology());
    if s.scheme() == Scheme::Loop {
        if let Some(net) = loop_bezier_patch(cage, topo, face) {
            out.quartic.push(net.map(|row| row.map(|p| p + offset)));
            return true;
        }
    } else if let Some(g) = catmull_clark_grid(cage, topo, face) {
        out.bicubic.push(bezier_patch(&g).map(|row| row.map(|p| p + offset)));
        return true;
    }
    false
}

/// Face `face` of the local surface `s` (whose points are relative to `offset`) at
/// `level`: an exact patch if regular, a stand-in if refinement stops here, else its
/// children on the once-subdivided 1-ring.
fn refine_face(
    s: &SubdivisionSurface,
    face: u32,
    level: usize,
    offset: Point<3>,
    refinement: Refinement,
    max_depth: usize,
    out: &mut LimitPatches,
) -> Result<()> {
    if push_exact(s, face, offset, out) {
        return Ok(());
    }
    let (cage, topo) = (s.cage(), s.topology());
    // One local step: the 1-ring subdivided once, moved to the origin. Face 0 of the
    // 1-ring is `face`, so its children are the first faces of the step.
    let ring = one_ring_faces(topo, face);
    let (mut local, _) = sub_cage(cage, topo, &ring);
    let o = local.vertices[0];
    for p in &mut local.vertices {
        *p -= o;
    }
    let local_topo = Topology::new(&local)?;
    let (child, children) = match s.scheme() {
        Scheme::Loop => (loop_step(&local, &local_topo)?, 4),
        _ => (catmull_clark_step(&local, &local_topo), topo.face_len(face)),
    };
    let next = SubdivisionSurface::new(child, s.scheme(), false)?;
    // From level 1 on every face is a quad (Catmull–Clark) or a triangle (Loop).
    if level >= 1 && (s.scheme() == Scheme::Loop || topo.face_len(face) == 4) {
        let stop_here = level >= max_depth || matches!(refinement, Refinement::Depth(d) if level >= d);
        if stop_here || matches!(refinement, Refinement::Tolerance { .. }) {
            let q = stand_in(s, face)?;
            // `next` holds the stand-in's points relative to o.
            let deviation = deviation(&next, &q.map(|p| p - o))?;
            let met = matches!(refinement, Refinement::Tolerance { tolerance, .. } if deviation <= tolerance);
            if stop_here || met {
                out.max_deviation = out.max_deviation.max(deviation);
                out.bilinear.push(q.map(|p| p + offset));
                out.levels.push(level);
                return Ok(());
            }
        }
    }
    for k in 0..children {
        refine_face(&next, k, level + 1, offset + o, refinement, max_depth, out)?;
    }
    Ok(())
}

/// The bilinear stand-in of `face`: the limit points of its corners; a Loop triangle
/// (c₀, c₁, c₂) as the quad (c₀, c₁, c₂, c₂), whose bilinear patch is the flat triangle in
/// the atlas chart (s, t) ↦ (s(1 − t), t).
fn stand_in(s: &SubdivisionSurface, face: u32) -> Result<[Point<3>; 4]> {
    let c = s.cage().face(face as usize);
    let mut q = [Point::<3>::zeros(); 4];
    for (k, &v) in c.iter().enumerate() {
        q[k] = s.limit_frame(v)?.position;
    }
    if c.len() == 3 {
        q[3] = q[2];
    }
    Ok(q)
}

/// The bilinear patch (1−u)(1−v)q₀ + u(1−v)q₁ + uv q₂ + (1−u)v q₃.
fn bilinear_at(q: &[Point<3>; 4], u: f64, v: f64) -> Point<3> {
    q[0] * ((1.0 - u) * (1.0 - v)) + q[1] * (u * (1.0 - v)) + q[2] * (u * v) + q[3] * ((1.0 - u) * v)
}

/// An exact patch of a child: bicubic B-spline grid or quartic Bézier net.
enum ChildPatch {
    Bicubic(Box<[[Point<3>; 4]; 4]>),
    Quartic(Box<QuarticNet>),
}

/// max |B(s, t) − S(s, t)| over the sample grid (without its corners) of stand-in `q` of a
/// face whose children are the first faces of `children` (its 1-ring subdivided once):
/// S at a sample is the child's exact limit at the sample's place in it — its polynomial
/// patch where the child is regular, else local evaluation. For Loop, (s, t) is the atlas
/// chart, the face's (u, v) = (s(1 − t), t).
fn deviation(children: &SubdivisionSurface, q: &[Point<3>; 4]) -> Result<f64> {
    let is_loop = children.scheme() == Scheme::Loop;
    let (cage, topo) = (children.cage(), children.topology());
    let patches: Vec<Option<ChildPatch>> = (0..4)
        .map(|k| {
            if is_loop {
                loop_bezier_patch(cage, topo, k).map(|net| ChildPatch::Quartic(Box::new(net)))
            } else {
                catmull_clark_grid(cage, topo, k).map(|g| ChildPatch::Bicubic(Box::new(g)))
            }
        })
        .collect();
    let n = SAMPLES - 1;
    let mut worst = 0.0f64;
    for i in 0..=n {
        for j in 0..=n {
            if (i == 0 || i == n) && (j == 0 || j == n) {
                continue;
            }
            let (s, t) = (i as f64 / n as f64, j as f64 / n as f64);
            let (u, v) = if is_loop { (s * (1.0 - t), t) } else { (s, t) };
            let (k, a, b) = if is_loop { triangle_child(u, v) } else { quad_child(u, v) };
            let (cu, cv) = (a[0][0] * u + a[0][1] * v + b.0, a[1][0] * u + a[1][1] * v + b.1);
            let (cu, cv) = (cu.clamp(0.0, 1.0), cv.clamp(0.0, 1.0));
            let exact = match &patches[k as usize] {
                Some(ChildPatch::Bicubic(g)) => bspline_patch_at(g, cu, cv),
                // The child's chart: (cu, cv) = (s′(1 − t′), t′).
                Some(ChildPatch::Quartic(net)) => {
                    let sc = if cv < 1.0 { (cu / (1.0 - cv)).clamp(0.0, 1.0) } else { 0.0 };
                    quartic_at(net, sc, cv)
                }
                None => children.evaluate(k as usize, cu, cv)?.position,
            };
            worst = worst.max((bilinear_at(q, s, t) - exact).norm());
        }
    }
    Ok(worst)
}

/// The uniform bicubic B-spline patch of grid g at (u, v).
fn bspline_patch_at(g: &[[Point<3>; 4]; 4], u: f64, v: f64) -> Point<3> {
    let (bu, bv) = (cubic_bspline_basis(u)[0], cubic_bspline_basis(v)[0]);
    let mut p = Point::<3>::zeros();
    for (i, row) in g.iter().enumerate() {
        for (j, x) in row.iter().enumerate() {
            p += x * (bu[i] * bv[j]);
        }
    }
    p
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

        let s = SubdivisionSurface::new(Cage::cube(), Scheme::CatmullClark, false).unwrap();
        let p = limit_patches(&s, 3).unwrap();
        assert_eq!((p.bicubic.len(), p.bilinear.len(), p.depth()), (2 * 72, 24, 3));
        // The limit point of a cube corner: (n²v + 4Σeᵢ + Σdᵢ)/(n(n + 5)) with n = 3,
        // Σeᵢ = (1, 1, 1), Σdᵢ = −(1, 1, 1): (9 + 4 − 1)/24 (1, 1, 1) = ½ (1, 1, 1).
        let corner = Point::<3>::new(0.5, 0.5, 0.5);
        assert!(p.bilinear.iter().any(|q| q.iter().any(|c| (c - corner).norm() < 1e-15)));
        // Every bicubic patch lies between the cage's limit and the cage: |x| ≤ 1.
        assert!(p.bicubic.iter().flatten().flatten().all(|q| q.amax() <= 1.0));
    }
}
