//! The `splinekit` command line: evaluate, fit, interpolate, refine, subdivide, tessellate,
//! render and animate shapes and scenes given as JSON documents (see docs/format.md).
//!
//! Exit status: 0 on success, 2 on bad input (with one line `error: …` on standard error
//! naming the offending field), never a panic trace.

mod budget;
mod commands;
mod gallery;
mod input;
mod output;

use clap::{Parser, Subcommand};

#[derive(Parser, Debug)]
#[command(
    name = "splinekit",
    version,
    about = "Curves and surfaces: Bézier, B-spline, NURBS, blending splines",
    long_about = "splinekit evaluates, fits, refines and subdivides parametric curves described by JSON \
                  shape documents (see docs/format.md). Input is a file path or - for standard input; \
                  JSON goes to standard output unless -o is given. Bad input ends with exit status 2 \
                  and one line on standard error naming the offending field."
)]
struct Cli {
    #[command(subcommand)]
    command: Command,
    /// Most memory one request may use: bytes, or with a suffix K, M, G (powers of 1024)
    /// or KB, MB, GB (default: the environment variable SPLINEKIT_MAX_MEMORY, else half the
    /// physical memory). Requests estimated to need more are refused before they start.
    #[arg(long, global = true, value_name = "BYTES")]
    max_memory: Option<String>,
    /// Most work one request may do, in operations (≈ floating-point operations; 10⁹ take
    /// about a second; default: SPLINEKIT_MAX_WORK, else 1e10).
    #[arg(long, global = true, value_name = "OPERATIONS")]
    max_work: Option<String>,
}

#[derive(Subcommand, Debug)]
enum Command {
    /// Evaluate a shape: points and derivatives at parameters.
    Eval(commands::eval::EvalArgs),
    /// Least-squares B-spline approximation of points.
    Fit(commands::fit::FitArgs),
    /// B-spline through every point (global interpolation).
    Interpolate(commands::fit::InterpolateArgs),
    /// Where two curves cross, touch or overlap, where one crosses itself, where a curve
    /// meets a surface, or the intersection curves of two surfaces.
    Intersect(commands::intersect::IntersectArgs),
    /// Offset of a plane curve or a surface at a signed distance, as B-splines within a
    /// tolerance (cusps and self-intersections of a curve's offset trimmed).
    Offset(commands::offset::OffsetArgs),
    /// Nearest point of a curve or surface to given points, or every local minimum.
    Project(commands::project::ProjectArgs),
    /// Topology, area and volume of a solid or surface (exact over its trimmed faces, and
    /// from its watertight mesh, with the mesh's open edges).
    Measure(commands::measure::MeasureArgs),
    /// Plane sections (contours) of a surface.
    Section(commands::section::SectionArgs),
    /// Knot insertion, degree elevation or knot removal; the curve stays the same.
    Refine(commands::refine::RefineArgs),
    /// Subdivision curves: Chaikin, Lane–Riesenfeld, 4-point.
    Subdivide(commands::subdivide::SubdivideArgs),
    /// Subdivision surfaces: Catmull–Clark, Loop, bilinear or Doo–Sabin on a polygon mesh (OBJ),
    /// the exact limit (points, normals, evaluation at a face and (u, v), STEP patches).
    SubdivideSurface(commands::subdivide_surface::SubdivideSurfaceArgs),
    /// Polylines of curves and triangle meshes of surfaces: SVG, OBJ, STL, PLY, glTF.
    Tessellate(commands::tessellate::TessellateArgs),
    /// Render a scene or shape to PNG (offscreen, wgpu).
    Render(commands::render::RenderArgs),
    /// Render a scene's animation to an animated GIF.
    Animate(commands::render::AnimateArgs),
    /// Show a scene in an interactive window (drag to orbit, scroll to zoom, space to pause).
    View(commands::view::ViewArgs),
    /// Exact geometry between JSON documents and STEP (ISO 10303-21) files.
    Convert(commands::convert::ConvertArgs),
    /// Render the showcase figures into a folder with index.html.
    Gallery(gallery::GalleryArgs),
}

fn one_line(s: &str) -> String {
    s.split_whitespace().collect::<Vec<_>>().join(" ")
}

fn main() {
    // SAFETY: the first statement of `main`, before any thread is spawned; the Vulkan
    // loader reads the variable later (see splinekit_render::backends).
    unsafe { splinekit_render::prepare_headless_environment() };
    std::panic::set_hook(Box::new(|info| {
        let msg = info
            .payload()
            .downcast_ref::<&str>()
            .map(|s| s.to_string())
            .or_else(|| info.payload().downcast_ref::<String>().cloned())
            .unwrap_or_default();
        eprintln!("error: internal error, please report it: {}", one_line(&msg));
    }));
    let cli = match Cli::try_parse() {
        Ok(cli) => cli,
        Err(e) => {
            use clap::error::ErrorKind;
            if matches!(
                e.kind(),
                ErrorKind::DisplayHelp
                    | ErrorKind::DisplayVersion
                    | ErrorKind::DisplayHelpOnMissingArgumentOrSubcommand
            ) {
                let _ = e.print();
                std::process::exit(if e.kind() == ErrorKind::DisplayHelpOnMissingArgumentOrSubcommand { 2 } else { 0 });
            }
            let text = e.render().to_string();
            // clap's message runs until its blank line before "Usage:"; keep that part.
            let message = text.split("\n\n").next().unwrap_or("invalid arguments");
            let message = message.trim_start_matches("error: ");
            eprintln!("error: {} (see --help)", one_line(message));
            std::process::exit(2);
        }
    };
    match splinekit_scene::budget::Budget::from_options(cli.max_memory.as_deref(), cli.max_work.as_deref()) {
        Ok(b) => budget::set(b),
        Err(e) => {
            eprintln!("error: {}", one_line(&e.to_string()));
            std::process::exit(2);
        }
    }
    let result = std::panic::catch_unwind(|| match &cli.command {
        Command::Eval(a) => commands::eval::run(a),
        Command::Fit(a) => commands::fit::run_fit(a),
        Command::Interpolate(a) => commands::fit::run_interpolate(a),
        Command::Intersect(a) => commands::intersect::run(a),
        Command::Offset(a) => commands::offset::run(a),
        Command::Project(a) => commands::project::run(a),
        Command::Measure(a) => commands::measure::run(a),
        Command::Refine(a) => commands::refine::run(a),
        Command::Section(a) => commands::section::run(a),
        Command::Subdivide(a) => commands::subdivide::run(a),
        Command::SubdivideSurface(a) => commands::subdivide_surface::run(a),
        Command::Tessellate(a) => commands::tessellate::run(a),
        Command::Render(a) => commands::render::run_render(a),
        Command::Animate(a) => commands::render::run_animate(a),
        Command::View(a) => commands::view::run(a),
        Command::Gallery(a) => gallery::run(a),
        Command::Convert(a) => commands::convert::run(a),
    });
    match result {
        Ok(Ok(())) => {}
        Ok(Err(e)) => {
            eprintln!("error: {}", one_line(&format!("{e:#}")));
            std::process::exit(2);
        }
        Err(_) => std::process::exit(70),
    }
}
