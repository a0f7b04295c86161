//! `splinekit tessellate`: polylines for curves, written as SVG or OBJ.

use anyhow::{Result, anyhow, bail};
use clap::Args;
use splinekit::curve::Curve;
use splinekit_mesh::{Polyline, Projection, SvgFigure};
use splinekit_scene::{CurveVisitor, ShapeDocument};
use std::fmt::Write;

use crate::input::read_shape;
use crate::output::write_text;

#[derive(Args, Debug)]
pub struct TessellateArgs {
    /// Shape document (JSON file, or - for standard input).
    pub shape: String,
    /// Output file; the extension picks the format: .svg (drawing) or .obj (polyline as
    /// `l` elements). Mesh formats (.stl, .ply, .gltf, .glb) come with surfaces.
    #[arg(short, long)]
    pub output: String,
    /// Regular sampling with this many segments.
    #[arg(long, conflicts_with = "tolerance")]
    pub density: Option<usize>,
    /// Adaptive sampling: largest distance between curve and polyline (default: 1/1000 of
    /// the curve's size).
    #[arg(long, allow_hyphen_values = true)]
    pub tolerance: Option<f64>,
}

/// Most points one curve file may hold.
const MAX_CURVE_POINTS: usize = 1_000_000;

struct Tessellate<'a>(&'a TessellateArgs, &'a str);

impl CurveVisitor for Tessellate<'_> {
    type Output = Result<String>;
    fn visit<const D: usize>(self, c: &dyn Curve<D>) -> Result<String> {
        let (args, ext) = (self.0, self.1);
        let poly = match (args.density, args.tolerance) {
            (Some(n), _) if n > MAX_CURVE_POINTS => {
                bail!("--density: at most {MAX_CURVE_POINTS} segments per file, got {n}")
            }
            (Some(n), _) => Polyline::regular(c, n),
            (None, Some(t)) => Polyline::adaptive_with_limit(c, t, MAX_CURVE_POINTS),
            (None, None) => {
                let rough = Polyline::regular(c, 64)?;
                let size = rough.points.iter().map(|p| (p - rough.points[0]).norm()).fold(0.0, f64::max).max(1e-12);
                Polyline::adaptive_with_limit(c, size * 1e-3, MAX_CURVE_POINTS)
            }
        }
        .map_err(|e| anyhow!("--{e}"))?;
        Ok(match ext {
            "svg" => {
                let proj = if D >= 3 { Projection::view(0.6, 0.45) } else { Projection::TOP };
                let mut fig = SvgFigure::new(800.0, 600.0, proj);
                fig.path(&poly.points, poly.closed, "#1f5fbf", 2.0);
                fig.render()
            }
            _ => {
                let mut s = String::from("# splinekit polyline\n");
                for p in &poly.points {
                    let c = |i: usize| if i < D { p[i] } else { 0.0 };
                    let _ = writeln!(s, "v {} {} {}", c(0), c(1), c(2));
                }
                let mut l = String::from("l");
                for i in 1..=poly.points.len() {
                    let _ = write!(l, " {i}");
                }
                if poly.closed {
                    l.push_str(" 1");
                }
                let _ = writeln!(s, "{l}");
                s
            }
        })
    }
}

pub fn run(args: &TessellateArgs) -> Result<()> {
    let ext = args.output.rsplit('.').next().unwrap_or("").to_ascii_lowercase();
    if !matches!(ext.as_str(), "svg" | "obj") {
        bail!("-o: curves are written as .svg or .obj, not '{}'", args.output);
    }
    let ShapeDocument::Curve(doc) = read_shape(&args.shape)? else {
        bail!("type: tessellate handles curves so far; triangle meshes of surfaces come with the mesh exports");
    };
    let curve = doc.build().map_err(|e| anyhow!("{e}"))?;
    let text = curve.visit(Tessellate(args, &ext))?;
    write_text(&text, Some(&args.output))
}
