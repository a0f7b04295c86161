//! `splinekit subdivide-surface`: Catmull–Clark, Loop, bilinear or Doo–Sabin subdivision
//! of a polygon mesh read from OBJ, written as OBJ (polygons) or, triangulated, as STL,
//! PLY, glTF or glb. `--limit` moves every vertex of the result onto the limit surface
//! (limit masks) and writes the limit normals (`vn` in OBJ); vertices keep their order, so
//! `--steps 0 --limit` gives the cage's own limit points in input order.
//!
//! Creases come from OpenSubdiv's OBJ tags: `t crease 2/1 A B S` makes the edge between
//! vertices A and B (0-based, as OpenSubdiv's shapes write them) of sharpness S.

use anyhow::{Result, anyhow, bail};
use clap::{Args, ValueEnum};
use splinekit::Point;
use splinekit::subdivision::surface::bezier_patches::MAX_DEPTH;
use splinekit::subdivision::surface::{BoundaryRule, Cage, Crease, Scheme as KernelScheme, SubdivisionSurface};
use splinekit_mesh::doo_sabin_limit::doo_sabin_limit_mesh;

use splinekit_mesh::export::format::phrase;
use splinekit_mesh::export::{ExportError, Format, Subject, mesh_bytes};
use splinekit_mesh::limit_mesh::{LimitMesh, limit_mesh};
use splinekit_mesh::subdivision_surface::{PolygonMesh, SurfaceScheme, read_obj_polygons, write_obj_polygons};

use crate::input::read_text;
use std::borrow::Cow;

#[derive(Clone, Copy, Debug, ValueEnum)]
pub enum Scheme {
    CatmullClark,
    Loop,
    Bilinear,
    DooSabin,
}

#[derive(Clone, Copy, Debug, ValueEnum)]
pub enum Boundary {
    EdgeOnly,
    EdgeAndCorner,
}

#[derive(Args, Debug)]
pub struct SubdivideSurfaceArgs {
    /// Control mesh as OBJ (v and f lines; any polygons; `t crease 2/1 A B S` tags), or -
    /// for standard input.
    pub mesh: String,
    /// The scheme.
    #[arg(long, value_enum)]
    pub scheme: Scheme,
    /// Number of subdivision steps.
    #[arg(long, default_value = "3")]
    pub steps: String,
    /// Put every vertex of the result on the limit surface and write limit normals
    /// (Catmull–Clark, Loop and bilinear by their limit masks; Doo–Sabin, on a closed
    /// mesh, at the centre its vertex face converges to).
    #[arg(long)]
    pub limit: bool,
    /// Loop: split polygons into triangle fans first instead of refusing them.
    #[arg(long)]
    pub triangulate: bool,
    /// Boundary rule: edge-only (boundary vertices smoothed) or edge-and-corner (corners
    /// of a single face interpolated).
    #[arg(long, value_enum, default_value = "edge-only")]
    pub boundary: Boundary,
    /// Evaluate the limit surface exactly at FACE,U,V (a cage face and parameters in it;
    /// repeatable) and print JSON: position, normal and partials (null at an extraordinary
    /// vertex). Catmull–Clark, Loop and bilinear; the cage as read, `--steps` not applied.
    #[arg(long, value_name = "FACE,U,V")]
    pub at: Vec<String>,
    /// .step output: refine each face at an extraordinary vertex to the fewest levels whose
    /// bilinear stand-in is within this tolerance (relative to the cage's bounding-box
    /// diagonal) of the exact limit, instead of --steps levels.
    #[arg(long)]
    pub tolerance: Option<f64>,
    /// Output: .obj (polygons), .stl, .stla, .ply, .gltf or .glb (triangulated, with normals),
    /// .step (Catmull–Clark or Loop limit surface: exact bicubic, or (4, 4) with one edge
    /// collapsed, patches on regular faces, faces at extraordinary vertices (and creases,
    /// Loop boundaries) refined locally --steps times (up to 30) or to --tolerance, the
    /// rest bilinear, or flat triangles, through limit points; bilinear: its faces); with
    /// --at, the JSON file (default standard output).
    #[arg(short, long)]
    pub output: Option<String>,
}

/// Parses `FACE,U,V`.
fn parse_at(s: &str) -> Result<(usize, f64, f64)> {
    let bad = || anyhow!("--at: expected FACE,U,V (a face index and two finite numbers), got '{s}'");
    let parts: Vec<&str> = s.split(',').map(str::trim).collect();
    if parts.len() != 3 {
        return Err(bad());
    }
    let face: usize = parts[0].parse().map_err(|_| bad())?;
    let u: f64 = parts[1].parse().map_err(|_| bad())?;
    let v: f64 = parts[2].parse().map_err(|_| bad())?;
    if !u.is_finite() || !v.is_finite() {
        return Err(bad());
    }
    Ok((face, u, v))
}

fn sample_json(s: &splinekit::subdivision::surface::LimitSample) -> serde_json::Value {
    let a = |p: &Point<3>| serde_json::json!([p.x, p.y, p.z]);
    serde_json::json!({
        "position": a(&s.position),
        "normal": a(&s.normal),
        "partials": s.partials.map(|d| serde_json::json!({
            "du": a(&d.du), "dv": a(&d.dv), "duu": a(&d.duu), "duv": a(&d.duv), "dvv": a(&d.dvv)
        })),
    })
}

/// `t crease 2/1 A B S` tags of an OBJ text (0-based vertex indices; the kernel's
/// [`read_obj_cage`](splinekit::subdivision::surface::read_obj_cage)).
pub fn read_obj_creases(text: &str) -> std::result::Result<Vec<Crease>, String> {
    Ok(splinekit::subdivision::surface::read_obj_cage(text)?.creases)
}

pub fn run(args: &SubdivideSurfaceArgs) -> Result<()> {
    let at: Vec<(usize, f64, f64)> = args.at.iter().map(|s| parse_at(s)).collect::<Result<_>>()?;
    let output = match (&args.output, at.is_empty()) {
        (Some(o), _) => o.clone(),
        (None, false) => String::new(),
        (None, true) => bail!("-o: an output file is needed (or --at FACE,U,V to evaluate)"),
    };
    let format = Format::of_output(&output);
    if at.is_empty() && !format.is_some_and(|f| Subject::SubdivisionCage.formats().contains(&f)) {
        bail!("-o: writes {}, not '{output}'", phrase(Subject::SubdivisionCage.formats()));
    }
    let step = format == Some(Format::Step);
    if args.tolerance.is_some() && !step {
        bail!("--tolerance: is for .step output (the depth of the patches at extraordinary vertices), use --steps");
    }
    // STEP refines only the faces at extraordinary vertices (linear in the depth).
    let max_steps = if step { MAX_DEPTH } else { 10 };
    let steps = super::eval::parse_count("--steps", &args.steps, max_steps)?;
    let text = read_text(&args.mesh, "mesh")?;
    let mesh = read_obj_polygons(&text).map_err(|e| anyhow!("mesh: {e}"))?;
    if mesh.faces.is_empty() {
        bail!("mesh: no faces (f lines) found");
    }
    // Each step makes about four corners of every corner (an n-gon becomes n quads); a
    // corner holds its point, its place in a face and its adjacency entries.
    let corners: f64 = mesh.faces.iter().map(|f| f.len() as f64).sum();
    let out_corners = if step { corners * 4.0 * 12.0 * steps as f64 } else { corners * 4f64.powi(steps as i32) };
    crate::budget::current().check(
        "--steps",
        &format!("{steps} steps on {} faces", mesh.faces.len()),
        splinekit_scene::budget::Cost::new(out_corners * 200.0, out_corners * 300.0),
    )?;
    let name = std::path::Path::new(&output).file_stem().and_then(|s| s.to_str()).unwrap_or("mesh").to_string();
    let kernel = match args.scheme {
        Scheme::DooSabin => {
            if !at.is_empty() {
                bail!("--at: Doo–Sabin has no exact evaluation here; use catmull-clark, loop or bilinear");
            }
            if step {
                bail!("-o: STEP export is for catmull-clark, loop and bilinear, not doo-sabin");
            }
            let out = mesh.subdivide(SurfaceScheme::DooSabin, steps).map_err(|e| anyhow!("mesh: {e}"))?;
            if args.limit {
                let m = doo_sabin_limit_mesh(&out).map_err(|e| anyhow!("mesh: {e}"))?;
                return write(Written::Limit(&m), &name, format, &output);
            }
            return write(Written::Polygons(&out), &name, format, &output);
        }
        Scheme::CatmullClark => KernelScheme::CatmullClark,
        Scheme::Loop => KernelScheme::Loop,
        Scheme::Bilinear => KernelScheme::Bilinear,
    };
    let creases = read_obj_creases(&text).map_err(|e| anyhow!("mesh: {e}"))?;
    let cage = Cage::new(mesh.vertices.iter().map(|p| Point::<3>::new(p[0], p[1], p[2])).collect(), &mesh.faces)
        .with_creases(creases)
        .with_boundary(match args.boundary {
            Boundary::EdgeOnly => BoundaryRule::EdgeOnly,
            Boundary::EdgeAndCorner => BoundaryRule::EdgeAndCorner,
        });
    let surface = SubdivisionSurface::new(cage, kernel, args.triangulate).map_err(|e| anyhow!("mesh: {e}"))?;
    if !at.is_empty() {
        let mut samples = Vec::with_capacity(at.len());
        for (k, &(face, u, v)) in at.iter().enumerate() {
            let s = surface.evaluate(face, u, v).map_err(|e| anyhow!("--at[{k}]: {e}"))?;
            samples.push(sample_json(&s));
        }
        return crate::output::write_json(&serde_json::Value::Array(samples), args.output.as_deref());
    }
    if step {
        return write_step(&surface, steps, args.tolerance, &name, &output);
    }
    let result = surface.subdivide(steps).map_err(|e| anyhow!("mesh: {e}"))?;
    if args.limit {
        let m = limit_mesh(&result).map_err(|e| anyhow!("mesh: {e}"))?;
        return write(Written::Limit(&m), &name, format, &output);
    }
    let c = result.cage();
    let faces: Vec<Vec<u32>> = (0..c.face_count()).map(|f| c.face(f).to_vec()).collect();
    let out = PolygonMesh { vertices: c.vertices.iter().map(|p| [p.x, p.y, p.z]).collect(), faces };
    write(Written::Polygons(&out), &name, format, &output)
}

/// What is written: the subdivided polygons, or (`--limit`) the limit mesh, its vertices
/// on the limit surface with their normals.
enum Written<'a> {
    Polygons(&'a PolygonMesh),
    Limit(&'a LimitMesh),
}

/// Writes `mesh` to `path`: for `.obj` as it is (the polygons, or the limit mesh with its
/// normals, `vn`), the other formats triangulated.
fn write(mesh: Written<'_>, name: &str, format: Option<Format>, path: &str) -> Result<()> {
    let format = format.ok_or_else(|| anyhow!("-o: no format in '{path}'"))?;
    let bytes = if format == Format::Obj {
        let mut bytes = Vec::new();
        match mesh {
            Written::Polygons(m) => write_obj_polygons(m, name, &mut bytes),
            Written::Limit(m) => write_obj_with_normals(m, name, &mut bytes),
        }
        .map(|()| bytes)
    } else {
        let triangles = match mesh {
            Written::Polygons(m) => m.triangulate(),
            Written::Limit(m) => m.triangles(),
        };
        mesh_bytes(Cow::Owned(triangles), name, format)
    }
    .map_err(|e| anyhow!("{e}"))?;
    crate::output::write_bytes(&bytes, Some(path))
}

/// The limit surface as STEP: one Bézier surface per patch of
/// [`limit_patches`](splinekit::subdivision::surface::bezier_patches::limit_patches) at
/// `depth` levels, or of
/// [`surface_patches`](splinekit_step::documents::subdivision::surface_patches) within a
/// relative tolerance (what `convert` does for a `subdivision_surface` document); reports
/// the patches and their deviation on standard error.
fn write_step(
    surface: &SubdivisionSurface,
    depth: usize,
    tolerance: Option<f64>,
    name: &str,
    path: &str,
) -> Result<()> {
    use splinekit::subdivision::surface::bezier_patches::limit_patches;
    use splinekit_step::documents::subdivision::{patches_scene, surface_patches};
    let patches = match tolerance {
        Some(t) => {
            surface_patches(surface, t)
                .map_err(|e| match e.to_string().strip_prefix("tolerance: ") {
                    Some(m) => anyhow!("--tolerance: {m}"),
                    None => anyhow!("mesh: {e}"),
                })?
                .0
        }
        None => {
            if depth == 0 {
                bail!(
                    "--steps: STEP export refines the faces at extraordinary vertices --steps times, at least 1, got 0"
                );
            }
            limit_patches(surface, depth).map_err(|e| anyhow!("mesh: {e}"))?
        }
    };
    let doc = patches_scene(&patches).ok_or_else(|| anyhow!("mesh: the limit surface has no patches"))?;
    let header = splinekit_step::part21::writer::HeaderInfo { name: name.to_string(), ..Default::default() };
    let (text, _) =
        splinekit_step::documents::export_document(&splinekit_scene::SceneOrShape::Scene(doc), name, 1e-6, &header)
            .map_err(|e| anyhow!("{path}: {e}"))?;
    let exact = match surface.scheme() {
        KernelScheme::Loop => format!("{} exact quartic patches", patches.quartic.len()),
        KernelScheme::Bilinear => {
            eprintln!("{} exact bilinear patches (the limit is the faces)", patches.bilinear.len());
            return crate::output::write_bytes(text.as_bytes(), Some(path));
        }
        _ => format!("{} exact bicubic patches", patches.bicubic.len()),
    };
    eprintln!(
        "{exact}, {} bilinear stand-ins (down to level {}) within {:.3e} of the limit",
        patches.bilinear.len(),
        patches.depth(),
        patches.max_deviation
    );
    crate::output::write_bytes(text.as_bytes(), Some(path))
}

/// OBJ of a limit mesh: `v` per vertex, `vn` per normal, faces `f v//n …`.
fn write_obj_with_normals(mesh: &LimitMesh, name: &str, out: &mut Vec<u8>) -> std::result::Result<(), ExportError> {
    use splinekit_mesh::export::representable::{Precision, check_vectors, one_line};
    use std::io::Write;
    check_vectors(&mesh.positions, Precision::Double, "OBJ", "vertices")?;
    writeln!(out, "# splinekit subdivision surface (limit positions and normals)\no {}", one_line(name))?;
    for v in &mesh.positions {
        writeln!(out, "v {} {} {}", v[0], v[1], v[2])?;
    }
    for n in &mesh.normals {
        writeln!(out, "vn {} {} {}", n[0], n[1], n[2])?;
    }
    for f in &mesh.faces {
        out.write_all(b"f")?;
        for &(v, n) in f {
            write!(out, " {}//{}", v + 1, n + 1)?;
        }
        out.write_all(b"\n")?;
    }
    Ok(())
}
