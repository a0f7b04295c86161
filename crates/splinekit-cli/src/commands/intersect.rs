//! `splinekit intersect`: where two curves meet (crossings, tangential contacts and
//! overlapping stretches), or where one curve crosses itself.

use anyhow::{Result, anyhow, bail};
use clap::Args;
use serde_json::{Value, json};
use splinekit::curve::Curve;
use splinekit::query::{CurveIntersections, IntersectionKind, intersect_curves, self_intersections};
use splinekit_scene::{CurveDocument, Curves, DimensionVisitor, ShapeDocument};

use crate::input::{parse_numbers, read_shape};
use crate::output::{check_finite, write_json};

#[derive(Args, Debug)]
pub struct IntersectArgs {
    /// First shape document (JSON file, or - for standard input).
    pub a: String,
    /// Second shape document; without it, the self-intersections of the first.
    pub b: Option<String>,
    /// Distance below which the shapes count as meeting (> 0).
    #[arg(long, default_value = "1e-9", allow_hyphen_values = true)]
    pub tolerance: String,
    /// Write the JSON here instead of standard output.
    #[arg(short, long)]
    pub output: Option<String>,
}

fn curve_document(path: &str, name: &str) -> Result<CurveDocument> {
    match read_shape(path)? {
        ShapeDocument::Curve(c) => Ok(c),
        ShapeDocument::Surface(_) => {
            bail!("{name}: surfaces are not supported by intersect yet (curve–curve and self-intersections only)")
        }
    }
}

fn to_json<const D: usize>(r: &CurveIntersections<D>) -> Value {
    let points: Vec<Value> = r
        .points
        .iter()
        .map(|p| {
            let kind = match p.kind {
                IntersectionKind::Crossing => "crossing",
                IntersectionKind::Tangent => "tangent",
            };
            json!({"params": [p.t_a, p.t_b], "point": p.point.iter().collect::<Vec<_>>(), "kind": kind})
        })
        .collect();
    let overlaps: Vec<Value> =
        r.overlaps.iter().map(|o| json!({"params_a": [o.a.start, o.a.end], "params_b": [o.b.0, o.b.1]})).collect();
    json!({"points": points, "overlaps": overlaps, "curves": []})
}

struct Intersect<'a> {
    b: Option<&'a CurveDocument>,
    tolerance: f64,
}

impl DimensionVisitor<Curves> for Intersect<'_> {
    type Output = Result<Value>;
    fn visit<const D: usize>(self, a: &dyn Curve<D>) -> Result<Value> {
        let Some(doc) = self.b else {
            return Ok(to_json(&self_intersections(a, self.tolerance)?));
        };
        let dim = doc.dimension().map_err(|e| anyhow!("B: {e}"))?;
        if dim != D {
            bail!("B: the curves must have the same dimension, A is {D}-D and B is {dim}-D");
        }
        let b = doc.build_in::<D>().map_err(|e| anyhow!("B: {e}"))?;
        Ok(to_json(&intersect_curves(a, b.as_ref(), self.tolerance)?))
    }
}

pub fn run(args: &IntersectArgs) -> Result<()> {
    let tolerance = match parse_numbers("--tolerance", &args.tolerance)?[..] {
        [t] if t > 0.0 => t,
        _ => bail!("--tolerance: expected one number > 0, got '{}'", args.tolerance),
    };
    let a = curve_document(&args.a, "A")?;
    let b = args.b.as_deref().map(|p| curve_document(p, "B")).transpose()?;
    let curve = a.build().map_err(|e| anyhow!("A: {e}"))?;
    let value = curve.visit(Intersect { b: b.as_ref(), tolerance })?;
    check_finite(&value, "result")?;
    write_json(&value, args.output.as_deref())
}
