//! `splinekit offset`: the offset of a plane curve (2-D, or 3-D with the normal of its
//! plane) or of a 3-D surface at a signed distance, as B-spline documents.

use anyhow::{Result, anyhow, bail};
use clap::Args;
use serde_json::{Value, json};
use splinekit::Point;
use splinekit::curve::Curve;
use splinekit::query::offset::hermite_fit::MAX_TOTAL_PIECES;
use splinekit::query::offset::surface_offset::MAX_GRID_POINTS;
use splinekit::query::{offset_curve, offset_surface};
use splinekit_scene::budget::Cost;
use splinekit_scene::points::from_points;
use splinekit_scene::refine::bspline_doc;
use splinekit_scene::surfaces::BSplineSurfaceDoc;
use splinekit_scene::{Curves, DimensionVisitor, ShapeDocument, SurfaceDocument};

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
    for (field, flag) in [("distance", "--distance"), ("tolerance", "--tolerance"), ("normal", "--normal")] {
        if let Some(rest) = message.strip_prefix(field).and_then(|r| r.strip_prefix(':')) {
            return anyhow!("{flag}:{rest}");
        }
    }
    anyhow!("SHAPE: {message}")
}

struct OffsetCurve {
    distance: f64,
    tolerance: f64,
    normal: Option<Point<3>>,
}

impl DimensionVisitor<Curves> for OffsetCurve {
    type Output = Result<Value>;
    fn visit<const D: usize>(self, curve: &dyn Curve<D>) -> Result<Value> {
        let normal = if D == 3 { self.normal.or(Some(Point::<3>::z())) } else { self.normal };
        let off = offset_curve(curve, self.distance, normal, self.tolerance).map_err(flagged)?;
        eprintln!(
            "offset: {} piece{}, max error {:.3e} (tolerance {:e}), {} cusps and {} self-intersections of the raw offset trimmed",
            off.pieces.len(),
            if off.pieces.len() == 1 { "" } else { "s" },
            off.max_error,
            self.tolerance,
            off.cusps.len(),
            off.crossings.len()
        );
        if let [piece] = &off.pieces[..] {
            return Ok(bspline_doc(&piece.curve).to_value());
        }
        let objects: Vec<Value> =
            off.pieces.iter().map(|p| json!({ "shape": bspline_doc(&p.curve).to_value() })).collect();
        Ok(json!({ "type": "scene", "objects": objects }))
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
                // At most MAX_TOTAL_PIECES pieces of 8 samples (each a point and two derivatives)
                // over all the approximations of the offset, all of them held at the most.
                let work = MAX_TOTAL_PIECES as f64 * 8.0 * 3.0 * cost.eval;
                let request = Cost::new(MAX_TOTAL_PIECES as f64 * 200.0, work);
                budget::check_request("--tolerance", "the offset's refinement", &cost, request)?;
                c.build()?.visit(OffsetCurve { distance, tolerance, normal })?
            }
            ShapeDocument::Surface(s) => {
                if normal.is_some() {
                    bail!("--normal: only curves take a plane normal; a surface is offset along its own normal");
                }
                let dim = s.dimension()?;
                if dim != 3 {
                    bail!("SHAPE: surface offsets are of 3-D surfaces, this one is {dim}-D");
                }
                // The last grid and those before it (a third more), at its nodes and midpoints,
                // each a point and a normal (up to nine evaluations at a singular point).
                let samples = 4.0 * 1.34 * MAX_GRID_POINTS as f64;
                let request = Cost::new(samples * 200.0, samples * 12.0 * cost.eval);
                budget::check_request("--tolerance", "the offset's refinement", &cost, request)?;
                let surface = s.build_in::<3>().map_err(|e| anyhow!("SHAPE: {e}"))?;
                let off = offset_surface(surface.as_ref(), distance, tolerance).map_err(flagged)?;
                eprintln!(
                    "offset: max error {:.3e} (tolerance {:e}), {} × {} grid",
                    off.max_error, tolerance, off.grid.0, off.grid.1
                );
                let b = &off.surface;
                let (ku, kv) = b.knots();
                let doc = SurfaceDocument::BsplineSurface(BSplineSurfaceDoc {
                    degree_u: b.degrees().0,
                    degree_v: b.degrees().1,
                    knots_u: ku.to_vec(),
                    knots_v: kv.to_vec(),
                    control_points: b.control_points().iter().map(|row| from_points(row)).collect(),
                    periodic_u: false,
                    periodic_v: false,
                });
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
