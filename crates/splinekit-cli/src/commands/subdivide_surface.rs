//! `splinekit subdivide-surface`: Catmull–Clark or Doo–Sabin subdivision of a polygon mesh
//! read from OBJ, written as OBJ (polygons) or, triangulated, as STL, PLY, glTF or glb.

use anyhow::{Result, anyhow, bail};
use clap::{Args, ValueEnum};
use splinekit_mesh::export::{GltfGeometry, GltfScene, ply, stl};
use splinekit_mesh::subdivision_surface::{SurfaceScheme, read_obj_polygons, write_obj_polygons};

use crate::input::read_text;

#[derive(Clone, Copy, Debug, ValueEnum)]
pub enum Scheme {
    CatmullClark,
    DooSabin,
}

#[derive(Args, Debug)]
pub struct SubdivideSurfaceArgs {
    /// Control mesh as OBJ (v and f lines; any polygons), or - for standard input.
    pub mesh: String,
    /// The scheme.
    #[arg(long, value_enum)]
    pub scheme: Scheme,
    /// Number of subdivision steps.
    #[arg(long, default_value = "3")]
    pub steps: String,
    /// Output: .obj (polygons), .stl, .ply, .gltf or .glb (triangulated, with normals).
    #[arg(short, long)]
    pub output: String,
}

pub fn run(args: &SubdivideSurfaceArgs) -> Result<()> {
    let ext = args.output.rsplit('.').next().unwrap_or("").to_ascii_lowercase();
    if !matches!(ext.as_str(), "obj" | "stl" | "ply" | "gltf" | "glb") {
        bail!("-o: writes .obj, .stl, .ply, .gltf or .glb, not '{}'", args.output);
    }
    let steps = super::eval::parse_count("--steps", &args.steps, 10)?;
    let mesh = read_obj_polygons(&read_text(&args.mesh, "mesh")?).map_err(|e| anyhow!("mesh: {e}"))?;
    if mesh.faces.is_empty() {
        bail!("mesh: no faces (f lines) found");
    }
    let scheme = match args.scheme {
        Scheme::CatmullClark => SurfaceScheme::CatmullClark,
        Scheme::DooSabin => SurfaceScheme::DooSabin,
    };
    let out = mesh.subdivide(scheme, steps).map_err(|e| anyhow!("mesh: {e}"))?;
    let name = std::path::Path::new(&args.output).file_stem().and_then(|s| s.to_str()).unwrap_or("mesh").to_string();
    let mut bytes = Vec::new();
    match ext.as_str() {
        "obj" => write_obj_polygons(&out, &name, &mut bytes),
        other => {
            let t = out.triangulate();
            match other {
                "stl" => stl::write_stl_binary(&t, &mut bytes),
                "ply" => ply::write_ply(&t, &mut bytes),
                _ => GltfScene::single(&name, GltfGeometry::Mesh(t), super::tessellate::EXPORT_COLOR)
                    .to_file_bytes(other)
                    .map(|b| bytes = b),
            }
        }
    }
    .map_err(|e| anyhow!("{e}"))?;
    std::fs::write(&args.output, bytes).map_err(|e| anyhow!("-o: cannot write {}: {e}", args.output))
}
