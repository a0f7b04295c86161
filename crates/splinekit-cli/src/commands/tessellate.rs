//! `splinekit tessellate`: curves as polylines (.svg, .obj, .gltf, .glb) and surfaces as
//! triangle meshes (.obj, .stl, .ply, .gltf, .glb), regular (`--density`) or adaptive
//! (`--tolerance`).

use anyhow::{Result, anyhow, bail};
use clap::Args;
use splinekit::curve::Curve;
use splinekit::surface::Surface;
use splinekit_mesh::export::by_extension::{MESH_FORMATS, formats_phrase, mesh_bytes, polyline_bytes};
use splinekit_mesh::surface_mesh::{adaptive_with_limit, regular, to3};
use splinekit_mesh::{AdaptiveTolerance, MeshOptions, Polyline, Projection, SvgFigure, TriangleMesh};
use splinekit_scene::budget::ShapeCost;
use splinekit_scene::{Curves, DimensionVisitor, SceneOrShape, ShapeDocument, Surfaces};

#[derive(Args, Debug)]
pub struct TessellateArgs {
    /// Shape document, or a scene document for .gltf/.glb (JSON file, or - for standard input).
    pub shape: String,
    /// Output file; the extension picks the format. Curves: .svg (drawing), .obj (`l`
    /// polyline), .gltf/.glb (line strip). Surfaces: .obj (with normals and uv), .stl
    /// (binary; .stla for ASCII), .ply (ASCII, normals and uv), .gltf/.glb.
    #[arg(short, long)]
    pub output: String,
    /// Regular sampling: segments for curves, cells per direction for surfaces.
    #[arg(long, conflicts_with = "tolerance")]
    pub density: Option<usize>,
    /// Adaptive sampling: largest distance between shape and polyline or mesh (default:
    /// curves 1/1000 of their size; surfaces a regular 64×64 grid).
    #[arg(long, allow_hyphen_values = true)]
    pub tolerance: Option<f64>,
    /// Pose the document's animation at this time (seconds).
    #[arg(long, allow_hyphen_values = true)]
    pub time: Option<String>,
}

/// Most points one curve file may hold.
const MAX_CURVE_POINTS: usize = 1_000_000;
/// Most cells per direction of a regular surface mesh.
const MAX_DENSITY: usize = 2048;

struct CurvePoly<'a>(&'a TessellateArgs);

impl DimensionVisitor<Curves> for CurvePoly<'_> {
    type Output = Result<(Vec<[f64; 3]>, bool, usize)>;
    fn visit<const D: usize>(self, c: &dyn Curve<D>) -> Self::Output {
        let args = self.0;
        let poly = match (args.density, args.tolerance) {
            (Some(n), _) if n > MAX_CURVE_POINTS => {
                bail!("--density: at most {MAX_CURVE_POINTS} segments per file, got {n}")
            }
            (Some(n), _) => Polyline::regular(c, n),
            (None, Some(t)) => Polyline::adaptive_with_limit(c, t, MAX_CURVE_POINTS),
            (None, None) => Polyline::adaptive_by_size(c, MAX_CURVE_POINTS),
        }
        .map_err(|e| anyhow!("--{e}"))?;
        Ok((poly.points.iter().map(to3).collect(), poly.closed, D))
    }
}

struct SurfaceTriangles<'a>(&'a TessellateArgs, bool, usize);

impl DimensionVisitor<Surfaces> for SurfaceTriangles<'_> {
    type Output = Result<TriangleMesh>;
    fn visit<const D: usize>(self, s: &dyn Surface<D>) -> Self::Output {
        let (args, uv, max_cells) = (self.0, self.1, self.2);
        let options = MeshOptions { uv };
        let mesh = match (args.density, args.tolerance) {
            (Some(n), _) if n == 0 || n > MAX_DENSITY => {
                bail!("--density: between 1 and {MAX_DENSITY} cells per direction, got {n}")
            }
            (Some(n), _) => regular(s, n, n, options),
            (None, Some(t)) => {
                let tolerance = AdaptiveTolerance { chord_height: t, normal_angle: 0.2, max_depth: 10 };
                adaptive_with_limit(s, (8, 8), tolerance, options, max_cells)
            }
            (None, None) => regular(s, 64, 64, options),
        }
        .map_err(|e| anyhow!("--{e}"))?;
        Ok(mesh)
    }
}

/// A scene as glTF: one node per drawn mesh or line; an animated scene's frames (its
/// clock's duration × fps) as morph targets with a weights animation.
fn write_scene(scene: &splinekit_scene::SceneDocument, args: &TessellateArgs, ext: &str) -> Result<()> {
    if !matches!(ext, "gltf" | "glb") {
        bail!("-o: scenes are written as .gltf or .glb, not '{}'", args.output);
    }
    let (frames, fps) = if scene.is_animated() { (scene.clock().frames(), scene.clock().fps) } else { (1, 1.0) };
    let frame = crate::budget::scene_frame(scene)?;
    crate::budget::current().check(
        if frames > 1 { "animation" } else { "objects" },
        &format!("{} objects over {frames} frames", scene.objects.len()),
        frame.times(frames as f64),
    )?;
    let gltf = splinekit_render::scene_to_gltf(scene, frames, fps)?;
    let bytes = gltf.to_file_bytes(ext).map_err(|e| anyhow!("{e}"))?;
    crate::output::write_bytes(&bytes, Some(&args.output))
}

pub fn run(args: &TessellateArgs) -> Result<()> {
    let ext = args.output.rsplit('.').next().unwrap_or("").to_ascii_lowercase();
    let mut doc = match crate::input::read_document(&args.shape, "shape")? {
        SceneOrShape::Scene(scene) => return write_scene(&scene, args, &ext),
        SceneOrShape::Shape(doc) => doc,
    };
    if let Some(t) = &args.time {
        doc.set_time(super::eval::parse_time(t)?);
    }
    let cost = doc.cost();
    crate::budget::check_shape(&cost)?;
    check_request(&doc, args, &cost)?;
    let name = std::path::Path::new(&args.output).file_stem().and_then(|s| s.to_str()).unwrap_or("shape").to_string();
    let bytes: Vec<u8> = match &doc {
        ShapeDocument::Curve(c) => {
            if !matches!(ext.as_str(), "svg" | "obj" | "gltf" | "glb") {
                bail!("-o: curves are written as .svg, .obj, .gltf or .glb, not '{}'", args.output);
            }
            let curve = c.build()?;
            let (points, closed, dim) = curve.visit(CurvePoly(args))?;
            match ext.as_str() {
                "svg" => {
                    let proj = if dim >= 3 { Projection::view(0.6, 0.45) } else { Projection::TOP };
                    let mut fig = SvgFigure::new(800.0, 600.0, proj);
                    let pts: Vec<splinekit::Point<3>> =
                        points.iter().map(|p| splinekit::Point::<3>::from(*p)).collect();
                    fig.path(&pts, closed, "#1f5fbf", 2.0);
                    fig.render().map_err(|e| anyhow!("{e}"))?.into_bytes()
                }
                _ => polyline_bytes(&points, closed, &name, &ext).map_err(|e| anyhow!("{e}"))?,
            }
        }
        ShapeDocument::Surface(s) => {
            if !MESH_FORMATS.contains(&ext.as_str()) {
                bail!("-o: surfaces are written as {}, not '{}'", formats_phrase(MESH_FORMATS), args.output);
            }
            let surface = s.build()?;
            let uv = matches!(ext.as_str(), "obj" | "ply" | "gltf" | "glb");
            let mesh = surface.visit(SurfaceTriangles(args, uv, crate::budget::adaptive_cells(&cost)))?;
            mesh_bytes(std::borrow::Cow::Owned(mesh), &name, &ext).map_err(|e| anyhow!("{e}"))?
        }
    };
    crate::output::write_bytes(&bytes, Some(&args.output))
}

/// Refuses a regular polyline or mesh (or the largest adaptive polyline) that would not
/// fit the budget; adaptive meshes get their budget as a cell limit instead.
fn check_request(doc: &ShapeDocument, args: &TessellateArgs, cost: &ShapeCost) -> Result<()> {
    let flag = if args.density.is_some() { "--density" } else { "--tolerance" };
    match doc {
        ShapeDocument::Curve(_) => {
            let points = args.density.map_or(MAX_CURVE_POINTS, |n| n.min(MAX_CURVE_POINTS)) as f64 + 1.0;
            let request = splinekit_scene::budget::polyline(points, cost.eval);
            crate::budget::check_request(flag, &format!("a polyline of up to {points} points"), cost, request)
        }
        ShapeDocument::Surface(_) if args.tolerance.is_none() => {
            let n = args.density.unwrap_or(64).min(MAX_DENSITY);
            let what = format!("a mesh of {n}×{n} cells");
            crate::budget::check_request("--density", &what, cost, crate::budget::regular_mesh(n, cost.eval))
        }
        ShapeDocument::Surface(_) => Ok(()),
    }
}
