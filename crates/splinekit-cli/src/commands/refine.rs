//! `splinekit refine`: knot insertion, degree elevation or knot removal on a document.

use anyhow::{Result, bail};
use clap::Args;
use splinekit_scene::ShapeDocument;
use splinekit_scene::refine::{Refinement, refine};

use crate::input::{parse_numbers, read_shapes};
use crate::output::{check_finite, write_json};

#[derive(Args, Debug)]
#[command(group(clap::ArgGroup::new("operation").required(true).args(["insert", "elevate", "remove"])))]
pub struct RefineArgs {
    /// Shape document (bezier, rational_bezier, bspline or nurbs; - for standard input), or
    /// a scene of them, written back with each object refined.
    pub shape: String,
    /// Knots to insert, comma-separated; repeat a value to insert it several times.
    #[arg(long, allow_hyphen_values = true)]
    pub insert: Option<String>,
    /// Raise the degree by K.
    #[arg(long)]
    pub elevate: Option<usize>,
    /// Knots to remove (once per listed value) where the curve moves by at most --tolerance.
    #[arg(long, allow_hyphen_values = true)]
    pub remove: Option<String>,
    /// Largest allowed deviation for --remove.
    #[arg(long, default_value = "1e-9")]
    pub tolerance: f64,
    /// Write the JSON here instead of standard output.
    #[arg(short, long)]
    pub output: Option<String>,
}

pub fn run(args: &RefineArgs) -> Result<()> {
    let r = if let Some(k) = &args.insert {
        Refinement::Insert(parse_numbers("--insert", k)?)
    } else if let Some(t) = args.elevate {
        Refinement::Elevate(t)
    } else if let Some(k) = &args.remove {
        if !(args.tolerance >= 0.0 && args.tolerance.is_finite()) {
            bail!("--tolerance: must be finite and ≥ 0, got {}", args.tolerance);
        }
        Refinement::Remove { knots: parse_numbers("--remove", k)?, tolerance: args.tolerance }
    } else {
        bail!("refine: give one of --insert, --elevate, --remove");
    };
    // A scene becomes the scene of its objects refined, each with its style.
    let v = read_shapes(&args.shape)?.map_each(|doc| {
        let ShapeDocument::Curve(doc) = doc else {
            bail!(
                "type: refine works on bezier, rational_bezier, bspline and nurbs curve documents; surface refinement is not on the command line yet"
            );
        };
        let out = refine(&doc, &r).map_err(|e| named_by_flag(&e.to_string(), &r))?;
        if let Refinement::Remove { knots, .. } = &r {
            if out.removed < knots.len() {
                eprintln!("refine: removed {} of {} knots within the tolerance", out.removed, knots.len());
            }
        }
        Ok(out.document.to_value())
    })?;
    check_finite(&v, "control_points")?;
    write_json(&v, args.output.as_deref())
}

/// The kernel and the document layer name the arguments of knot operations `insert`,
/// `elevate`, `remove` and `knots`; on the command line the user wrote them as flags, so an
/// error about one of them names the flag.
fn named_by_flag(message: &str, r: &Refinement) -> anyhow::Error {
    let flag = match r {
        Refinement::Insert(_) => "--insert",
        Refinement::Elevate(_) => "--elevate",
        Refinement::Remove { .. } => "--remove",
    };
    for argument in ["insert", "elevate", "remove", "knots"] {
        if let Some(rest) = message.strip_prefix(argument).and_then(|r| r.strip_prefix(':')) {
            return anyhow::anyhow!("{flag}:{rest}");
        }
    }
    anyhow::anyhow!("{message}")
}
