//! `splinekit measure`: what a solid or surface measures — its topology (faces, edges,
//! vertices, shells, solids), its area and volume integrated over the exact trimmed faces,
//! and the same from its watertight mesh at a chord tolerance, with the mesh's open edges
//! and its box.

use anyhow::{Result, anyhow};
use clap::Args;
use serde_json::{Value, json};
use splinekit::brep::{Brep, integrals};
use splinekit_mesh::brep_mesh::{brep_mesh, open_edges};
use splinekit_mesh::{AdaptiveTolerance, MeshOptions, TriangleMesh};
use splinekit_scene::{ShapeDocument, SurfaceDocument};

use crate::input::read_document;
use crate::output::write_json;

#[derive(Args, Debug)]
pub struct MeasureArgs {
    /// Shape or scene document, or a STEP file (.step, .stp), or - for standard input.
    pub shape: String,
    /// Chord tolerance of the mesh (default: 10⁻³ of the box diagonal of the shape's
    /// vertices or samples).
    #[arg(long)]
    pub tolerance: Option<f64>,
    /// Write the JSON here instead of standard output.
    #[arg(short, long)]
    pub output: Option<String>,
}

/// The box of a mesh's positions: [min, max].
fn mesh_box(m: &TriangleMesh) -> Value {
    let (mut lo, mut hi) = ([f64::INFINITY; 3], [f64::NEG_INFINITY; 3]);
    for p in &m.positions {
        for k in 0..3 {
            lo[k] = lo[k].min(p[k]);
            hi[k] = hi[k].max(p[k]);
        }
    }
    json!([lo, hi])
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

/// What one B-rep measures.
fn measure_brep(b: &Brep, tolerance: Option<f64>) -> Result<Value> {
    let tolerance = tolerance.unwrap_or(1e-3 * vertex_diagonal(b));
    let mesh = brep_mesh(b, tolerance)?;
    let closed: Vec<usize> = (0..b.shells().len()).filter(|&s| b.shells()[s].closed).collect();
    let solids = b
        .solids()
        .iter()
        .map(|s| -> Result<Value> { Ok(json!({"shells": s.shells, "volume": integrals::volume(b, &s.shells).ok()})) })
        .collect::<Result<Vec<_>>>()?;
    Ok(json!({
        "faces": b.faces().len(),
        "edges": b.edges().len(),
        "vertices": b.vertices().len(),
        "shells": b.shells().len(),
        "closed_shells": closed.len(),
        "solids": solids,
        "area": integrals::area(b),
        "volume": integrals::volume(b, &closed).ok(),
        "mesh": {
            "tolerance": tolerance,
            "triangles": mesh.triangles.len(),
            "area": mesh.area(),
            "volume": mesh.signed_volume(),
            "open_edges": open_edges(&mesh),
            "box": mesh_box(&mesh),
        },
    }))
}

/// What one shape measures: a B-rep as [`measure_brep`], another surface by its adaptive
/// mesh; curves are refused.
fn measure(doc: ShapeDocument, tolerance: Option<f64>) -> Result<Value> {
    match doc {
        ShapeDocument::Surface(SurfaceDocument::Brep(d)) => measure_brep(&d.build()?, tolerance),
        ShapeDocument::Surface(s) => {
            crate::budget::check_shape(&s.cost())?;
            let surface = s.build_in::<3>()?;
            let size = splinekit::query::SurfaceExtent::extent(surface.as_ref()).diagonal();
            let size = if size > 0.0 && size.is_finite() { size } else { 1.0 };
            let tol = tolerance.unwrap_or(1e-3 * size);
            let t = AdaptiveTolerance { chord_height: tol, normal_angle: 0.5, max_depth: 10 };
            let mesh = splinekit_mesh::adaptive_mesh::adaptive(surface.as_ref(), (8, 8), t, MeshOptions::default())?;
            Ok(json!({
                "mesh": {
                    "tolerance": tol,
                    "triangles": mesh.triangles.len(),
                    "area": mesh.area(),
                    "volume": mesh.signed_volume(),
                    "open_edges": open_edges(&mesh),
                    "box": mesh_box(&mesh),
                }
            }))
        }
        ShapeDocument::Curve(c) => {
            Err(anyhow!("SHAPE: a {} is a curve; measure takes surfaces and solids", c.type_name()))
        }
    }
}

pub fn run(args: &MeasureArgs) -> Result<()> {
    if let Some(t) = args.tolerance
        && !(t > 0.0 && t.is_finite())
    {
        anyhow::bail!("--tolerance: must be positive and finite, got {t}");
    }
    let value = match read_document(&args.shape, "SHAPE")? {
        splinekit_scene::SceneOrShape::Shape(doc) => measure(doc, args.tolerance)?,
        splinekit_scene::SceneOrShape::Scene(scene) => {
            let objects = scene
                .objects
                .into_iter()
                .enumerate()
                .map(|(i, o)| measure(o.shape, args.tolerance).map_err(|e| anyhow!("objects[{i}].shape: {e}")))
                .collect::<Result<Vec<_>>>()?;
            json!({ "objects": objects })
        }
    };
    write_json(&value, args.output.as_deref())
}
