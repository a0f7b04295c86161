//! `splinekit eval`: positions and derivatives of a shape at parameters.

use anyhow::{Result, anyhow, bail};
use clap::Args;
use serde_json::{Value, json};
use splinekit::Point;
use splinekit::curve::Curve;
use splinekit_scene::{CurveVisitor, ShapeDocument};

use crate::input::{parse_numbers, read_shape};
use crate::output::{number, write_json};

/// Most parameters one call may evaluate.
pub const MAX_SAMPLES: usize = 10_000_000;
/// Highest derivative order one call may ask for.
pub const MAX_DERIVATIVES: usize = 64;

#[derive(Args, Debug)]
pub struct EvalArgs {
    /// Shape document (JSON file, or - for standard input).
    pub shape: String,
    /// Parameters to evaluate at, comma-separated (e.g. 0,0.25,0.5). Open curves refuse
    /// parameters outside their domain; closed curves wrap them around.
    #[arg(long, allow_hyphen_values = true, conflicts_with = "samples", required_unless_present = "samples")]
    pub at: Option<String>,
    /// Number of parameters spread evenly over the whole domain, ends included.
    #[arg(long, allow_hyphen_values = true)]
    pub samples: Option<String>,
    /// Also print derivatives of orders 1 … K with respect to the curve's parameter.
    #[arg(long, default_value = "0", allow_hyphen_values = true)]
    pub derivatives: String,
    /// Write the JSON here instead of standard output.
    #[arg(short, long)]
    pub output: Option<String>,
}

fn parse_count(name: &str, text: &str, max: usize) -> Result<usize> {
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
    order: usize,
}

impl CurveVisitor for EvalCurve<'_> {
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
    let at = args.at.as_deref().map(|s| parse_numbers("--at", s)).transpose()?;
    if at.as_ref().is_some_and(|a| a.len() > MAX_SAMPLES) {
        bail!("--at: more than {MAX_SAMPLES} parameters");
    }
    let samples = match &args.samples {
        Some(s) => parse_count("--samples", s, MAX_SAMPLES)?,
        None => 0,
    };
    let doc = read_shape(&args.shape)?;
    let value = match doc {
        ShapeDocument::Curve(c) => {
            let curve = c.build().map_err(|e| anyhow!("{e}"))?;
            curve.visit(EvalCurve { at: at.as_deref(), samples, order })?
        }
    };
    write_json(&value, args.output.as_deref())
}
