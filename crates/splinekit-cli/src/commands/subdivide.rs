//! `splinekit subdivide`: subdivision curves from a control polygon.

use anyhow::{Result, anyhow, bail};
use clap::{Args, ValueEnum};
use splinekit::subdivision::{ChaikinOptions, FourPointOptions, chaikin, four_point, lane_riesenfeld};
use splinekit_scene::points::{from_points, to_points};
use splinekit_scene::with_dimension;

use crate::input::read_points;
use crate::output::JsonOut;
use splinekit_scene::budget::Cost;

#[derive(Clone, Copy, Debug, ValueEnum)]
pub enum Scheme {
    /// Corner cutting ¾/¼ (limit: uniform quadratic B-spline).
    Chaikin,
    /// Doubling and d averaging passes (limit: uniform B-spline of degree d).
    #[value(name = "lane_riesenfeld", alias = "lane-riesenfeld")]
    LaneRiesenfeld,
    /// Dyn–Levin–Gregory interpolatory 4-point scheme.
    #[value(name = "four_point", alias = "four-point")]
    FourPoint,
}

#[derive(Args, Debug)]
pub struct SubdivideArgs {
    /// Control polygon: CSV (one point per line) or a JSON array of points; - for stdin.
    pub points: String,
    /// The scheme.
    #[arg(long, value_enum)]
    pub scheme: Scheme,
    /// Degree of the Lane–Riesenfeld limit B-spline (default 3); Chaikin is degree 2; the
    /// 4-point scheme has no degree and ignores it.
    #[arg(long)]
    pub degree: Option<usize>,
    /// Number of subdivision steps.
    #[arg(long)]
    pub steps: usize,
    /// Treat the polygon as closed (cyclic). The output then lists each point once,
    /// without repeating the first at the end.
    #[arg(long)]
    pub closed: bool,
    /// Keep the end points of an open polygon (Chaikin only).
    #[arg(long = "keep-ends")]
    pub keep_ends: bool,
    /// Tension w of the 4-point scheme (default 1/16).
    #[arg(long, default_value_t = 1.0 / 16.0)]
    pub tension: f64,
    /// Write the JSON here instead of standard output.
    #[arg(short, long)]
    pub output: Option<String>,
}

pub fn run(args: &SubdivideArgs) -> Result<()> {
    let pts = read_points(&args.points)?;
    let dim = pts[0].len();
    let passes = match args.scheme {
        Scheme::LaneRiesenfeld => args.degree.unwrap_or(3) as f64 + 1.0,
        _ => 1.0,
    };
    let out_points = pts.len() as f64 * 2f64.powi(args.steps.min(1100) as i32) + 4.0;
    let numbers = out_points * dim as f64;
    crate::budget::current().check(
        "--steps",
        &format!("{} steps on {} points", args.steps, pts.len()),
        Cost::new(numbers * 8.0 * 3.0, numbers * 4.0 * passes) + crate::budget::output(numbers),
    )?;
    let out: Vec<Vec<f64>> = with_dimension!(dim, "points", D => {
        let p = to_points::<D>(&pts);
        let r = match args.scheme {
            Scheme::Chaikin => {
                if let Some(d) = args.degree.filter(|&d| d != 2) {
                    bail!("--degree: Chaikin's scheme is of degree 2, got {d} (use --scheme lane_riesenfeld)");
                }
                chaikin(&p, args.steps, ChaikinOptions { closed: args.closed, keep_ends: args.keep_ends })
            }
            Scheme::LaneRiesenfeld => {
                let d = args.degree.unwrap_or(3);
                if d == 0 || d > 64 {
                    bail!("--degree: must be between 1 and 64, got {d}");
                }
                lane_riesenfeld(&p, d, args.steps, args.closed)
            }
            Scheme::FourPoint => {
                four_point(&p, args.steps, FourPointOptions { closed: args.closed, tension: args.tension })
            }
        }
        .map_err(|e| anyhow!("{}", e.to_string().replacen("steps:", "--steps:", 1).replacen("tension:", "--tension:", 1).replacen("degree:", "--degree:", 1)))?;
        Ok(from_points(&r))
    })
    .map_err(|e: anyhow::Error| e)?;
    let mut json = JsonOut::create(args.output.as_deref())?;
    json.raw(b"[")?;
    for (i, p) in out.iter().enumerate() {
        if i > 0 {
            json.raw(b",")?;
        }
        json.point(p, || format!("points[{i}] of the subdivided polygon"))?;
    }
    json.raw(b"]\n")?;
    json.finish()
}
