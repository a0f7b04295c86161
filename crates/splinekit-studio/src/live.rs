//! Live re-evaluation: a blending-spline surface or curve kept sampled and on the GPU while
//! its local pieces move or their Bézier control points are edited. After a frame or a
//! local's control points change, only the parameter ranges the kernel reports
//! ([`BlendingSplineSurface::set_transform`], [`BlendingSplineSurface::set_bezier_net`] →
//! rectangles, [`BlendingSplineCurve::set_transform`],
//! [`BlendingSplineCurve::set_local_bezier_points`] → intervals) are re-evaluated
//! ([`SurfaceGridSamples::refresh`], [`CurveSamples::refresh`]), re-packed into the
//! renderer's vertex layouts (meshes: position, normal, linear colour = 10 × f32; line
//! segments: two ends, linear colour, width, padding = 12 × f32) and written to the vertex
//! buffer as whole grid rows or segment runs.

use splinekit::blend::{BlendingSplineCurve, BlendingSplineSurface};
use splinekit::curve::CurveSamples;
use splinekit::frame::Affine;
use splinekit::surface::SurfaceGridSamples;
use splinekit::{Interval, Point};
use splinekit_render::renderer::{MESH_VERTEX_FLOATS, SEGMENT_FLOATS};
use splinekit_render::scene::srgba_to_linear;

fn bytes(data: &[f32]) -> Vec<u8> {
    data.iter().flat_map(|x| x.to_le_bytes()).collect()
}

fn vertex_buffer(device: &wgpu::Device, size: usize) -> wgpu::Buffer {
    device.create_buffer(&wgpu::BufferDescriptor {
        label: Some("live geometry"),
        size: (4 * size) as u64,
        usage: wgpu::BufferUsages::VERTEX | wgpu::BufferUsages::COPY_DST,
        mapped_at_creation: false,
    })
}

/// A blending-spline surface sampled on an nu × nv grid with normals, mirrored in a vertex
/// buffer.
pub struct LiveSurface {
    /// The surface.
    pub surface: BlendingSplineSurface<3>,
    samples: SurfaceGridSamples<3>,
    color: [f32; 4],
    vertices: Vec<f32>,
    /// The vertex buffer (the renderer's mesh layout).
    pub buffer: wgpu::Buffer,
}

impl LiveSurface {
    /// Samples the surface on an nu × nv grid and uploads it.
    pub fn new(
        device: &wgpu::Device,
        queue: &wgpu::Queue,
        surface: BlendingSplineSurface<3>,
        (nu, nv): (usize, usize),
        color: [f32; 4],
    ) -> Result<Self, splinekit::Error> {
        let samples = SurfaceGridSamples::uniform(&surface, nu, nv)?;
        let mut live = LiveSurface {
            buffer: vertex_buffer(device, nu * nv * MESH_VERTEX_FLOATS),
            surface,
            samples,
            color: srgba_to_linear(color),
            vertices: vec![0.0; nu * nv * MESH_VERTEX_FLOATS],
        };
        live.pack_and_upload(queue, 0..nu);
        Ok(live)
    }

    /// Moves patch (k, l) to `frame`: re-evaluates the rectangles it affects and uploads the
    /// grid rows they cover. Returns the number of samples re-evaluated.
    pub fn set_transform(&mut self, queue: &wgpu::Queue, (k, l): (usize, usize), frame: Affine<3>) -> usize {
        let rects = self.surface.set_transform(k, l, frame);
        self.refresh(queue, &rects)
    }

    /// Replaces the net of Bézier patch (k, l) (rest frame, row-major,
    /// [`BlendingSplineSurface::set_bezier_net`]): re-evaluates the rectangles it affects
    /// and uploads their rows. Returns the number of samples re-evaluated.
    pub fn set_bezier_net(
        &mut self,
        queue: &wgpu::Queue,
        (k, l): (usize, usize),
        net: Vec<Point<3>>,
    ) -> Result<usize, splinekit::Error> {
        let rects = self.surface.set_bezier_net(k, l, net)?;
        Ok(self.refresh(queue, &rects))
    }

    fn refresh(&mut self, queue: &wgpu::Queue, rects: &[splinekit::ParamRect]) -> usize {
        let done = self.samples.refresh(&self.surface, rects);
        for rect in rects {
            let rows = rows_in(self.samples.us(), rect.u);
            self.pack_and_upload(queue, rows);
        }
        done
    }

    /// The packed vertices (what the buffer holds).
    pub fn vertices(&self) -> &[f32] {
        &self.vertices
    }

    /// Packs grid rows `rows` (all columns) and writes them to the buffer.
    fn pack_and_upload(&mut self, queue: &wgpu::Queue, rows: std::ops::Range<usize>) {
        let nv = self.samples.vs().len();
        let (points, normals) = (self.samples.points(), self.samples.normals());
        for i in rows.start * nv..rows.end * nv {
            let v = &mut self.vertices[i * MESH_VERTEX_FLOATS..(i + 1) * MESH_VERTEX_FLOATS];
            let (p, n) = (&points[i], &normals[i]);
            v[..3].copy_from_slice(&[p.x as f32, p.y as f32, p.z as f32]);
            v[3..6].copy_from_slice(&[n.x as f32, n.y as f32, n.z as f32]);
            v[6..].copy_from_slice(&self.color);
        }
        let range = rows.start * nv * MESH_VERTEX_FLOATS..rows.end * nv * MESH_VERTEX_FLOATS;
        if !range.is_empty() {
            queue.write_buffer(&self.buffer, (4 * range.start) as u64, &bytes(&self.vertices[range]));
        }
    }
}

/// The indices of the sorted parameters `xs` inside the closed interval.
fn rows_in(xs: &[f64], i: Interval) -> std::ops::Range<usize> {
    xs.partition_point(|&x| x < i.start)..xs.partition_point(|&x| x <= i.end)
}

/// A blending-spline curve sampled at n parameters, mirrored as line segments.
pub struct LiveCurve {
    /// The curve.
    pub curve: BlendingSplineCurve<3>,
    samples: CurveSamples<3>,
    color: [f32; 4],
    width: f32,
    segments: Vec<f32>,
    /// The segment instance buffer (the renderer's line layout).
    pub buffer: wgpu::Buffer,
}

impl LiveCurve {
    /// Samples the curve at `n` parameters and uploads its n − 1 segments.
    pub fn new(
        device: &wgpu::Device,
        queue: &wgpu::Queue,
        curve: BlendingSplineCurve<3>,
        n: usize,
        color: [f32; 4],
        width: f32,
    ) -> Result<Self, splinekit::Error> {
        let samples = CurveSamples::uniform(&curve, n, 0)?;
        let count = n - 1;
        let mut live = LiveCurve {
            buffer: vertex_buffer(device, count * SEGMENT_FLOATS),
            curve,
            samples,
            color: srgba_to_linear(color),
            width,
            segments: vec![0.0; count * SEGMENT_FLOATS],
        };
        live.pack_and_upload(queue, 0..n);
        Ok(live)
    }

    /// Moves local curve k to `frame`: re-evaluates the intervals it affects and uploads the
    /// segments touching them. Returns the number of samples re-evaluated.
    pub fn set_transform(&mut self, queue: &wgpu::Queue, k: usize, frame: Affine<3>) -> usize {
        let ranges = self.curve.set_transform(k, frame);
        self.refresh(queue, &ranges)
    }

    /// Replaces the control points of local k's Bézier curve (rest frame,
    /// [`BlendingSplineCurve::set_local_bezier_points`], GMlib's updateCoeffs): re-evaluates
    /// the local's support and uploads the segments touching it. Returns the number of
    /// samples re-evaluated.
    pub fn set_local_bezier_points(
        &mut self,
        queue: &wgpu::Queue,
        k: usize,
        points: Vec<Point<3>>,
    ) -> Result<usize, splinekit::Error> {
        let ranges = self.curve.set_local_bezier_points(k, points)?;
        Ok(self.refresh(queue, &ranges))
    }

    fn refresh(&mut self, queue: &wgpu::Queue, ranges: &[Interval]) -> usize {
        let done = self.samples.refresh(&self.curve, ranges);
        for r in ranges {
            let samples = rows_in(self.samples.params(), *r);
            self.pack_and_upload(queue, samples);
        }
        done
    }

    /// The packed segments (what the buffer holds).
    pub fn segments(&self) -> &[f32] {
        &self.segments
    }

    /// Packs the segments that end at samples `range` (one before, to the last) and writes
    /// them.
    fn pack_and_upload(&mut self, queue: &wgpu::Queue, range: std::ops::Range<usize>) {
        let count = self.samples.params().len() - 1;
        let (first, last) = (range.start.saturating_sub(1), range.end.min(count));
        let at = |i: usize| -> [f32; 3] {
            let p: &Point<3> = &self.samples.at(i)[0];
            [p.x as f32, p.y as f32, p.z as f32]
        };
        for s in first..last {
            let seg = &mut self.segments[s * SEGMENT_FLOATS..(s + 1) * SEGMENT_FLOATS];
            seg[..3].copy_from_slice(&at(s));
            seg[3..6].copy_from_slice(&at(s + 1));
            seg[6..10].copy_from_slice(&self.color);
            seg[10..].copy_from_slice(&[self.width, 0.0]);
        }
        let floats = first * SEGMENT_FLOATS..last * SEGMENT_FLOATS;
        if !floats.is_empty() {
            queue.write_buffer(&self.buffer, (4 * floats.start) as u64, &bytes(&self.segments[floats]));
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use splinekit_scene::{Decoration, ShapeDocument};

    fn shape(text: &str) -> ShapeDocument {
        ShapeDocument::from_json(text).expect("a valid shape")
    }

    /// After moving a piece, the live geometry equals geometry made afresh from the moved
    /// shape (so the refreshed ranges were all that changed).
    #[test]
    fn refreshed_geometry_equals_fresh_geometry() {
        let renderer = splinekit_render::Renderer::new().expect("a headless adapter (Mesa llvmpipe)");
        let (device, queue) = (renderer.device(), renderer.queue());
        let torus = shape(r#"{"type":"blending_spline_surface","model":{"type":"torus"},"local_surfaces":[8,8]}"#);
        let ShapeDocument::Surface(s) = &torus else { panic!("a surface") };
        let Decoration::LocalPatches(d) = s.decoration() else { panic!("blending") };
        let mut live =
            LiveSurface::new(device, queue, d.surface::<3>().expect("builds"), (64, 64), [0.5; 4]).expect("live");
        let frame = Affine::translation(Point::<3>::new(0.0, 0.0, 0.4));
        let done = live.set_transform(queue, (3, 4), frame);
        assert!(done > 0 && done < 64 * 64 / 2, "refreshed {done} of {} samples", 64 * 64);
        let fresh = LiveSurface::new(device, queue, live.surface.clone(), (64, 64), [0.5; 4]).expect("fresh");
        assert_eq!(live.vertices(), fresh.vertices());

        let heart = shape(r#"{"type":"blending_spline","model":{"type":"heart"},"local_curves":10}"#);
        let ShapeDocument::Curve(c) = &heart else { panic!("a curve") };
        let Decoration::LocalCurves(d) = c.decoration() else { panic!("blending") };
        let mut live = LiveCurve::new(device, queue, d.curve::<3>().expect("builds"), 1000, [0.9, 0.2, 0.5, 1.0], 3.0)
            .expect("live");
        let done = live.set_transform(queue, 2, Affine::translation(Point::<3>::new(-1.0, 0.5, 0.0)));
        assert!(done > 0 && done < 400, "refreshed {done} of 1000 samples");
        let fresh = LiveCurve::new(device, queue, live.curve.clone(), 1000, [0.9, 0.2, 0.5, 1.0], 3.0).expect("fresh");
        assert_eq!(live.segments(), fresh.segments());

        // A control point of local 6's Bézier moved (GMlib's updateCoeffs): its support only.
        let mut points = live.curve.local_bezier_points(6).expect("Bézier locals").to_vec();
        points[2] += Point::<3>::new(0.7, -0.4, 0.3);
        let before = live.segments().to_vec();
        let done = live.set_local_bezier_points(queue, 6, points).expect("an edit");
        assert!(done > 0 && done < 400, "refreshed {done} of 1000 samples");
        assert_ne!(live.segments(), &before[..], "the curve changed");
        let fresh = LiveCurve::new(device, queue, live.curve.clone(), 1000, [0.9, 0.2, 0.5, 1.0], 3.0).expect("fresh");
        assert_eq!(live.segments(), fresh.segments());
        let e = live.set_local_bezier_points(queue, 6, vec![Point::<3>::zeros(); 2]).expect_err("too few");
        assert!(e.to_string().starts_with("local_control_points: expected 4 control points"), "{e}");

        let mut live = LiveSurface::new(device, queue, torus_surface(), (64, 64), [0.5; 4]).expect("live");
        let mut net = live.surface.bezier_rest_net(2, 5).expect("Bézier patches").0.to_vec();
        net[6].z += 0.8;
        let done = live.set_bezier_net(queue, (2, 5), net).expect("an edit");
        assert!(done > 0 && done < 64 * 64 / 2, "refreshed {done} of {} samples", 64 * 64);
        let fresh = LiveSurface::new(device, queue, live.surface.clone(), (64, 64), [0.5; 4]).expect("fresh");
        assert_eq!(live.vertices(), fresh.vertices());
    }

    fn torus_surface() -> BlendingSplineSurface<3> {
        let torus = shape(r#"{"type":"blending_spline_surface","model":{"type":"torus"},"local_surfaces":[8,8]}"#);
        let ShapeDocument::Surface(s) = &torus else { panic!("a surface") };
        let Decoration::LocalPatches(d) = s.decoration() else { panic!("blending") };
        d.surface::<3>().expect("builds")
    }
}
