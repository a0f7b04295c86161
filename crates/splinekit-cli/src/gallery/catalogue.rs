//! The catalogue: every model surface and curve of the registry — the kinds declared by
//! `model_document!`, which are the ones offered as blending-spline models — drawn from its
//! example document (the studio's Add menu) as a small picture: each on its own
//! (`catalogue/TYPE.png`, the index page's grid) and all on one sheet
//! (`catalogue/all.png`), in the registry's order, surfaces first. A kind added to the
//! registry shows here without an edit.

use anyhow::{Result, anyhow};
use splinekit_render::{Image, Renderer};
use splinekit_scene::scenes::SceneDocument;
use splinekit_scene::{CurveDocument, SurfaceDocument};

use super::Folder;
use crate::commands::render::render_frame_with_camera;

/// The size of one picture.
pub const TILE: (u32, u32) = (240, 180);
/// Pictures per row of the sheet.
const COLUMNS: usize = 6;

/// Views other than the scene's default camera (azimuth 50°, elevation 28°), in degrees,
/// where a shape is known by another side: Boy's surface by its three-fold symmetry about z.
const VIEWS: &[(&str, f64, f64)] = &[("boy_surface", 50.0, 89.0)];

/// One kind's picture: its `type` and the file written.
pub struct Tile {
    pub name: &'static str,
    pub file: String,
}

/// The model kinds' example documents, as JSON, with the colour each is drawn in.
fn models() -> Vec<(&'static str, serde_json::Value, [f64; 3])> {
    let surfaces = SurfaceDocument::examples()
        .into_iter()
        .filter(|d| d.blending_model())
        .map(|d| (d.type_name(), d.to_value(), [0.2, 0.6, 0.65]));
    let curves = CurveDocument::examples()
        .into_iter()
        .filter(|d| d.blending_model())
        .map(|d| (d.type_name(), d.to_value(), [0.15, 0.3, 0.75]));
    surfaces.chain(curves).collect()
}

/// Renders every model kind's picture and the sheet of all of them into `catalogue/`.
pub fn catalogue(folder: &Folder, renderer: &Renderer) -> Result<Vec<Tile>> {
    folder.create_dir("catalogue")?;
    let mut tiles = Vec::new();
    let mut images = Vec::new();
    for (name, shape, color) in models() {
        let mut scene = serde_json::json!({
            "type": "scene",
            "objects": [{"shape": shape, "color": color}],
            "size": [TILE.0, TILE.1],
        });
        if let Some((_, azimuth, elevation)) = VIEWS.iter().find(|v| v.0 == name) {
            scene["camera"] = serde_json::json!({"azimuth": azimuth, "elevation": elevation});
        }
        let scene = SceneDocument::parse(&scene).map_err(|e| anyhow!("catalogue: {name}: {e}"))?;
        let (img, _) = render_frame_with_camera(renderer, &scene, None, TILE, None)?;
        let file = format!("catalogue/{name}.png");
        folder.write(&file, &img.to_png())?;
        tiles.push(Tile { name, file });
        images.push(img);
    }
    folder.write("catalogue/all.png", &sheet(&images).to_png())?;
    Ok(tiles)
}

/// The pictures side by side, `COLUMNS` to a row, on white.
fn sheet(images: &[Image]) -> Image {
    let rows = images.len().div_ceil(COLUMNS);
    let (w, h) = (TILE.0 as usize, TILE.1 as usize);
    let width = w * COLUMNS;
    let mut rgba = vec![255u8; width * h * rows * 4];
    for (k, img) in images.iter().enumerate() {
        let (x0, y0) = ((k % COLUMNS) * w, (k / COLUMNS) * h);
        for y in 0..h {
            let from = &img.rgba[y * w * 4..(y + 1) * w * 4];
            let at = ((y0 + y) * width + x0) * 4;
            rgba[at..at + w * 4].copy_from_slice(from);
        }
    }
    Image { width: width as u32, height: (h * rows) as u32, rgba }
}

/// The index page's section: the sheet's link and the grid of pictures, each named.
pub fn html(tiles: &[Tile]) -> String {
    let mut html = format!(
        "<h2>The catalogue</h2><p>Every model surface and curve ({} kinds), drawn from its example \
         document; <a href=\"catalogue/all.png\">all on one picture</a>.</p><div class=\"catalogue\">\n",
        tiles.len()
    );
    for t in tiles {
        html.push_str(&format!(
            "<figure><img src=\"{}\" loading=\"lazy\" alt=\"{}\"><figcaption><code>{}</code></figcaption></figure>\n",
            t.file, t.name, t.name
        ));
    }
    html.push_str("</div>\n");
    html
}
