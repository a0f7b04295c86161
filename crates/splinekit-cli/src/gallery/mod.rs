//! `splinekit gallery`: renders the showcase — shaded scenes (PNG), animations (GIF) with
//! glTF exports, and plots (SVG) — into a folder with an index page.

mod figures;
mod queries;
mod scenes;
mod subdivision;

use anyhow::{Context, Result, anyhow};
use clap::Args;
use indicatif::ProgressBar;
use splinekit_render::{Renderer, scene_to_gltf, write_gif};
use splinekit_scene::scenes::SceneDocument;
use std::path::PathBuf;
use std::time::Instant;

use crate::commands::render::{animation_camera, progress, render_frame};

#[derive(Args, Debug)]
pub struct GalleryArgs {
    /// Folder for the figures and index.html (created if missing).
    #[arg(short, long, default_value = "gallery")]
    pub output: PathBuf,
}

struct Entry {
    /// The picture shown (PNG, GIF or SVG).
    file: String,
    /// A glTF export, if any.
    gltf: Option<String>,
    /// A STEP file of the exact geometry, for the figures whose every object has an exact
    /// STEP form.
    step: Option<String>,
    caption: String,
}

pub fn run(args: &GalleryArgs) -> Result<()> {
    let start = Instant::now();
    std::fs::create_dir_all(&args.output).with_context(|| format!("-o: cannot create '{}'", args.output.display()))?;
    let folder = Folder(&args.output);
    let plots = plots(&folder)?;
    let renderer =
        Renderer::new().map_err(|e| anyhow!("gallery: the plots are in {}, but {e}", args.output.display()))?;
    let rendered = rendered(&folder, &renderer)?;
    folder.write("index.html", index_html(&rendered, &plots).as_bytes())?;
    eprintln!(
        "gallery: {} rendered scenes and {} plots in {} ({:.1} s, {}); open {}",
        rendered.len(),
        plots.len(),
        args.output.display(),
        start.elapsed().as_secs_f64(),
        renderer.adapter_name(),
        args.output.join("index.html").display()
    );
    Ok(())
}

/// The gallery's folder.
struct Folder<'a>(&'a std::path::Path);

impl Folder<'_> {
    /// Writes the file `name` in the folder.
    fn write(&self, name: &str, bytes: &[u8]) -> Result<()> {
        let path = self.0.join(name);
        splinekit_scene::write_file(&path, bytes).with_context(|| format!("-o: cannot write '{}'", path.display()))
    }
}

/// Writes the plots (SVG).
fn plots(folder: &Folder) -> Result<Vec<Entry>> {
    let mut plots = vec![
        figures::bspline_from_control_points()?,
        figures::least_squares_circle()?,
        figures::lane_riesenfeld_closed()?,
        figures::de_casteljau()?,
        figures::bernstein_basis()?,
        figures::bspline_basis()?,
        figures::nurbs_circle()?,
        figures::hermite_and_catmull_rom()?,
        figures::subdivision_schemes()?,
        figures::refinement()?,
    ];
    plots.extend(figures::model_curves()?);
    plots.extend(figures::blending()?);
    plots.extend([queries::crossings()?, queries::heart_offsets()?, queries::contours()?]);
    plots
        .iter()
        .map(|f| {
            folder.write(f.file, f.svg.as_bytes())?;
            Ok(Entry { file: f.file.to_string(), gltf: None, step: None, caption: f.caption.to_string() })
        })
        .collect()
}

/// Renders the gallery's scenes (PNG, or GIF when animated, each with a glb export) and
/// the subdivision figures.
fn rendered(folder: &Folder, renderer: &Renderer) -> Result<Vec<Entry>> {
    let docs: Vec<(&str, SceneDocument, &str)> = scenes::SCENES
        .iter()
        .map(|(name, json, caption)| {
            let v: serde_json::Value = serde_json::from_str(json).map_err(|e| anyhow!("scene {name}: {e}"))?;
            Ok((*name, SceneDocument::parse(&v).map_err(|e| anyhow!("scene {name}: {e}"))?, *caption))
        })
        .collect::<Result<_>>()?;
    let work: u64 =
        docs.iter().map(|(_, d, _)| if d.is_animated() { 1 + d.animation.frames() as u64 } else { 1 }).sum();
    let bar = progress(work, "gallery");
    let mut rendered = Vec::new();
    for (name, doc, caption) in &docs {
        let file = render_scene(folder, renderer, name, doc, &bar)?;
        let step = exact_step(folder, name, doc)?;
        rendered.push(Entry { file, gltf: Some(format!("{name}.glb")), step, caption: caption.to_string() });
        bar.inc(1);
    }
    for (stem, caption, img, glb) in subdivision::figures(renderer)? {
        folder.write(&format!("{stem}.png"), &img.to_png())?;
        folder.write(&format!("{stem}.glb"), &glb)?;
        rendered.push(Entry { file: format!("{stem}.png"), gltf: Some(format!("{stem}.glb")), step: None, caption });
    }
    let (stem, caption, img, glb) = queries::torus_cylinder(renderer)?;
    folder.write(&format!("{stem}.png"), &img.to_png())?;
    folder.write(&format!("{stem}.glb"), &glb)?;
    rendered.push(Entry { file: format!("{stem}.png"), gltf: Some(format!("{stem}.glb")), step: None, caption });
    bar.finish_and_clear();
    Ok(rendered)
}

/// Writes `name.step` when every object of the scene has an exact STEP form (splines,
/// conics, quadrics, exact sweeps, polynomial blending splines); returns its file name.
fn exact_step(folder: &Folder, name: &str, doc: &SceneDocument) -> Result<Option<String>> {
    if !doc.objects.iter().all(|o| splinekit_step::documents::exports_exactly(&o.shape)) {
        return Ok(None);
    }
    let header = splinekit_step::part21::writer::HeaderInfo { name: name.to_string(), ..Default::default() };
    let scene = splinekit_scene::SceneOrShape::Scene(doc.clone());
    let (text, _) = splinekit_step::documents::export_document(&scene, name, 1e-6, &header)
        .map_err(|e| anyhow!("{name}.step: {e}"))?;
    let file = format!("{name}.step");
    folder.write(&file, text.as_bytes())?;
    Ok(Some(file))
}

/// Writes one scene as `name.png` (or `name.gif`, counting frames on `bar`) and
/// `name.glb`; returns the picture's file name.
fn render_scene(
    folder: &Folder,
    renderer: &Renderer,
    name: &str,
    doc: &SceneDocument,
    bar: &ProgressBar,
) -> Result<String> {
    let size = (doc.size[0], doc.size[1]);
    let glb = format!("{name}.glb");
    if doc.is_animated() {
        let fps = doc.animation.fps;
        let frames = doc.animation.frames();
        let camera = animation_camera(doc, size)?;
        let mut images = Vec::with_capacity(frames);
        for k in 0..frames {
            images.push(render_frame(renderer, doc, Some(k as f64 / fps), size, camera)?);
            bar.inc(1);
        }
        let mut gif = Vec::new();
        write_gif(&mut gif, &images, fps as f32).map_err(|e| anyhow!("{name}.gif: {e}"))?;
        folder.write(&format!("{name}.gif"), &gif)?;
        folder.write(&glb, &scene_to_gltf(doc, frames, fps).map_err(|e| anyhow!("{name}: {e}"))?.to_glb()?)?;
        Ok(format!("{name}.gif"))
    } else {
        let img = render_frame(renderer, doc, None, size, None)?;
        folder.write(&format!("{name}.png"), &img.to_png())?;
        folder.write(&glb, &scene_to_gltf(doc, 1, 1.0).map_err(|e| anyhow!("{name}: {e}"))?.to_glb()?)?;
        Ok(format!("{name}.png"))
    }
}

/// The index page: the rendered figures, then the plots.
fn index_html(rendered: &[Entry], plots: &[Entry]) -> String {
    let mut html = String::from(
        "<!doctype html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>splinekit gallery</title>\n\
         <style>body{font-family:sans-serif;max-width:1400px;margin:auto;padding:1em}\
         .grid{display:grid;grid-template-columns:repeat(auto-fill,minmax(420px,1fr));gap:1.5em}\
         figure{margin:0}img{width:100%;border:1px solid #ddd}figcaption{font-size:0.9em;color:#333}</style></head>\n\
         <body><h1>splinekit gallery</h1><p>Every figure is computed and drawn by splinekit: shaded scenes \
         rendered offscreen with wgpu (the scene documents are in <code>examples/scenes/</code>), animations \
         as GIF, each with a glTF export (and a STEP file of the exact geometry where every object has an \
         exact STEP form), and plots as SVG.</p>\n",
    );
    for (title, entries) in [("Scenes and animations", rendered), ("Plots", plots)] {
        html.push_str(&format!("<h2>{title}</h2><div class=\"grid\">\n"));
        for e in entries {
            let mut link = e.gltf.as_ref().map(|g| format!(" <a href=\"{g}\">glTF</a>")).unwrap_or_default();
            if let Some(step) = &e.step {
                link.push_str(&format!(" <a href=\"{step}\">STEP</a>"));
            }
            html.push_str(&format!(
                "<figure><img src=\"{}\" alt=\"{}\"><figcaption>{}{link}</figcaption></figure>\n",
                e.file, e.file, e.caption
            ));
        }
        html.push_str("</div>\n");
    }
    html.push_str("</body></html>\n");
    html
}
