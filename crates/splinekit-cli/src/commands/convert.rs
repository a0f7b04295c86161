//! `splinekit convert IN -o OUT`: exact geometry between JSON documents and STEP
//! (ISO 10303-21, AP214), formats by extension: `.json` ↔ `.step`/`.stp`, and STEP →
//! STEP (normalised: re-written from the geometry read).

use anyhow::{Result, anyhow, bail};
use clap::Args;
use serde_json::json;
use splinekit_mesh::export::Format;
use splinekit_scene::{SceneOrShape, ShapeDocument, SurfaceDocument};
use splinekit_step::documents::faces::loop_samples;
use splinekit_step::documents::{Exported, Form, export_pieces, import_items, samples};
use splinekit_step::export::write_step;
use splinekit_step::part21::StepFile;
use splinekit_step::part21::writer::HeaderInfo;

#[derive(Args, Debug)]
pub struct ConvertArgs {
    /// Input: a shape or scene document (.json, or - for JSON on standard input) or a STEP
    /// file (.step, .stp).
    pub input: String,
    /// Output: .step/.stp (STEP AP214 in millimetres) or .json (a shape document, or a scene
    /// when the STEP file holds several objects); - writes JSON to standard output.
    #[arg(short, long)]
    pub output: String,
    /// Largest deviation of B-spline approximations (objects without an exact STEP form),
    /// relative to each object's size (bounding-box diagonal).
    #[arg(long, default_value_t = 1e-6)]
    pub tolerance: f64,
    /// Also write a JSON report: per object its form, measured deviation, parameter map and
    /// 128 samples (parameters and splinekit's points), and for trimmed surfaces their loops
    /// in the STEP surface's parameters, for checking the file elsewhere.
    #[arg(long)]
    pub report: Option<String>,
}

/// The format of a file named `path` (`-`: JSON on standard input or output): a document
/// or STEP, else the error of `flag`.
fn format_of(path: &str, flag: &str) -> Result<Format> {
    match Format::of_name(path) {
        _ if path == "-" => Ok(Format::Json),
        Some(f @ (Format::Json | Format::Step)) => Ok(f),
        _ => bail!("{flag}: unknown format of '{path}' (expected .json, .step or .stp)"),
    }
}

fn stem(path: &str) -> String {
    std::path::Path::new(path).file_stem().and_then(|s| s.to_str()).unwrap_or("splinekit").to_string()
}

pub fn run(args: &ConvertArgs) -> Result<()> {
    if !(args.tolerance.is_finite() && args.tolerance > 0.0) {
        bail!("--tolerance: must be a positive number, got {}", args.tolerance);
    }
    let (input, output) = (format_of(&args.input, "IN")?, format_of(&args.output, "--output")?);
    if input == Format::Json && output == Format::Json {
        bail!("--output: JSON to JSON is no conversion; give a .step or .stp output");
    }
    if input == Format::Json { json_to_step(args) } else { step_to_any(args, output) }
}

fn describe(e: &Exported) -> String {
    match e.form {
        Form::Exact => "exact".to_string(),
        Form::ExactPolynomial { degree } => format!(
            "exact B-spline: piecewise polynomial of degree {} (Bézier locals and a polynomial B-function), measured deviation {:.1e}",
            if degree.1 == 0 { degree.0.to_string() } else { format!("({}, {})", degree.0, degree.1) },
            e.max_deviation
        ),
        Form::Approximated => {
            format!("B-spline approximation, max deviation {:.2e} (tolerance {:.2e})", e.max_deviation, e.tolerance)
        }
    }
}

fn json_to_step(args: &ConvertArgs) -> Result<()> {
    let text = crate::input::read_text(&args.input, "IN")?;
    let doc =
        SceneOrShape::from_json_in(&text, &crate::input::document_folder(&args.input)).map_err(|e| anyhow!("{e}"))?;
    let name = stem(&args.input);
    let pieces = export_pieces(&doc, &name, args.tolerance).map_err(|e| anyhow!("{e}"))?;
    let items: Vec<_> = pieces.iter().flat_map(|p| p.items.iter().map(|e| e.item.clone())).collect();
    splinekit_scene::write_file(&args.output, write_step(&items, &name, &HeaderInfo::now(&name)).as_bytes())
        .map_err(|e| anyhow!("--output: cannot write '{}': {e}", args.output))?;
    for e in pieces.iter().flat_map(|p| &p.items) {
        eprintln!("{}: {}", e.item.name, describe(e));
    }
    if let Some(path) = &args.report {
        // Each STEP item beside the expanded shape it came from (a brep's faces, a
        // subdivision surface's patches, a triangle surface's triangles: several items).
        let mut items = Vec::new();
        for (piece, e) in pieces.iter().flat_map(|p| p.items.iter().map(move |e| (p, e))) {
            let shape = &piece.shape;
            let count = if matches!(shape, ShapeDocument::Curve(_)) { 128 } else { 12 };
            let mut s = samples(shape, e, count).map_err(|e| anyhow!("{e}"))?;
            if let Some(p) = &piece.placement {
                s.iter_mut().for_each(|s| s.point = p.point(s.point));
            }
            let kind = match shape {
                ShapeDocument::Curve(_) => "curve",
                ShapeDocument::Surface(SurfaceDocument::Trimmed(_)) => "face",
                ShapeDocument::Surface(_) => "surface",
            };
            let mut item = json!({
                "name": e.item.name,
                "kind": kind,
                "form": match e.form { Form::Exact => "exact", Form::ExactPolynomial { .. } => "exact_polynomial", Form::Approximated => "approximated" },
                "max_deviation": e.max_deviation,
                "tolerance": e.tolerance,
                "params": s.iter().map(|s| [s.param.0, s.param.1]).collect::<Vec<_>>(),
                "step_params": s.iter().map(|s| [s.step_param.0, s.step_param.1]).collect::<Vec<_>>(),
                "points": s.iter().map(|s| <[f64; 3]>::from(s.point)).collect::<Vec<_>>(),
                "map": { "u": [e.map.u.0, e.map.u.1], "v": [e.map.v.0, e.map.v.1] },
            });
            if let ShapeDocument::Surface(SurfaceDocument::Trimmed(t)) = shape {
                let loops = loop_samples(t, &e.map, 2048).map_err(|e| anyhow!("{e}"))?;
                item["loops"] =
                    json!(loops.iter().map(|l| l.iter().map(|p| [p.0, p.1]).collect::<Vec<_>>()).collect::<Vec<_>>());
                item["has_outer"] = json!(t.outer.is_some());
                // The periods of a closed surface in STEP parameters: loops may cross its
                // seams, and a point is inside when a copy one period away is.
                let surface = t.surface.build_in::<3>().map_err(|e| anyhow!("{e}"))?;
                let period = |closed: bool, scale: f64, length: f64| closed.then_some((scale * length).abs());
                item["periods"] = json!([
                    period(surface.is_closed_u(), e.map.u.0, surface.domain_u().length()),
                    period(surface.is_closed_v(), e.map.v.0, surface.domain_v().length()),
                ]);
            }
            items.push(item);
        }
        let report = json!({ "items": items });
        splinekit_scene::write_file(path, serde_json::to_string(&report)?.as_bytes())
            .map_err(|e| anyhow!("--report: cannot write '{path}': {e}"))?;
    }
    Ok(())
}

fn step_to_any(args: &ConvertArgs, output: Format) -> Result<()> {
    let file = if args.input == "-" {
        StepFile::from_reader(std::io::stdin().lock())
    } else {
        StepFile::open(std::path::Path::new(&args.input))
    }
    .map_err(|e| anyhow!("IN: {e}"))?;
    let imported = import_items(&file).map_err(|e| anyhow!("IN: {e}"))?;
    for (name, count) in &imported.not_understood {
        eprintln!("warning: {count} × {name} not converted (no splinekit equivalent yet)");
    }
    if imported.items.is_empty() {
        bail!("IN: the file holds no curve or surface that splinekit reads");
    }
    match output {
        Format::Step => {
            let items = imported.step_items().map_err(|e| anyhow!("IN: {e}"))?;
            let name = stem(&args.input);
            splinekit_scene::write_file(&args.output, write_step(&items, &name, &HeaderInfo::now(&name)).as_bytes())
                .map_err(|e| anyhow!("--output: cannot write '{}': {e}", args.output))?;
        }
        // JSON (`format_of` gives only JSON or STEP).
        _ => crate::output::write_json(&imported.to_value(), (args.output != "-").then_some(args.output.as_str()))?,
    }
    Ok(())
}
