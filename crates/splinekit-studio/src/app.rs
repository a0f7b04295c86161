//! The window: winit events in, egui panels and the 3-D view out. Each redraw runs the
//! panels (which edit the [`Studio`]), composes and draws the scene into the view's
//! target, paints egui over the window surface and presents it.

use std::path::PathBuf;
use std::sync::Arc;
use std::time::Instant;

use winit::application::ApplicationHandler;
use winit::dpi::PhysicalSize;
use winit::event::WindowEvent;
use winit::event_loop::ActiveEventLoop;
use winit::window::{Window, WindowId};

use crate::actions::{Action, pressed};
use crate::analysis::analysis_panel;
use crate::command::Command;
use crate::error::StudioError;
use crate::gpu::Gpu;
use crate::options::Options;
use crate::panels::{FileFields, SIDE_WIDTH, animation_panel, help_overlay, menu_bar, objects_panel, properties_panel};
use crate::report::{handle_report, widget_report};
use crate::snapping::snapping_panel;
use crate::studio::Studio;
use crate::view_camera::Projector;
use crate::viewport::{ViewFrame, ViewInput, view};

/// The running window.
pub struct App {
    /// The studio's state.
    pub studio: Studio,
    options: Options,
    window: Option<Arc<Window>>,
    gpu: Option<Gpu>,
    egui: egui::Context,
    egui_state: Option<egui_winit::State>,
    projector: Option<Projector>,
    view: ViewFrame,
    frames: usize,
    /// Frame-time overlay on, and the last frame's timings (ms): whole frame, scene.
    overlay: bool,
    /// The help overlay (`?`) shown.
    help: bool,
    timings: (f64, f64),
    last_frame: Instant,
    files: FileFields,
    last_report: String,
    /// Each frame's times and whether a drag was in progress.
    frame_log: Vec<FrameLog>,
    /// Close after the frame being drawn.
    quitting: bool,
    /// The whole window as last painted (with `--window-screenshot`).
    window_image: Option<splinekit_render::Image>,
    /// The first error that ended the event loop.
    pub error: Option<StudioError>,
}

/// The panels' background (egui's dark panel fill): the colour the window is cleared to.
const PANEL_FILL: egui::Color32 = egui::Color32::from_gray(27);

/// An egui context in the dark theme whose panels are not filled: the window is cleared to
/// [`PANEL_FILL`] instead. A clear costs a software rasteriser next to nothing, while
/// filling the panels' rectangles runs egui's fragment shader on a third of the window's
/// pixels; the window looks the same.
fn transparent_panels() -> egui::Context {
    let ctx = egui::Context::default();
    ctx.set_theme(egui::Theme::Dark);
    ctx.style_mut_of(egui::Theme::Dark, |s| {
        debug_assert_eq!(s.visuals.panel_fill, PANEL_FILL, "egui's dark panel fill");
        s.visuals.panel_fill = egui::Color32::TRANSPARENT;
    });
    ctx
}

/// One frame's times in ms (see `--report-frame-times`).
#[derive(Debug, Clone, Copy)]
struct FrameLog {
    /// The whole frame's work: panels, the 3-D view, egui's painting and the present.
    work: f64,
    /// The panels (egui's layout of the window).
    panels: f64,
    /// The 3-D view: composition and drawing.
    scene: f64,
    /// egui's tessellation, its painting, the present ([`Gpu::stages`]).
    tessellate: f64,
    paint: f64,
    present: f64,
    dragging: bool,
}

impl App {
    /// The window on `studio`, not yet open.
    pub fn new(studio: Studio, options: Options) -> Self {
        let open = studio.document.path().map(|p| p.display().to_string()).unwrap_or_default();
        let files = FileFields { open, export: "shape.obj".into() };
        App {
            studio,
            options,
            window: None,
            gpu: None,
            egui: transparent_panels(),
            egui_state: None,
            projector: None,
            view: ViewFrame::default(),
            frames: 0,
            overlay: false,
            help: false,
            timings: (0.0, 0.0),
            last_frame: Instant::now(),
            files,
            last_report: String::new(),
            window_image: None,
            quitting: false,
            frame_log: Vec::new(),
            error: None,
        }
    }

    fn fail(&mut self, event_loop: &ActiveEventLoop, e: impl ToString) {
        self.error.get_or_insert(StudioError::Graphics(e.to_string()));
        event_loop.exit();
    }

    /// The inner size: `--window-size`, else the scene's size plus the side panels.
    fn initial_size(&self) -> PhysicalSize<u32> {
        let (w, h) = self.options.window_size.unwrap_or((
            self.studio.document.scene().size[0] + 2 * SIDE_WIDTH as u32 + 30,
            self.studio.document.scene().size[1] + 90,
        ));
        PhysicalSize::new(w, h)
    }

    /// One frame: panels, scene, present; then the scripted exits and the handle report.
    fn redraw(&mut self, event_loop: &ActiveEventLoop) {
        let (Some(window), Some(_)) = (self.window.clone(), self.gpu.as_ref()) else { return };
        let start = Instant::now();
        self.studio.clock.tick(self.studio.document.scene().clock().duration);
        let raw = match self.egui_state.as_mut() {
            Some(s) => s.take_egui_input(&window),
            None => return,
        };
        let mut commands = Vec::new();
        self.studio.view.widgets.clear();
        let output = self.egui.clone().run_ui(raw, |ui| commands.extend(self.panels(ui)));
        let panels_ms = start.elapsed().as_secs_f64() * 1e3;
        if let Some(s) = self.egui_state.as_mut() {
            s.handle_platform_output(&window, output.platform_output.clone());
        }
        for c in commands {
            self.studio.queue(c);
        }
        for action in self.studio.run_commands() {
            self.window_action(action);
        }
        let scene_start = Instant::now();
        if let Err(e) = self.draw_view() {
            self.studio.status.say(&e);
        }
        let scene_ms = scene_start.elapsed().as_secs_f64() * 1e3;
        let ppp = self.egui.pixels_per_point();
        let repaint_now = output.viewport_output.values().any(|v| v.repaint_delay.is_zero());
        let capture = self.options.window_screenshot.is_some();
        if let Some(gpu) = self.gpu.as_mut() {
            match gpu.present(&self.egui, output, ppp, capture) {
                Ok(image) => self.window_image = image.or(self.window_image.take()),
                Err(e) => return self.fail(event_loop, e),
            }
        }
        self.timings = (self.last_frame.elapsed().as_secs_f64() * 1e3, scene_ms);
        let [_, tessellate, paint, present] = self.gpu.as_ref().map_or([0.0; 4], |g| g.stages);
        self.frame_log.push(FrameLog {
            work: start.elapsed().as_secs_f64() * 1e3,
            panels: panels_ms,
            scene: scene_ms,
            tessellate,
            paint,
            present,
            dragging: self.studio.gesture.is_some(),
        });
        self.last_frame = start;
        self.after_frame(event_loop, &window, repaint_now);
    }

    /// Counts the frame, writes the handle report, and closes after `--frames`.
    fn after_frame(&mut self, event_loop: &ActiveEventLoop, window: &Window, repaint_now: bool) {
        self.frames += 1;
        self.write_report();
        if self.quitting || self.options.frames.is_some_and(|n| self.frames >= n) {
            if let Err(e) = self.final_screenshots() {
                self.error.get_or_insert(e);
            }
            event_loop.exit();
            return;
        }
        let playing = self.studio.clock.playing && self.studio.document.scene().is_animated();
        if playing || repaint_now || self.options.frames.is_some() || self.overlay || self.projector.is_none() {
            window.request_redraw();
        }
    }

    /// The panels around the view; returns the commands asked for by menu and keys.
    fn panels(&mut self, ui: &mut egui::Ui) -> Vec<Command> {
        let mut out: Vec<Command> = pressed(ui.ctx()).into_iter().map(Command::Action).collect();
        egui::Panel::top("menu").show(ui, |ui| {
            let on = [(Action::FrameTimes, self.overlay), (Action::Help, self.help)];
            out.extend(menu_bar(ui, &mut self.files, &on));
        });
        help_overlay(ui.ctx(), &mut self.help);
        egui::Panel::bottom("status").exact_size(56.0).resizable(false).show(ui, |ui| {
            animation_panel(ui, &mut self.studio);
            let text = self.studio.status.message.clone().unwrap_or_else(|| "ready".into());
            ui.label(text);
        });
        egui::Panel::left("objects").exact_size(SIDE_WIDTH).resizable(false).show(ui, |ui| {
            egui::ScrollArea::vertical().show(ui, |ui| {
                objects_panel(ui, &mut self.studio);
                ui.separator();
                snapping_panel(ui, &mut self.studio.snapping);
                ui.separator();
                analysis_panel(ui, &mut self.studio.analysis, self.studio.selection.object);
            });
        });
        egui::Panel::right("properties").exact_size(SIDE_WIDTH).resizable(false).show(ui, |ui| {
            egui::ScrollArea::vertical().show(ui, |ui| properties_panel(ui, &mut self.studio));
        });
        egui::CentralPanel::no_frame().show(ui, |ui| {
            if let Some(e) = self.studio.status.load_error.clone() {
                ui.colored_label(egui::Color32::from_rgb(200, 40, 40), format!("Cannot open the document:\n{e}"));
                if ui.button("Dismiss").clicked() {
                    self.studio.status.load_error = None;
                }
                return;
            }
            let overlay =
                self.overlay.then(|| format!("frame {:.1} ms  scene {:.1} ms", self.timings.0, self.timings.1));
            let drawn = self.gpu.as_ref().is_some_and(Gpu::has_view);
            let input = ViewInput { drawn, projector: self.projector.as_ref(), overlay };
            self.view = view(ui, &mut self.studio, input);
        });
        out
    }

    /// Composes and draws the scene into the view at the view's size.
    fn draw_view(&mut self) -> Result<(), StudioError> {
        let Some(gpu) = self.gpu.as_mut() else { return Ok(()) };
        let size = (self.view.rect_px[2].max(1), self.view.rect_px[3].max(1));
        // On a software adapter a drag is drawn single-sampled, its last frame multisampled.
        let multisampled = !(gpu.software && self.studio.gesture.is_some());
        let scene = self.studio.view_scene(size, true)?;
        self.projector = Some(Projector::with_bounds(&scene.overlay, scene.bounds, size));
        gpu.draw_view(&scene, size, multisampled).map_err(|e| StudioError::Graphics(e.to_string()))?;
        Ok(())
    }

    /// Writes `--report-handles` when the handles' positions changed.
    fn write_report(&mut self) {
        let (Some(path), Some(projector)) = (&self.options.report_handles, &self.projector) else { return };
        let r = self.view.rect_px;
        let mut report = handle_report(
            &self.studio.shown_handles().cloned().collect::<Vec<_>>(),
            projector,
            [r[0], r[1]],
            [r[2], r[3]],
        );
        report["widgets"] = widget_report(&self.studio.view.widgets, self.egui.pixels_per_point());
        let text = report.to_string();
        if text != self.last_report {
            // Written whole to a temporary file, then renamed: a reader never sees half.
            if splinekit_scene::write_file(path, text.as_bytes()).is_ok() {
                self.last_report = text;
            }
        }
    }

    /// Saves the 3-D view (drawn without the hover and selection highlights) as PNG.
    fn screenshot(&mut self) -> Result<PathBuf, StudioError> {
        let path = self.options.screenshot.clone().unwrap_or_else(|| PathBuf::from("studio-screenshot.png"));
        let graphics = |e: &dyn std::fmt::Display| StudioError::Graphics(e.to_string());
        let Some(gpu) = self.gpu.as_mut() else { return Err(graphics(&"no window")) };
        let size = (self.view.rect_px[2].max(1), self.view.rect_px[3].max(1));
        let scene = self.studio.view_scene(size, false)?;
        gpu.draw_view(&scene, size, true).map_err(|e| graphics(&e))?;
        let image = gpu.read_view().map_err(|e| graphics(&e))?.ok_or_else(|| graphics(&"nothing drawn yet"))?;
        image.save_png(&path).map_err(|e| StudioError::Output {
            option: "--screenshot",
            path: path.clone(),
            message: e.to_string(),
        })?;
        Ok(path)
    }

    /// On closing: `--screenshot` (the 3-D view), `--window-screenshot` (the window) and
    /// `--report-frame-times`.
    fn final_screenshots(&mut self) -> Result<(), StudioError> {
        if self.options.screenshot.is_some() {
            self.screenshot()?;
        }
        if let (Some(path), Some(image)) = (&self.options.window_screenshot, &self.window_image) {
            image.save_png(path).map_err(|e| StudioError::Output {
                option: "--window-screenshot",
                path: path.clone(),
                message: e.to_string(),
            })?;
        }
        if let Some(path) = &self.options.report_frame_times {
            let log = &self.frame_log;
            let times = |f: fn(&FrameLog) -> f64| log.iter().map(f).collect::<Vec<f64>>();
            let dragging: Vec<bool> = log.iter().map(|f| f.dragging).collect();
            let text = serde_json::json!({
                "work_ms": times(|f| f.work),
                "panels_ms": times(|f| f.panels),
                "scene_ms": times(|f| f.scene),
                "tessellate_ms": times(|f| f.tessellate),
                "paint_ms": times(|f| f.paint),
                "present_ms": times(|f| f.present),
                "dragging": dragging,
            })
            .to_string();
            splinekit_scene::write_file(path, text.as_bytes()).map_err(|e| StudioError::Output {
                option: "--report-frame-times",
                path: path.clone(),
                message: e.to_string(),
            })?;
        }
        Ok(())
    }

    /// Carries out an action only the window can (the studio runs the others).
    fn window_action(&mut self, action: Action) {
        match action {
            Action::Screenshot => {
                let done = self.screenshot();
                let message = done.map_or_else(|e| e.to_string(), |p| format!("screenshot {}", p.display()));
                self.studio.status.message = Some(message);
            }
            // Closed after this frame is painted, so that its screenshots show it.
            Action::Quit => self.quitting = true,
            Action::FrameTimes => self.overlay = !self.overlay,
            Action::Help => self.help = !self.help,
            other => {
                self.studio.run_action(other);
            }
        }
    }
}

impl ApplicationHandler for App {
    fn resumed(&mut self, event_loop: &ActiveEventLoop) {
        if self.window.is_some() {
            return;
        }
        let attrs = Window::default_attributes().with_title("splinekit studio").with_inner_size(self.initial_size());
        let window = match event_loop.create_window(attrs) {
            Ok(w) => Arc::new(w),
            Err(e) => return self.fail(event_loop, format!("view: cannot open a window: {e}")),
        };
        match Gpu::new(window.clone(), event_loop.owned_display_handle(), PANEL_FILL) {
            Ok(gpu) => self.gpu = Some(gpu),
            Err(e) => return self.fail(event_loop, e),
        }
        let id = egui::ViewportId::ROOT;
        let scale = Some(window.scale_factor() as f32);
        self.egui_state = Some(egui_winit::State::new(self.egui.clone(), id, &window, scale, None, None));
        window.request_redraw();
        self.window = Some(window);
    }

    fn window_event(&mut self, event_loop: &ActiveEventLoop, _id: WindowId, event: WindowEvent) {
        let Some(window) = self.window.clone() else { return };
        let response = self.egui_state.as_mut().map(|s| s.on_window_event(&window, &event));
        match event {
            WindowEvent::CloseRequested => {
                self.quitting = true;
                window.request_redraw();
            }
            WindowEvent::Resized(size) => {
                if let Some(gpu) = self.gpu.as_mut() {
                    gpu.resize(size.width, size.height);
                }
                window.request_redraw();
            }
            WindowEvent::DroppedFile(path) => {
                self.studio.open(path);
                window.request_redraw();
            }
            WindowEvent::RedrawRequested => self.redraw(event_loop),
            _ => {
                if response.is_some_and(|r| r.repaint) {
                    window.request_redraw();
                }
            }
        }
    }
}
