//! `splinekit intersect`: where two curves meet (crossings, tangential contacts and
//! overlapping stretches), where one curve crosses itself, or where a curve meets a
//! surface.

use anyhow::{Result, bail};
use clap::Args;
use splinekit_scene::answers::intersect;

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

/// Parses a positive number given to `flag`.
pub fn positive(flag: &str, text: &str) -> Result<f64> {
    match parse_numbers(flag, text)?[..] {
        [t] if t > 0.0 => Ok(t),
        _ => bail!("{flag}: expected one number > 0, got '{text}'"),
    }
}

pub fn run(args: &IntersectArgs) -> Result<()> {
    let (tolerance, chord) = args.precision.parse()?;
    let a = read_shape(&args.a)?;
    let b = args.b.as_deref().map(read_shape).transpose()?;
    let value = intersect(&a, b.as_ref(), ("A", "B"), tolerance, chord)?;
    check_finite(&value, "result")?;
    write_json(&value, args.output.as_deref())
}
