//! `splinekit view`: an interactive window showing a scene (or shape), rendered offscreen
//! by the same renderer as `render` and shown with softbuffer. Drag with the left button
//! to orbit, scroll to zoom, space to pause or play the animation, R to reset the view,
//! Escape or Q to close. `--frames N` closes after N frames and `--screenshot FILE` saves
//! the last one (for scripted use, e.g. under xvfb-run).

use std::num::NonZeroU32;
use std::rc::Rc;
use std::time::Instant;

use anyhow::{Result, anyhow};
use clap::Args;
use splinekit_render::{Camera, Image, Renderer, compose};
use splinekit_scene::scenes::SceneDocument;
use winit::application::ApplicationHandler;
use winit::dpi::{LogicalSize, PhysicalPosition};
use winit::event::{ElementState, MouseButton, MouseScrollDelta, WindowEvent};
use winit::event_loop::{ActiveEventLoop, ControlFlow, EventLoop};
use winit::keyboard::{Key, NamedKey};
use winit::window::{Window, WindowId};

use super::render::read_scene;

#[derive(Args, Debug)]
pub struct ViewArgs {
    /// Scene or shape document (JSON file, or - for standard input).
    pub scene: String,
    /// Close after this many frames.
    #[arg(long)]
    pub frames: Option<String>,
    /// Save the last frame shown as PNG.
    #[arg(long)]
    pub screenshot: Option<String>,
}

struct View {
    scene: SceneDocument,
    /// Whether the scene has an animation (looked up once).
    animated: bool,
    renderer: Renderer,
    window: Option<Rc<Window>>,
    surface: Option<softbuffer::Surface<Rc<Window>, Rc<Window>>>,
    /// Orbit angles in radians and distance factor.
    azimuth: f32,
    elevation: f32,
    zoom: f32,
    dragging: bool,
    last_cursor: Option<PhysicalPosition<f64>>,
    playing: bool,
    clock: f64,
    last_tick: Instant,
    frames_left: Option<usize>,
    screenshot: Option<String>,
    last_image: Option<Image>,
    error: Option<anyhow::Error>,
}

impl View {
    fn draw(&mut self) -> Result<()> {
        let (Some(window), Some(surface)) = (&self.window, &mut self.surface) else { return Ok(()) };
        let size = window.inner_size();
        let (w, h) = (size.width.max(1), size.height.max(1));
        let now = Instant::now();
        if self.playing {
            self.clock += now.duration_since(self.last_tick).as_secs_f64();
        }
        self.last_tick = now;
        let time = self.animated.then_some(self.clock % self.scene.animation.duration.max(1e-3));
        let mut rs = compose(&self.scene, time, w as f32 / h as f32)?;
        let flat = rs.painter_order;
        if !flat || self.azimuth != 0.0 || self.elevation != 0.0 {
            if let Some(b) = rs.bounds() {
                let fitted = Camera::fit(b, 0.87 + self.azimuth, 0.49 + self.elevation, w as f32 / h as f32);
                rs.camera = Some(fitted.zoomed(self.zoom));
                rs.painter_order = false;
            }
        } else if let Some(c) = rs.camera {
            rs.camera = Some(c.zoomed(self.zoom));
        }
        let img = self.renderer.render(&rs, w.min(4096), h.min(4096))?;
        surface
            .resize(NonZeroU32::new(img.width).expect("width ≥ 1"), NonZeroU32::new(img.height).expect("height ≥ 1"))
            .map_err(|e| anyhow!("window: {e}"))?;
        let mut buffer = surface.buffer_mut().map_err(|e| anyhow!("window: {e}"))?;
        for (dst, px) in buffer.iter_mut().zip(img.rgba.chunks_exact(4)) {
            *dst = (px[0] as u32) << 16 | (px[1] as u32) << 8 | px[2] as u32;
        }
        buffer.present().map_err(|e| anyhow!("window: {e}"))?;
        self.last_image = Some(img);
        Ok(())
    }
}

impl ApplicationHandler for View {
    fn resumed(&mut self, event_loop: &ActiveEventLoop) {
        if self.window.is_some() {
            return;
        }
        let attrs = Window::default_attributes()
            .with_title("splinekit view")
            .with_inner_size(LogicalSize::new(self.scene.size[0], self.scene.size[1]));
        let made = event_loop.create_window(attrs).map_err(|e| anyhow!("window: {e}")).and_then(|w| {
            let w = Rc::new(w);
            let context = softbuffer::Context::new(w.clone()).map_err(|e| anyhow!("window: {e}"))?;
            let surface = softbuffer::Surface::new(&context, w.clone()).map_err(|e| anyhow!("window: {e}"))?;
            Ok((w, surface))
        });
        match made {
            Ok((w, s)) => {
                w.request_redraw();
                self.window = Some(w);
                self.surface = Some(s);
            }
            Err(e) => {
                self.error = Some(e);
                event_loop.exit();
            }
        }
    }

    fn window_event(&mut self, event_loop: &ActiveEventLoop, _id: WindowId, event: WindowEvent) {
        let redraw = |v: &Self| {
            if let Some(w) = &v.window {
                w.request_redraw();
            }
        };
        match event {
            WindowEvent::CloseRequested => event_loop.exit(),
            WindowEvent::RedrawRequested => {
                if let Err(e) = self.draw() {
                    self.error = Some(e);
                    event_loop.exit();
                    return;
                }
                if let Some(n) = &mut self.frames_left {
                    *n = n.saturating_sub(1);
                    if *n == 0 {
                        event_loop.exit();
                        return;
                    }
                }
                if self.playing && self.animated || self.frames_left.is_some() {
                    redraw(self);
                }
            }
            WindowEvent::Resized(_) => redraw(self),
            WindowEvent::MouseInput { state, button: MouseButton::Left, .. } => {
                self.dragging = state == ElementState::Pressed;
                self.last_cursor = None;
            }
            WindowEvent::CursorMoved { position, .. } if self.dragging => {
                if let Some(last) = self.last_cursor {
                    self.azimuth -= 0.01 * (position.x - last.x) as f32;
                    self.elevation = (self.elevation + 0.01 * (position.y - last.y) as f32).clamp(-1.5, 1.0);
                    redraw(self);
                }
                self.last_cursor = Some(position);
            }
            WindowEvent::MouseWheel { delta, .. } => {
                let steps = match delta {
                    MouseScrollDelta::LineDelta(_, y) => y,
                    MouseScrollDelta::PixelDelta(p) => (p.y / 40.0) as f32,
                };
                self.zoom = (self.zoom * 0.9f32.powf(steps)).clamp(0.05, 20.0);
                redraw(self);
            }
            WindowEvent::KeyboardInput { event, .. } if event.state == ElementState::Pressed => match event.logical_key
            {
                Key::Named(NamedKey::Escape) => event_loop.exit(),
                Key::Named(NamedKey::Space) => {
                    self.playing = !self.playing;
                    self.last_tick = Instant::now();
                    redraw(self);
                }
                Key::Character(c) if c.as_str() == "q" => event_loop.exit(),
                Key::Character(c) if c.as_str() == "r" => {
                    (self.azimuth, self.elevation, self.zoom) = (0.0, 0.0, 1.0);
                    redraw(self);
                }
                _ => {}
            },
            _ => {}
        }
    }
}

pub fn run(args: &ViewArgs) -> Result<()> {
    let scene = read_scene(&args.scene)?;
    let frames_left = args.frames.as_deref().map(|f| super::eval::parse_count("--frames", f, 1_000_000)).transpose()?;
    if frames_left == Some(0) {
        anyhow::bail!("--frames: need at least one frame");
    }
    if let Some(path) = &args.screenshot
        && !path.to_ascii_lowercase().ends_with(".png")
    {
        anyhow::bail!("--screenshot: writes .png files, not '{path}'");
    }
    let event_loop = EventLoop::new().map_err(|e| {
        anyhow!("view: cannot open a window ({e}); it needs a display (X11: set DISPLAY, or run under xvfb-run)")
    })?;
    event_loop.set_control_flow(ControlFlow::Wait);
    let renderer = Renderer::new()?;
    let mut view = View {
        animated: scene.is_animated(),
        scene,
        renderer,
        window: None,
        surface: None,
        azimuth: 0.0,
        elevation: 0.0,
        zoom: 1.0,
        dragging: false,
        last_cursor: None,
        playing: true,
        clock: 0.0,
        last_tick: Instant::now(),
        frames_left,
        screenshot: args.screenshot.clone(),
        last_image: None,
        error: None,
    };
    event_loop.run_app(&mut view).map_err(|e| anyhow!("view: {e}"))?;
    if let Some(e) = view.error {
        return Err(e);
    }
    if let (Some(path), Some(img)) = (&view.screenshot, &view.last_image) {
        img.save_png(std::path::Path::new(path)).map_err(|e| anyhow!("--screenshot: cannot write {path}: {e}"))?;
    }
    Ok(())
}
