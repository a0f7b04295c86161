//! `splinekit eval`: positions and derivatives of a shape at parameters.

use anyhow::{Result, anyhow, bail};
use clap::Args;
use serde_json::{Value, json};
use splinekit::Point;
use splinekit::curve::Curve;
use splinekit_scene::{Curves, DimensionVisitor, ShapeDocument};

use crate::input::{parse_numbers, read_shape};
use crate::output::{number, write_json};

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
    /// closed ones wrap them around.
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

/// Parses `--time` (a finite number of seconds).
pub(crate) fn parse_time(text: &str) -> Result<f64> {
    let t: f64 = text.trim().parse().map_err(|_| anyhow!("--time: '{text}' is not a number"))?;
    if !t.is_finite() {
        bail!("--time: must be finite, got {t}");
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

struct EvalCurve<'a> {
    at: Option<&'a [f64]>,
    samples: usize,
    arc_length: bool,
    order: usize,
}

impl DimensionVisitor<Curves> for EvalCurve<'_> {
    type Output = Result<Value>;
    fn visit<const D: usize>(self, curve: &dyn Curve<D>) -> Result<Value> {
        let dom = curve.domain();
        let params: Vec<f64> = match self.at {
            Some(list) => {
                if !curve.is_closed() {
                    let slack = 1e-12 * dom.length().max(dom.start.abs()).max(dom.end.abs());
                    if let Some(t) = list.iter().find(|&&t| t < dom.start - slack || t > dom.end + slack) {
                        bail!(
                            "--at: parameter {t} is outside the domain [{}, {}] of this open curve",
                            dom.start,
                            dom.end
                        );
                    }
                }
                list.to_vec()
            }
            None => {
                let n = self.samples;
                if n == 0 {
                    bail!("--samples: must be at least 1");
                }
                if self.arc_length && n >= 2 {
                    super::arc_length::equal_length_params(curve, n)?
                } else {
                    (0..n)
                        .map(|i| {
                            if n == 1 {
                                dom.start
                            } else if i + 1 == n {
                                dom.end
                            } else {
                                dom.lerp(i as f64 / (n - 1) as f64)
                            }
                        })
                        .collect()
                }
            }
        };
        let total = params.len().saturating_mul((self.order + 1) * D);
        if total > 100_000_000 {
            bail!(
                "request too large: {} parameters × {} orders × {D} coordinates exceeds 100000000 numbers",
                params.len(),
                self.order + 1
            );
        }
        let w = self.order + 1;
        let mut values = vec![Point::<D>::zeros(); params.len() * w];
        curve.eval_many(&params, self.order, &mut values);
        let coords = |p: &Point<D>, what: &str| -> Result<Value> {
            Ok(Value::Array(p.iter().map(|&c| number(c, what)).collect::<Result<_>>()?))
        };
        let mut points = Vec::with_capacity(params.len());
        let mut derivs = Vec::with_capacity(params.len());
        for (i, &t) in params.iter().enumerate() {
            let at = format!("the point at t = {t}");
            points.push(coords(&values[i * w], &at)?);
            let d: Vec<Value> = (1..w)
                .map(|k| coords(&values[i * w + k], &format!("derivative {k} at t = {t}")))
                .collect::<Result<_>>()?;
            derivs.push(Value::Array(d));
        }
        Ok(json!({ "params": params, "points": points, "derivatives": derivs }))
    }
}

pub fn run(args: &EvalArgs) -> Result<()> {
    let order = parse_count("--derivatives", &args.derivatives, MAX_DERIVATIVES)?;
    let mut doc = read_shape(&args.shape)?;
    if let Some(t) = &args.time {
        doc.set_time(parse_time(t)?);
    }
    let value = match doc {
        ShapeDocument::Curve(c) => {
            if args.grid.is_some() {
                bail!("--grid: curves take --at T,... or --samples N");
            }
            let at = args.at.as_deref().map(parse_curve_params).transpose()?;
            if at.as_ref().is_some_and(|a| a.len() > MAX_SAMPLES) {
                bail!("--at: more than {MAX_SAMPLES} parameters");
            }
            let samples = match &args.samples {
                Some(s) => parse_count("--samples", s, MAX_SAMPLES)?,
                None => 0,
            };
            let curve = c.build()?;
            curve.visit(EvalCurve { at: at.as_deref(), samples, arc_length: args.arc_length, order })?
        }
        ShapeDocument::Surface(s) => {
            if args.samples.is_some() || args.arc_length {
                bail!("--samples: surfaces take --at U:V,... or --grid NU,NV");
            }
            if order > MAX_SURFACE_DERIVATIVES {
                bail!("--derivatives: {order} is more than the limit of {MAX_SURFACE_DERIVATIVES} for surfaces");
            }
            let at = args.at.as_deref().map(parse_surface_params).transpose()?;
            let grid = args.grid.as_deref().map(parse_grid).transpose()?;
            let surface = s.build()?;
            surface.visit(super::eval_surface::EvalSurface { at: at.as_deref(), grid, order })?
        }
    };
    write_json(&value, args.output.as_deref())
}

/// Highest total order of surface partials one call may ask for.
pub const MAX_SURFACE_DERIVATIVES: usize = 16;

fn parse_curve_params(text: &str) -> Result<Vec<f64>> {
    if text.contains(':') {
        bail!("--at: curves take single parameters T,T,..., not U:V pairs");
    }
    parse_numbers("--at", text)
}

fn parse_surface_params(text: &str) -> Result<Vec<(f64, f64)>> {
    let pairs: Result<Vec<(f64, f64)>> = text
        .split(',')
        .map(|pair| {
            let Some((u, v)) = pair.split_once(':') else {
                bail!("--at: surfaces take U:V pairs, got '{}'", pair.trim());
            };
            let u = parse_numbers("--at", u)?;
            let v = parse_numbers("--at", v)?;
            Ok((u[0], v[0]))
        })
        .collect();
    let pairs = pairs?;
    if pairs.len() > MAX_SAMPLES {
        bail!("--at: more than {MAX_SAMPLES} parameters");
    }
    Ok(pairs)
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
