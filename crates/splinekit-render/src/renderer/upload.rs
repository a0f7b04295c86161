//! Uploading a scene's geometry to the device and reading it back: the [`Renderer`]
//! methods that make a [`Geometry`] in the pipelines' layouts ([`crate::geometry`] packs
//! the floats) and read its buffers back for tests. A child of the renderer, which uploads
//! before it draws; the geometry module itself knows nothing of the renderer.

use wgpu::util::DeviceExt;

use crate::geometry::{
    Geometry, GeometryData, Instances, MESH_VERTEX_FLOATS, MeshBuffers, POINT_FLOATS, SEGMENT_FLOATS, USAGE, bytes,
    pack_line, pack_mesh_vertices, pack_points, segment_count,
};
use crate::renderer::Renderer;
use crate::scene::RenderScene;

impl Renderer {
    /// Uploads the meshes, the lines as instanced segments and the points as instanced
    /// discs, with colours converted to linear; buffers can be written in place and read
    /// back.
    pub fn upload(&self, scene: &RenderScene) -> Geometry {
        let device = self.device();
        let buffer = |data: &[u8], usage: wgpu::BufferUsages| {
            device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
                label: None,
                contents: data,
                usage: usage | USAGE,
            })
        };
        let mut meshes = Vec::new();
        for (item, m) in scene.meshes.iter().enumerate() {
            if m.triangles.is_empty() {
                continue;
            }
            let mut v = Vec::with_capacity(m.positions.len() * MESH_VERTEX_FLOATS);
            pack_mesh_vertices(m, 0..m.positions.len(), &mut v);
            let flat: Vec<u32> = m.triangles.iter().flatten().copied().collect();
            meshes.push(MeshBuffers {
                vertices: buffer(bytes(&v), wgpu::BufferUsages::VERTEX),
                indices: buffer(bytes(&flat), wgpu::BufferUsages::INDEX),
                index_count: flat.len() as u32,
                vertex_count: m.positions.len(),
                item,
            });
        }
        let (lines, line_runs) = self.line_instances(scene);
        Geometry { meshes, lines, line_runs, points: self.point_instances(scene) }
    }

    /// Uploads the scene's lines afresh into `geometry` (its meshes and points stay).
    pub fn renew_lines(&self, geometry: &mut Geometry, scene: &RenderScene) {
        (geometry.lines, geometry.line_runs) = self.line_instances(scene);
    }

    /// Uploads the scene's points afresh into `geometry` (its meshes and lines stay).
    pub fn renew_points(&self, geometry: &mut Geometry, scene: &RenderScene) {
        geometry.points = self.point_instances(scene);
    }

    fn line_instances(&self, scene: &RenderScene) -> (Option<Instances>, Vec<(usize, usize)>) {
        let mut segments: Vec<f32> = Vec::new();
        let mut runs = Vec::with_capacity(scene.lines.len());
        for l in &scene.lines {
            runs.push((segments.len() / SEGMENT_FLOATS, segment_count(l)));
            pack_line(l, &mut segments);
        }
        // Room for a quarter more segments: a polyline spliced during a drag may gain some
        // without the buffer being made again.
        let room = segments.len() / 4 + 64 * SEGMENT_FLOATS;
        (self.instances(&segments, SEGMENT_FLOATS, room), runs)
    }

    fn point_instances(&self, scene: &RenderScene) -> Option<Instances> {
        let mut points: Vec<f32> = Vec::new();
        pack_points(&scene.points, &mut points);
        self.instances(&points, POINT_FLOATS, 0)
    }

    /// Instances of `data` (`floats` each) in a buffer with `room` floats to spare.
    fn instances(&self, data: &[f32], floats: usize, room: usize) -> Option<Instances> {
        if data.is_empty() {
            return None;
        }
        let mut contents = Vec::with_capacity(data.len() + room);
        contents.extend_from_slice(data);
        contents.resize(data.len() + room / floats * floats, 0.0);
        Some(Instances {
            buffer: self.device().create_buffer_init(&wgpu::util::BufferInitDescriptor {
                label: None,
                contents: bytes(&contents),
                usage: wgpu::BufferUsages::VERTEX | USAGE,
            }),
            count: (data.len() / floats) as u32,
            capacity: contents.len() / floats,
        })
    }

    /// Reads the geometry's buffers back (for tests that check a buffer written in place
    /// against one uploaded afresh): the instances drawn, not the room after them.
    pub fn read_geometry(&self, geometry: &Geometry) -> Result<GeometryData, crate::RenderError> {
        let read = |b: &wgpu::Buffer| self.read_buffer(b);
        Ok(GeometryData {
            meshes: geometry.meshes.iter().map(|m| read(&m.vertices)).collect::<Result<_, _>>()?,
            segments: match &geometry.lines {
                Some(l) => read(&l.buffer)?[..l.count as usize * SEGMENT_FLOATS].to_vec(),
                None => Vec::new(),
            },
            points: match &geometry.points {
                Some(p) => read(&p.buffer)?[..p.count as usize * POINT_FLOATS].to_vec(),
                None => Vec::new(),
            },
        })
    }

    fn read_buffer(&self, source: &wgpu::Buffer) -> Result<Vec<f32>, crate::RenderError> {
        let device = self.device();
        let staging = device.create_buffer(&wgpu::BufferDescriptor {
            label: None,
            size: source.size(),
            usage: wgpu::BufferUsages::COPY_DST | wgpu::BufferUsages::MAP_READ,
            mapped_at_creation: false,
        });
        let mut encoder = device.create_command_encoder(&Default::default());
        encoder.copy_buffer_to_buffer(source, 0, &staging, 0, source.size());
        self.queue().submit([encoder.finish()]);
        let slice = staging.slice(..);
        let (tx, rx) = std::sync::mpsc::channel();
        slice.map_async(wgpu::MapMode::Read, move |r| {
            let _ = tx.send(r);
        });
        let failed = |e: String| crate::RenderError::Readback(e);
        device.poll(wgpu::PollType::wait_indefinitely()).map_err(|e| failed(e.to_string()))?;
        rx.recv().map_err(|e| failed(e.to_string()))?.map_err(|e| failed(e.to_string()))?;
        let data = slice.get_mapped_range().map_err(|e| failed(format!("{e:?}")))?;
        let floats = data.chunks_exact(4).map(|b| f32::from_le_bytes([b[0], b[1], b[2], b[3]])).collect();
        drop(data);
        staging.unmap();
        Ok(floats)
    }
}
