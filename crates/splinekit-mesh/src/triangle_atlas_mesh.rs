//! Meshes of triangular shapes ([`TriangleAtlas`]: Bézier, rational and GERBS triangles,
//! sub-triangles, triangulation interpolants and blends) made in each triangle's own
//! barycentric coordinates, not on the collapsed square of its chart: level n cuts every
//! triangle into n² sub-triangles at the lattice points (i/n, j/n, 1 − (i + j)/n), so there
//! are no slivers at the collapsed corner. Where the atlas knows which corners are shared
//! ([`TriangleAtlas::corner_ids`]) every shared corner and every lattice point of a shared
//! edge is evaluated once and used by both triangles, so the mesh is watertight (one level
//! for the whole atlas). Normals are each triangle's own (the mean of both sides on a
//! shared edge, so a C⁰ surface shades smoothly and a C¹ one exactly).
//!
//! The front ends (`tessellate`, `render`, glTF, the studio, Python) mesh on every core
//! ([`uniform_threads`]); the mesh is the one-thread mesh bit for bit.
//!
//! Tolerance: the level is the smallest power of two at which, in every triangle, the
//! surface at the midpoints of the sub-triangles' edges and at their centroids lies within
//! the chord height of the flat sub-triangles, measured along the surface's normal there
//! (the whole distance where it has none).

use std::collections::HashMap;

use splinekit::triangle::TriangleAtlas;
use splinekit::{Error, Point, Result};

use crate::mesh_options::{MAX_VERTICES, MeshOptions, to3};
use crate::triangle_mesh::TriangleMesh;

/// Where a lattice point lies, for sharing it between triangles.
#[derive(Clone, Copy, PartialEq, Eq, Hash)]
enum Key {
    Corner(u32),
    /// Edge from the smaller vertex number to the larger, point k of n from the smaller.
    Edge(u32, u32, u32),
    Inner(u32, u32, u32),
}

/// The mesh of every triangle of `atlas` at `level` (n ≥ 1 sub-divisions per edge), on
/// the calling thread.
pub fn uniform<const D: usize>(atlas: &TriangleAtlas<D>, level: usize, options: MeshOptions) -> Result<TriangleMesh> {
    uniform_threads(atlas, level, options, 1)
}

/// [`uniform`] with the surface evaluated on `threads` threads (0: as many as the machine
/// has cores), each taking a run of consecutive triangles. The mesh is the same bit for bit
/// whatever the count: which lattice point becomes which vertex is decided first, on one
/// thread, every point and normal is evaluated once, and the normals of shared points are
/// summed afterwards in triangle order.
pub fn uniform_threads<const D: usize>(
    atlas: &TriangleAtlas<D>,
    level: usize,
    options: MeshOptions,
    threads: usize,
) -> Result<TriangleMesh> {
    let charts = atlas.charts();
    let per = (level + 1) * (level + 2) / 2;
    if level == 0 || charts.len().saturating_mul(per) > MAX_VERTICES {
        return Err(Error::invalid(
            "density",
            format!(
                "need 1 to {MAX_VERTICES} vertices with at least one cut per edge, got {} triangles at level {level}",
                charts.len()
            ),
        ));
    }
    let n = level as u32;
    let ids = atlas.corner_ids();
    let mut mesh = TriangleMesh::default();
    let mut shared: HashMap<Key, u32> = HashMap::new();
    // The vertex of each chart's lattice point (chart c's at c·per + index(i, j)), and the
    // first vertex each chart adds: chart c evaluates the points of vertices
    // first[c] .. first[c + 1], which it meets first.
    let mut lattice = vec![0u32; charts.len() * per];
    let mut first = Vec::with_capacity(charts.len() + 1);
    let mut count = 0u32;
    let index = |i: u32, j: u32| -> usize {
        // Row by i (the power of u), j within it.
        let i = i as usize;
        let j = j as usize;
        i * (2 * level + 3 - i) / 2 + j
    };
    for (c, local) in lattice.chunks_mut(per).enumerate() {
        first.push(count);
        for i in 0..=n {
            for j in 0..=n - i {
                let k = n - i - j;
                let key = ids.map(|ids| {
                    let corner = ids[c];
                    // Barycentric weights (i, j, k) at corners u, v, w.
                    let nonzero: Vec<(u32, u32)> =
                        [(i, corner[0]), (j, corner[1]), (k, corner[2])].into_iter().filter(|(a, _)| *a > 0).collect();
                    match nonzero.as_slice() {
                        [(_, v)] => Key::Corner(*v),
                        [(a, va), (_, vb)] => {
                            if va < vb {
                                Key::Edge(*va, *vb, n - a)
                            } else {
                                Key::Edge(*vb, *va, *a)
                            }
                        }
                        _ => Key::Inner(c as u32, i, j),
                    }
                });
                let existing = key.and_then(|k| shared.get(&k).copied());
                let id = match existing {
                    Some(id) => id,
                    None => {
                        let id = count;
                        count += 1;
                        if options.uv {
                            mesh.uvs.push([i as f64 / n as f64, j as f64 / n as f64]);
                        }
                        if let Some(key) = key {
                            shared.insert(key, id);
                        }
                        id
                    }
                };
                local[index(i, j)] = id;
            }
        }
        for i in 0..n {
            for j in 0..n - i {
                // (i, j) → (i+1, j) → (i, j+1): counter-clockwise in (u, v).
                mesh.triangles.push([local[index(i, j)], local[index(i + 1, j)], local[index(i, j + 1)]]);
                if i + j + 1 < n {
                    mesh.triangles.push([local[index(i + 1, j)], local[index(i + 1, j + 1)], local[index(i, j + 1)]]);
                }
            }
        }
    }
    first.push(count);
    // Each chart's normals at its lattice points, and the points of the vertices it adds.
    let mut normals = vec![[0.0f64; 3]; charts.len() * per];
    mesh.positions = vec![[0.0f64; 3]; count as usize];
    let evaluate = |c: usize, normals: &mut [[f64; 3]], positions: &mut [[f64; 3]]| {
        let tri = charts[c].as_ref();
        let local = &lattice[c * per..(c + 1) * per];
        for i in 0..=n {
            for j in 0..=n - i {
                let (u, v) = (i as f64 / n as f64, j as f64 / n as f64);
                let w = (n - i - j) as f64 / n as f64;
                let at = index(i, j);
                normals[at] = tri.normal(u, v, w).map(|x| to3(&x)).unwrap_or([0.0; 3]);
                let id = local[at];
                if id >= first[c] {
                    positions[(id - first[c]) as usize] = to3(&tri.point(u, v, w));
                }
            }
        }
    };
    let threads = match threads {
        0 => std::thread::available_parallelism().map_or(1, |t| t.get()),
        t => t,
    }
    .clamp(1, charts.len().max(1));
    if threads == 1 {
        for c in 0..charts.len() {
            let (a, b) = (first[c] as usize, first[c + 1] as usize);
            evaluate(c, &mut normals[c * per..(c + 1) * per], &mut mesh.positions[a..b]);
        }
    } else {
        std::thread::scope(|scope| {
            let (mut normals, mut positions) = (&mut normals[..], &mut mesh.positions[..]);
            let mut start = 0;
            for t in 0..threads {
                let end = charts.len() * (t + 1) / threads;
                let (nh, nt) = std::mem::take(&mut normals).split_at_mut((end - start) * per);
                let (ph, pt) = std::mem::take(&mut positions).split_at_mut((first[end] - first[start]) as usize);
                (normals, positions) = (nt, pt);
                let (evaluate, first) = (&evaluate, &first);
                scope.spawn(move || {
                    let (mut nh, mut ph) = (nh, ph);
                    for c in start..end {
                        let (nc, nr) = std::mem::take(&mut nh).split_at_mut(per);
                        let (pc, pr) = std::mem::take(&mut ph).split_at_mut((first[c + 1] - first[c]) as usize);
                        (nh, ph) = (nr, pr);
                        evaluate(c, nc, pc);
                    }
                });
                start = end;
            }
        });
    }
    let mut normal_sums = vec![[0.0f64; 3]; count as usize];
    for (id, nrm) in lattice.iter().zip(&normals) {
        let s = &mut normal_sums[*id as usize];
        (0..3).for_each(|a| s[a] += nrm[a]);
    }
    mesh.normals = normal_sums
        .iter()
        .map(|s| {
            let len = (s[0] * s[0] + s[1] * s[1] + s[2] * s[2]).sqrt();
            if len > 0.0 && len.is_finite() { [s[0] / len, s[1] / len, s[2] / len] } else { [0.0; 3] }
        })
        .collect();
    crate::mesh_cleanup::finish(&mut mesh, "density")?;
    Ok(mesh)
}

/// The largest distance, over every triangle at `level`, from the surface at the midpoints
/// of the sub-triangles' edges and at their centroids to the flat sub-triangles.
fn deviation<const D: usize>(atlas: &TriangleAtlas<D>, level: usize) -> f64 {
    let n = level as f64;
    let mut worst = 0.0f64;
    for chart in atlas.charts() {
        let t = chart.as_ref();
        let p = |a: f64, b: f64| -> Point<D> { t.point(a / n, b / n, 1.0 - (a + b) / n) };
        // The distance along the surface's normal there (the chord height; a point of the
        // surface that the lattice only places elsewhere along it is no error), or the whole
        // distance where there is no normal.
        let off = |a: f64, b: f64, flat: Point<D>| -> f64 {
            let d = p(a, b) - flat;
            match t.normal(a / n, b / n, 1.0 - (a + b) / n) {
                Some(nrm) => d.dot(&nrm).abs(),
                None => d.norm(),
            }
        };
        let mut check = |corners: [(f64, f64); 3]| {
            let q = corners.map(|(a, b)| p(a, b));
            for (x, y) in [(0, 1), (1, 2), (2, 0)] {
                let (a, b) = ((corners[x].0 + corners[y].0) / 2.0, (corners[x].1 + corners[y].1) / 2.0);
                worst = worst.max(off(a, b, (q[x] + q[y]) / 2.0));
            }
            let (ca, cb) = (
                (corners[0].0 + corners[1].0 + corners[2].0) / 3.0,
                (corners[0].1 + corners[1].1 + corners[2].1) / 3.0,
            );
            worst = worst.max(off(ca, cb, (q[0] + q[1] + q[2]) / 3.0));
        };
        for i in 0..level {
            for j in 0..level - i {
                let (a, b) = (i as f64, j as f64);
                check([(a, b), (a + 1.0, b), (a, b + 1.0)]);
                if i + j + 1 < level {
                    check([(a + 1.0, b), (a + 1.0, b + 1.0), (a, b + 1.0)]);
                }
            }
        }
        if !worst.is_finite() {
            return f64::INFINITY;
        }
    }
    worst
}

/// The level ([`uniform`]) whose flat sub-triangles are within `tolerance` of the surface,
/// refusing one of more than `max_triangles` triangles.
pub fn level_for<const D: usize>(atlas: &TriangleAtlas<D>, tolerance: f64, max_triangles: usize) -> Result<usize> {
    if !(tolerance > 0.0 && tolerance.is_finite()) {
        return Err(Error::invalid("tolerance", format!("must be positive and finite, got {tolerance}")));
    }
    let count = atlas.charts().len() as f64;
    let mut level = 1usize;
    loop {
        if count * (level * level) as f64 > max_triangles.min(MAX_VERTICES) as f64 {
            return Err(Error::invalid(
                "tolerance",
                format!(
                    "{tolerance:?} needs more than {max_triangles} triangles ({} triangles cut {level} times per edge)",
                    atlas.charts().len()
                ),
            ));
        }
        let d = deviation(atlas, level);
        if d <= tolerance {
            return Ok(level);
        }
        if !d.is_finite() {
            return Err(Error::invalid("surface", "the surface is not finite where the mesh samples it"));
        }
        // The chord height falls as 1/n² on smooth triangles: jump to the power of two that
        // decay predicts (at least the next), refusing at once what the budget cannot hold.
        let predicted = level as f64 * (d / tolerance).sqrt();
        if count * predicted * predicted > max_triangles.min(MAX_VERTICES) as f64 {
            return Err(Error::invalid(
                "tolerance",
                format!(
                    "{tolerance:?} needs about {:.1e} triangles ({} triangles cut about {predicted:.0} times per edge, from the chord height {d:.2e} at {level}), more than {max_triangles}",
                    count * predicted * predicted,
                    atlas.charts().len()
                ),
            ));
        }
        let mut next = level * 2;
        while (next as f64) < predicted / 2.0 {
            next *= 2;
        }
        level = next;
    }
}

/// The mesh within `tolerance` (see [`level_for`]).
pub fn within_tolerance<const D: usize>(
    atlas: &TriangleAtlas<D>,
    tolerance: f64,
    max_triangles: usize,
    options: MeshOptions,
) -> Result<TriangleMesh> {
    let level = level_for(atlas, tolerance, max_triangles)?;
    uniform_threads(atlas, level, options, 0)
}

/// The level that a regular `nu` × `nv` grid's density asks for of an atlas of `charts`
/// triangles: about as many vertices in all as the grid would have.
pub fn level_for_density(nu: usize, nv: usize, charts: usize) -> usize {
    let per = (nu as f64 + 1.0) * (nv as f64 + 1.0) / charts.max(1) as f64;
    // (n + 1)(n + 2)/2 ≈ per.
    ((2.0 * per).sqrt() - 1.5).round().max(1.0) as usize
}
