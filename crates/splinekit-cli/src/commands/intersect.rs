//! `splinekit intersect`: where two curves meet (crossings, tangential contacts and
//! overlapping stretches), where one curve crosses itself, or where a curve meets a
//! surface.

use anyhow::{Result, anyhow, bail};
use clap::Args;
use serde_json::{Value, json};
use splinekit::curve::Curve;
use splinekit::query::{
    CurveIntersections, CurveSurfaceIntersection, EarlyStop, IntersectionBranch, IntersectionKind,
    intersect_curve_surface, intersect_curves, intersect_surfaces, self_intersections,
};
use splinekit_scene::refine::bspline_doc;
use splinekit_scene::{CurveDocument, Curves, DimensionVisitor, ShapeDocument, SurfaceDocument};

use crate::input::{parse_numbers, read_shape};
use crate::output::{check_finite, write_json};

#[derive(Args, Debug)]
pub struct IntersectArgs {
    /// First shape document (JSON file, or - for standard input).
    pub a: String,
    /// Second shape document; without it, the self-intersections of the first.
    pub b: Option<String>,
    #[command(flatten)]
    pub precision: Precision,
    /// Write the JSON here instead of standard output.
    #[arg(short, long)]
    pub output: Option<String>,
}

/// The `--tolerance` and `--chord` of a search for intersection curves, declared once for
/// `intersect` and `section` (the same names, defaults and checks; `section` words their
/// help for its planes with `mut_arg`).
#[derive(Args, Debug)]
pub struct Precision {
    /// Distance below which the shapes count as meeting (> 0).
    #[arg(long, default_value = "1e-9", allow_hyphen_values = true)]
    pub tolerance: String,
    /// Chord error of the polylines of surface–surface intersection curves (> 0).
    #[arg(long, default_value = "1e-4", allow_hyphen_values = true)]
    pub chord: String,
}

impl Precision {
    /// The tolerance and the chord error, in that order, each one number > 0 (else the
    /// flag's error).
    pub fn parse(&self) -> Result<(f64, f64)> {
        Ok((positive("--tolerance", &self.tolerance)?, positive("--chord", &self.chord)?))
    }
}

fn kind_name(kind: IntersectionKind) -> &'static str {
    match kind {
        IntersectionKind::Crossing => "crossing",
        IntersectionKind::Tangent => "tangent",
    }
}

/// A curve–surface answer: `params` are [t, u, v].
fn curve_surface_json(r: &[CurveSurfaceIntersection]) -> Value {
    let points: Vec<Value> = r
        .iter()
        .map(|p| json!({"params": [p.t, p.u, p.v], "point": [p.point.x, p.point.y, p.point.z], "kind": kind_name(p.kind)}))
        .collect();
    json!({"points": points, "overlaps": [], "curves": []})
}

/// The JSON of intersection branches: `{points, params_a, params_b, closed, tangent,
/// early_stop, bspline, fit_error}`, the B-spline fitted within `fit` of the points where
/// it can be.
pub fn branches_json(branches: &[IntersectionBranch], fit: f64) -> Result<Vec<Value>> {
    branches
        .iter()
        .map(|b| {
            let stop = b.early_stop.map(|s| match s {
                EarlyStop::Tangential => "tangential",
                EarlyStop::StepLimit => "step_limit",
                EarlyStop::PointLimit => "point_limit",
            });
            let points: Vec<[f64; 3]> = b.points.iter().map(|p| [p.x, p.y, p.z]).collect();
            let (bspline, error) = match b.points.len() {
                0 | 1 => (Value::Null, Value::Null),
                _ => {
                    let f = b.fit_bspline(fit)?;
                    (serde_json::to_value(bspline_doc(&f.curve))?, json!(f.max_error))
                }
            };
            Ok(json!({"points": points, "params_a": b.params_a, "params_b": b.params_b, "closed": b.closed,
                "tangent": b.tangent, "early_stop": stop, "bspline": bspline, "fit_error": error}))
        })
        .collect()
}

/// Parses a positive number given to `flag`.
pub fn positive(flag: &str, text: &str) -> Result<f64> {
    match parse_numbers(flag, text)?[..] {
        [t] if t > 0.0 => Ok(t),
        _ => bail!("{flag}: expected one number > 0, got '{text}'"),
    }
}

/// Builds two 3-D surfaces and intersects them.
fn two_surfaces(a: &SurfaceDocument, b: &SurfaceDocument, tolerance: f64, chord: f64) -> Result<Value> {
    let fit = chord;
    for (name, dim) in [("A", a.dimension()), ("B", b.dimension())] {
        let dim = dim.map_err(|e| anyhow!("{name}: {e}"))?;
        if dim != 3 {
            bail!("{name}: surfaces intersect in 3-D only, this surface is {dim}-D");
        }
    }
    let sa = a.build_in::<3>().map_err(|e| anyhow!("A: {e}"))?;
    let sb = b.build_in::<3>().map_err(|e| anyhow!("B: {e}"))?;
    let branches = intersect_surfaces(sa.as_ref(), sb.as_ref(), tolerance, chord)?;
    Ok(json!({"points": [], "overlaps": [], "curves": branches_json(&branches, fit)?}))
}

/// Builds a 3-D curve and surface, `name_c` and `name_s` naming them in errors.
fn curve_and_surface(
    c: &CurveDocument,
    s: &SurfaceDocument,
    (name_c, name_s): (&str, &str),
    tolerance: f64,
) -> Result<Value> {
    for (name, dim) in [(name_c, c.dimension()), (name_s, s.dimension())] {
        let dim = dim.map_err(|e| anyhow!("{name}: {e}"))?;
        if dim != 3 {
            bail!("{name}: a curve and a surface intersect in 3-D only, this shape is {dim}-D");
        }
    }
    let curve = c.build_in::<3>().map_err(|e| anyhow!("{name_c}: {e}"))?;
    let surface = s.build_in::<3>().map_err(|e| anyhow!("{name_s}: {e}"))?;
    Ok(curve_surface_json(&intersect_curve_surface(curve.as_ref(), surface.as_ref(), tolerance)?))
}

fn to_json<const D: usize>(r: &CurveIntersections<D>) -> Value {
    let points: Vec<Value> = r
        .points
        .iter()
        .map(|p| {
            json!({"params": [p.t_a, p.t_b], "point": p.point.iter().collect::<Vec<_>>(), "kind": kind_name(p.kind)})
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
    let (tolerance, chord) = args.precision.parse()?;
    let a = read_shape(&args.a)?;
    let b = args.b.as_deref().map(read_shape).transpose()?;
    let value = match (&a, &b) {
        (ShapeDocument::Curve(a), None) => {
            a.build().map_err(|e| anyhow!("A: {e}"))?.visit(Intersect { b: None, tolerance })?
        }
        (ShapeDocument::Curve(a), Some(ShapeDocument::Curve(b))) => {
            a.build().map_err(|e| anyhow!("A: {e}"))?.visit(Intersect { b: Some(b), tolerance })?
        }
        (ShapeDocument::Curve(c), Some(ShapeDocument::Surface(s))) => curve_and_surface(c, s, ("A", "B"), tolerance)?,
        (ShapeDocument::Surface(s), Some(ShapeDocument::Curve(c))) => curve_and_surface(c, s, ("B", "A"), tolerance)?,
        (ShapeDocument::Surface(_), None) => {
            bail!("B: a surface needs a second shape (self-intersections of surfaces are not computed)")
        }
        (ShapeDocument::Surface(a), Some(ShapeDocument::Surface(b))) => two_surfaces(a, b, tolerance, chord)?,
    };
    check_finite(&value, "result")?;
    write_json(&value, args.output.as_deref())
}
