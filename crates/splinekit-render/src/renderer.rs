//! The wgpu renderer: one device, three pipelines (meshes, lines, points), offscreen
//! targets with 4× MSAA (or single-sampled, [`Renderer::target_sampled`]) and a depth
//! buffer, read back into an [`Image`].

use wgpu::util::DeviceExt;

use crate::geometry::{Geometry, bytes};
use crate::image::Image;
use crate::scene::{RenderScene, srgba_to_linear};

mod upload;

/// Why rendering failed.
#[derive(Debug, thiserror::Error)]
pub enum RenderError {
    /// No adapter at all.
    #[error(
        "no graphics adapter found: install a GPU driver, or Mesa for software rendering (Debian/Ubuntu: apt-get install libegl1 libgl1-mesa-dri)"
    )]
    NoAdapter,
    /// The device could not be created.
    #[error("the graphics device could not be created: {0}")]
    Device(String),
    /// A bad request (image size, …).
    #[error("{0}")]
    Invalid(String),
    /// Reading the image back failed.
    #[error("reading the rendered image back failed: {0}")]
    Readback(String),
}

/// Largest image side (its one home is the budget's [`splinekit_scene::budget::MAX_IMAGE_SIDE`],
/// which the default work budget admits as a square image).
pub const MAX_SIDE: u32 = splinekit_scene::budget::MAX_IMAGE_SIDE;
/// The multisampling of [`Renderer::render`] and of the targets [`Renderer::target`] makes.
pub const SAMPLES: u32 = 4;
const COLOR_FORMAT: wgpu::TextureFormat = wgpu::TextureFormat::Rgba8UnormSrgb;
const DEPTH_FORMAT: wgpu::TextureFormat = wgpu::TextureFormat::Depth32Float;

/// An offscreen renderer (create once, render many frames).
pub struct Renderer {
    device: wgpu::Device,
    queue: wgpu::Queue,
    pipelines: Pipelines,
    /// The pipelines of single-sampled targets, made on first use.
    single: std::sync::OnceLock<Pipelines>,
    bind_layout: wgpu::BindGroupLayout,
    adapter_name: String,
}

/// The render pipelines: shaded meshes; lines and points with depth testing, and without
/// it for plane figures drawn in painter's order.
struct Pipelines {
    mesh: wgpu::RenderPipeline,
    line: wgpu::RenderPipeline,
    point: wgpu::RenderPipeline,
    flat_line: wgpu::RenderPipeline,
    flat_point: wgpu::RenderPipeline,
}

/// The textures a frame is drawn into: multisampled colour and depth, the resolved image
/// (sRGB; a window can copy it into an `Rgba8Unorm` texture to show the bytes), and the
/// buffer it is copied into for reading (rows padded to 256 bytes). Made by
/// [`Renderer::target`]; reused frame after frame while the size stays. A single-sampled
/// target has no multisampled colour: it is drawn straight into the image.
pub struct RenderTarget {
    size: wgpu::Extent3d,
    samples: u32,
    msaa: Option<wgpu::Texture>,
    depth: wgpu::Texture,
    resolved: wgpu::Texture,
    readback: wgpu::Buffer,
    padded_row: u32,
}

impl RenderTarget {
    /// Width and height in pixels.
    pub fn size(&self) -> (u32, u32) {
        (self.size.width, self.size.height)
    }

    /// Samples a pixel: [`SAMPLES`], or 1.
    pub fn samples(&self) -> u32 {
        self.samples
    }

    /// The resolved image: `Rgba8UnormSrgb`, usable as a copy source and texture binding.
    pub fn resolved(&self) -> &wgpu::Texture {
        &self.resolved
    }
}

pub use crate::geometry::{MESH_VERTEX_FLOATS, POINT_FLOATS, SEGMENT_FLOATS};

impl Renderer {
    /// Finds an adapter (Vulkan or GL, or what `WGPU_BACKEND` names: see
    /// [`crate::backends`]; headless, Mesa's llvmpipe and lavapipe both work) and builds the
    /// pipelines.
    pub fn new() -> Result<Self, RenderError> {
        pollster::block_on(Self::new_async())
    }

    async fn new_async() -> Result<Self, RenderError> {
        let mut desc = wgpu::InstanceDescriptor::new_without_display_handle();
        desc.backends = crate::backends::backends();
        desc.flags = wgpu::InstanceFlags::empty();
        let instance = wgpu::Instance::new(desc);
        let adapter = instance
            .request_adapter(&wgpu::RequestAdapterOptions {
                power_preference: wgpu::PowerPreference::HighPerformance,
                compatible_surface: None,
                force_fallback_adapter: false,
                apply_limit_buckets: false,
            })
            .await
            .map_err(|_| RenderError::NoAdapter)?;
        let adapter_name = format!("{} ({:?})", adapter.get_info().name, adapter.get_info().backend);
        let (device, queue) = adapter
            .request_device(&wgpu::DeviceDescriptor::default())
            .await
            .map_err(|e| RenderError::Device(e.to_string()))?;
        Ok(Self::from_device(device, queue, adapter_name))
    }

    /// The adapter in use, e.g. "llvmpipe (LLVM 15.0.6, 256 bits) (Gl)".
    pub fn adapter_name(&self) -> &str {
        &self.adapter_name
    }

    /// A renderer on a device made elsewhere (e.g. by a window that presents to a surface
    /// of the same adapter); `adapter_name` describes it.
    pub fn from_device(device: wgpu::Device, queue: wgpu::Queue, adapter_name: String) -> Self {
        let bind_layout = bind_layout(&device);
        let pipelines = Pipelines::new(&device, &bind_layout, SAMPLES);
        Renderer { device, queue, pipelines, single: std::sync::OnceLock::new(), bind_layout, adapter_name }
    }

    /// The device the renderer draws with.
    pub fn device(&self) -> &wgpu::Device {
        &self.device
    }

    /// The queue the renderer submits to.
    pub fn queue(&self) -> &wgpu::Queue {
        &self.queue
    }

    /// Renders the scene into a `width` × `height` image: [`Self::target`], [`Self::draw`],
    /// [`Self::read`].
    pub fn render(&self, scene: &RenderScene, width: u32, height: u32) -> Result<Image, RenderError> {
        let targets = self.target(width, height)?;
        self.draw(scene, &targets);
        self.read(&targets)
    }

    /// Draws the scene into the target: uploads its geometry ([`Self::upload`]) and draws
    /// it ([`Self::draw_layers`]).
    pub fn draw(&self, scene: &RenderScene, targets: &RenderTarget) {
        let geometry = self.upload(scene);
        self.draw_layers(scene, scene.bounds(), &[&geometry], targets);
    }

    /// Draws geometry uploaded before in one render pass into the multisampled textures,
    /// resolved into [`RenderTarget::resolved`]: the meshes of every layer, then their
    /// lines, then their points, as one scene holding the layers' items in order would be
    /// drawn. Camera, lights, background and painter's order come from `scene`, the depth
    /// range from `bounds` (of all layers; [`RenderScene::view_projection_in`]).
    pub fn draw_layers(
        &self,
        scene: &RenderScene,
        bounds: Option<([f32; 3], [f32; 3])>,
        layers: &[&Geometry],
        targets: &RenderTarget,
    ) {
        let (width, height) = targets.size();
        let uniform = self.device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
            label: None,
            contents: bytes(&globals(scene, bounds, width, height)),
            usage: wgpu::BufferUsages::UNIFORM,
        });
        let bind = self.device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: None,
            layout: &self.bind_layout,
            entries: &[wgpu::BindGroupEntry { binding: 0, resource: uniform.as_entire_binding() }],
        });
        let mut encoder = self.device.create_command_encoder(&Default::default());
        self.pass(&mut encoder, targets, &bind, layers, scene);
        self.queue.submit([encoder.finish()]);
    }

    /// Copies the target's resolved image to the CPU.
    pub fn read(&self, targets: &RenderTarget) -> Result<Image, RenderError> {
        let mut encoder = self.device.create_command_encoder(&Default::default());
        encoder.copy_texture_to_buffer(
            wgpu::TexelCopyTextureInfo {
                texture: &targets.resolved,
                mip_level: 0,
                origin: wgpu::Origin3d::ZERO,
                aspect: wgpu::TextureAspect::All,
            },
            wgpu::TexelCopyBufferInfo {
                buffer: &targets.readback,
                layout: wgpu::TexelCopyBufferLayout {
                    offset: 0,
                    bytes_per_row: Some(targets.padded_row),
                    rows_per_image: Some(targets.size.height),
                },
            },
            targets.size,
        );
        self.queue.submit([encoder.finish()]);
        self.read_back(targets)
    }

    /// The textures and read-back buffer of a `width` × `height` frame with [`SAMPLES`]×
    /// multisampling; each side in 1..=[`MAX_SIDE`].
    pub fn target(&self, width: u32, height: u32) -> Result<RenderTarget, RenderError> {
        self.target_sampled(width, height, true)
    }

    /// [`Self::target`], multisampled or not: a single-sampled frame costs a quarter of
    /// the rasterisation (a window on a software adapter draws that way while dragging).
    pub fn target_sampled(&self, width: u32, height: u32, multisampled: bool) -> Result<RenderTarget, RenderError> {
        if !(1..=MAX_SIDE).contains(&width) || !(1..=MAX_SIDE).contains(&height) {
            return Err(RenderError::Invalid(format!(
                "--size: each side must be between 1 and {MAX_SIDE} pixels, got {width}x{height}"
            )));
        }
        let size = wgpu::Extent3d { width, height, depth_or_array_layers: 1 };
        let texture = |samples: u32, format: wgpu::TextureFormat, usage: wgpu::TextureUsages| {
            self.device.create_texture(&wgpu::TextureDescriptor {
                label: None,
                size,
                mip_level_count: 1,
                sample_count: samples,
                dimension: wgpu::TextureDimension::D2,
                format,
                usage,
                view_formats: &[],
            })
        };
        let padded_row = (4 * width).div_ceil(256) * 256;
        let shown = wgpu::TextureUsages::RENDER_ATTACHMENT
            | wgpu::TextureUsages::COPY_SRC
            | wgpu::TextureUsages::TEXTURE_BINDING;
        let samples = if multisampled { SAMPLES } else { 1 };
        Ok(RenderTarget {
            size,
            samples,
            msaa: multisampled.then(|| texture(SAMPLES, COLOR_FORMAT, wgpu::TextureUsages::RENDER_ATTACHMENT)),
            depth: texture(samples, DEPTH_FORMAT, wgpu::TextureUsages::RENDER_ATTACHMENT),
            resolved: texture(1, COLOR_FORMAT, shown),
            readback: self.device.create_buffer(&wgpu::BufferDescriptor {
                label: None,
                size: padded_row as u64 * height as u64,
                usage: wgpu::BufferUsages::COPY_DST | wgpu::BufferUsages::MAP_READ,
                mapped_at_creation: false,
            }),
            padded_row,
        })
    }

    /// One render pass: clear to the background, then meshes, lines and points.
    fn pass(
        &self,
        encoder: &mut wgpu::CommandEncoder,
        targets: &RenderTarget,
        bind: &wgpu::BindGroup,
        layers: &[&Geometry],
        scene: &RenderScene,
    ) {
        let bg = srgba_to_linear(scene.background);
        let (mv, dv, rv) = (
            targets.msaa.as_ref().map(|t| t.create_view(&Default::default())),
            targets.depth.create_view(&Default::default()),
            targets.resolved.create_view(&Default::default()),
        );
        // Multisampled: drawn into the samples, resolved into the image; else into the image.
        let (view, resolve_target) = match &mv {
            Some(mv) => (mv, Some(&rv)),
            None => (&rv, None),
        };
        let p = if targets.samples == SAMPLES {
            &self.pipelines
        } else {
            self.single.get_or_init(|| Pipelines::new(&self.device, &self.bind_layout, targets.samples))
        };
        let mut pass = encoder.begin_render_pass(&wgpu::RenderPassDescriptor {
            label: None,
            color_attachments: &[Some(wgpu::RenderPassColorAttachment {
                view,
                depth_slice: None,
                resolve_target,
                ops: wgpu::Operations {
                    load: wgpu::LoadOp::Clear(wgpu::Color {
                        r: bg[0] as f64,
                        g: bg[1] as f64,
                        b: bg[2] as f64,
                        a: bg[3] as f64,
                    }),
                    store: wgpu::StoreOp::Store,
                },
            })],
            depth_stencil_attachment: Some(wgpu::RenderPassDepthStencilAttachment {
                view: &dv,
                depth_ops: Some(wgpu::Operations { load: wgpu::LoadOp::Clear(1.0), store: wgpu::StoreOp::Discard }),
                stencil_ops: None,
            }),
            timestamp_writes: None,
            occlusion_query_set: None,
            multiview_mask: None,
        });
        pass.set_bind_group(0, bind, &[]);
        pass.set_pipeline(&p.mesh);
        for m in layers.iter().flat_map(|g| &g.meshes) {
            pass.set_vertex_buffer(0, m.vertices.slice(..));
            pass.set_index_buffer(m.indices.slice(..), wgpu::IndexFormat::Uint32);
            pass.draw_indexed(0..m.index_count, 0, 0..1);
        }
        let (line, point) = if scene.painter_order { (&p.flat_line, &p.flat_point) } else { (&p.line, &p.point) };
        for (pipeline, lines) in [(line, true), (point, false)] {
            pass.set_pipeline(pipeline);
            for g in layers {
                if let Some(i) = if lines { &g.lines } else { &g.points } {
                    pass.set_vertex_buffer(0, i.buffer.slice(..));
                    pass.draw(0..6, 0..i.count);
                }
            }
        }
    }

    /// Waits for the frame and copies the resolved image out of the padded read-back buffer.
    fn read_back(&self, targets: &RenderTarget) -> Result<Image, RenderError> {
        let (width, height) = (targets.size.width, targets.size.height);
        let slice = targets.readback.slice(..);
        let (tx, rx) = std::sync::mpsc::channel();
        slice.map_async(wgpu::MapMode::Read, move |r| {
            let _ = tx.send(r);
        });
        self.device.poll(wgpu::PollType::wait_indefinitely()).map_err(|e| RenderError::Readback(e.to_string()))?;
        rx.recv()
            .map_err(|e| RenderError::Readback(e.to_string()))?
            .map_err(|e| RenderError::Readback(e.to_string()))?;
        let data = slice.get_mapped_range().map_err(|e| RenderError::Readback(format!("{e:?}")))?;
        let mut rgba = Vec::with_capacity((4 * width * height) as usize);
        for row in 0..height as usize {
            let start = row * targets.padded_row as usize;
            rgba.extend_from_slice(&data[start..start + 4 * width as usize]);
        }
        drop(data);
        targets.readback.unmap();
        Ok(Image { width, height, rgba })
    }
}

/// The layout of the one uniform block, seen by vertex and fragment stages.
fn bind_layout(device: &wgpu::Device) -> wgpu::BindGroupLayout {
    device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
        label: None,
        entries: &[wgpu::BindGroupLayoutEntry {
            binding: 0,
            visibility: wgpu::ShaderStages::VERTEX | wgpu::ShaderStages::FRAGMENT,
            ty: wgpu::BindingType::Buffer {
                ty: wgpu::BufferBindingType::Uniform,
                has_dynamic_offset: false,
                min_binding_size: None,
            },
            count: None,
        }],
    })
}

/// The uniform block: view-projection matrix, eye, viewport, lights and ambient light (see
/// `shaders.wgsl`), with the camera fitted to `bounds` when the scene has none.
fn globals(scene: &RenderScene, bounds: Option<([f32; 3], [f32; 3])>, width: u32, height: u32) -> [f32; 36] {
    let (view_proj, eye) = scene.view_projection_in(bounds, width, height);
    let mut globals = [0.0f32; 36];
    for c in 0..4 {
        globals[4 * c..4 * c + 4].copy_from_slice(&view_proj[c]);
    }
    globals[16..19].copy_from_slice(&eye);
    globals[20..24].copy_from_slice(&[width as f32, height as f32, 2e-4, 0.0]);
    for (k, (dir, intensity)) in scene.lights.iter().enumerate() {
        globals[24 + 4 * k..27 + 4 * k].copy_from_slice(dir);
        globals[27 + 4 * k] = *intensity;
    }
    globals[32] = scene.ambient;
    globals
}

impl Pipelines {
    /// The pipelines drawing into targets of `samples` samples a pixel.
    fn new(device: &wgpu::Device, bind_layout: &wgpu::BindGroupLayout, samples: u32) -> Self {
        let shader = device.create_shader_module(wgpu::ShaderModuleDescriptor {
            label: Some("splinekit shaders"),
            source: wgpu::ShaderSource::Wgsl(include_str!("shaders.wgsl").into()),
        });
        let layout = device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
            label: None,
            bind_group_layouts: &[Some(bind_layout)],
            immediate_size: 0,
        });
        let pipeline = |vs: &str, fs: &str, buffers: &[Option<wgpu::VertexBufferLayout>], depth: Depth| {
            pipeline(device, &layout, &shader, (vs, fs), buffers, depth, samples)
        };
        let mesh_attrs = wgpu::vertex_attr_array![0 => Float32x3, 1 => Float32x3, 2 => Float32x4];
        let line_attrs = wgpu::vertex_attr_array![0 => Float32x3, 1 => Float32x3, 2 => Float32x4, 3 => Float32];
        let point_attrs = wgpu::vertex_attr_array![0 => Float32x3, 1 => Float32, 2 => Float32x4];
        let buffer_layout = |stride: u64, step_mode: wgpu::VertexStepMode, attributes| {
            [Some(wgpu::VertexBufferLayout { array_stride: stride, step_mode, attributes })]
        };
        let mesh_layout = buffer_layout(4 * MESH_VERTEX_FLOATS as u64, wgpu::VertexStepMode::Vertex, &mesh_attrs[..]);
        let line_layout = buffer_layout(4 * SEGMENT_FLOATS as u64, wgpu::VertexStepMode::Instance, &line_attrs[..]);
        let point_layout = buffer_layout(4 * POINT_FLOATS as u64, wgpu::VertexStepMode::Instance, &point_attrs[..]);
        Pipelines {
            mesh: pipeline("vs_mesh", "fs_mesh", &mesh_layout, Depth { write: true, test: true }),
            line: pipeline("vs_line", "fs_flat", &line_layout, Depth { write: true, test: true }),
            point: pipeline("vs_point", "fs_point", &point_layout, Depth { write: false, test: true }),
            flat_line: pipeline("vs_line", "fs_flat", &line_layout, Depth { write: false, test: false }),
            flat_point: pipeline("vs_point", "fs_point", &point_layout, Depth { write: false, test: false }),
        }
    }
}

/// Whether a pipeline writes depth and tests against it.
#[derive(Clone, Copy)]
struct Depth {
    write: bool,
    test: bool,
}

/// A pipeline of the shader's entry points `vs` and `fs` drawing into the colour and depth
/// targets with alpha blending and `samples` samples a pixel.
fn pipeline(
    device: &wgpu::Device,
    layout: &wgpu::PipelineLayout,
    shader: &wgpu::ShaderModule,
    (vs, fs): (&str, &str),
    buffers: &[Option<wgpu::VertexBufferLayout>],
    depth: Depth,
    samples: u32,
) -> wgpu::RenderPipeline {
    device.create_render_pipeline(&wgpu::RenderPipelineDescriptor {
        label: Some(vs),
        layout: Some(layout),
        vertex: wgpu::VertexState {
            module: shader,
            entry_point: Some(vs),
            buffers,
            compilation_options: Default::default(),
        },
        fragment: Some(wgpu::FragmentState {
            module: shader,
            entry_point: Some(fs),
            targets: &[Some(wgpu::ColorTargetState {
                format: COLOR_FORMAT,
                blend: Some(wgpu::BlendState::ALPHA_BLENDING),
                write_mask: wgpu::ColorWrites::ALL,
            })],
            compilation_options: Default::default(),
        }),
        primitive: wgpu::PrimitiveState { cull_mode: None, ..Default::default() },
        depth_stencil: Some(wgpu::DepthStencilState {
            format: DEPTH_FORMAT,
            depth_write_enabled: Some(depth.write),
            depth_compare: Some(if depth.test {
                wgpu::CompareFunction::LessEqual
            } else {
                wgpu::CompareFunction::Always
            }),
            stencil: Default::default(),
            bias: Default::default(),
        }),
        multisample: wgpu::MultisampleState { count: samples, ..Default::default() },
        multiview_mask: None,
        cache: None,
    })
}
