//! Triangle meshes of surfaces: a regular (u, v) grid, or an adaptive quad-tree refined to a
//! chord-height and normal-angle tolerance. Seams of closed surfaces are welded (the last
//! row of vertices is the first) unless (u, v) coordinates are asked for, in which case the
//! seam vertices are duplicated with bitwise-equal positions, so there are no cracks either
//! way. Trimmed surfaces are triangulated in the parameter plane with their trimming loops
//! as constraints ([`crate::trimmed_mesh`]).

use std::collections::HashMap;

use splinekit::surface::{Surface, unit_normal};
use splinekit::{Error, Point, Result};

use crate::triangle_mesh::{TriangleMesh, norm, sub};

/// Most vertices a surface mesh may have.
pub const MAX_VERTICES: usize = 20_000_000;

/// The first three coordinates of a point (missing ones 0).
pub fn to3<const D: usize>(p: &Point<D>) -> [f64; 3] {
    let mut q = [0.0; 3];
    for (k, v) in q.iter_mut().enumerate().take(D.min(3)) {
        *v = p[k];
    }
    q
}

/// Options for surface meshes.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MeshOptions {
    /// Store normalised (u, v) per vertex (duplicating seam vertices of closed surfaces).
    pub uv: bool,
}

impl Default for MeshOptions {
    fn default() -> Self {
        MeshOptions { uv: true }
    }
}

/// The regular mesh with `nu` × `nv` cells (two triangles each).
pub fn regular<const D: usize, S: Surface<D> + ?Sized>(
    surface: &S,
    nu: usize,
    nv: usize,
    options: MeshOptions,
) -> Result<TriangleMesh> {
    if nu == 0 || nv == 0 || (nu + 1).saturating_mul(nv + 1) > MAX_VERTICES {
        return Err(Error::invalid(
            "density",
            format!("need 1 to {MAX_VERTICES} vertices with at least one cell each way, got {nu}×{nv} cells"),
        ));
    }
    if let Some(loops) = surface.trim_loops() {
        return crate::trimmed_mesh::trimmed(surface, &loops, nu.max(nv), options);
    }
    let (du, dv) = (surface.domain_u(), surface.domain_v());
    let us: Vec<f64> = (0..=nu).map(|i| if i == nu { du.end } else { du.lerp(i as f64 / nu as f64) }).collect();
    let vs: Vec<f64> = (0..=nv).map(|j| if j == nv { dv.end } else { dv.lerp(j as f64 / nv as f64) }).collect();
    let mut points = vec![Point::<D>::zeros(); us.len() * vs.len()];
    let mut normals = vec![Point::<D>::zeros(); us.len() * vs.len()];
    surface.eval_grid_with_normals(&us, &vs, &mut points, &mut normals);
    let weld_u = surface.is_closed_u() && !options.uv;
    let weld_v = surface.is_closed_v() && !options.uv;
    let (ru, rv) = (if weld_u { nu } else { nu + 1 }, if weld_v { nv } else { nv + 1 });
    let index = |i: usize, j: usize| -> u32 { ((i % ru) * rv + (j % rv)) as u32 };
    let mut mesh = TriangleMesh::default();
    for i in 0..ru {
        for j in 0..rv {
            let k = i * vs.len() + j;
            mesh.positions.push(to3(&points[k]));
            mesh.normals.push(to3(&normals[k]));
            if options.uv {
                mesh.uvs.push([i as f64 / nu as f64, j as f64 / nv as f64]);
            }
        }
    }
    let inside: Option<Vec<bool>> = surface.trim_contains(us[0], vs[0]).map(|_| {
        (0..us.len() * vs.len())
            .map(|k| surface.trim_contains(us[k / vs.len()], vs[k % vs.len()]) == Some(true))
            .collect()
    });
    for i in 0..nu {
        for j in 0..nv {
            if let Some(inside) = &inside
                && ![(i, j), (i + 1, j), (i, j + 1), (i + 1, j + 1)].iter().all(|&(a, b)| inside[a * vs.len() + b])
            {
                continue;
            }
            let (a, b, c, d) = (index(i, j), index(i + 1, j), index(i + 1, j + 1), index(i, j + 1));
            mesh.triangles.push([a, b, c]);
            mesh.triangles.push([a, c, d]);
        }
    }
    finish(&mut mesh);
    Ok(mesh)
}

fn finish(mesh: &mut TriangleMesh) {
    mesh.drop_degenerate();
    mesh.repair_normals();
}

/// Tolerances of the adaptive mesh.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct AdaptiveTolerance {
    /// Largest distance of the surface from a cell's flat approximation (at the cell centre
    /// and edge midpoints).
    pub chord_height: f64,
    /// Largest angle in radians between the normals at a cell's corners and centre.
    pub normal_angle: f64,
    /// Deepest quad-tree level below the initial grid.
    pub max_depth: u32,
}

/// An adaptive mesh: an initial grid of `base` = (n_u, n_v) cells, each split in four while
/// it is farther than the chord height from flat or its normals turn more than the angle
/// (down to `max_depth` levels). Cells are triangulated as a fan from their centre whenever a
/// finer neighbour put vertices on their edges, so neighbouring levels stitch without cracks.
/// Trimmed surfaces keep the leaves whose corners are all inside the trim; [`regular`]
/// follows the trimming curves exactly.
pub fn adaptive<const D: usize, S: Surface<D> + ?Sized>(
    surface: &S,
    base: (usize, usize),
    tolerance: AdaptiveTolerance,
    options: MeshOptions,
) -> Result<TriangleMesh> {
    if !(tolerance.chord_height > 0.0 && tolerance.chord_height.is_finite()) {
        return Err(Error::invalid(
            "tolerance",
            format!("must be positive and finite, got {}", tolerance.chord_height),
        ));
    }
    if tolerance.normal_angle.is_nan()
        || tolerance.normal_angle <= 0.0
        || tolerance.max_depth > 16
        || base.0 == 0
        || base.1 == 0
        || base.0 * base.1 > 1 << 20
    {
        return Err(Error::invalid(
            "tolerance",
            format!(
                "need a positive normal angle, depth ≤ 16 and a base grid of 1 to 2²⁰ cells, got {}, {}, {}×{}",
                tolerance.normal_angle, tolerance.max_depth, base.0, base.1
            ),
        ));
    }
    let mut builder = Adaptive::new(surface, base, tolerance, options);
    let scale = 1i64 << tolerance.max_depth;
    for i in 0..base.0 as i64 {
        for j in 0..base.1 as i64 {
            builder.refine(i * scale, j * scale, scale)?;
        }
    }
    let mut mesh = builder.triangulate();
    finish(&mut mesh);
    Ok(mesh)
}

struct Adaptive<'a, const D: usize, S: Surface<D> + ?Sized> {
    surface: &'a S,
    tolerance: AdaptiveTolerance,
    options: MeshOptions,
    /// Lattice size in each direction (base cells × 2^depth).
    size: (i64, i64),
    vertices: HashMap<(i64, i64), u32>,
    mesh: TriangleMesh,
    /// Leaves as (i, j, size) in lattice units.
    leaves: Vec<(i64, i64, i64)>,
    /// Evaluations: lattice point → (position, unit normal).
    cache: HashMap<(i64, i64), ([f64; 3], [f64; 3])>,
}

impl<'a, const D: usize, S: Surface<D> + ?Sized> Adaptive<'a, D, S> {
    fn new(surface: &'a S, base: (usize, usize), tolerance: AdaptiveTolerance, options: MeshOptions) -> Self {
        let scale = 1i64 << tolerance.max_depth;
        Adaptive {
            surface,
            tolerance,
            options,
            size: (base.0 as i64 * scale, base.1 as i64 * scale),
            vertices: HashMap::new(),
            mesh: TriangleMesh::default(),
            leaves: Vec::new(),
            cache: HashMap::new(),
        }
    }
    fn params(&self, i: i64, j: i64) -> (f64, f64) {
        let (du, dv) = (self.surface.domain_u(), self.surface.domain_v());
        let u = if i == self.size.0 { du.end } else { du.lerp(i as f64 / self.size.0 as f64) };
        let v = if j == self.size.1 { dv.end } else { dv.lerp(j as f64 / self.size.1 as f64) };
        (u, v)
    }
    fn sample(&mut self, i: i64, j: i64) -> ([f64; 3], [f64; 3]) {
        if let Some(s) = self.cache.get(&(i, j)) {
            return *s;
        }
        let (u, v) = self.params(i, j);
        let mut out = [Point::<D>::zeros(); 4];
        self.surface.eval_partials(u, v, 1, 1, &mut out);
        let n = unit_normal(&out[2], &out[1]).map(|n| to3(&n)).unwrap_or([0.0; 3]);
        let s = (to3(&out[0]), n);
        self.cache.insert((i, j), s);
        s
    }
    fn refine(&mut self, i: i64, j: i64, size: i64) -> Result<()> {
        let corners = [(i, j), (i + size, j), (i + size, j + size), (i, j + size)];
        let split = size > 1 && {
            let c: Vec<_> = corners.iter().map(|&(a, b)| self.sample(a, b)).collect();
            let h = size / 2;
            let centre = self.sample(i + h, j + h);
            let mid = [
                self.sample(i + h, j),
                self.sample(i + size, j + h),
                self.sample(i + h, j + size),
                self.sample(i, j + h),
            ];
            let bilinear = [
                0.25 * (c[0].0[0] + c[1].0[0] + c[2].0[0] + c[3].0[0]),
                0.25 * (c[0].0[1] + c[1].0[1] + c[2].0[1] + c[3].0[1]),
                0.25 * (c[0].0[2] + c[1].0[2] + c[2].0[2] + c[3].0[2]),
            ];
            let mut far = norm(sub(centre.0, bilinear)) > self.tolerance.chord_height;
            for k in 0..4 {
                let (a, b) = (c[k].0, c[(k + 1) % 4].0);
                let m = [0.5 * (a[0] + b[0]), 0.5 * (a[1] + b[1]), 0.5 * (a[2] + b[2])];
                far |= norm(sub(mid[k].0, m)) > self.tolerance.chord_height;
            }
            let cos = self.tolerance.normal_angle.cos();
            let turned = c.iter().chain(mid.iter()).any(|s| {
                let d = s.1[0] * centre.1[0] + s.1[1] * centre.1[1] + s.1[2] * centre.1[2];
                norm(s.1) > 0.5 && norm(centre.1) > 0.5 && d < cos
            });
            far || turned
        };
        if split {
            let h = size / 2;
            self.refine(i, j, h)?;
            self.refine(i + h, j, h)?;
            self.refine(i, j + h, h)?;
            self.refine(i + h, j + h, h)?;
        } else {
            for &(a, b) in &corners {
                self.vertex(a, b)?;
            }
            self.leaves.push((i, j, size));
        }
        Ok(())
    }
    /// The lattice key of a vertex: seams of closed surfaces wrap unless (u, v) is stored.
    fn key(&self, i: i64, j: i64) -> (i64, i64) {
        let wu = self.surface.is_closed_u() && !self.options.uv;
        let wv = self.surface.is_closed_v() && !self.options.uv;
        (if wu { i % self.size.0 } else { i }, if wv { j % self.size.1 } else { j })
    }
    fn vertex(&mut self, i: i64, j: i64) -> Result<u32> {
        let key = self.key(i, j);
        if let Some(&v) = self.vertices.get(&key) {
            return Ok(v);
        }
        if self.mesh.positions.len() >= MAX_VERTICES {
            return Err(Error::invalid("tolerance", format!("needs more than {MAX_VERTICES} vertices")));
        }
        let (p, n) = self.sample(key.0, key.1);
        let idx = self.mesh.positions.len() as u32;
        self.mesh.positions.push(p);
        self.mesh.normals.push(n);
        if self.options.uv {
            self.mesh.uvs.push([i as f64 / self.size.0 as f64, j as f64 / self.size.1 as f64]);
        }
        self.vertices.insert(key, idx);
        Ok(idx)
    }
    /// Vertices strictly inside the lattice edge from (a) to (b) (axis-aligned, length
    /// a power of two), in order: found by looking for midpoints recursively.
    fn edge_vertices(&self, a: (i64, i64), b: (i64, i64), out: &mut Vec<u32>) {
        let len = (b.0 - a.0).abs().max((b.1 - a.1).abs());
        if len < 2 {
            return;
        }
        let m = ((a.0 + b.0) / 2, (a.1 + b.1) / 2);
        if let Some(&v) = self.vertices.get(&self.key(m.0, m.1)) {
            self.edge_vertices(a, m, out);
            out.push(v);
            self.edge_vertices(m, b, out);
        }
    }
    fn triangulate(mut self) -> TriangleMesh {
        let leaves = std::mem::take(&mut self.leaves);
        let inside = |s: &Self, i: i64, j: i64| {
            let (u, v) = s.params(i, j);
            s.surface.trim_contains(u, v) != Some(false)
        };
        for (i, j, size) in leaves {
            let corners = [(i, j), (i + size, j), (i + size, j + size), (i, j + size)];
            if !corners.iter().all(|&(a, b)| inside(&self, a, b)) {
                continue;
            }
            let ids: Vec<u32> = corners.iter().map(|&(a, b)| self.vertices[&self.key(a, b)]).collect();
            let mut ring = Vec::new();
            for k in 0..4 {
                ring.push(ids[k]);
                self.edge_vertices(corners[k], corners[(k + 1) % 4], &mut ring);
            }
            if ring.len() == 4 {
                self.mesh.triangles.push([ring[0], ring[1], ring[2]]);
                self.mesh.triangles.push([ring[0], ring[2], ring[3]]);
            } else {
                let h = size / 2;
                let c = self.vertex(i + h, j + h).expect("within the vertex limit");
                for k in 0..ring.len() {
                    self.mesh.triangles.push([c, ring[k], ring[(k + 1) % ring.len()]]);
                }
            }
        }
        self.mesh
    }
}
