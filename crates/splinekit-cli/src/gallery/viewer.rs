//! The gallery's 3-D viewer: each figure's glb shown by three.js in the page, starting from
//! the camera of its picture, animations played as morph targets.
//!
//! A page opened from the file system (double-click on index.html) may not fetch or import
//! local files in Chromium, so everything the page runs is a classic script beside it:
//! three.js (the pinned bundle of `splinekit_render::web_viewer`, built from `tools/browser/` — see its README),
//! `viewer.js`, and one `models/NAME.js` per figure carrying the glb in base64.

use anyhow::Result;
use serde_json::json;
use splinekit_mesh::export::base64::base64;
use splinekit_render::Camera;
use splinekit_render::web_viewer::{THREE_BUNDLE, THREE_LICENSE};

use super::Folder;
/// The viewer (readable, not minified).
const VIEWER_JS: &str = include_str!("viewer.js");

/// Where the page's scripts are, relative to index.html.
pub const SCRIPTS: [&str; 2] = ["vendor/three-gltf-orbit.min.js", "viewer.js"];

/// How a figure's model first shows: as its picture does.
#[derive(Debug, Clone)]
pub struct ViewStart {
    /// The picture's camera (`None`: the viewer fits one, as the renderer does).
    pub camera: Option<Camera>,
    /// The picture's size in pixels (the view keeps its aspect).
    pub size: (u32, u32),
    /// Background colour (sRGB, 0 to 1).
    pub background: [f64; 3],
    /// The animation's period in seconds (frames / fps, as the GIF loops), for animated
    /// figures.
    pub period: Option<f64>,
}

/// Writes the viewer's scripts and licence into the gallery.
pub fn write_scripts(folder: &Folder) -> Result<()> {
    folder.create_dir("vendor")?;
    folder.write(SCRIPTS[0], THREE_BUNDLE.as_bytes())?;
    folder.write("vendor/three-LICENSE", THREE_LICENSE.as_bytes())?;
    folder.write(SCRIPTS[1], VIEWER_JS.as_bytes())
}

/// Writes `models/STEM.js`, the glb as a script for the viewer; returns its path.
pub fn write_model(folder: &Folder, stem: &str, glb: &[u8]) -> Result<String> {
    folder.create_dir("models")?;
    let path = format!("models/{stem}.js");
    let name = serde_json::to_string(stem).expect("a string serialises");
    folder.write(&path, format!("splinekitGallery.addModel({name}, \"{}\");\n", base64(glb)).as_bytes())?;
    Ok(path)
}

/// The figure's `data-view` attribute: the model script and how it first shows.
pub fn data_view(stem: &str, src: &str, start: &ViewStart) -> String {
    let camera = start.camera.map(|c| match c {
        Camera::Perspective { eye, target, up, fov_y } => {
            json!({"eye": eye, "target": target, "up": up, "fov_y": fov_y})
        }
        Camera::Orthographic { eye, target, up, half_height } => {
            json!({"eye": eye, "target": target, "up": up, "half_height": half_height})
        }
    });
    let spec = json!({
        "name": stem,
        "src": src,
        "size": [start.size.0, start.size.1],
        "background": start.background,
        "camera": camera,
        "duration": start.period,
    });
    html_attribute(&spec.to_string())
}

/// `text` escaped for an HTML attribute in double quotes.
pub fn html_attribute(text: &str) -> String {
    text.replace('&', "&amp;").replace('"', "&quot;").replace('<', "&lt;").replace('>', "&gt;")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn data_view_is_json_escaped_for_an_attribute() {
        let start = ViewStart {
            camera: Some(Camera::Orthographic {
                eye: [0.0, 0.0, 5.0],
                target: [0.0; 3],
                up: [0.0, 1.0, 0.0],
                half_height: 2.5,
            }),
            size: (480, 360),
            background: [1.0, 1.0, 1.0],
            period: Some(1.0),
        };
        let attr = data_view("a&b", "models/a&b.js", &start);
        assert!(!attr.contains('"') && !attr.contains('<'), "{attr}");
        let back = attr.replace("&quot;", "\"").replace("&lt;", "<").replace("&gt;", ">").replace("&amp;", "&");
        let v: serde_json::Value = serde_json::from_str(&back).unwrap();
        assert_eq!(v["name"], "a&b");
        assert_eq!(v["camera"]["half_height"], 2.5);
        assert_eq!(v["size"], json!([480, 360]));
        assert_eq!(v["duration"], 1.0);
    }

    #[test]
    fn the_vendored_bundle_defines_the_global_the_viewer_reads() {
        assert!(THREE_BUNDLE.starts_with("/* three.js "), "the bundle names its three.js version first");
        assert!(THREE_BUNDLE.contains("var SplinekitThree="));
        assert!(VIEWER_JS.contains("window.SplinekitThree"));
        assert!(THREE_LICENSE.contains("MIT License"));
    }
}
