//! How the studio is started (the command line's `splinekit view` flags).

use std::path::PathBuf;

/// Start-up options.
#[derive(Debug, Clone, Default)]
pub struct Options {
    /// The document to open (`None`: `text`, else the starter scene).
    pub path: Option<PathBuf>,
    /// The document's JSON text when it came from standard input (saved as `studio.json`).
    pub text: Option<String>,
    /// Close after this many frames (scripts).
    pub frames: Option<usize>,
    /// Where F12 and the last frame write the 3-D view as PNG.
    pub screenshot: Option<PathBuf>,
    /// Where the whole window (panels and view) is written as PNG after the last frame.
    pub window_screenshot: Option<PathBuf>,
    /// The window's inner size in pixels (default: the scene's size plus the panels).
    pub window_size: Option<(u32, u32)>,
    /// Write each frame's time (ms: whole frame's work, of it the 3-D view's composition and
    /// drawing) as JSON here when closing.
    pub report_frame_times: Option<PathBuf>,
    /// Write the handles' window pixel positions here as JSON after every frame that moves
    /// them (for end-to-end tests that drive the mouse).
    pub report_handles: Option<PathBuf>,
}
