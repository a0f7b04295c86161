//! `splinekit measure`: what a solid or surface measures — its topology (faces, edges,
//! vertices, shells, solids), its area and volume integrated over the exact trimmed faces,
//! and the same from its watertight mesh at a chord tolerance, with the mesh's open edges
//! and its box.

use anyhow::{Result, anyhow};
use clap::Args;
use serde_json::{Value, json};
use splinekit_mesh::measure::{measure_brep, measure_surface};
use splinekit_scene::placement::PlacementDoc;
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

/// What one shape measures ([`splinekit_mesh::measure`]), its box where `placement`
/// puts it; curves are refused.
fn measure(doc: ShapeDocument, tolerance: Option<f64>, placement: Option<&PlacementDoc>) -> Result<Value> {
    let placement = placement.map(|p| p.transform().map_err(|e| anyhow!("placement: {e}"))).transpose()?;
    let motion = placement.as_ref().map(|t| move |p: [f64; 3]| t.apply(p));
    let motion = motion.as_ref().map(|f| f as &(dyn Fn([f64; 3]) -> [f64; 3] + Sync));
    match doc {
        ShapeDocument::Surface(s) => {
            if let SurfaceDocument::Brep(d) = &s {
                return Ok(measure_brep(&d.build()?, tolerance, motion)?);
            }
            crate::budget::check_shape(&s.cost())?;
            Ok(measure_surface(s.build_in::<3>()?.as_ref(), tolerance, motion)?)
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
        splinekit_scene::SceneOrShape::Shape(doc) => measure(doc, args.tolerance, None)?,
        splinekit_scene::SceneOrShape::Scene(scene) => {
            let objects = scene
                .objects
                .into_iter()
                .enumerate()
                .map(|(i, o)| {
                    measure(o.shape, args.tolerance, o.placement.as_ref())
                        .map_err(|e| anyhow!("objects[{i}].shape: {e}"))
                })
                .collect::<Result<Vec<_>>>()?;
            json!({ "objects": objects })
        }
    };
    write_json(&value, args.output.as_deref())
}
