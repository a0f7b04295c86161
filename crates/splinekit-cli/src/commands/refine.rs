//! `splinekit refine`: knot insertion, degree elevation or knot removal on a document.

use anyhow::{Result, anyhow, bail};
use clap::Args;
use splinekit::surface::Direction;
use splinekit_scene::blending::{insert_knot_line, insert_local_curve, set_closed, split_knot_line, split_local_curve};
use splinekit_scene::refine::{Refinement, refine};
use splinekit_scene::{CurveDocument, ShapeDocument, SurfaceDocument};

use crate::input::{parse_numbers, read_shapes};
use crate::output::{check_finite, write_json};

#[derive(Args, Debug)]
#[command(group(clap::ArgGroup::new("operation").required(true).args([
    "insert", "elevate", "remove", "insert_local", "split_knot", "insert_knot_line", "split_knot_line", "closed"
])))]
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
    /// Blending-spline curves: insert a local curve at the new knot T (the curve's own
    /// Taylor piece there; built from a model or from Hermite data).
    #[arg(long, allow_hyphen_values = true)]
    pub insert_local: Option<f64>,
    /// Blending-spline curves: double interior knot K and copy its local (a joint that the
    /// copies' frames can turn into a corner).
    #[arg(long)]
    pub split_knot: Option<usize>,
    /// Blending-spline surfaces: insert the knot line u=T or v=T (a row or column of
    /// patches fitted to the surface there), written `u:T` or `v:T`.
    #[arg(long, allow_hyphen_values = true)]
    pub insert_knot_line: Option<String>,
    /// Blending-spline surfaces: split knot line K along the other direction (GMlib's
    /// splitKnotAlong: the row or column of patches copied), written `u:K` or `v:K`.
    #[arg(long)]
    pub split_knot_line: Option<String>,
    /// Blending-spline curves: turn open (`false`) or closed (`true`), keeping the locals
    /// it can (see docs/format.md).
    #[arg(long)]
    pub closed: Option<bool>,
    /// Largest allowed deviation for --remove.
    #[arg(long, default_value = "1e-9")]
    pub tolerance: f64,
    /// Write the JSON here instead of standard output.
    #[arg(short, long)]
    pub output: Option<String>,
}

pub fn run(args: &RefineArgs) -> Result<()> {
    if let Some(edit) = BlendingEdit::of(args)? {
        let v = read_shapes(&args.shape)?.map_each(|doc| edit.apply(doc))?;
        check_finite(&v, "control_points")?;
        return write_json(&v, args.output.as_deref());
    }
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

/// A knot edit of a blending spline (curve or surface), by its flag.
enum BlendingEdit {
    InsertLocal(f64),
    SplitKnot(usize),
    InsertKnotLine(Direction, f64),
    SplitKnotLine(Direction, usize),
    Closed(bool),
}

impl BlendingEdit {
    /// The edit the flags ask for, if any; `--insert-knot-line`/`--split-knot-line` parsed
    /// as `u:X` or `v:X`.
    fn of(args: &RefineArgs) -> Result<Option<Self>> {
        let line = |flag: &str, text: &str| -> Result<(Direction, String)> {
            let (d, x) = text.split_once(':').ok_or_else(|| anyhow!("{flag}: expected u:X or v:X, got \"{text}\""))?;
            let direction = match d.trim() {
                "u" => Direction::U,
                "v" => Direction::V,
                other => bail!("{flag}: the direction must be u or v, got \"{other}\""),
            };
            Ok((direction, x.trim().to_string()))
        };
        Ok(Some(if let Some(t) = args.insert_local {
            BlendingEdit::InsertLocal(t)
        } else if let Some(k) = args.split_knot {
            BlendingEdit::SplitKnot(k)
        } else if let Some(text) = &args.insert_knot_line {
            let (d, x) = line("--insert-knot-line", text)?;
            let t: f64 = x
                .parse()
                .map_err(|_| anyhow!("--insert-knot-line: expected a number after {text:.1}:, got \"{x}\""))?;
            BlendingEdit::InsertKnotLine(d, t)
        } else if let Some(text) = &args.split_knot_line {
            let (d, x) = line("--split-knot-line", text)?;
            let k: usize = x
                .parse()
                .map_err(|_| anyhow!("--split-knot-line: expected a knot index after {text:.1}:, got \"{x}\""))?;
            BlendingEdit::SplitKnotLine(d, k)
        } else if let Some(c) = args.closed {
            BlendingEdit::Closed(c)
        } else {
            return Ok(None);
        }))
    }

    /// The flag, for messages.
    fn flag(&self) -> &'static str {
        match self {
            BlendingEdit::InsertLocal(_) => "--insert-local",
            BlendingEdit::SplitKnot(_) => "--split-knot",
            BlendingEdit::InsertKnotLine(..) => "--insert-knot-line",
            BlendingEdit::SplitKnotLine(..) => "--split-knot-line",
            BlendingEdit::Closed(_) => "--closed",
        }
    }

    /// The edited document (errors about the edit's argument name the flag).
    fn apply(&self, doc: ShapeDocument) -> Result<serde_json::Value> {
        let flagged = |e: splinekit_scene::DocumentError| {
            let m = e.to_string();
            for argument in ["t", "k", "u", "v", "closed"] {
                if let Some(rest) = m.strip_prefix(argument).and_then(|r| r.strip_prefix(':')) {
                    return anyhow!("{}:{rest}", self.flag());
                }
            }
            anyhow!("{m}")
        };
        match (self, doc) {
            (BlendingEdit::InsertLocal(t), ShapeDocument::Curve(CurveDocument::BlendingSpline(d))) => {
                Ok(CurveDocument::BlendingSpline(insert_local_curve(&d, *t).map_err(flagged)?.0).to_value())
            }
            (BlendingEdit::SplitKnot(k), ShapeDocument::Curve(CurveDocument::BlendingSpline(d))) => {
                Ok(CurveDocument::BlendingSpline(split_local_curve(&d, *k).map_err(flagged)?).to_value())
            }
            (BlendingEdit::Closed(c), ShapeDocument::Curve(CurveDocument::BlendingSpline(d))) => {
                Ok(CurveDocument::BlendingSpline(set_closed(&d, *c).map_err(flagged)?).to_value())
            }
            (
                BlendingEdit::InsertKnotLine(dir, t),
                ShapeDocument::Surface(SurfaceDocument::BlendingSplineSurface(d)),
            ) => {
                let out = insert_knot_line(&d, *dir, *t).map_err(flagged)?.0;
                Ok(SurfaceDocument::BlendingSplineSurface(out).to_value())
            }
            (
                BlendingEdit::SplitKnotLine(dir, k),
                ShapeDocument::Surface(SurfaceDocument::BlendingSplineSurface(d)),
            ) => {
                let out = split_knot_line(&d, *dir, *k).map_err(flagged)?;
                Ok(SurfaceDocument::BlendingSplineSurface(out).to_value())
            }
            (edit, doc) => {
                let wants = match edit {
                    BlendingEdit::InsertKnotLine(..) | BlendingEdit::SplitKnotLine(..) => "blending_spline_surface",
                    _ => "blending_spline",
                };
                let got = match &doc {
                    ShapeDocument::Curve(c) => c.type_name(),
                    ShapeDocument::Surface(s) => s.type_name(),
                };
                bail!("type: {} works on {wants} documents, got {got}", edit.flag())
            }
        }
    }
}
