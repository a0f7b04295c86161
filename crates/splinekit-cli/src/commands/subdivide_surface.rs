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
    // Each step makes about four corners of every corner (an n-gon becomes n quads); a
    // corner holds its point, its place in a face and its hash-map entries.
    let corners: f64 = mesh.faces.iter().map(|f| f.len() as f64).sum();
    let out_corners = corners * 4f64.powi(steps as i32);
    crate::budget::current().check(
        "--steps",
        &format!("{steps} steps on {} faces", mesh.faces.len()),
        splinekit_scene::budget::Cost::new(out_corners * 200.0, out_corners * 300.0),
    )?;
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
    crate::output::write_bytes(&bytes, Some(&args.output))
}
