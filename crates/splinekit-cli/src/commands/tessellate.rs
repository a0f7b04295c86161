//! `splinekit tessellate`: curves as polylines (.svg, .obj, .gltf, .glb), surfaces as
//! triangle meshes (.obj, .stl, .stla, .ply, .gltf, .glb), regular (`--density`) or
//! adaptive (`--tolerance`), and scenes in every mesh format (each object at its own
//! `density`, as the renderer draws it).

use anyhow::{Result, anyhow, bail};
use clap::Args;
use splinekit::curve::Curve;
use splinekit::surface::Surface;
use std::path::Path;

use splinekit_mesh::export::by_extension::{mesh_bytes, object_name, polyline_bytes, polyline_svg};
use splinekit_mesh::export::{Format, Subject};
use splinekit_mesh::surface_mesh::{adaptive_with_limit, regular, to3};
use splinekit_mesh::{AdaptiveTolerance, MeshOptions, Polyline, TriangleMesh};
use splinekit_scene::budget::ShapeCost;
use splinekit_scene::{Curves, DimensionVisitor, SceneOrShape, ShapeDocument, Surfaces};

#[derive(Args, Debug)]
pub struct TessellateArgs {
    /// Shape or scene document (JSON file, or - for standard input).
    pub shape: String,
    /// Output file; the extension picks the format. Curves: .svg (drawing), .obj (`l`
    /// polyline), .gltf/.glb (line strip). Surfaces: .obj (with normals and uv), .stl
    /// (binary; .stla for ASCII), .ply (ASCII, normals and uv), .gltf/.glb. Scenes: .obj (a
    /// group per object, curves as `l` lines), .stl/.stla (every surface in one mesh; a
    /// curve is refused), .ply (one mesh, curves as edges), .gltf/.glb (animated as morph
    /// targets).
    #[arg(short, long)]
    pub output: String,
    /// Regular sampling: segments for curves, cells per direction for surfaces.
    #[arg(long, conflicts_with = "tolerance")]
    pub density: Option<usize>,
    /// Adaptive sampling: largest distance between shape and polyline or mesh (default:
    /// curves 1/1000 of their size; surfaces a regular 64×64 grid).
    #[arg(long, allow_hyphen_values = true)]
    pub tolerance: Option<f64>,
    /// Pose the document's animation at this time (seconds); a scene written as .gltf/.glb
    /// carries its whole animation instead.
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

/// A scene in any mesh format ([`splinekit_render::scene_file`]): glTF with one node per
/// drawn mesh or line and an animated scene's frames (its clock's duration × fps) as morph
/// targets; OBJ a group per object; STL and PLY one mesh (PLY with the lines as edges).
fn write_scene(scene: &splinekit_scene::SceneDocument, args: &TessellateArgs, format: Option<Format>) -> Result<()> {
    let format = Subject::Scene.check(format, &args.output).map_err(|e| anyhow!("-o: {e}"))?;
    let time = args.time.as_deref().map(super::eval::parse_time).transpose()?;
    let frames = if format.is_gltf() && scene.is_animated() { scene.clock().frames() } else { 1 };
    let frame = crate::budget::scene_frame(scene)?;
    crate::budget::current().check(
        if frames > 1 { "animation" } else { "objects" },
        &format!("{} objects over {frames} frames", scene.objects.len()),
        frame.times(frames as f64),
    )?;
    let bytes = splinekit_render::scene_file(scene, format, &object_name(Path::new(&args.output)), time)?;
    crate::output::write_bytes(&bytes, Some(&args.output))
}

pub fn run(args: &TessellateArgs) -> Result<()> {
    let format = Format::of_output(&args.output);
    let mut doc = match crate::input::read_document(&args.shape, "shape")? {
        SceneOrShape::Scene(scene) => return write_scene(&scene, args, format),
        SceneOrShape::Shape(doc) => doc,
    };
    if let Some(t) = &args.time {
        doc.set_time(super::eval::parse_time(t)?);
    }
    let cost = doc.cost();
    crate::budget::check_shape(&cost)?;
    check_request(&doc, args, &cost)?;
    let name = object_name(Path::new(&args.output));
    let bytes: Vec<u8> = match &doc {
        ShapeDocument::Curve(c) => {
            let format = Subject::Curve.check(format, &args.output).map_err(|e| anyhow!("-o: {e}"))?;
            let curve = c.build()?;
            let (points, closed, dim) = curve.visit(CurvePoly(args))?;
            match format {
                Format::Svg => polyline_svg(&points, closed, dim).map_err(|e| anyhow!("{e}"))?.into_bytes(),
                _ => polyline_bytes(&points, closed, &name, format).map_err(|e| anyhow!("{e}"))?,
            }
        }
        ShapeDocument::Surface(s) => {
            let format = Subject::Surface.check(format, &args.output).map_err(|e| anyhow!("-o: {e}"))?;
            let surface = s.build()?;
            let uv = matches!(format, Format::Obj | Format::Ply | Format::Gltf | Format::Glb);
            let mesh = surface.visit(SurfaceTriangles(args, uv, crate::budget::adaptive_cells(&cost)))?;
            mesh_bytes(std::borrow::Cow::Owned(mesh), &name, format).map_err(|e| anyhow!("{e}"))?
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
