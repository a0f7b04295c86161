//! Triangle meshes of a subdivision surface's limit: the cage subdivided k times and placed
//! on the limit surface ([`crate::limit_mesh`]: every vertex at its limit point with its
//! limit normal), k chosen for a density or a tolerance. [`crate::surface_mesh::regular`]
//! and [`crate::surface_mesh::adaptive_with_limit`] come here for every surface that is a
//! subdivision limit ([`Surface::subdivision`](splinekit::surface::Surface::subdivision)),
//! so `tessellate`, `render`, glTF export, the studio and Python all mesh it so.
//!
//! - A density of n cells per direction asks for about n² cells, like an n × n grid: the
//!   fewest steps k with (faces after k steps) ≥ n².
//! - A tolerance δ: the mesh of level k is within δ of the limit when every vertex that
//!   step k + 1 adds (face points and edge points; Loop: edge points) has its limit point
//!   within δ, along its limit normal, of the interpolant of level k's limit points there
//!   (the centroid of the face's corners, the midpoint of the edge's ends) — the chord
//!   height at the face and edge midpoints, where a flat interpolant between points of the
//!   surface strays most. (Along the surface the two differ by more near extraordinary
//!   vertices, where the parametrisation shrinks by the subdominant eigenvalue, not ½, a
//!   step; that is no distance from the surface.) The chord height shrinks by about 4 a
//!   step.

use splinekit::subdivision::surface::{LimitFrame, Scheme, SubdivisionSurface};
use splinekit::{Error, Point, Result};

use crate::limit_mesh::limit_mesh;
use crate::mesh_options::MAX_VERTICES;
use crate::triangle_mesh::TriangleMesh;

/// The fewest steps that give at least n² faces (and at most [`MAX_VERTICES`]).
pub fn steps_for_density(s: &SubdivisionSurface, n: usize) -> usize {
    let want = n.saturating_mul(n);
    let (mut faces, mut corners) = (s.cage().face_count(), s.cage().face_vertices.len());
    let mut k = 0;
    while faces < want {
        let next = if s.scheme() == Scheme::Loop { faces * 4 } else { corners };
        if next > MAX_VERTICES {
            break;
        }
        (faces, corners) = (next, next * if s.scheme() == Scheme::Loop { 3 } else { 4 });
        k += 1;
    }
    k
}

/// The limit mesh of `s` after `steps` steps, as triangles.
pub fn limit_triangles(s: &SubdivisionSurface, steps: usize) -> Result<TriangleMesh> {
    Ok(limit_mesh(&s.subdivide(steps)?)?.triangles())
}

/// The largest distance, along the limit normal, between the limit points of the vertices
/// that the step from `coarse` to `fine` adds and the interpolant of `coarse`'s limit
/// points there (see the module's documentation); `limits` and `fine` are the limit frames
/// of each.
pub fn midpoint_deviation(coarse: &SubdivisionSurface, limits: &[LimitFrame], fine: &[LimitFrame]) -> f64 {
    let off = |f: &LimitFrame, p: Point<3>| (f.position - p).dot(&f.normal).abs();
    let (cage, topo) = (coarse.cage(), coarse.topology());
    let nv = cage.vertices.len();
    let mut worst = 0.0f64;
    let mut edge_base = nv;
    if coarse.scheme() != Scheme::Loop {
        for f in 0..cage.face_count() {
            let face = cage.face(f);
            let centre =
                face.iter().fold(Point::<3>::zeros(), |a, &v| a + limits[v as usize].position) / face.len() as f64;
            worst = worst.max(off(&fine[nv + f], centre));
        }
        edge_base += cage.face_count();
    }
    for (e, &[a, b]) in topo.edges.iter().enumerate() {
        let mid = (limits[a as usize].position + limits[b as usize].position) * 0.5;
        worst = worst.max(off(&fine[edge_base + e], mid));
    }
    worst
}

/// The limit mesh of the fewest steps whose deviation from the limit (see the module's
/// documentation) is at most `tolerance`, refusing one of more than `max_faces` faces (the
/// next level, which measures it, is built too: about 4 × as many); also the deviation
/// reached and the steps.
pub fn within_tolerance(
    s: &SubdivisionSurface,
    tolerance: f64,
    max_faces: usize,
) -> Result<(TriangleMesh, f64, usize)> {
    if !(tolerance > 0.0 && tolerance.is_finite()) {
        return Err(Error::invalid("tolerance", format!("must be positive and finite, got {tolerance}")));
    }
    let max_faces = max_faces.min(MAX_VERTICES);
    let mut level = s.clone();
    let mut level_frames = level.limit_frames()?;
    let mut reached = None;
    for k in 0.. {
        if level.cage().face_count() > max_faces {
            let (steps, deviation) = reached.unwrap_or((0, f64::INFINITY));
            return Err(Error::invalid(
                "tolerance",
                format!(
                    "the limit within {tolerance} needs more than {max_faces} faces ({steps} steps give a mesh within {deviation:.3e})"
                ),
            ));
        }
        let fine = level.step()?;
        let fine_frames = fine.limit_frames()?;
        let deviation = midpoint_deviation(&level, &level_frames, &fine_frames);
        if deviation <= tolerance {
            return Ok((limit_mesh(&level)?.triangles(), deviation, k));
        }
        // The chord height shrinks by at most about 4 a step, so the steps still needed are at
        // least log₄(deviation / tolerance): refuse now when their faces would not fit.
        let more = (deviation / tolerance).log(4.0).ceil().max(1.0);
        let faces = fine.cage().face_count() as f64 * 4f64.powf(more - 1.0);
        if faces > max_faces as f64 {
            return Err(Error::invalid(
                "tolerance",
                format!(
                    "the limit within {tolerance} needs about {faces:.0} faces or more, more than {max_faces} ({k} steps give a mesh within {deviation:.3e})"
                ),
            ));
        }
        reached = Some((k, deviation));
        (level, level_frames) = (fine, fine_frames);
    }
    unreachable!("the loop returns")
}
