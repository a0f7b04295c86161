//! `splinekit offset`: the offset of a plane curve (2-D, or 3-D with the normal of its
//! plane) or of a 3-D surface at a signed distance, as B-spline documents.

use anyhow::{Result, anyhow, bail};
use clap::Args;
use serde_json::{Value, json};
use splinekit::Point;
use splinekit_scene::ShapeDocument;
use splinekit_scene::answers::{OffsetCurve, offset_argument, offset_surface_document};

use crate::budget;
use crate::commands::intersect::positive;
use crate::input::{parse_numbers, read_shapes};
use crate::output::{check_finite, write_json};

#[derive(Args, Debug)]
pub struct OffsetArgs {
    /// Curve or surface document (JSON file, or - for standard input), or a scene of them,
    /// written back as the scene of their offsets.
    pub shape: String,
    /// Signed distance d: curves to the right of their direction (T × N), surfaces along
    /// S_u × S_v; negative for the other side.
    #[arg(long, allow_hyphen_values = true)]
    pub distance: String,
    /// Largest distance of the answer from the exact offset (> 0).
    #[arg(long, default_value = "1e-6", allow_hyphen_values = true)]
    pub tolerance: String,
    /// 3-D curves: the normal direction N of the plane the curve lies in, X,Y,Z (default
    /// 0,0,1: the plane z = const of the model curves).
    #[arg(long, allow_hyphen_values = true)]
    pub normal: Option<String>,
    /// Write the JSON here instead of standard output.
    #[arg(short, long)]
    pub output: Option<String>,
}

/// The flag a kernel error is about, on the command line.
fn flagged(e: splinekit::Error) -> anyhow::Error {
    let message = e.to_string();
    match offset_argument(&e) {
        Some(field) => anyhow!("--{field}{}", &message[field.len()..]),
        None => anyhow!("SHAPE: {message}"),
    }
}

pub fn run(args: &OffsetArgs) -> Result<()> {
    let distance = match parse_numbers("--distance", &args.distance)?[..] {
        [d] => d,
        _ => bail!("--distance: expected one number, got '{}'", args.distance),
    };
    let tolerance = positive("--tolerance", &args.tolerance)?;
    let normal = match &args.normal {
        None => None,
        Some(text) => match parse_numbers("--normal", text)?[..] {
            [x, y, z] => Some(Point::<3>::new(x, y, z)),
            ref other => bail!("--normal: expected X,Y,Z, got {} numbers", other.len()),
        },
    };
    let offset = |doc: ShapeDocument| -> Result<Value> {
        let cost = doc.cost();
        budget::check_shape(&cost)?;
        Ok(match doc {
            ShapeDocument::Curve(c) => {
                let request = splinekit_scene::budget::offset_curve(cost.eval);
                budget::check_request("--tolerance", "the offset's refinement", &cost, request)?;
                let (pieces, report) =
                    c.build()?.visit(OffsetCurve { distance, tolerance, normal }).map_err(flagged)?;
                eprintln!("{report}");
                if let [piece] = &pieces[..] {
                    piece.to_value()
                } else {
                    let objects: Vec<Value> = pieces.iter().map(|p| json!({ "shape": p.to_value() })).collect();
                    json!({ "type": "scene", "objects": objects })
                }
            }
            ShapeDocument::Surface(s) => {
                if normal.is_some() {
                    bail!("--normal: only curves take a plane normal; a surface is offset along its own normal");
                }
                let dim = s.dimension()?;
                if dim != 3 {
                    bail!("SHAPE: surface offsets are of 3-D surfaces, this one is {dim}-D");
                }
                let request = splinekit_scene::budget::offset_surface(cost.eval);
                budget::check_request("--tolerance", "the offset's refinement", &cost, request)?;
                let surface = s.build_in::<3>().map_err(|e| anyhow!("SHAPE: {e}"))?;
                let (doc, report) = offset_surface_document(surface.as_ref(), distance, tolerance).map_err(flagged)?;
                eprintln!("{report}");
                doc.to_value()
            }
        })
    };
    // A scene becomes the scene of its objects' offsets (an offset of several pieces gives
    // as many objects, each with the style of the one it came from).
    let value = read_shapes(&args.shape)?.map_each(offset)?;
    check_finite(&value, "control_points")?;
    write_json(&value, args.output.as_deref())
}
