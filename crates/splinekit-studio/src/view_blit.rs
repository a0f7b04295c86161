//! The 3-D view's image drawn into egui's render pass by a paint callback.
//!
//! egui would show the view as a textured quad through its own fragment shader, which
//! filters the texture, multiplies by the vertex colour and carries its dithering and
//! software-filtering branches. On a software rasteriser (Mesa's llvmpipe) every pixel of
//! that shader runs on the CPU, and the view covers about half of the window. Here the
//! view is one triangle covering the callback's viewport whose fragment shader fetches
//! one texel, `textureLoad(view, ⌊uv · size⌋)`, and writes it without blending: the same
//! bytes egui's nearest-filtered quad writes when dithering is off (it is on software
//! adapters), a fraction of the work.
//!
//! The pipeline and the bind group of the current view texture live in egui-wgpu's
//! callback resources ([`ViewBlit`]); [`paint_view`] adds the callback to a painter.

/// The WGSL of the blit: a triangle twice the viewport's size (so that it covers the
/// viewport), `uv` running 0..1 across the viewport, the texel below each pixel's centre.
const SHADER: &str = r"
struct Out {
    @builtin(position) position: vec4<f32>,
    @location(0) uv: vec2<f32>,
};

@vertex
fn vs_main(@builtin(vertex_index) i: u32) -> Out {
    let uv = vec2<f32>(f32((i << 1u) & 2u), f32(i & 2u));
    var out: Out;
    out.position = vec4<f32>(uv.x * 2.0 - 1.0, 1.0 - uv.y * 2.0, 0.0, 1.0);
    out.uv = uv;
    return out;
}

@group(0) @binding(0) var view_image: texture_2d<f32>;

@fragment
fn fs_main(in: Out) -> @location(0) vec4<f32> {
    let size = vec2<i32>(textureDimensions(view_image));
    let texel = clamp(vec2<i32>(floor(in.uv * vec2<f32>(size))), vec2<i32>(0), size - vec2<i32>(1));
    return textureLoad(view_image, texel, 0);
}
";

/// The blit's pipeline and the bind group of the view texture it shows (none before the
/// first view is drawn).
pub struct ViewBlit {
    pipeline: wgpu::RenderPipeline,
    layout: wgpu::BindGroupLayout,
    bind_group: Option<wgpu::BindGroup>,
}

impl ViewBlit {
    /// The blit for a render target of `format` (the window surface's).
    pub fn new(device: &wgpu::Device, format: wgpu::TextureFormat) -> Self {
        let module = device.create_shader_module(wgpu::ShaderModuleDescriptor {
            label: Some("3-D view blit"),
            source: wgpu::ShaderSource::Wgsl(SHADER.into()),
        });
        let layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
            label: Some("3-D view blit"),
            entries: &[wgpu::BindGroupLayoutEntry {
                binding: 0,
                visibility: wgpu::ShaderStages::FRAGMENT,
                ty: wgpu::BindingType::Texture {
                    sample_type: wgpu::TextureSampleType::Float { filterable: false },
                    view_dimension: wgpu::TextureViewDimension::D2,
                    multisampled: false,
                },
                count: None,
            }],
        });
        let pipeline_layout = device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
            label: Some("3-D view blit"),
            bind_group_layouts: &[Some(&layout)],
            immediate_size: 0,
        });
        let pipeline = device.create_render_pipeline(&wgpu::RenderPipelineDescriptor {
            label: Some("3-D view blit"),
            layout: Some(&pipeline_layout),
            vertex: wgpu::VertexState {
                module: &module,
                entry_point: Some("vs_main"),
                compilation_options: Default::default(),
                buffers: &[],
            },
            fragment: Some(wgpu::FragmentState {
                module: &module,
                entry_point: Some("fs_main"),
                compilation_options: Default::default(),
                targets: &[Some(wgpu::ColorTargetState { format, blend: None, write_mask: wgpu::ColorWrites::ALL })],
            }),
            primitive: wgpu::PrimitiveState::default(),
            depth_stencil: None,
            multisample: wgpu::MultisampleState::default(),
            multiview_mask: None,
            cache: None,
        });
        ViewBlit { pipeline, layout, bind_group: None }
    }

    /// Shows `view` (the view's `Rgba8Unorm` texture) from now on.
    pub fn show(&mut self, device: &wgpu::Device, view: &wgpu::TextureView) {
        self.bind_group = Some(device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some("3-D view blit"),
            layout: &self.layout,
            entries: &[wgpu::BindGroupEntry { binding: 0, resource: wgpu::BindingResource::TextureView(view) }],
        }));
    }
}

/// The paint callback: draws the blit over the viewport egui sets to its rectangle.
struct ViewBlitCallback;

impl egui_wgpu::CallbackTrait for ViewBlitCallback {
    fn paint(
        &self,
        _info: egui::PaintCallbackInfo,
        render_pass: &mut wgpu::RenderPass<'static>,
        resources: &egui_wgpu::CallbackResources,
    ) {
        let Some(blit) = resources.get::<ViewBlit>() else { return };
        let Some(bind_group) = &blit.bind_group else { return };
        render_pass.set_pipeline(&blit.pipeline);
        render_pass.set_bind_group(0, bind_group, &[]);
        render_pass.draw(0..3, 0..1);
    }
}

/// Paints the 3-D view's last image into `rect` (nothing when the window has no view yet).
pub fn paint_view(painter: &egui::Painter, rect: egui::Rect) {
    painter.add(egui_wgpu::Callback::new_paint_callback(rect, ViewBlitCallback));
}
