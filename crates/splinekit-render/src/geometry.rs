//! A scene's geometry on the device, kept between frames: one vertex and index buffer per
//! mesh and one instance buffer of line segments and one of points, in the pipelines'
//! layouts (the one home of those layouts). A window that changes a few vertices or one
//! line writes just those ([`Geometry::write_mesh_vertices`], [`Geometry::write_line`],
//! `Queue::write_buffer`), leaving the rest of the buffers as they are; what it then draws
//! is what uploading the whole changed scene afresh draws, because the buffers hold the
//! same bytes (the studio's tests read them back,
//! [`Renderer::read_geometry`](crate::Renderer::read_geometry)).

use std::ops::Range;

use crate::scene::{LineItem, MeshItem, PointItem, RenderScene, srgba_to_linear};

/// Floats of one mesh vertex in the vertex buffer: position, normal, linear colour.
pub const MESH_VERTEX_FLOATS: usize = 10;
/// Floats of one line-segment instance: its two ends, linear colour, width and padding.
pub const SEGMENT_FLOATS: usize = 12;
/// Floats of one point instance: position, size, linear colour.
pub const POINT_FLOATS: usize = 8;

/// Buffers that can be written in place and read back.
pub(crate) const USAGE: wgpu::BufferUsages = wgpu::BufferUsages::COPY_DST.union(wgpu::BufferUsages::COPY_SRC);

pub(crate) fn bytes<T: Copy>(data: &[T]) -> &[u8] {
    // SAFETY: T is plain f32/u32 data (no padding, no pointers); the slice is read only.
    unsafe { std::slice::from_raw_parts(data.as_ptr() as *const u8, std::mem::size_of_val(data)) }
}

/// Packs vertices `range` of a mesh: position, normal (zero when missing), linear colour
/// (per vertex, else the mesh's).
pub fn pack_mesh_vertices(m: &MeshItem, range: Range<usize>, out: &mut Vec<f32>) {
    let color = srgba_to_linear(m.color);
    for i in range {
        out.extend_from_slice(&m.positions[i]);
        out.extend_from_slice(m.normals.get(i).unwrap_or(&[0.0; 3]));
        out.extend_from_slice(&m.colors.get(i).map_or(color, |c| srgba_to_linear(*c)));
    }
}

/// The number of segments a line is drawn with: n − 1, or n when closed (n > 2).
pub fn segment_count(l: &LineItem) -> usize {
    let n = l.points.len();
    if l.closed && n > 2 { n } else { n.saturating_sub(1) }
}

/// Packs a line's segments (from point i to point i + 1, the last to the first when
/// closed): both ends, linear colour, width, padding.
pub fn pack_line(l: &LineItem, out: &mut Vec<f32>) {
    pack_line_segments(l, 0..segment_count(l), out);
}

/// Packs segments `range` of a line as [`pack_line`] does.
pub fn pack_line_segments(l: &LineItem, range: Range<usize>, out: &mut Vec<f32>) {
    let c = srgba_to_linear(l.color);
    let n = l.points.len();
    let per_vertex = l.colors.len() == n;
    for i in range {
        out.extend_from_slice(&l.points[i]);
        out.extend_from_slice(&l.points[(i + 1) % n]);
        if per_vertex {
            let (a, b) = (l.colors[i], l.colors[(i + 1) % n]);
            out.extend_from_slice(&srgba_to_linear([0, 1, 2, 3].map(|k| 0.5 * (a[k] + b[k]))));
        } else {
            out.extend_from_slice(&c);
        }
        out.extend_from_slice(&[l.width, 0.0]);
    }
}

/// Packs points: position, size, linear colour.
pub fn pack_points(points: &[PointItem], out: &mut Vec<f32>) {
    for p in points {
        out.extend_from_slice(&p.position);
        out.push(p.size);
        out.extend_from_slice(&srgba_to_linear(p.color));
    }
}

/// One mesh on the device.
pub(crate) struct MeshBuffers {
    pub(crate) vertices: wgpu::Buffer,
    pub(crate) indices: wgpu::Buffer,
    pub(crate) index_count: u32,
    pub(crate) vertex_count: usize,
    /// Its index in the scene's meshes (meshes without triangles are not uploaded).
    pub(crate) item: usize,
}

/// Instances (segments or points) in one buffer: `count` drawn, room for `capacity`.
pub(crate) struct Instances {
    pub(crate) buffer: wgpu::Buffer,
    pub(crate) count: u32,
    pub(crate) capacity: usize,
}

/// A scene's geometry on the device ([`Renderer::upload`](crate::Renderer::upload); drawn by
/// [`Renderer::draw_layers`](crate::Renderer::draw_layers)).
pub struct Geometry {
    pub(crate) meshes: Vec<MeshBuffers>,
    pub(crate) lines: Option<Instances>,
    /// Per line of the scene, its first segment and number of segments.
    pub(crate) line_runs: Vec<(usize, usize)>,
    pub(crate) points: Option<Instances>,
}

/// What [`Renderer::read_geometry`](crate::Renderer::read_geometry) reads back: each
/// uploaded mesh's vertex floats, the segment floats and the point floats.
#[derive(Debug, Clone, PartialEq)]
pub struct GeometryData {
    /// Per mesh with triangles, its packed vertices.
    pub meshes: Vec<Vec<f32>>,
    /// The packed segments of all lines.
    pub segments: Vec<f32>,
    /// The packed points.
    pub points: Vec<f32>,
}

impl Geometry {
    /// Writes vertices `range` of the scene's mesh `mesh` (as [`pack_mesh_vertices`] packs
    /// them) into its vertex buffer; `false` (nothing written) when that mesh is not the
    /// uploaded one's size, so the caller uploads afresh.
    pub fn write_mesh_vertices(
        &self,
        queue: &wgpu::Queue,
        scene: &RenderScene,
        mesh: usize,
        range: Range<usize>,
    ) -> bool {
        let (Some(m), Some(b)) = (scene.meshes.get(mesh), self.meshes.iter().find(|b| b.item == mesh)) else {
            return false;
        };
        if m.positions.len() != b.vertex_count || range.end > b.vertex_count {
            return false;
        }
        if range.is_empty() {
            return true;
        }
        let mut data = Vec::with_capacity(range.len() * MESH_VERTEX_FLOATS);
        let offset = (4 * range.start * MESH_VERTEX_FLOATS) as u64;
        pack_mesh_vertices(m, range, &mut data);
        queue.write_buffer(&b.vertices, offset, bytes(&data));
        true
    }

    /// Writes the segments of the scene's line `line` into the segment buffer; `false`
    /// (nothing written) when its number of segments is not the uploaded one's.
    pub fn write_line(&self, queue: &wgpu::Queue, scene: &RenderScene, line: usize) -> bool {
        let (Some(l), Some(&(first, count)), Some(lines)) =
            (scene.lines.get(line), self.line_runs.get(line), &self.lines)
        else {
            return false;
        };
        if segment_count(l) != count {
            return false;
        }
        if count == 0 {
            return true;
        }
        let mut data = Vec::with_capacity(count * SEGMENT_FLOATS);
        pack_line(l, &mut data);
        queue.write_buffer(&lines.buffer, (4 * first * SEGMENT_FLOATS) as u64, bytes(&data));
        true
    }

    /// Writes segments `segments` (of those [`pack_line`] packs) of the scene's line `line`,
    /// the rest of its segments being the uploaded ones (a polyline spliced in place). When
    /// the line's number of segments is no longer the uploaded one's, its segments from
    /// `segments.start` on and those of every later line are written (moved to follow it)
    /// while the buffer has room for them; `false` (nothing written) when it has not, so
    /// the caller uploads the lines afresh ([`Renderer::renew_lines`](crate::Renderer::renew_lines)).
    pub fn write_line_segments(
        &mut self,
        queue: &wgpu::Queue,
        scene: &RenderScene,
        line: usize,
        segments: Range<usize>,
    ) -> bool {
        let (Some(l), Some(&(first, count)), Some(lines)) =
            (scene.lines.get(line), self.line_runs.get(line), self.lines.as_mut())
        else {
            return false;
        };
        if scene.lines.len() != self.line_runs.len() {
            return false;
        }
        let now = segment_count(l);
        let mut data = Vec::new();
        if now == count {
            let segments = segments.start.min(now)..segments.end.min(now);
            if segments.is_empty() {
                return true;
            }
            pack_line_segments(l, segments.clone(), &mut data);
            queue.write_buffer(&lines.buffer, (4 * (first + segments.start) * SEGMENT_FLOATS) as u64, bytes(&data));
            return true;
        }
        let total = lines.count as usize + now - count;
        if total > lines.capacity {
            return false;
        }
        let start = segments.start.min(now);
        pack_line_segments(l, start..now, &mut data);
        for later in &scene.lines[line + 1..] {
            pack_line(later, &mut data);
        }
        queue.write_buffer(&lines.buffer, (4 * (first + start) * SEGMENT_FLOATS) as u64, bytes(&data));
        lines.count = total as u32;
        self.line_runs[line].1 = now;
        for run in &mut self.line_runs[line + 1..] {
            run.0 = run.0 + now - count;
        }
        true
    }

    /// Writes the scene's points into the point buffer; `false` (nothing written) when
    /// their number is not the uploaded one's.
    pub fn write_points(&self, queue: &wgpu::Queue, scene: &RenderScene) -> bool {
        let Some(points) = &self.points else { return scene.points.is_empty() };
        if points.count as usize != scene.points.len() {
            return false;
        }
        let mut data = Vec::with_capacity(scene.points.len() * POINT_FLOATS);
        pack_points(&scene.points, &mut data);
        queue.write_buffer(&points.buffer, 0, bytes(&data));
        true
    }

    /// Whether this geometry's meshes were uploaded from a scene with the same meshes
    /// (those with triangles, by index, each with as many vertices) as `scene`: the
    /// meshes that may be written in place to become `scene`'s.
    pub fn meshes_fit(&self, scene: &RenderScene) -> bool {
        let meshes = scene.meshes.iter().enumerate().filter(|(_, m)| !m.triangles.is_empty());
        meshes.clone().count() == self.meshes.len()
            && meshes.zip(&self.meshes).all(|((i, m), b)| b.item == i && b.vertex_count == m.positions.len())
    }

    /// Whether this geometry's segments were uploaded from lines with as many segments
    /// each as `scene`'s.
    pub fn lines_fit(&self, scene: &RenderScene) -> bool {
        scene.lines.len() == self.line_runs.len()
            && scene.lines.iter().zip(&self.line_runs).all(|(l, r)| segment_count(l) == r.1)
    }
}
