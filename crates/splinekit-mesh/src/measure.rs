//! What a surface or solid measures, as `splinekit measure` prints it and Python's
//! `splinekit.measure` returns it: a B-rep's topology (faces, edges, vertices, shells,
//! solids), its area and volume integrated over the exact trimmed faces
//! ([`splinekit::brep::integrals`]), and the same from its watertight mesh at a chord
//! tolerance with the mesh's open edges and box; another surface by its adaptive mesh.

use serde_json::{Value, json};
use splinekit::brep::{Brep, integrals};
use splinekit::surface::Surface;
use splinekit::{Error, Result};

use crate::brep_mesh::{brep_mesh, open_edges};
use crate::{AdaptiveTolerance, MeshOptions, TriangleMesh};

/// The default chord tolerance, relative to the diagonal of the shape's box (of a B-rep's
/// vertices, of another surface's extent).
pub const DEFAULT_RELATIVE_TOLERANCE: f64 = 1e-3;

/// Where a measured shape stands: a rigid motion of its points (a scene object's
/// placement), which moves the box and leaves lengths, areas and volumes as they are.
pub type Motion<'a> = Option<&'a (dyn Fn([f64; 3]) -> [f64; 3] + Sync)>;

/// The box of a mesh's positions, moved by `motion`: [min, max].
fn mesh_box(m: &TriangleMesh, motion: Motion<'_>) -> Value {
    let (mut lo, mut hi) = ([f64::INFINITY; 3], [f64::NEG_INFINITY; 3]);
    for p in &m.positions {
        let p = motion.map_or(*p, |f| f(*p));
        for k in 0..3 {
            lo[k] = lo[k].min(p[k]);
            hi[k] = hi[k].max(p[k]);
        }
    }
    json!([lo, hi])
}

/// The mesh's own measures: tolerance, triangles, area, signed volume, open edges, box.
fn mesh_measures(mesh: &TriangleMesh, tolerance: f64, motion: Motion<'_>) -> Value {
    json!({
        "tolerance": tolerance,
        "triangles": mesh.triangles.len(),
        "area": mesh.area(),
        "volume": mesh.signed_volume(),
        "open_edges": open_edges(mesh),
        "box": mesh_box(mesh, motion),
    })
}

/// The diagonal of the box of the B-rep's vertices (1 without vertices).
fn vertex_diagonal(b: &Brep) -> f64 {
    let (mut lo, mut hi) = ([f64::INFINITY; 3], [f64::NEG_INFINITY; 3]);
    for p in b.vertices() {
        for k in 0..3 {
            lo[k] = lo[k].min(p[k]);
            hi[k] = hi[k].max(p[k]);
        }
    }
    let d = (0..3).map(|k| (hi[k] - lo[k]).powi(2)).sum::<f64>().sqrt();
    if d > 0.0 && d.is_finite() { d } else { 1.0 }
}

/// What one B-rep measures (see the module); `tolerance` defaults to
/// [`DEFAULT_RELATIVE_TOLERANCE`] of its vertices' box diagonal; the box where `motion`
/// takes it.
pub fn measure_brep(b: &Brep, tolerance: Option<f64>, motion: Motion<'_>) -> Result<Value> {
    check_tolerance(tolerance)?;
    let tolerance = tolerance.unwrap_or(DEFAULT_RELATIVE_TOLERANCE * vertex_diagonal(b));
    let mesh = brep_mesh(b, tolerance)?;
    let closed: Vec<usize> = (0..b.shells().len()).filter(|&s| b.shells()[s].closed).collect();
    let solids: Vec<Value> = b
        .solids()
        .iter()
        .map(|s| json!({"shells": s.shells, "volume": integrals::volume(b, &s.shells).ok()}))
        .collect();
    // The closed shells' volume is the solids' sum where the solids hold them all.
    let in_solids: usize = b.solids().iter().map(|s| s.shells.len()).sum();
    let volume = if in_solids == closed.len() && b.solids().iter().all(|s| s.shells.iter().all(|k| closed.contains(k)))
    {
        solids.iter().map(|s| s["volume"].as_f64()).sum::<Option<f64>>()
    } else {
        integrals::volume(b, &closed).ok()
    };
    Ok(json!({
        "faces": b.faces().len(),
        "edges": b.edges().len(),
        "vertices": b.vertices().len(),
        "shells": b.shells().len(),
        "closed_shells": closed.len(),
        "solids": solids,
        "area": integrals::area(b),
        "volume": volume,
        "mesh": mesh_measures(&mesh, tolerance, motion),
    }))
}

/// A tolerance given must be positive and finite.
fn check_tolerance(tolerance: Option<f64>) -> Result<()> {
    match tolerance {
        Some(t) if !(t > 0.0 && t.is_finite()) => {
            Err(Error::invalid("tolerance", format!("must be positive and finite, got {t}")))
        }
        _ => Ok(()),
    }
}

/// What a surface other than a B-rep measures: its adaptive mesh's measures (`tolerance`
/// defaulting to [`DEFAULT_RELATIVE_TOLERANCE`] of its extent's diagonal). A surface whose
/// [`Surface::brep`] is a B-rep is measured as [`measure_brep`].
pub fn measure_surface(surface: &dyn Surface<3>, tolerance: Option<f64>, motion: Motion<'_>) -> Result<Value> {
    check_tolerance(tolerance)?;
    if let Some(b) = surface.brep() {
        return measure_brep(b, tolerance, motion);
    }
    let size = splinekit::query::SurfaceExtent::extent(surface).diagonal();
    let size = if size > 0.0 && size.is_finite() { size } else { 1.0 };
    let tolerance = tolerance.unwrap_or(DEFAULT_RELATIVE_TOLERANCE * size);
    let t = AdaptiveTolerance { chord_height: tolerance, normal_angle: 0.5, max_depth: 10 };
    let mesh = crate::adaptive_mesh::adaptive(surface, (8, 8), t, MeshOptions::default())?;
    Ok(json!({ "mesh": mesh_measures(&mesh, tolerance, motion) }))
}
