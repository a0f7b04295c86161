//! What the renderer draws: triangle meshes, polylines and points, in world coordinates,
//! with colours in sRGB (converted to linear for shading).

use crate::camera::Camera;

/// A shaded triangle mesh.
#[derive(Debug, Clone, Default)]
pub struct MeshItem {
    /// Vertex positions.
    pub positions: Vec<[f32; 3]>,
    /// Unit vertex normals (zero-length ones fall back to the face normal).
    pub normals: Vec<[f32; 3]>,
    /// sRGB colours per vertex (empty: `color` everywhere).
    pub colors: Vec<[f32; 4]>,
    /// The colour when there are no per-vertex colours.
    pub color: [f32; 4],
    /// Triangles.
    pub triangles: Vec<[u32; 3]>,
}

/// A polyline drawn `width` pixels wide.
#[derive(Debug, Clone, Default)]
pub struct LineItem {
    /// The vertices.
    pub points: Vec<[f32; 3]>,
    /// Whether the last vertex connects to the first.
    pub closed: bool,
    /// sRGB colour.
    pub color: [f32; 4],
    /// Width in pixels.
    pub width: f32,
    /// sRGB colours per vertex (a colour map), or empty for `color` throughout; each
    /// segment is drawn in the mean of its ends' colours.
    pub colors: Vec<[f32; 4]>,
}

/// A point drawn as a disc `size` pixels across.
#[derive(Debug, Clone, Copy, Default)]
pub struct PointItem {
    /// Position.
    pub position: [f32; 3],
    /// sRGB colour.
    pub color: [f32; 4],
    /// Diameter in pixels.
    pub size: f32,
}

/// A scene to render.
#[derive(Debug, Clone)]
pub struct RenderScene {
    /// Shaded meshes.
    pub meshes: Vec<MeshItem>,
    /// Lines (drawn over meshes at equal depth).
    pub lines: Vec<LineItem>,
    /// Points (drawn last).
    pub points: Vec<PointItem>,
    /// Background, sRGB.
    pub background: [f32; 4],
    /// The camera; `None` fits one to the bounds (see [`Camera::fit`]).
    pub camera: Option<Camera>,
    /// Directions the two lights shine towards, and their intensities.
    pub lights: [([f32; 3], f32); 2],
    /// Ambient light.
    pub ambient: f32,
    /// Draw lines and points in order without depth testing (plane figures, where
    /// overlapping curves would otherwise fight over equal depths).
    pub painter_order: bool,
    /// Which items each object of a composed document made, in order (empty for scenes
    /// made by hand; [`crate::compose`]).
    pub objects: Vec<ObjectItems>,
}

/// The items one object of a composed document made: ranges of [`RenderScene::meshes`],
/// [`RenderScene::lines`] and [`RenderScene::points`].
#[derive(Debug, Clone, Default, PartialEq)]
pub struct ObjectItems {
    /// Its meshes.
    pub meshes: std::ops::Range<usize>,
    /// Its lines (shape, parameter lines, decorations).
    pub lines: std::ops::Range<usize>,
    /// Its points.
    pub points: std::ops::Range<usize>,
    /// Whether it is a plane figure (a curve of at most two dimensions).
    pub flat: bool,
}

impl Default for RenderScene {
    fn default() -> Self {
        RenderScene {
            meshes: Vec::new(),
            lines: Vec::new(),
            points: Vec::new(),
            background: [1.0, 1.0, 1.0, 1.0],
            camera: None,
            lights: [([-0.4, -0.6, -1.0], 0.75), ([0.8, 0.3, 0.2], 0.35)],
            ambient: 0.22,
            painter_order: false,
            objects: Vec::new(),
        }
    }
}

impl RenderScene {
    /// The camera's projection × view matrix (column-major) for a `width` × `height`
    /// image, with the depth range fitted to the scene's bounding sphere, and the eye
    /// position: what the renderer draws with, and what picking projects with.
    pub fn view_projection(&self, width: u32, height: u32) -> ([[f32; 4]; 4], [f32; 3]) {
        self.view_projection_in(self.bounds(), width, height)
    }

    /// [`Self::view_projection`] with the scene's bounds given (those of several layers
    /// drawn together, [`crate::Renderer::draw_layers`]).
    pub fn view_projection_in(
        &self,
        bounds: Option<([f32; 3], [f32; 3])>,
        width: u32,
        height: u32,
    ) -> ([[f32; 4]; 4], [f32; 3]) {
        let aspect = width as f32 / height as f32;
        let bounds = bounds.unwrap_or(([-1.0; 3], [1.0; 3]));
        let camera = self.camera.unwrap_or_else(|| Camera::fit(bounds, 0.9, 0.5, aspect));
        let (lo, hi) = bounds;
        let centre = [(lo[0] + hi[0]) / 2.0, (lo[1] + hi[1]) / 2.0, (lo[2] + hi[2]) / 2.0];
        let eye = camera.eye();
        let distance =
            |p: [f32; 3]| ((eye[0] - p[0]).powi(2) + (eye[1] - p[1]).powi(2) + (eye[2] - p[2]).powi(2)).sqrt();
        let radius = ((hi[0] - lo[0]).powi(2) + (hi[1] - lo[1]).powi(2) + (hi[2] - lo[2]).powi(2)).sqrt() / 2.0;
        let target = match camera {
            Camera::Perspective { target, .. } | Camera::Orthographic { target, .. } => target,
        };
        let depth_radius = radius + (distance(centre) - distance(target)).abs();
        (camera.view_projection(aspect, depth_radius), eye)
    }

    /// The axis-aligned bounds of everything in the scene; `None` when empty.
    pub fn bounds(&self) -> Option<([f32; 3], [f32; 3])> {
        let all = self
            .meshes
            .iter()
            .flat_map(|m| m.positions.iter())
            .chain(self.lines.iter().flat_map(|l| l.points.iter()))
            .chain(self.points.iter().map(|p| &p.position))
            .filter(|p| p.iter().all(|x| x.is_finite()));
        let mut b: Option<([f32; 3], [f32; 3])> = None;
        for p in all {
            b = Some(match b {
                None => (*p, *p),
                Some((lo, hi)) => (
                    [lo[0].min(p[0]), lo[1].min(p[1]), lo[2].min(p[2])],
                    [hi[0].max(p[0]), hi[1].max(p[1]), hi[2].max(p[2])],
                ),
            });
        }
        b
    }
}

/// sRGB → linear for one channel.
pub fn srgb_to_linear(c: f32) -> f32 {
    if c <= 0.04045 { c / 12.92 } else { ((c + 0.055) / 1.055).powf(2.4) }
}

/// An sRGB colour with alpha → linear colour with the same alpha (what the shaders take).
pub fn srgba_to_linear(c: [f32; 4]) -> [f32; 4] {
    [srgb_to_linear(c[0]), srgb_to_linear(c[1]), srgb_to_linear(c[2]), c[3]]
}
