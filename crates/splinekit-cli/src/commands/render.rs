//! `splinekit render` (a PNG of a scene or shape) and `splinekit animate` (a GIF of a
//! scene's animation).

use anyhow::{Result, anyhow, bail};
use clap::Args;
use indicatif::{ProgressBar, ProgressStyle};
use splinekit_mesh::export::Format;
use splinekit_render::{Camera, Image, Renderer, compose, write_gif};
use splinekit_scene::scenes::SceneDocument;

#[derive(Args, Debug)]
pub struct RenderArgs {
    /// Scene or shape document (JSON file, or - for standard input).
    pub scene: String,
    /// Output PNG file.
    #[arg(short, long)]
    pub output: String,
    /// Image size WxH in pixels (default: the scene's, else 800x600).
    #[arg(long)]
    pub size: Option<String>,
    /// Pose the scene's animation at this time (seconds).
    #[arg(long, allow_hyphen_values = true)]
    pub time: Option<String>,
}

#[derive(Args, Debug)]
pub struct AnimateArgs {
    /// Scene or shape document with an animation (JSON file, or - for standard input).
    pub scene: String,
    /// Output GIF file.
    #[arg(short, long)]
    pub output: String,
    /// Number of frames (default: the scene's duration × fps).
    #[arg(long)]
    pub frames: Option<String>,
    /// Frames per second (default: the scene's, else 20).
    #[arg(long)]
    pub fps: Option<String>,
    /// Image size WxH in pixels (default: the scene's, else 800x600).
    #[arg(long)]
    pub size: Option<String>,
}

pub fn parse_size(text: &str) -> Result<(u32, u32)> {
    let (w, h) =
        text.split_once(['x', 'X', ',']).ok_or_else(|| anyhow!("--size: expected WxH like 800x600, got '{text}'"))?;
    let side = |s: &str| -> Result<u32> {
        let v: u32 = s.trim().parse().map_err(|_| anyhow!("--size: '{s}' is not a whole number"))?;
        if !(1..=splinekit_render::renderer::MAX_SIDE).contains(&v) {
            bail!("--size: each side must be between 1 and {} pixels, got {v}", splinekit_render::renderer::MAX_SIDE);
        }
        Ok(v)
    };
    Ok((side(w)?, side(h)?))
}

/// `--size` if given, else the scene's size.
fn image_size(arg: Option<&str>, scene: &SceneDocument) -> Result<(u32, u32)> {
    match arg {
        Some(s) => parse_size(s),
        None => Ok((scene.size[0], scene.size[1])),
    }
}

pub fn read_scene(path: &str) -> Result<SceneDocument> {
    Ok(crate::input::read_document(path, "scene")?.into_scene())
}

/// Renders one frame of a scene (with `camera`, or the scene's own).
pub fn render_frame(
    renderer: &Renderer,
    scene: &SceneDocument,
    time: Option<f64>,
    size: (u32, u32),
    camera: Option<Camera>,
) -> Result<Image> {
    Ok(render_frame_with_camera(renderer, scene, time, size, camera)?.0)
}

/// `render_frame`, also returning the camera the frame was drawn with (the gallery's 3-D
/// viewer starts from it, so that the model first shows as its picture does).
pub fn render_frame_with_camera(
    renderer: &Renderer,
    scene: &SceneDocument,
    time: Option<f64>,
    size: (u32, u32),
    camera: Option<Camera>,
) -> Result<(Image, Option<Camera>)> {
    let mut rs = compose(scene, time, size.0 as f32 / size.1 as f32)?;
    check_drawable(&rs)?;
    if camera.is_some() {
        rs.camera = camera;
    }
    Ok((renderer.render(&rs, size.0, size.1)?, rs.camera))
}

/// Refuses a composed scene with coordinates that are not finite in single precision (the
/// renderer's): they would draw nothing and leave a blank image.
fn check_drawable(rs: &splinekit_render::RenderScene) -> Result<()> {
    let finite = |p: &[f32; 3]| p.iter().all(|x| x.is_finite());
    if let Some(i) = rs.meshes.iter().position(|m| !m.positions.iter().all(finite)) {
        bail!("objects: mesh {i} has coordinates beyond single precision (±3.4e38); the scene cannot be drawn");
    }
    if let Some(i) = rs.lines.iter().position(|l| !l.points.iter().all(finite)) {
        bail!("objects: line {i} has coordinates beyond single precision (±3.4e38); the scene cannot be drawn");
    }
    if let Some(i) = rs.points.iter().position(|p| !finite(&p.position)) {
        bail!("objects: point {i} has coordinates beyond single precision (±3.4e38); the scene cannot be drawn");
    }
    Ok(())
}

/// One camera for every frame of an animation: the scene's at time 0, moved back by 12 %
/// to leave room for the motion (a camera refitted per frame would zoom back and forth).
pub fn animation_camera(scene: &SceneDocument, size: (u32, u32)) -> Result<Option<Camera>> {
    let rs = compose(scene, Some(0.0), size.0 as f32 / size.1 as f32)?;
    Ok(rs.camera.map(|c| c.zoomed(1.12)))
}

pub fn run_render(args: &RenderArgs) -> Result<()> {
    if Format::of_name(&args.output) != Some(Format::Png) {
        bail!("-o: render writes .png files, not '{}'", args.output);
    }
    let scene = read_scene(&args.scene)?;
    let size = image_size(args.size.as_deref(), &scene)?;
    let time = args.time.as_deref().map(super::eval::parse_time).transpose()?;
    crate::budget::check_render(&scene, size, 1, "--size")?;
    let renderer = Renderer::new()?;
    let img = render_frame(&renderer, &scene, time, size, None)?;
    crate::output::write_bytes(&img.to_png(), Some(&args.output))
}

pub fn run_animate(args: &AnimateArgs) -> Result<()> {
    if Format::of_name(&args.output) != Some(Format::Gif) {
        bail!("-o: animate writes .gif files, not '{}'", args.output);
    }
    let scene = read_scene(&args.scene)?;
    let size = image_size(args.size.as_deref(), &scene)?;
    let fps = match &args.fps {
        Some(f) => {
            let v: f64 = f.trim().parse().map_err(|_| anyhow!("--fps: '{f}' is not a number"))?;
            if !(v > 0.0 && v <= 100.0) {
                bail!("--fps: must be in (0, 100], got {v}");
            }
            v
        }
        None => scene.clock().fps,
    };
    let frames = match &args.frames {
        Some(n) => super::eval::parse_count("--frames", n, 2000)?,
        None => scene.clock().frames_at(fps),
    };
    if frames == 0 {
        bail!("--frames: need at least one frame");
    }
    if frames as u64 * size.0 as u64 * size.1 as u64 > 2_000_000_000 {
        bail!("--frames: {frames} frames of {}x{} are more than 2·10⁹ pixels", size.0, size.1);
    }
    crate::budget::check_render(&scene, size, frames, if args.frames.is_some() { "--frames" } else { "animation" })?;
    let renderer = Renderer::new()?;
    let bar = progress(frames as u64, "rendering");
    let camera = animation_camera(&scene, size)?;
    let mut images = Vec::with_capacity(frames);
    for k in 0..frames {
        images.push(render_frame(&renderer, &scene, Some(k as f64 / fps), size, camera)?);
        bar.inc(1);
    }
    bar.finish_and_clear();
    let mut gif = Vec::new();
    write_gif(&mut gif, &images, fps as f32).map_err(|e| anyhow!("-o: {e}"))?;
    crate::output::write_bytes(&gif, Some(&args.output))
}

/// A progress bar on standard error (drawn only when standard error is a terminal).
pub fn progress(len: u64, what: &str) -> ProgressBar {
    let bar = ProgressBar::with_draw_target(Some(len), indicatif::ProgressDrawTarget::stderr());
    bar.set_style(ProgressStyle::with_template("{msg} {bar:30} {pos}/{len} {elapsed}").expect("valid template"));
    bar.set_message(what.to_string());
    bar
}
