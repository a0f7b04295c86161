//! Triangle meshes of trimmed surfaces by constrained Delaunay triangulation (spade) in
//! the parameter plane: the trimming loops (resampled to the grid spacing) are constraint
//! edges, interior grid points fill the region, and triangles outside the trim are dropped.
//! The mesh boundary therefore follows the trimming curves instead of a staircase of cells.

use std::collections::HashMap;

use spade::{ConstrainedDelaunayTriangulation, Point2, Triangulation};
use splinekit::surface::{Surface, TrimLoops, unit_normal};
use splinekit::{Error, Point, Result};

use crate::surface_mesh::{MeshOptions, to3};
use crate::triangle_mesh::TriangleMesh;

/// The mesh of a trimmed surface with grid spacing 1/`n` of the domain in each direction.
pub fn trimmed<const D: usize, S: Surface<D> + ?Sized>(
    surface: &S,
    loops: &TrimLoops<'_>,
    n: usize,
    options: MeshOptions,
) -> Result<TriangleMesh> {
    let (du, dv) = (surface.domain_u(), surface.domain_v());
    // Work in the unit square.
    let to_unit = |p: &Point<2>| [(p[0] - du.start) / du.length(), (p[1] - dv.start) / dv.length()];
    let spacing = 1.0 / n as f64;
    let resample = |poly: &[Point<2>]| -> Vec<[f64; 2]> {
        let pts: Vec<[f64; 2]> = poly.iter().map(to_unit).collect();
        let mut out = vec![pts[0]];
        let mut run = 0.0;
        for w in pts.windows(2) {
            run += ((w[1][0] - w[0][0]).powi(2) + (w[1][1] - w[0][1]).powi(2)).sqrt();
            if run >= 0.5 * spacing {
                out.push(w[1]);
                run = 0.0;
            }
        }
        if out.len() < 8 {
            let step = (pts.len() / 8).max(1);
            out = pts.iter().step_by(step).copied().collect();
        }
        out
    };
    let mut rings: Vec<Vec<[f64; 2]>> = Vec::new();
    match loops.outer {
        Some(o) => rings.push(resample(o)),
        None => {
            let mut r = Vec::new();
            for k in 0..n {
                r.push([k as f64 * spacing, 0.0]);
            }
            for k in 0..n {
                r.push([1.0, k as f64 * spacing]);
            }
            for k in 0..n {
                r.push([1.0 - k as f64 * spacing, 1.0]);
            }
            for k in 0..n {
                r.push([0.0, 1.0 - k as f64 * spacing]);
            }
            rings.push(r);
        }
    }
    rings.extend(loops.holes.iter().map(|h| resample(h)));

    let mut cdt: ConstrainedDelaunayTriangulation<Point2<f64>> = ConstrainedDelaunayTriangulation::new();
    let insert = |cdt: &mut ConstrainedDelaunayTriangulation<Point2<f64>>, p: [f64; 2]| {
        cdt.insert(Point2::new(p[0], p[1])).map_err(|e| {
            Error::invalid("trim", format!("the point ({}, {}) cannot be triangulated: {e:?}", p[0], p[1]))
        })
    };
    for (r, ring) in rings.iter().enumerate() {
        let handles = ring.iter().map(|&p| insert(&mut cdt, p)).collect::<Result<Vec<_>>>()?;
        for k in 0..handles.len() {
            let (a, b) = (handles[k], handles[(k + 1) % handles.len()]);
            if a == b {
                continue;
            }
            if !cdt.can_add_constraint(a, b) {
                return Err(Error::invalid(
                    if r == 0 { "outer".to_string() } else { format!("holes[{}]", r - 1) },
                    "trimming loops must not cross themselves or each other",
                ));
            }
            cdt.add_constraint(a, b);
        }
    }
    // Interior grid points away from the loops.
    let inside = |p: [f64; 2]| surface.trim_contains(du.lerp(p[0]), dv.lerp(p[1])) != Some(false);
    let near_loop = |p: [f64; 2]| {
        rings.iter().flatten().any(|q| (p[0] - q[0]).powi(2) + (p[1] - q[1]).powi(2) < (0.4 * spacing).powi(2))
    };
    for i in 1..n {
        for j in 1..n {
            let p = [i as f64 * spacing, j as f64 * spacing];
            if inside(p) && !near_loop(p) {
                insert(&mut cdt, p)?;
            }
        }
    }
    // Triangles inside the trim, with their vertices evaluated once.
    let mut mesh = TriangleMesh::default();
    let mut index: HashMap<usize, u32> = HashMap::new();
    let mut partials = [Point::<D>::zeros(); 4];
    for face in cdt.inner_faces() {
        let vs = face.vertices();
        let c = vs.iter().fold([0.0, 0.0], |acc, v| [acc[0] + v.position().x / 3.0, acc[1] + v.position().y / 3.0]);
        if !inside(c) {
            continue;
        }
        let mut tri = [0u32; 3];
        for (k, v) in vs.iter().enumerate() {
            let key = v.fix().index();
            tri[k] = *index.entry(key).or_insert_with(|| {
                let p = v.position();
                let (u, w) = (du.lerp(p.x), dv.lerp(p.y));
                surface.eval_partials(u, w, 1, 1, &mut partials);
                mesh.positions.push(to3(&partials[0]));
                mesh.normals.push(unit_normal(&partials[2], &partials[1]).map(|n| to3(&n)).unwrap_or([0.0; 3]));
                if options.uv {
                    mesh.uvs.push([p.x, p.y]);
                }
                (mesh.positions.len() - 1) as u32
            });
        }
        mesh.triangles.push(tri);
    }
    mesh.drop_degenerate();
    mesh.repair_normals();
    Ok(mesh)
}
