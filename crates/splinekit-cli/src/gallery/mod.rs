//! `splinekit gallery`: renders the showcase — shaded scenes (PNG), animations (GIF) with
//! glTF exports, and plots (SVG) — into a folder with an index page that shows every glTF
//! export in a 3-D viewer (three.js, `viewer.rs`) and works opened from the file system.

mod catalogue;
mod figures;
mod queries;
mod scenes;
mod subdivision;
mod viewer;

use anyhow::{Context, Result, anyhow};
use clap::Args;
use indicatif::ProgressBar;
use splinekit_render::{Renderer, scene_to_gltf, write_gif};
use splinekit_scene::scenes::SceneDocument;
use std::path::PathBuf;
use std::time::Instant;

use crate::commands::render::{animation_camera, progress, render_frame, render_frame_with_camera};
use viewer::ViewStart;

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
    /// The 3-D view of the glTF export: its model script and how it first shows.
    view: Option<(String, ViewStart)>,
}

pub fn run(args: &GalleryArgs) -> Result<()> {
    let start = Instant::now();
    std::fs::create_dir_all(&args.output).with_context(|| format!("-o: cannot create '{}'", args.output.display()))?;
    let folder = Folder(&args.output);
    let plots = plots(&folder)?;
    let renderer =
        Renderer::new().map_err(|e| anyhow!("gallery: the plots are in {}, but {e}", args.output.display()))?;
    let rendered = rendered(&folder, &renderer)?;
    let tiles = catalogue::catalogue(&folder, &renderer)?;
    viewer::write_scripts(&folder)?;
    folder.write("index.html", index_html(&rendered, &catalogue::html(&tiles), &plots).as_bytes())?;
    eprintln!(
        "gallery: {} rendered scenes, the catalogue of {} model kinds and {} plots in {} ({:.1} s, {}); open {}",
        rendered.len(),
        tiles.len(),
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

    /// Creates the folder `name` in the gallery if missing.
    fn create_dir(&self, name: &str) -> Result<()> {
        let path = self.0.join(name);
        std::fs::create_dir_all(&path).with_context(|| format!("-o: cannot create '{}'", path.display()))
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
        figures::bfunction_derivatives()?,
        figures::blending_basis()?,
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
            Ok(Entry { file: f.file.to_string(), gltf: None, step: None, caption: f.caption.to_string(), view: None })
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
    let work: u64 = docs.iter().map(|(_, d, _)| if d.is_animated() { 1 + d.clock().frames() as u64 } else { 1 }).sum();
    let bar = progress(work, "gallery");
    let mut rendered = Vec::new();
    for (name, doc, caption) in &docs {
        let (file, view) = render_scene(folder, renderer, name, doc, &bar)?;
        let step = exact_step(folder, name, doc)?;
        rendered.push(Entry {
            file,
            gltf: Some(format!("{name}.glb")),
            step,
            caption: caption.to_string(),
            view: Some(view),
        });
        bar.inc(1);
    }
    let mut figures = subdivision::figures(renderer)?;
    figures.push(queries::torus_cylinder(renderer)?);
    for (stem, caption, img, glb, camera) in figures {
        folder.write(&format!("{stem}.png"), &img.to_png())?;
        folder.write(&format!("{stem}.glb"), &glb)?;
        let start =
            ViewStart { camera: Some(camera), size: (img.width, img.height), background: [1.0; 3], period: None };
        let view = (viewer::write_model(folder, &stem, &glb)?, start);
        rendered.push(Entry {
            file: format!("{stem}.png"),
            gltf: Some(format!("{stem}.glb")),
            step: None,
            caption,
            view: Some(view),
        });
    }
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

/// Writes one scene as `name.png` (or `name.gif`, counting frames on `bar`), `name.glb` and
/// the viewer's `models/name.js`; returns the picture's file name and the 3-D view.
fn render_scene(
    folder: &Folder,
    renderer: &Renderer,
    name: &str,
    doc: &SceneDocument,
    bar: &ProgressBar,
) -> Result<(String, (String, ViewStart))> {
    let size = (doc.size[0], doc.size[1]);
    let glb = format!("{name}.glb");
    let start = |camera, period| ViewStart { camera, size, background: doc.background, period };
    if doc.is_animated() {
        let fps = doc.clock().fps;
        let frames = doc.clock().frames();
        let camera = animation_camera(doc, size)?;
        let mut images = Vec::with_capacity(frames);
        for k in 0..frames {
            images.push(render_frame(renderer, doc, Some(k as f64 / fps), size, camera)?);
            bar.inc(1);
        }
        let mut gif = Vec::new();
        write_gif(&mut gif, &images, fps as f32).map_err(|e| anyhow!("{name}.gif: {e}"))?;
        folder.write(&format!("{name}.gif"), &gif)?;
        let bytes = scene_to_gltf(doc, frames, fps).map_err(|e| anyhow!("{name}: {e}"))?.to_glb()?;
        folder.write(&glb, &bytes)?;
        let model = viewer::write_model(folder, name, &bytes)?;
        Ok((format!("{name}.gif"), (model, start(camera, Some(frames as f64 / fps)))))
    } else {
        let (img, camera) = render_frame_with_camera(renderer, doc, None, size, None)?;
        folder.write(&format!("{name}.png"), &img.to_png())?;
        let bytes = scene_to_gltf(doc, 1, 1.0).map_err(|e| anyhow!("{name}: {e}"))?.to_glb()?;
        folder.write(&glb, &bytes)?;
        let model = viewer::write_model(folder, name, &bytes)?;
        Ok((format!("{name}.png"), (model, start(camera, None))))
    }
}

/// The index page: the rendered figures, each in a 3-D viewer with its picture as the poster,
/// the catalogue's section, then the plots.
fn index_html(rendered: &[Entry], catalogue: &str, plots: &[Entry]) -> String {
    let mut html = String::from(
        "<!doctype html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>splinekit gallery</title>\n\
         <meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n\
         <style>body{font-family:sans-serif;max-width:1400px;margin:auto;padding:1em}\
         .grid{display:grid;grid-template-columns:repeat(auto-fill,minmax(420px,1fr));gap:1.5em}\
         figure{margin:0}img{width:100%;border:1px solid #ddd}figcaption{font-size:0.9em;color:#333}\
         .view{position:relative;border:1px solid #ddd;background:#fff}\
         .view img{display:block;border:0;height:100%;object-fit:contain}\
         .view canvas{display:block;width:100%;height:100%;cursor:grab;touch-action:none}\
         .view.ready img{display:none}\
         .view.loading::after,.view.failed::after{position:absolute;right:0.5em;bottom:0.4em;font-size:0.8em;\
         color:#555;background:#fffd;padding:0 0.3em}\
         .view.loading::after{content:\"loading the 3-D view\u{2026}\"}\
         .view.failed::after{content:\"picture only: the 3-D view failed\"}\
         .timebar{display:flex;gap:0.6em;align-items:center;margin:0.3em 0}\
         .timebar button{min-width:4.5em}.timebar input{flex:1}.timebar output{font-variant-numeric:tabular-nums}\
         .catalogue{display:grid;grid-template-columns:repeat(auto-fill,minmax(160px,1fr));gap:0.5em}\
         .catalogue figcaption{text-align:center}\
         </style></head>\n\
         <body><h1>splinekit gallery</h1><p>Every figure is computed and drawn by splinekit: shaded scenes \
         rendered offscreen with wgpu (the scene documents are in <code>examples/scenes/</code>), animations \
         as GIF, each with a glTF export (and a STEP file of the exact geometry where every object has an \
         exact STEP form), and plots as SVG.</p>\n\
         <p>Each scene shows its glTF export in a 3-D view (three.js) once it is loaded, starting from the \
         picture's camera: drag to turn it, wheel to zoom, right-drag or shift-drag to pan, double-click to \
         go back; animations play as morph targets, with a button to pause and a slider to scrub. The \
         picture link shows the rendering.</p>\n",
    );
    for (title, entries) in [("Scenes and animations", rendered), ("Plots", plots)] {
        if title == "Plots" {
            html.push_str(catalogue);
        }
        html.push_str(&format!("<h2>{title}</h2><div class=\"grid\">\n"));
        for e in entries {
            let mut link = String::new();
            if e.view.is_some() {
                link.push_str(&format!(" <a href=\"{}\">picture</a>", e.file));
            }
            if let Some(g) = &e.gltf {
                link.push_str(&format!(" <a href=\"{g}\">glTF</a>"));
            }
            if let Some(step) = &e.step {
                link.push_str(&format!(" <a href=\"{step}\">STEP</a>"));
            }
            match &e.view {
                Some((src, start)) => {
                    let stem = e.file.rsplit_once('.').map_or(e.file.as_str(), |(stem, _)| stem);
                    html.push_str(&format!(
                        "<figure data-view=\"{}\"><div class=\"view\" style=\"aspect-ratio:{}/{}\">\
                         <img src=\"{}\" loading=\"lazy\" alt=\"{}\"></div>",
                        viewer::data_view(stem, src, start),
                        start.size.0,
                        start.size.1,
                        e.file,
                        e.file
                    ));
                    if start.period.is_some() {
                        html.push_str(
                            "<div class=\"timebar\" hidden><button type=\"button\" aria-pressed=\"false\">play</button>\
                             <input type=\"range\" min=\"0\" max=\"1\" step=\"0.001\" value=\"0\" aria-label=\"time\">\
                             <output>0.00 s</output></div>",
                        );
                    }
                    html.push_str(&format!("<figcaption>{}{link}</figcaption></figure>\n", e.caption));
                }
                None => html.push_str(&format!(
                    "<figure><img src=\"{}\" loading=\"lazy\" alt=\"{}\"><figcaption>{}{link}</figcaption></figure>\n",
                    e.file, e.file, e.caption
                )),
            }
        }
        html.push_str("</div>\n");
    }
    for script in viewer::SCRIPTS {
        html.push_str(&format!("<script src=\"{script}\"></script>\n"));
    }
    html.push_str("</body></html>\n");
    html
}
