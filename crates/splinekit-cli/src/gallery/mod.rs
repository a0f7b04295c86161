//! `splinekit gallery`: renders the showcase figures into a folder with an index page.

mod figures;

use anyhow::{Context, Result};
use clap::Args;
use std::path::PathBuf;
use std::time::Instant;

#[derive(Args, Debug)]
pub struct GalleryArgs {
    /// Folder for the figures and index.html (created if missing).
    #[arg(short, long, default_value = "gallery")]
    pub output: PathBuf,
}

pub fn run(args: &GalleryArgs) -> Result<()> {
    let start = Instant::now();
    let mut figures = vec![
        figures::bspline_from_control_points()?,
        figures::least_squares_circle()?,
        figures::lane_riesenfeld_closed()?,
        figures::rose()?,
        figures::de_casteljau()?,
        figures::bernstein_basis()?,
        figures::bspline_basis()?,
        figures::nurbs_circle()?,
        figures::hermite_and_catmull_rom()?,
        figures::subdivision_schemes()?,
        figures::refinement()?,
    ];
    figures.extend(figures::model_curves()?);
    figures.extend(figures::surfaces()?);
    figures.extend(figures::blending()?);
    figures.extend(figures::heart_blending_spline()?);
    std::fs::create_dir_all(&args.output).with_context(|| format!("-o: cannot create '{}'", args.output.display()))?;
    let mut html = String::from(
        "<!doctype html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>splinekit gallery</title>\n\
         <style>body{font-family:sans-serif;max-width:1400px;margin:auto;padding:1em}\
         .grid{display:grid;grid-template-columns:repeat(auto-fill,minmax(420px,1fr));gap:1.5em}\
         figure{margin:0}img{width:100%;border:1px solid #ddd}figcaption{font-size:0.9em;color:#333}</style></head>\n\
         <body><h1>splinekit gallery</h1><p>Every figure is computed and drawn by splinekit.</p><div class=\"grid\">\n",
    );
    for f in &figures {
        let path = args.output.join(f.file);
        std::fs::write(&path, &f.svg).with_context(|| format!("-o: cannot write '{}'", path.display()))?;
        html.push_str(&format!(
            "<figure><img src=\"{}\" alt=\"{}\"><figcaption>{}</figcaption></figure>\n",
            f.file, f.file, f.caption
        ));
    }
    html.push_str("</div></body></html>\n");
    let index = args.output.join("index.html");
    std::fs::write(&index, html).with_context(|| format!("-o: cannot write '{}'", index.display()))?;
    eprintln!(
        "gallery: {} figures in {} ({:.2} s); open {}",
        figures.len(),
        args.output.display(),
        start.elapsed().as_secs_f64(),
        index.display()
    );
    Ok(())
}
