//! `splinekit measure`: what a solid or surface measures — its topology (faces, edges,
//! vertices, shells, solids), its area and volume integrated over the exact trimmed faces,
//! and the same from its watertight mesh at a chord tolerance, with the mesh's open edges
//! and its box.

use anyhow::{Result, anyhow};
use clap::Args;
use serde_json::{Value, json};
use splinekit_mesh::measure::{measure_brep, measure_surface};
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

/// What one shape measures ([`splinekit_mesh::measure`]); curves are refused.
fn measure(doc: ShapeDocument, tolerance: Option<f64>) -> Result<Value> {
    match doc {
        ShapeDocument::Surface(s) => {
            if let SurfaceDocument::Brep(d) = &s {
                return Ok(measure_brep(&d.build()?, tolerance)?);
            }
            crate::budget::check_shape(&s.cost())?;
            Ok(measure_surface(s.build_in::<3>()?.as_ref(), tolerance)?)
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
