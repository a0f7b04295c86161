//! Triangle meshes of surfaces on a regular (u, v) grid.
//!
//! The sides of the parameter rectangle are glued as the surface glues them
//! ([`crate::boundary_gluing`]): a side whose image is a point (a pole or apex) becomes one
//! vertex with a fan of triangles around it, and seams (closed directions, and sides that
//! meet without the model saying so) are welded, so closed surfaces give closed meshes.
//! When (u, v) coordinates are asked for, the two sides of a seam stay separate vertices
//! whose positions and normals are copied bitwise from one side, so there are no cracks
//! either way. The result is finished by [`crate::mesh_cleanup`] (closed meshes face
//! outward). Trimmed surfaces are triangulated in the parameter plane with their trimming
//! loops as constraints ([`crate::trimmed_mesh`]); adaptive meshes are in
//! [`crate::adaptive_mesh`]; subdivision limits are meshed by subdividing their cage
//! ([`crate::subdivision_mesh`]); triangles on their own barycentric lattices
//! ([`crate::triangle_atlas_mesh`]).

use splinekit::surface::Surface;
use splinekit::{Error, Point, Result};

use crate::boundary_gluing::{Gluing, Node};
use crate::triangle_mesh::TriangleMesh;

pub use crate::adaptive_mesh::{adaptive, adaptive_with_limit};
use crate::mesh_options::lattice_param;
pub use crate::mesh_options::{AdaptiveTolerance, MAX_VERTICES, MeshOptions, to3};

/// The regular mesh with `nu` × `nv` cells (two triangles each, one where a cell touches a
/// pole).
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
    if let Some(b) = surface.brep() {
        return crate::brep_mesh::brep_mesh(b, crate::brep_mesh::tolerance_for_density(b, nu.max(nv)));
    }
    if let Some(loops) = surface.trim_loops() {
        return crate::trimmed_mesh::trimmed(surface, &loops, nu.max(nv), options);
    }
    if let Some(atlas) = surface.triangle_atlas() {
        let level = crate::triangle_atlas_mesh::level_for_density(nu, nv, atlas.charts().len());
        return crate::triangle_atlas_mesh::uniform_threads(atlas, level, options, 0);
    }
    if let Some(s) = surface.subdivision() {
        let steps = crate::subdivision_mesh::steps_for_density(s, nu.max(nv));
        return crate::subdivision_mesh::limit_triangles(s, steps);
    }
    let (du, dv) = (surface.domain_u(), surface.domain_v());
    let n = (nu as i64, nv as i64);
    let us: Vec<f64> = (0..=n.0).map(|i| lattice_param(du, i, n.0)).collect();
    let vs: Vec<f64> = (0..=n.1).map(|j| lattice_param(dv, j, n.1)).collect();
    let mut points = vec![Point::<D>::zeros(); us.len() * vs.len()];
    let mut normals = vec![Point::<D>::zeros(); us.len() * vs.len()];
    surface.eval_grid_with_normals(&us, &vs, &mut points, &mut normals);
    let gluing = Gluing::detect(surface);
    let stride = vs.len() as i64;
    let at = |i: i64, j: i64| (i * stride + j) as usize;
    let mut mesh = TriangleMesh::default();
    let mut grid_ids = vec![u32::MAX; points.len()];
    let mut pole_ids = [u32::MAX; 4];
    let mut ids = vec![0u32; points.len()];
    for i in 0..=n.0 {
        for j in 0..=n.1 {
            let slot = match gluing.node(i, j, n, !options.uv) {
                Node::Pole(c) => &mut pole_ids[c],
                Node::Grid(a, b) => &mut grid_ids[at(a, b)],
            };
            if *slot == u32::MAX {
                *slot = mesh.positions.len() as u32;
                let (p, nrm, uv) = match gluing.node(i, j, n, true) {
                    Node::Pole(c) => {
                        let pole = gluing.pole(c);
                        (pole.position, pole.normal.unwrap_or([0.0; 3]), pole.uv)
                    }
                    Node::Grid(a, b) => {
                        (to3(&points[at(a, b)]), to3(&normals[at(a, b)]), [i as f64 / nu as f64, j as f64 / nv as f64])
                    }
                };
                mesh.positions.push(p);
                mesh.normals.push(nrm);
                if options.uv {
                    mesh.uvs.push(uv);
                }
            }
            ids[at(i, j)] = *slot;
        }
    }
    for i in 0..n.0 {
        for j in 0..n.1 {
            let (a, b, c, d) = (ids[at(i, j)], ids[at(i + 1, j)], ids[at(i + 1, j + 1)], ids[at(i, j + 1)]);
            mesh.triangles.push([a, b, c]);
            mesh.triangles.push([a, c, d]);
        }
    }
    crate::mesh_cleanup::finish(&mut mesh, "density")?;
    Ok(mesh)
}
