//! `splinekit eval`: positions and derivatives of a shape at parameters.

use anyhow::{Result, anyhow, bail};
use clap::Args;
use splinekit::Point;
use splinekit::curve::Curve;
use splinekit_scene::budget::{Cost, ShapeCost};
use splinekit_scene::{Curves, DimensionVisitor, SceneOrShape, ShapeDocument};

use crate::input::{parse_numbers, read_text};
use crate::output::JsonOut;

use super::spread::spread;

/// Most parameters one call may evaluate.
pub const MAX_SAMPLES: usize = 10_000_000;
/// Highest derivative order one call may ask for.
pub const MAX_DERIVATIVES: usize = 64;

#[derive(Args, Debug)]
#[command(group(clap::ArgGroup::new("where").required(true).args(["at", "samples", "grid"])))]
pub struct EvalArgs {
    /// Shape document (JSON file, or - for standard input).
    pub shape: String,
    /// Parameters to evaluate at, comma-separated: T,T,... for curves (e.g. 0,0.25,0.5),
    /// U:V,U:V,... for surfaces. Open directions refuse parameters outside the domain;
    /// closed ones wrap them around. Triangle documents also take T:U:V (triangle T at the
    /// barycentric point (u, v, 1 − u − v)) or T:U:V:W, with partials in (u, v).
    #[arg(long, allow_hyphen_values = true)]
    pub at: Option<String>,
    /// Curves: number of parameters spread evenly over the whole domain, ends included.
    #[arg(long, allow_hyphen_values = true)]
    pub samples: Option<String>,
    /// Curves with --samples: spread the parameters at equal arc length instead.
    #[arg(long, requires = "samples")]
    pub arc_length: bool,
    /// Surfaces: NU,NV parameters spread evenly over each direction, ends included;
    /// the output lists (u, v) with u varying slowest.
    #[arg(long)]
    pub grid: Option<String>,
    /// Also print derivatives of orders 1 … K with respect to the curve's parameter
    /// (surfaces: all partials of total order 1 … K).
    #[arg(long, default_value = "0", allow_hyphen_values = true)]
    pub derivatives: String,
    /// Pose the document's animation (blending-spline `animation` tracks) at this time in
    /// seconds; without it the shape is evaluated in its rest pose.
    #[arg(long, allow_hyphen_values = true)]
    pub time: Option<String>,
    /// Write the JSON here instead of standard output.
    #[arg(short, long)]
    pub output: Option<String>,
}

/// The largest `--time` in seconds (about 31 700 years): far beyond it the phase of a
/// motion, 2π f T + φ, has lost every digit (and near 1e308 it overflows).
pub(crate) const MAX_TIME: f64 = 1e12;

/// Parses `--time` (a finite number of seconds within ±[`MAX_TIME`]).
pub(crate) fn parse_time(text: &str) -> Result<f64> {
    let t: f64 = text.trim().parse().map_err(|_| anyhow!("--time: '{text}' is not a number"))?;
    if !t.is_finite() {
        bail!("--time: must be finite, got {t}");
    }
    if t.abs() > MAX_TIME {
        bail!("--time: {t} s is beyond the limit of ±{MAX_TIME:e} s");
    }
    Ok(t)
}

pub(crate) fn parse_count(name: &str, text: &str, max: usize) -> Result<usize> {
    let v: i128 = text.trim().parse().map_err(|_| anyhow!("{name}: '{text}' is not a whole number"))?;
    if v < 0 {
        bail!("{name}: must not be negative, got {v}");
    }
    if v > max as i128 {
        bail!("{name}: {v} is more than the limit of {max}");
    }
    Ok(v as usize)
}

/// The parameters asked for: a list, or `samples` evenly over the domain (ends included).
enum Params<'a> {
    List(&'a [f64]),
    Samples(usize),
    /// At equal arc length.
    ArcLength(usize),
}

impl Params<'_> {
    fn len(&self) -> usize {
        match self {
            Params::List(l) => l.len(),
            Params::Samples(n) | Params::ArcLength(n) => *n,
        }
    }
    /// The parameters on `curve`.
    fn on<const D: usize>(&self, curve: &dyn Curve<D>) -> Result<Vec<f64>> {
        let dom = curve.domain();
        Ok(match self {
            Params::List(l) => l.to_vec(),
            Params::ArcLength(n) if *n >= 2 => super::arc_length::equal_length_params(curve, *n)?,
            Params::Samples(n) | Params::ArcLength(n) => (0..*n).map(|i| spread(i, *n, dom)).collect(),
        })
    }
    /// The flag that asked for them.
    fn flag(&self) -> &'static str {
        match self {
            Params::List(_) => "--at",
            Params::Samples(_) | Params::ArcLength(_) => "--samples",
        }
    }
    /// Evaluations of the curve that finding them takes (arc length: a table of running
    /// lengths and Newton steps per parameter, counted as 16 evaluations each).
    fn evaluations(&self) -> f64 {
        match self {
            Params::ArcLength(n) => 16.0 * *n as f64,
            _ => 0.0,
        }
    }
}

/// Evaluates a curve at the parameters and streams `{"params", "points", "derivatives"}`.
struct EvalCurve<'a> {
    params: Params<'a>,
    order: usize,
    out: &'a mut JsonOut,
}

impl DimensionVisitor<Curves> for EvalCurve<'_> {
    type Output = Result<()>;
    fn visit<const D: usize>(self, curve: &dyn Curve<D>) -> Result<()> {
        let dom = curve.domain();
        if let Params::List(list) = self.params
            && !curve.is_closed()
        {
            let slack = 1e-12 * dom.length().max(dom.start.abs()).max(dom.end.abs());
            if let Some(t) = list.iter().find(|&&t| t < dom.start - slack || t > dom.end + slack) {
                bail!("--at: parameter {t} is outside the domain [{}, {}] of this open curve", dom.start, dom.end);
            }
        }
        let w = self.order + 1;
        let params = self.params.on(curve)?;
        let n = params.len();
        let mut values = vec![Point::<D>::zeros(); n * w];
        curve.eval_many(&params, self.order, &mut values);
        let out = self.out;
        out.raw(b"{\"params\":[")?;
        for (i, &t) in params.iter().enumerate() {
            if i > 0 {
                out.raw(b",")?;
            }
            out.number(t, || format!("params[{i}]"))?;
        }
        out.raw(b"],\"points\":[")?;
        for (i, &t) in params.iter().enumerate() {
            if i > 0 {
                out.raw(b",")?;
            }
            out.point(values[i * w].as_slice(), || format!("points[{i}] (t = {t})"))?;
        }
        out.raw(b"],\"derivatives\":[")?;
        for (i, &t) in params.iter().enumerate() {
            out.raw(if i > 0 { b",[" } else { b"[" })?;
            for k in 1..w {
                if k > 1 {
                    out.raw(b",")?;
                }
                out.point(values[i * w + k].as_slice(), || {
                    format!("derivatives[{i}][{}] (order {k} at t = {t})", k - 1)
                })?;
            }
            out.raw(b"]")?;
        }
        out.raw(b"]}")
    }
}

/// Refuses an evaluation of `count` parameters (asked for by `flag`) with `order`
/// derivatives that would not fit the budget: the document's building, the parameters
/// and values held in memory, their evaluation and formatting.
fn check_curve_request(params: &Params, order: usize, dimension: usize, cost: &ShapeCost) -> Result<()> {
    let (count, flag) = (params.len(), params.flag());
    let n = count as f64;
    let numbers = n * (order as f64 + 1.0) * dimension as f64;
    let work = cost.evaluations(n, order) + cost.evaluations(params.evaluations(), 1);
    let request = crate::budget::output(n + numbers) + Cost::new(0.0, work);
    crate::budget::check_request(
        flag,
        &format!(
            "{count} parameters with {order} derivatives ({:.1e} operations each, driven by {})",
            cost.eval * (order as f64 + 1.0),
            cost.field
        ),
        cost,
        request,
    )
}

pub fn run(args: &EvalArgs) -> Result<()> {
    let order = parse_count("--derivatives", &args.derivatives, MAX_DERIVATIVES)?;
    let time = args.time.as_deref().map(parse_time).transpose()?;
    let text = read_text(&args.shape, "SHAPE")?;
    match SceneOrShape::from_json_in(&text, &crate::input::document_folder(&args.shape))? {
        SceneOrShape::Shape(mut doc) => {
            if let Some(t) = time {
                doc.set_time(t);
            }
            let write = prepare(doc, args, order)?;
            let mut out = JsonOut::create(args.output.as_deref())?;
            write(&mut out)?;
            out.raw(b"\n")?;
            out.finish()
        }
        // A scene (`splinekit offset` prints one when the offset has several pieces):
        // every object is checked and built before anything is written, then answered in
        // order as `{"objects": [ANSWER, ...]}`, each ANSWER what the object alone gives.
        SceneOrShape::Scene(scene) => {
            let writes = scene
                .objects
                .into_iter()
                .enumerate()
                .map(|(i, object)| {
                    let mut doc = object.shape;
                    if let Some(t) = time {
                        doc.set_time(t);
                    }
                    prepare(doc, args, order).map_err(|e| anyhow!("objects[{i}].shape: {e}"))
                })
                .collect::<Result<Vec<_>>>()?;
            let mut out = JsonOut::create(args.output.as_deref())?;
            out.raw(b"{\"objects\":[")?;
            for (i, write) in writes.into_iter().enumerate() {
                if i > 0 {
                    out.raw(b",")?;
                }
                write(&mut out).map_err(|e| anyhow!("objects[{i}].shape: {e}"))?;
            }
            out.raw(b"]}\n")?;
            out.finish()
        }
    }
}

/// The parameters asked for: the `--at` list when given, else `samples` (at equal arc
/// length with `arc_length`).
fn curve_params(at: Option<&[f64]>, samples: usize, arc_length: bool) -> Params<'_> {
    match at {
        Some(list) => Params::List(list),
        None if arc_length => Params::ArcLength(samples),
        None => Params::Samples(samples),
    }
}

/// Writes one shape's answer (a JSON object, no line break) once the output is open.
type Answer = Box<dyn FnOnce(&mut JsonOut) -> Result<()>>;

/// Checks the request for one shape against the options and the budget and builds the
/// shape; the answer is written later, so that a scene writes nothing when any of its
/// objects is refused.
fn prepare(doc: ShapeDocument, args: &EvalArgs, order: usize) -> Result<Answer> {
    match doc {
        ShapeDocument::Curve(c) => {
            if args.grid.is_some() {
                bail!("--grid: curves take --at T,... or --samples N");
            }
            let at = args.at.as_deref().map(parse_curve_params).transpose()?;
            if at.as_ref().is_some_and(|a| a.len() > MAX_SAMPLES) {
                bail!("--at: more than {MAX_SAMPLES} parameters");
            }
            let (samples, arc_length) = match (&at, &args.samples) {
                (Some(_), _) => (0, false),
                (None, Some(s)) => match parse_count("--samples", s, MAX_SAMPLES)? {
                    0 => bail!("--samples: must be at least 1"),
                    n => (n, args.arc_length),
                },
                (None, None) => bail!("give --at T,... or --samples N"),
            };
            let cost = c.cost();
            crate::budget::check_shape(&cost)?;
            let dimension = c.dimension()?;
            check_curve_request(&curve_params(at.as_deref(), samples, arc_length), order, dimension, &cost)?;
            let curve = c.build()?;
            Ok(Box::new(move |out: &mut JsonOut| {
                curve.visit(EvalCurve { params: curve_params(at.as_deref(), samples, arc_length), order, out })
            }))
        }
        ShapeDocument::Surface(s) => {
            if args.samples.is_some() || args.arc_length {
                bail!("--samples: surfaces take --at U:V,... or --grid NU,NV");
            }
            if order > MAX_SURFACE_DERIVATIVES {
                bail!("--derivatives: {order} is more than the limit of {MAX_SURFACE_DERIVATIVES} for surfaces");
            }
            let (at, triangles) = match args.at.as_deref().map(parse_surface_params).transpose()? {
                None => (None, None),
                Some(SurfaceAt::Pairs(p)) => (Some(p), None),
                Some(SurfaceAt::Triangles(t)) => (None, Some(t)),
            };
            let grid = args.grid.as_deref().map(parse_grid).transpose()?;
            let cost = s.cost();
            crate::budget::check_shape(&cost)?;
            let request =
                super::eval_surface::EvalSurface { at: at.as_deref(), triangles: triangles.as_deref(), grid, order };
            request.check_budget(s.dimension()?, &cost)?;
            let surface = s.build()?;
            Ok(Box::new(move |out: &mut JsonOut| {
                let request = super::eval_surface::EvalSurface {
                    at: at.as_deref(),
                    triangles: triangles.as_deref(),
                    grid,
                    order,
                };
                surface.visit(super::eval_surface::SurfaceOutput { request, out })
            }))
        }
    }
}

/// Highest total order of surface partials one call may ask for.
pub const MAX_SURFACE_DERIVATIVES: usize = 16;

fn parse_curve_params(text: &str) -> Result<Vec<f64>> {
    if text.contains(':') {
        bail!("--at: curves take single parameters T,T,..., not U:V pairs");
    }
    parse_numbers("--at", text)
}

/// The `--at` points of a surface: (u, v) pairs, or points (triangle, u, v) of triangles.
enum SurfaceAt {
    Pairs(Vec<(f64, f64)>),
    Triangles(Vec<(usize, f64, f64)>),
}

/// How far a barycentric coordinate may stray below 0 (or their sum from 1) by rounding.
const BARYCENTRIC_SLACK: f64 = 1e-12;

fn parse_surface_params(text: &str) -> Result<SurfaceAt> {
    let mut pairs = Vec::new();
    let mut triangles = Vec::new();
    for item in text.split(',') {
        let parts: Vec<&str> = item.split(':').collect();
        let number = |s: &str| -> Result<f64> { Ok(parse_numbers("--at", s)?[0]) };
        match parts.as_slice() {
            [u, v] => pairs.push((number(u)?, number(v)?)),
            [t, u, v, rest @ ..] if rest.len() <= 1 => {
                let t = number(t)?;
                if !(t >= 0.0 && t.fract() == 0.0 && t < 1e15) {
                    bail!("--at: the triangle T of T:U:V must be a whole number ≥ 0, got '{}'", item.trim());
                }
                let (u, v) = (number(u)?, number(v)?);
                let w = match rest.first() {
                    Some(w) => {
                        let w = number(w)?;
                        if (u + v + w - 1.0).abs() > BARYCENTRIC_SLACK {
                            bail!("--at: u + v + w must be 1, got {u} + {v} + {w} in '{}'", item.trim());
                        }
                        w
                    }
                    None => 1.0 - u - v,
                };
                if u < -BARYCENTRIC_SLACK || v < -BARYCENTRIC_SLACK || w < -BARYCENTRIC_SLACK {
                    bail!(
                        "--at: ({u}, {v}, {w}) is outside the triangle (every barycentric coordinate must be ≥ 0) in '{}'",
                        item.trim()
                    );
                }
                triangles.push((t as usize, u, v));
            }
            _ => bail!("--at: surfaces take U:V pairs (triangle documents also T:U:V), got '{}'", item.trim()),
        }
        if pairs.len() + triangles.len() > MAX_SAMPLES {
            bail!("--at: more than {MAX_SAMPLES} parameters");
        }
    }
    match (pairs.is_empty(), triangles.is_empty()) {
        (_, true) => Ok(SurfaceAt::Pairs(pairs)),
        (true, false) => Ok(SurfaceAt::Triangles(triangles)),
        (false, false) => bail!("--at: give either U:V pairs or T:U:V triangle points, not both"),
    }
}

fn parse_grid(text: &str) -> Result<(usize, usize)> {
    let Some((a, b)) = text.split_once(',') else {
        bail!("--grid: expected NU,NV, got '{text}'");
    };
    let nu = parse_count("--grid", a, MAX_SAMPLES)?;
    let nv = parse_count("--grid", b, MAX_SAMPLES)?;
    if nu == 0 || nv == 0 {
        bail!("--grid: both counts must be at least 1, got {nu},{nv}");
    }
    if nu.saturating_mul(nv) > MAX_SAMPLES {
        bail!("--grid: {nu} × {nv} points is more than the limit of {MAX_SAMPLES}");
    }
    Ok((nu, nv))
}
