//! The window's graphics: one wgpu device for the window surface, the scene renderer and
//! egui. The 3-D view is drawn by [`splinekit_render::Renderer::draw`] into its own
//! target (the same pipelines, 4× MSAA and sRGB image as `splinekit render`), copied into
//! an `Rgba8Unorm` texture that a paint callback in egui's pass shows texel for texel
//! ([`crate::view_blit`]; the bytes are gamma-space, as egui blends, and GL has no
//! sRGB-reinterpreting views), and read back from the target for screenshots.
//!
//! On a software adapter (Mesa's llvmpipe) every pixel is shaded on the CPU, so there the
//! view is drawn single-sampled while a drag is in progress (a quarter of the
//! rasterisation; the still frame after the drag is multisampled again) and egui paints
//! without dithering. A hardware adapter draws as before.

use std::sync::Arc;

use splinekit_render::{Geometry, Image, RenderScene, RenderTarget, Renderer};
use winit::event_loop::OwnedDisplayHandle;
use winit::window::Window;

use crate::live_view::Changes;
use crate::studio::ViewScene;
use crate::view_blit::ViewBlit;

/// Why the window's graphics could not start.
#[derive(Debug, thiserror::Error)]
#[error("view: {0}")]
pub struct GpuError(pub String);

/// The surface, the renderers and the 3-D view's target.
pub struct Gpu {
    surface: wgpu::Surface<'static>,
    config: wgpu::SurfaceConfiguration,
    /// The scene renderer (owns the device and queue).
    pub renderer: Renderer,
    egui: egui_wgpu::Renderer,
    view: Option<View>,
    /// The adapter rasterises on the CPU.
    pub software: bool,
    /// The composed scene's geometry, kept between frames and written in place.
    geometry: Option<Geometry>,
    /// Wait for the device after each stage, so that [`Gpu::stages`] splits the frame
    /// (`SPLINEKIT_FRAME_STAGES=1`; for measuring only: it stops the stages overlapping).
    sync_stages: bool,
    /// The last frame's stages in ms: the 3-D view's drawing (waited for with
    /// `sync_stages`), egui's tessellation, egui's painting, the present.
    pub stages: [f64; 4],
    /// The colour the window is cleared to (gamma-space, as egui paints).
    background: wgpu::Color,
}

/// The 3-D view's target, its single-sampled twin (made on first use), and the
/// `Rgba8Unorm` copy the blit shows.
struct View {
    target: RenderTarget,
    single: Option<RenderTarget>,
    shown: wgpu::Texture,
}

impl Gpu {
    /// Graphics for `window` on the first adapter that can present to it (Vulkan or GL, or
    /// what `WGPU_BACKEND` names, as the offscreen renderer; GL on Mesa's llvmpipe or Vulkan
    /// on lavapipe without a GPU).
    /// The window is cleared to `background` before egui paints.
    pub fn new(window: Arc<Window>, display: OwnedDisplayHandle, background: egui::Color32) -> Result<Self, GpuError> {
        let mut desc = wgpu::InstanceDescriptor::new_with_display_handle(Box::new(display));
        desc.backends = splinekit_render::backends::backends();
        desc.flags = wgpu::InstanceFlags::empty();
        let instance = wgpu::Instance::new(desc);
        let size = window.inner_size();
        let surface = instance.create_surface(window).map_err(|e| GpuError(e.to_string()))?;
        let adapter = pollster::block_on(instance.request_adapter(&wgpu::RequestAdapterOptions {
            power_preference: wgpu::PowerPreference::HighPerformance,
            compatible_surface: Some(&surface),
            force_fallback_adapter: false,
            apply_limit_buckets: false,
        }))
        .map_err(|e| GpuError(format!("no graphics adapter can draw into the window ({e})")))?;
        let name = format!("{} ({:?})", adapter.get_info().name, adapter.get_info().backend);
        let software = adapter.get_info().device_type == wgpu::DeviceType::Cpu;
        let (device, queue) = pollster::block_on(adapter.request_device(&wgpu::DeviceDescriptor::default()))
            .map_err(|e| GpuError(e.to_string()))?;
        let mut config = surface
            .get_default_config(&adapter, size.width.max(1), size.height.max(1))
            .ok_or_else(|| GpuError("the window surface is not supported by the adapter".into()))?;
        // egui blends in gamma space: a non-sRGB format of the surface's family.
        config.format = config.format.remove_srgb_suffix();
        config.present_mode = wgpu::PresentMode::AutoVsync;
        surface.configure(&device, &config);
        // Dithering costs a noise function a pixel, which llvmpipe computes on the CPU.
        let options = egui_wgpu::RendererOptions { dithering: !software, ..Default::default() };
        let mut egui = egui_wgpu::Renderer::new(&device, config.format, options);
        egui.callback_resources.insert(ViewBlit::new(&device, config.format));
        let renderer = Renderer::from_device(device, queue, name);
        let sync_stages = std::env::var_os("SPLINEKIT_FRAME_STAGES").is_some();
        let [r, g, b, _] = background.to_array().map(|c| f64::from(c) / 255.0);
        let background = wgpu::Color { r, g, b, a: 1.0 };
        Ok(Gpu {
            surface,
            config,
            renderer,
            egui,
            view: None,
            software,
            geometry: None,
            sync_stages,
            stages: [0.0; 4],
            background,
        })
    }

    /// Follows a window resize.
    pub fn resize(&mut self, width: u32, height: u32) {
        if width > 0 && height > 0 && (width, height) != (self.config.width, self.config.height) {
            self.config.width = width;
            self.config.height = height;
            self.surface.configure(self.renderer.device(), &self.config);
        }
    }

    /// Draws the view's scene into the 3-D view's target (resized to `size`; multisampled,
    /// or with `multisampled` false into the single-sampled one), copies it to the texture
    /// the blit shows ([`crate::view_blit`]). The composed scene's geometry stays on
    /// the device between frames: only the items the view lists as changed are written
    /// ([`keep_geometry`]); the overlays are uploaded each frame.
    pub fn draw_view(&mut self, scene: &ViewScene, size: (u32, u32), multisampled: bool) -> Result<(), GpuError> {
        let max = splinekit_render::renderer::MAX_SIDE;
        let size = (size.0.clamp(1, max), size.1.clamp(1, max));
        if self.view.as_ref().is_none_or(|v| v.target.size() != size) {
            self.view = Some(self.new_view(size)?);
        }
        if !multisampled && let Some(v) = self.view.as_mut().filter(|v| v.single.is_none()) {
            v.single = Some(self.renderer.target_sampled(size.0, size.1, false).map_err(|e| GpuError(e.to_string()))?);
        }
        keep_geometry(&self.renderer, &mut self.geometry, scene.composed, &scene.changes);
        let overlay = self.renderer.upload(&scene.overlay);
        let v = self.view.as_ref().expect("made above");
        let target = if multisampled { &v.target } else { v.single.as_ref().expect("made above") };
        let geometry = self.geometry.as_ref().expect("kept above");
        self.renderer.draw_layers(&scene.overlay, scene.bounds, &[geometry, &overlay], target);
        let mut encoder = self.renderer.device().create_command_encoder(&Default::default());
        encoder.copy_texture_to_texture(
            target.resolved().as_image_copy(),
            v.shown.as_image_copy(),
            wgpu::Extent3d { width: size.0, height: size.1, depth_or_array_layers: 1 },
        );
        self.renderer.queue().submit([encoder.finish()]);
        self.wait_if_profiling();
        Ok(())
    }

    /// With `sync_stages`, waits until the device has done all submitted work.
    fn wait_if_profiling(&self) {
        if self.sync_stages {
            let _ = self.renderer.device().poll(wgpu::PollType::wait_indefinitely());
        }
    }

    /// A view of `size` pixels, shown by the blit from now on.
    fn new_view(&mut self, size: (u32, u32)) -> Result<View, GpuError> {
        let target = self.renderer.target(size.0, size.1).map_err(|e| GpuError(e.to_string()))?;
        let device = self.renderer.device();
        let shown = device.create_texture(&wgpu::TextureDescriptor {
            label: Some("3-D view"),
            size: wgpu::Extent3d { width: size.0, height: size.1, depth_or_array_layers: 1 },
            mip_level_count: 1,
            sample_count: 1,
            dimension: wgpu::TextureDimension::D2,
            format: wgpu::TextureFormat::Rgba8Unorm,
            usage: wgpu::TextureUsages::COPY_DST | wgpu::TextureUsages::TEXTURE_BINDING,
            view_formats: &[],
        });
        let blit = self.egui.callback_resources.get_mut::<ViewBlit>().expect("inserted by Gpu::new");
        blit.show(device, &shown.create_view(&Default::default()));
        Ok(View { target, single: None, shown })
    }

    /// Whether the 3-D view has been drawn.
    pub fn has_view(&self) -> bool {
        self.view.is_some()
    }

    /// Reads the 3-D view's last multisampled image back.
    pub fn read_view(&self) -> Result<Option<Image>, GpuError> {
        self.view.as_ref().map(|v| self.renderer.read(&v.target)).transpose().map_err(|e| GpuError(e.to_string()))
    }

    /// Paints egui's output over a clear window and presents it (texture changes are
    /// applied even when the surface has no frame to give); with `capture`, returns the
    /// whole window's image too.
    pub fn present(
        &mut self,
        ctx: &egui::Context,
        mut output: egui::FullOutput,
        pixels_per_point: f32,
        capture: bool,
    ) -> Result<Option<Image>, GpuError> {
        let (device, queue) = (self.renderer.device(), self.renderer.queue());
        for (id, deltas) in output.textures_delta.set.drain() {
            for delta in deltas {
                self.egui.update_texture(device, queue, id, &delta);
            }
        }
        let freed: Vec<egui::TextureId> = output.textures_delta.free.drain().collect();
        let shapes = std::mem::take(&mut output.shapes);
        let image = match self.frame() {
            Some(frame) => self.paint(ctx, shapes, pixels_per_point, frame, capture)?,
            None => None,
        };
        for id in &freed {
            self.egui.free_texture(id);
        }
        Ok(image)
    }

    /// The surface's next texture; `None` (after reconfiguring if outdated) when there is
    /// none this time.
    fn frame(&self) -> Option<wgpu::SurfaceTexture> {
        match self.surface.get_current_texture() {
            wgpu::CurrentSurfaceTexture::Success(f) | wgpu::CurrentSurfaceTexture::Suboptimal(f) => Some(f),
            wgpu::CurrentSurfaceTexture::Outdated | wgpu::CurrentSurfaceTexture::Lost => {
                self.surface.configure(self.renderer.device(), &self.config);
                None
            }
            _ => None,
        }
    }

    /// Tessellates and paints egui's shapes into `frame` and presents it; with
    /// `capture`, also into an offscreen texture that is read back (the whole window).
    fn paint(
        &mut self,
        ctx: &egui::Context,
        shapes: Vec<egui::epaint::ClippedShape>,
        pixels_per_point: f32,
        frame: wgpu::SurfaceTexture,
        capture: bool,
    ) -> Result<Option<Image>, GpuError> {
        let t0 = std::time::Instant::now();
        let jobs = ctx.tessellate(shapes, pixels_per_point);
        let t1 = std::time::Instant::now();
        let screen =
            egui_wgpu::ScreenDescriptor { size_in_pixels: [self.config.width, self.config.height], pixels_per_point };
        let view = frame.texture.create_view(&Default::default());
        self.paint_into(&view, &jobs, &screen);
        self.wait_if_profiling();
        let t2 = std::time::Instant::now();
        self.renderer.queue().present(frame);
        let t3 = std::time::Instant::now();
        let ms = |a: std::time::Instant, b: std::time::Instant| (b - a).as_secs_f64() * 1e3;
        self.stages[1..].copy_from_slice(&[ms(t0, t1), ms(t1, t2), ms(t2, t3)]);
        if !capture {
            return Ok(None);
        }
        let (w, h) = (self.config.width, self.config.height);
        let texture = self.renderer.device().create_texture(&wgpu::TextureDescriptor {
            label: Some("window capture"),
            size: wgpu::Extent3d { width: w, height: h, depth_or_array_layers: 1 },
            mip_level_count: 1,
            sample_count: 1,
            dimension: wgpu::TextureDimension::D2,
            format: self.config.format,
            usage: wgpu::TextureUsages::RENDER_ATTACHMENT | wgpu::TextureUsages::COPY_SRC,
            view_formats: &[],
        });
        self.paint_into(&texture.create_view(&Default::default()), &jobs, &screen);
        read_texture(&self.renderer, &texture, self.config.format).map(Some)
    }

    /// One egui pass into `view`.
    fn paint_into(
        &mut self,
        view: &wgpu::TextureView,
        jobs: &[egui::ClippedPrimitive],
        screen: &egui_wgpu::ScreenDescriptor,
    ) {
        let (device, queue) = (self.renderer.device(), self.renderer.queue());
        let mut encoder = device.create_command_encoder(&Default::default());
        let extra = self.egui.update_buffers(device, queue, &mut encoder, jobs, screen);
        {
            let pass = encoder.begin_render_pass(&wgpu::RenderPassDescriptor {
                label: Some("egui"),
                color_attachments: &[Some(wgpu::RenderPassColorAttachment {
                    view,
                    depth_slice: None,
                    resolve_target: None,
                    ops: wgpu::Operations { load: wgpu::LoadOp::Clear(self.background), store: wgpu::StoreOp::Store },
                })],
                depth_stencil_attachment: None,
                timestamp_writes: None,
                occlusion_query_set: None,
                multiview_mask: None,
            });
            self.egui.render(&mut pass.forget_lifetime(), jobs, screen);
        }
        queue.submit(extra.into_iter().chain([encoder.finish()]));
    }
}

/// Brings the kept geometry of the composed scene up to date with the `changes` since it
/// was last drawn: the listed meshes' vertex ranges are written in place; the listed lines
/// and runs of segments too (a spliced polyline that gained or lost points has its
/// segments from the run on and the later lines' moved,
/// [`Geometry::write_line_segments`]), unless the segment buffer has no room left or some
/// line no longer has as many segments, when it is uploaded afresh; the points (a few hundred at most)
/// are written whenever something changed. Everything is uploaded afresh when there is no
/// geometry yet, the changes are [`Changes::All`], or the meshes no longer fit. Returns
/// whether the mesh buffers were kept.
pub fn keep_geometry(renderer: &Renderer, kept: &mut Option<Geometry>, scene: &RenderScene, changes: &Changes) -> bool {
    let queue = renderer.queue();
    match (kept.as_mut(), changes) {
        (Some(g), Changes::Items { meshes, lines, runs }) if g.meshes_fit(scene) => {
            for (m, r) in meshes {
                g.write_mesh_vertices(queue, scene, *m, r.clone());
            }
            // One run a line: from its first changed segment to its last.
            let mut joined: Vec<(usize, std::ops::Range<usize>)> = Vec::new();
            for (l, r) in runs {
                match joined.iter_mut().find(|(j, _)| j == l) {
                    Some((_, j)) => *j = j.start.min(r.start)..j.end.max(r.end),
                    None => joined.push((*l, r.clone())),
                }
            }
            let mut fits = true;
            for (l, r) in joined {
                fits &= g.write_line_segments(queue, scene, l, r);
            }
            if !fits || !g.lines_fit(scene) {
                renderer.renew_lines(g, scene);
            } else {
                for &l in lines {
                    g.write_line(queue, scene, l);
                }
            }
            let changed = !meshes.is_empty() || !lines.is_empty() || !runs.is_empty();
            if changed && !g.write_points(queue, scene) {
                renderer.renew_points(g, scene);
            }
            true
        }
        _ => {
            *kept = Some(renderer.upload(scene));
            false
        }
    }
}

/// Copies an RGBA or BGRA texture to the CPU as RGBA.
fn read_texture(renderer: &Renderer, texture: &wgpu::Texture, format: wgpu::TextureFormat) -> Result<Image, GpuError> {
    let (w, h) = (texture.width(), texture.height());
    let padded = (4 * w).div_ceil(256) * 256;
    let device = renderer.device();
    let buffer = device.create_buffer(&wgpu::BufferDescriptor {
        label: None,
        size: u64::from(padded) * u64::from(h),
        usage: wgpu::BufferUsages::COPY_DST | wgpu::BufferUsages::MAP_READ,
        mapped_at_creation: false,
    });
    let mut encoder = device.create_command_encoder(&Default::default());
    encoder.copy_texture_to_buffer(
        texture.as_image_copy(),
        wgpu::TexelCopyBufferInfo {
            buffer: &buffer,
            layout: wgpu::TexelCopyBufferLayout { offset: 0, bytes_per_row: Some(padded), rows_per_image: Some(h) },
        },
        wgpu::Extent3d { width: w, height: h, depth_or_array_layers: 1 },
    );
    renderer.queue().submit([encoder.finish()]);
    let slice = buffer.slice(..);
    slice.map_async(wgpu::MapMode::Read, |_| {});
    device.poll(wgpu::PollType::wait_indefinitely()).map_err(|e| GpuError(e.to_string()))?;
    let data = slice.get_mapped_range().map_err(|e| GpuError(format!("{e:?}")))?;
    let bgra = matches!(format, wgpu::TextureFormat::Bgra8Unorm | wgpu::TextureFormat::Bgra8UnormSrgb);
    let mut rgba = Vec::with_capacity((4 * w * h) as usize);
    for row in 0..h as usize {
        for px in data[row * padded as usize..row * padded as usize + 4 * w as usize].chunks_exact(4) {
            rgba.extend_from_slice(&if bgra { [px[2], px[1], px[0], 255] } else { [px[0], px[1], px[2], 255] });
        }
    }
    Ok(Image { width: w, height: h, rgba })
}
