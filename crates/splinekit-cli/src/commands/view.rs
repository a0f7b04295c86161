//! `splinekit view`: the studio (crate `splinekit-studio`), an interactive editor of the
//! scene or shape. `--frames N` closes after N frames and `--screenshot FILE` saves the
//! 3-D view at the end (for scripted use, e.g. under xvfb-run); `--window-size WxH` fixes
//! the window and `--report-handles FILE` writes where the handles are (end-to-end tests).

use std::path::PathBuf;

use anyhow::{Result, anyhow};
use clap::Args;

#[derive(Args, Debug)]
pub struct ViewArgs {
    /// Scene or shape document (JSON file; none: a starter scene).
    pub scene: Option<String>,
    /// Close after this many frames.
    #[arg(long)]
    pub frames: Option<String>,
    /// Save the 3-D view as PNG when closing (and on F12).
    #[arg(long)]
    pub screenshot: Option<String>,
    /// Save the whole window (panels and view) as PNG when closing.
    #[arg(long)]
    pub window_screenshot: Option<String>,
    /// Window size WxH in pixels.
    #[arg(long)]
    pub window_size: Option<String>,
    /// Write the handles' window pixel positions as JSON to this file.
    #[arg(long)]
    pub report_handles: Option<String>,
    /// Write each frame's time in milliseconds as JSON to this file when closing.
    #[arg(long)]
    pub report_frame_times: Option<String>,
}

pub fn run(args: &ViewArgs) -> Result<()> {
    let frames = args.frames.as_deref().map(|f| super::eval::parse_count("--frames", f, 1_000_000)).transpose()?;
    if frames == Some(0) {
        anyhow::bail!("--frames: need at least one frame");
    }
    for (flag, path) in [("--screenshot", &args.screenshot), ("--window-screenshot", &args.window_screenshot)] {
        if let Some(path) = path
            && !path.to_ascii_lowercase().ends_with(".png")
        {
            anyhow::bail!("{flag}: writes .png files, not '{path}'");
        }
    }
    let window_size = args
        .window_size
        .as_deref()
        .map(|s| super::render::parse_size(s).map_err(|e| anyhow!(e.to_string().replace("--size", "--window-size"))))
        .transpose()?;
    let from_stdin = args.scene.as_deref() == Some("-");
    // A STEP file opens as the scene of its objects (saved with Ctrl+S under a new name).
    let step = args.scene.as_deref().filter(|p| crate::input::is_step(p));
    let text = match step {
        Some(path) => Some(crate::input::read_step_document(path, "scene")?.into_scene().to_value().to_string()),
        None => from_stdin.then(|| crate::input::read_text("-", "scene")).transpose()?,
    };
    let from_stdin = from_stdin || step.is_some();
    if let Some(t) = &text {
        // Checked here so that a bad document fails like every command, before a window.
        splinekit_scene::SceneOrShape::from_json_in(t, std::path::Path::new("."))?;
    }
    let options = splinekit_studio::Options {
        path: args.scene.as_ref().filter(|_| !from_stdin).map(PathBuf::from),
        text,
        frames,
        screenshot: args.screenshot.as_ref().map(PathBuf::from),
        window_screenshot: args.window_screenshot.as_ref().map(PathBuf::from),
        window_size,
        report_handles: args.report_handles.as_ref().map(PathBuf::from),
        report_frame_times: args.report_frame_times.as_ref().map(PathBuf::from),
    };
    splinekit_studio::run(options).map_err(|e| anyhow!(e))
}
