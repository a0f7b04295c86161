//! The last steps of every surface mesher, which make its output acceptable to programs
//! that check meshes (the Khronos glTF validator, trimesh):
//!
//! 1. short edges whose two ends round to the same 32-bit floats are collapsed, so no
//!    triangle degenerates when a file stores single precision (STL, glTF);
//! 2. triangles with a repeated vertex are dropped and unused vertices removed;
//! 3. missing normals (isolated singular points) become the area-weighted mean of the
//!    adjacent faces' normals, so every normal has unit length;
//! 4. a closed, consistently oriented mesh whose signed volume is negative is turned inside
//!    out (triangles and normals), so closed surfaces face outward.
//!
//! Closedness is judged after merging vertices with bitwise-equal positions, because meshes
//! that store (u, v) keep both sides of a seam as separate vertices at the same place.

use foldhash::{HashMap, HashMapExt};

use splinekit::{Error, Result};

use crate::triangle_mesh::TriangleMesh;

/// Runs the steps above; fails when nothing is left (a grid too coarse for the surface).
/// A surface that is one point wherever the mesh sampled it (a Bézier patch whose control
/// points are all one point) is named as such, not blamed on `field`.
pub(crate) fn finish(mesh: &mut TriangleMesh, field: &str) -> Result<()> {
    let single_point = match mesh.bounds() {
        Some(b) if b.min == b.max => Some(b.min),
        _ => None,
    };
    collapse_single_precision_edges(mesh);
    mesh.triangles.retain(|[a, b, c]| a != b && b != c && a != c);
    drop_unused_vertices(mesh);
    if mesh.triangles.is_empty() {
        if let Some(p) = single_point {
            return Err(Error::invalid(
                "surface",
                format!("the surface is the single point ({}, {}, {}): it has no area to mesh", p[0], p[1], p[2]),
            ));
        }
        return Err(Error::invalid(
            field,
            "too coarse for this surface: every triangle collapsed to a point or a line",
        ));
    }
    mesh.repair_normals();
    orient_outward(mesh);
    Ok(())
}

/// Merges the two ends of every edge that single precision cannot tell apart although the
/// surface can spare it: their positions round to the same finite f32 and the edge is
/// shorter than 10⁻⁶ of the mesh's extent (union–find; the lower index survives). Meshes
/// too small or too far from the origin for f32 as a whole are left for the
/// single-precision writers to refuse.
fn collapse_single_precision_edges(mesh: &mut TriangleMesh) {
    let Some(b) = mesh.bounds() else { return };
    let extent = (0..3).map(|k| 0.5 * b.max[k] - 0.5 * b.min[k]).fold(0.0, f64::max);
    let singles: Vec<Option<[u32; 3]>> = mesh
        .positions
        .iter()
        .map(|p| {
            // `+ 0.0` turns −0 into +0: one point for the file, though not bit for bit (the
            // pinch of a horn torus has both).
            let p = p.map(|x| x as f32 + 0.0);
            p.iter().all(|x| x.is_finite()).then(|| p.map(f32::to_bits))
        })
        .collect();
    let single = |i: u32| singles[i as usize];
    let short = |a: u32, b: u32| {
        let (p, q) = (mesh.positions[a as usize], mesh.positions[b as usize]);
        (0..3).all(|k| (p[k] - q[k]).abs() <= 1e-6 * extent)
    };
    let mut parent: Vec<u32> = (0..mesh.positions.len() as u32).collect();
    fn root(parent: &mut [u32], mut i: u32) -> u32 {
        while parent[i as usize] != i {
            parent[i as usize] = parent[parent[i as usize] as usize];
            i = parent[i as usize];
        }
        i
    }
    let mut merged = false;
    for t in &mesh.triangles {
        for k in 0..3 {
            let (a, b) = (t[k], t[(k + 1) % 3]);
            if a != b && single(a).is_some() && single(a) == single(b) && short(a, b) {
                let (ra, rb) = (root(&mut parent, a), root(&mut parent, b));
                if ra != rb {
                    parent[ra.max(rb) as usize] = ra.min(rb);
                    merged = true;
                }
            }
        }
    }
    if merged {
        for t in mesh.triangles.iter_mut() {
            *t = t.map(|i| root(&mut parent, i));
        }
    }
}

/// Removes vertices no triangle uses, renumbering the triangles.
fn drop_unused_vertices(mesh: &mut TriangleMesh) {
    let mut new_index = vec![u32::MAX; mesh.positions.len()];
    for t in &mesh.triangles {
        for &i in t {
            new_index[i as usize] = 0;
        }
    }
    let mut next = 0u32;
    for slot in new_index.iter_mut() {
        if *slot == 0 {
            *slot = next;
            next += 1;
        }
    }
    if next as usize == mesh.positions.len() {
        return;
    }
    fn keep<T: Copy>(v: &mut Vec<T>, new_index: &[u32]) {
        if v.len() == new_index.len() {
            let mut k = 0;
            v.retain(|_| {
                k += 1;
                new_index[k - 1] != u32::MAX
            });
        }
    }
    keep(&mut mesh.positions, &new_index);
    keep(&mut mesh.normals, &new_index);
    keep(&mut mesh.uvs, &new_index);
    keep(&mut mesh.colors, &new_index);
    for t in mesh.triangles.iter_mut() {
        *t = t.map(|i| new_index[i as usize]);
    }
}

/// Turns a closed, consistently oriented mesh of negative signed volume inside out.
fn orient_outward(mesh: &mut TriangleMesh) {
    let mut same_place: HashMap<[u64; 3], u32> = HashMap::new();
    let place: Vec<u32> = (0..mesh.positions.len())
        .map(|i| *same_place.entry(mesh.positions[i].map(f64::to_bits)).or_insert(i as u32))
        .collect();
    // Directed edges: a closed, consistently oriented mesh uses each once in each direction.
    let mut directed: HashMap<(u32, u32), u32> = HashMap::new();
    for t in &mesh.triangles {
        for k in 0..3 {
            *directed.entry((place[t[k] as usize], place[t[(k + 1) % 3] as usize])).or_insert(0) += 1;
        }
    }
    let closed_and_oriented = directed.iter().all(|(&(a, b), &n)| n == 1 && directed.get(&(b, a)) == Some(&1));
    // A volume that overflowed to NaN is not negative: such meshes stay as they are.
    let inside_out = mesh.signed_volume() < 0.0;
    if !closed_and_oriented || !inside_out {
        return;
    }
    for t in mesh.triangles.iter_mut() {
        t.swap(1, 2);
    }
    for n in mesh.normals.iter_mut() {
        *n = n.map(|x| -x);
    }
}
