//! `splinekit fit` and `splinekit interpolate`: B-splines from points.

use anyhow::{Result, anyhow, bail};
use clap::{Args, ValueEnum};
use splinekit::Point;
use splinekit::fit::{self, FitOptions, InterpolationOptions, KnotPlacement, Parametrization};
use splinekit_scene::curves::CurveDocument;
use splinekit_scene::points::to_points;
use splinekit_scene::refine::bspline_doc;
use splinekit_scene::with_dimension;

use crate::input::{parse_numbers, parse_points, read_points, read_text};
use crate::output::{check_finite, write_json};
use serde_json::Value;
use splinekit_scene::{Curves, DimensionVisitor, ShapeDocument};

#[derive(Clone, Copy, Debug, ValueEnum)]
pub enum ParamsArg {
    /// t_i = i/(m − 1).
    Uniform,
    /// Proportional to the distance between consecutive points.
    Chord,
    /// Proportional to the square root of that distance.
    Centripetal,
}

#[derive(Clone, Copy, Debug, ValueEnum)]
pub enum KnotsArg {
    /// Clamped, uniform on [0, 1].
    Uniform,
    /// Averaged from the parameters, so every knot span holds data.
    Averaged,
}

impl From<ParamsArg> for Parametrization {
    fn from(p: ParamsArg) -> Self {
        match p {
            ParamsArg::Uniform => Parametrization::Uniform,
            ParamsArg::Chord => Parametrization::ChordLength,
            ParamsArg::Centripetal => Parametrization::Centripetal,
        }
    }
}

/// Largest degree accepted for fitting and interpolation.
const MAX_DEGREE: usize = 64;

#[derive(Args, Debug)]
pub struct FitArgs {
    /// Points: CSV (one point per line) or a JSON array of points; - for standard input.
    /// A shape document (a JSON object with a "type") is a model curve instead: it is
    /// sampled at --samples parameters evenly over its domain and the samples are fitted
    /// with parameters proportional to the model's own.
    pub points: String,
    /// Number of samples taken from a model curve (shape document input only).
    #[arg(long, default_value = "200")]
    pub samples: usize,
    /// Degree of the B-spline (1 … 64).
    #[arg(long)]
    pub degree: usize,
    /// Number of control points (degree + 1 … number of points).
    #[arg(long = "control-points")]
    pub control_points: usize,
    /// Parameters of the data points on [0, 1].
    #[arg(long, value_enum, default_value = "chord")]
    pub params: ParamsArg,
    /// Placement of the knots.
    #[arg(long, value_enum, default_value = "averaged")]
    pub knots: KnotsArg,
    /// Fit a closed (periodic) curve; the last point connects back to the first.
    #[arg(long)]
    pub closed: bool,
    /// Make the curve start at the first point and end at the last one exactly.
    #[arg(long = "interpolate-ends", conflicts_with = "closed")]
    pub interpolate_ends: bool,
    /// Print the fit's RMS and maximum error and condition estimate on standard error.
    #[arg(long)]
    pub report: bool,
    /// Write the JSON here instead of standard output.
    #[arg(short, long)]
    pub output: Option<String>,
}

#[derive(Args, Debug)]
pub struct InterpolateArgs {
    /// Points: CSV (one point per line) or a JSON array of points; - for standard input.
    pub points: String,
    /// Degree of the B-spline (1 … 64).
    #[arg(long)]
    pub degree: usize,
    /// Parameters of the data points on [0, 1].
    #[arg(long, value_enum, default_value = "chord")]
    pub params: ParamsArg,
    /// Interpolate a closed (periodic) curve.
    #[arg(long)]
    pub closed: bool,
    /// First derivative c'(0), comma-separated (needs --end-derivative too).
    #[arg(
        long = "start-derivative",
        allow_hyphen_values = true,
        requires = "end_derivative",
        conflicts_with = "closed"
    )]
    pub start_derivative: Option<String>,
    /// First derivative c'(1), comma-separated.
    #[arg(long = "end-derivative", allow_hyphen_values = true, requires = "start_derivative")]
    pub end_derivative: Option<String>,
    /// Write the JSON here instead of standard output.
    #[arg(short, long)]
    pub output: Option<String>,
}

fn check_degree(p: usize) -> Result<()> {
    if p == 0 || p > MAX_DEGREE {
        bail!("--degree: must be between 1 and {MAX_DEGREE}, got {p}");
    }
    Ok(())
}

/// Refuses a fit of `points` data points (given by `field`) whose least-squares solve
/// would not fit the budget (see [`splinekit_scene::budget::least_squares_fit`]).
fn check_fit_budget(field: &str, points: usize, args: &FitArgs, dimension: usize) -> Result<()> {
    let (n, p) = (args.control_points, args.degree);
    let cost = splinekit_scene::budget::least_squares_fit(points as f64, n as f64, p, dimension);
    if n > points {
        return Ok(()); // the fit refuses it before allocating, with a message that says so
    }
    let what = format!("a degree-{p} fit of {points} points with {n} control points");
    Ok(crate::budget::current().check(field, &what, cost)?)
}

pub fn run_fit(args: &FitArgs) -> Result<()> {
    check_degree(args.degree)?;
    let text = read_text(&args.points, "POINTS")?;
    if let Ok(Value::Object(map)) = serde_json::from_str::<Value>(&text)
        && map.contains_key("type")
    {
        return run_fit_model(args, &Value::Object(map));
    }
    let pts = parse_points(&text)?;
    let dim = pts[0].len();
    check_fit_budget("POINTS", pts.len(), args, dim)?;
    let doc = with_dimension!(dim, "points", D => {
        let points = to_points::<D>(&pts);
        let mut o = FitOptions::new(args.degree, args.control_points);
        o.params = args.params.into();
        o.knots = match args.knots { KnotsArg::Uniform => KnotPlacement::Uniform, KnotsArg::Averaged => KnotPlacement::Averaged };
        o.closed = args.closed;
        o.interpolate_ends = args.interpolate_ends;
        let f = fit::fit(&points, &o).map_err(|e| anyhow!("{}", rename_fields(&e.to_string())))?;
        if args.report {
            eprintln!("fit: rms error {:.6e}, max error {:.6e}, condition estimate {:.3e}", f.rms_error, f.max_error, f.condition_estimate);
        }
        Ok(bspline_doc(&f.curve))
    })
    .map_err(|e: anyhow::Error| e)?;
    let v = doc.to_value();
    check_finite(&v, "control_points")?;
    write_json(&v, args.output.as_deref())
}

/// Fits a model curve: samples it and fits the samples at the model's own parameters.
fn run_fit_model(args: &FitArgs, doc: &Value) -> Result<()> {
    if args.samples < 2 || args.samples > 10_000_000 {
        bail!("--samples: must be between 2 and 10000000, got {}", args.samples);
    }
    let ShapeDocument::Curve(model) = ShapeDocument::parse(doc)? else {
        bail!("POINTS: fit takes points or a model curve, not a surface document");
    };
    let curve = model.build()?;
    check_fit_budget("--samples", args.samples, args, curve.dimension())?;
    let closed = args.closed;
    struct FitModel<'a>(&'a FitArgs, bool);
    impl DimensionVisitor<Curves> for FitModel<'_> {
        type Output = Result<CurveDocument>;
        fn visit<const D: usize>(self, c: &dyn splinekit::curve::Curve<D>) -> Result<CurveDocument> {
            let (args, closed) = (self.0, self.1);
            let mut o = FitOptions::new(args.degree, args.control_points);
            o.knots = match args.knots {
                KnotsArg::Uniform => KnotPlacement::Uniform,
                KnotsArg::Averaged => KnotPlacement::Averaged,
            };
            o.closed = closed;
            o.interpolate_ends = args.interpolate_ends;
            let f = fit::fit_curve(c, args.samples, &o).map_err(|e| anyhow!("{}", rename_fields(&e.to_string())))?;
            if args.report {
                eprintln!(
                    "fit: rms error {:.6e}, max error {:.6e}, condition estimate {:.3e}",
                    f.rms_error, f.max_error, f.condition_estimate
                );
            }
            Ok(bspline_doc(&f.curve))
        }
    }
    let doc = curve.visit(FitModel(args, closed))?;
    let v = doc.to_value();
    check_finite(&v, "control_points")?;
    write_json(&v, args.output.as_deref())
}

pub fn run_interpolate(args: &InterpolateArgs) -> Result<()> {
    check_degree(args.degree)?;
    let pts = read_points(&args.points)?;
    let dim = pts[0].len();
    let doc = with_dimension!(dim, "points", D => {
        let points = to_points::<D>(&pts);
        let mut o = InterpolationOptions::<D>::new(args.degree);
        o.params = args.params.into();
        o.closed = args.closed;
        if let (Some(a), Some(b)) = (&args.start_derivative, &args.end_derivative) {
            let a = parse_numbers("--start-derivative", a)?;
            let b = parse_numbers("--end-derivative", b)?;
            if a.len() != D || b.len() != D {
                bail!("--start-derivative/--end-derivative: expected {D} coordinates like the points, got {} and {}", a.len(), b.len());
            }
            o.end_derivatives = Some((Point::<D>::from_column_slice(&a), Point::<D>::from_column_slice(&b)));
        }
        let r = fit::interpolate(&points, &o).map_err(|e| anyhow!("{}", rename_fields(&e.to_string())))?;
        Ok(bspline_doc(&r.curve))
    })
    .map_err(|e: anyhow::Error| e)?;
    let v = doc.to_value();
    check_finite(&v, "control_points")?;
    write_json(&v, args.output.as_deref())
}

/// Kernel field names as the command line spells them.
fn rename_fields(msg: &str) -> String {
    if let Some(rest) = msg.strip_prefix("control_points:") {
        format!("--control-points:{rest}")
    } else if let Some(rest) = msg.strip_prefix("degree:") {
        format!("--degree:{rest}")
    } else {
        msg.to_string()
    }
}
