//! The cost of drawing a scene: its objects meshed as the renderer meshes them, and the
//! images of the frames kept until they are written. Shared by `splinekit render`,
//! `splinekit animate`, `splinekit tessellate` of scenes and Python's `splinekit.render`.

use super::{Budget, Bytes, Cost, regular_mesh};
use crate::error::{DocumentError, Result};
use crate::{SceneDocument, ShapeDocument};

/// Bytes the renderer holds per pixel of an image: 4× multisampled colour and depth,
/// the resolved image, its read-back copy and the image kept.
pub const RENDER_BYTES_PER_PIXEL: f64 = 4.0 * 4.0 + 4.0 * 4.0 + 4.0 + 4.0 + 4.0;
/// Work of one pixel of a software render (rasterising four samples, resolving, reading
/// back, encoding): 128 operations. One image of the largest size, [`MAX_IMAGE_SIDE`]² =
/// 6.7·10⁷ pixels, is then 8.6·10⁹ operations — within the default work budget
/// ([`super::DEFAULT_MAX_WORK`], 10¹⁰) with room for a scene's meshes, so the documented
/// largest image renders without raising a limit (a test pins this agreement).
pub const RENDER_WORK_PER_PIXEL: f64 = 128.0;
/// The largest image side the renderer draws (`splinekit_render::renderer::MAX_SIDE`,
/// `render --size`, Python's `size`); a square image of this side fits
/// [`MAX_RENDER_BUFFER`] exactly (a row of 8192 · 4 bytes is a multiple of 256).
pub const MAX_IMAGE_SIDE: u32 = 8192;
/// The largest buffer the renderer's device accepts (wgpu's default limit, 256 MiB): the
/// read-back of one image must fit it.
pub const MAX_RENDER_BUFFER: f64 = 256.0 * 1024.0 * 1024.0;
/// Points of a curve drawn adaptively (no `density` in its style) at most.
pub const MAX_DRAWN_CURVE_POINTS: f64 = 200_000.0;

/// Which argument to blame for each part of a render request, as the caller spells it
/// (`--size` on the command line, `size` in Python).
#[derive(Debug, Clone, Copy)]
pub struct RenderFields<'a> {
    /// The image size.
    pub size: &'a str,
    /// The number of frames (`--frames`, `animation`).
    pub frames: &'a str,
}

impl Budget {
    /// The cost of composing one frame of `scene` (every object's document checked on its
    /// own first, named `objects[i].shape.…`): surfaces as meshes of their style's density
    /// (default 64), curves as polylines of their density (default: adaptive, up to
    /// [`MAX_DRAWN_CURVE_POINTS`] points).
    pub fn scene_frame(&self, scene: &SceneDocument) -> Result<Cost> {
        let mut total = Cost::ZERO;
        for (i, object) in scene.objects.iter().enumerate() {
            let cost = object.shape.cost();
            self.check_shape(&cost).map_err(|e| e.within(&format!("objects[{i}].shape")))?;
            let drawn = match &object.shape {
                ShapeDocument::Surface(_) => regular_mesh(object.style.density.unwrap_or(64), cost.eval),
                ShapeDocument::Curve(_) => {
                    let points = object.style.density.map_or(MAX_DRAWN_CURVE_POINTS, |n| n as f64 + 1.0);
                    Cost::new(points * 64.0, points * (3.0 * cost.eval + 100.0))
                }
            };
            total = total + cost.build + drawn;
        }
        Ok(total)
    }

    /// Refuses `frames` renders of `scene` at `size` (width, height) that would not fit
    /// this budget or the renderer's buffers, naming `objects` (the scene's meshes and
    /// polylines too large), `fields.size` (the image too large) or `fields.frames` (too
    /// many frames). Every rendered frame is kept until the file is written (GIF frames:
    /// one byte a pixel after quantisation, counted at four).
    pub fn check_render(
        &self,
        scene: &SceneDocument,
        size: (u32, u32),
        frames: usize,
        fields: RenderFields<'_>,
    ) -> Result<()> {
        let pixels = size.0 as f64 * size.1 as f64;
        let row = (size.0 as f64 * 4.0 / 256.0).ceil() * 256.0;
        if row * size.1 as f64 > MAX_RENDER_BUFFER {
            return Err(DocumentError::budget(
                fields.size,
                format!(
                    "a {}x{} image needs a read-back buffer of {}, more than the renderer's limit of {} (at most {MAX_IMAGE_SIDE}x{MAX_IMAGE_SIDE} pixels)",
                    size.0,
                    size.1,
                    Bytes(row * size.1 as f64),
                    Bytes(MAX_RENDER_BUFFER)
                ),
            ));
        }
        let frame = self.scene_frame(scene)?;
        let drawing = format!("drawing {} objects", scene.objects.len());
        self.check("objects", &drawing, frame)?;
        let image = Cost::new(pixels * RENDER_BYTES_PER_PIXEL, pixels * RENDER_WORK_PER_PIXEL);
        let rendering = format!("rendering {}x{}", size.0, size.1);
        self.check(fields.size, &rendering, image)?;
        // Each fits alone: the larger part of the two is the one to blame.
        let one = image + frame;
        let share = |c: Cost| (c.bytes / self.max_bytes).max(c.work / self.max_work);
        let blamed = if share(frame) > share(image) { "objects" } else { fields.size };
        self.check(blamed, &format!("{drawing}, {rendering}"), one)?;
        let n = frames as f64;
        let all = Cost::new(one.bytes + n * pixels * 4.0, n * one.work);
        self.check(fields.frames, &format!("{frames} frames of {}x{}", size.0, size.1), all)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn scene(text: &str) -> SceneDocument {
        crate::SceneOrShape::from_json(text).unwrap().into_scene()
    }

    const FIELDS: RenderFields<'static> = RenderFields { size: "size", frames: "frames" };

    #[test]
    fn an_image_past_the_read_back_limit_names_the_size() {
        let s = scene(r#"{"type":"circle","radius":1}"#);
        let e = Budget::machine().check_render(&s, (9000, 9000), 1, FIELDS).unwrap_err();
        assert_eq!(e.path, "size");
        assert!(e.message.contains("9000x9000") && e.message.contains("268.4 MB"), "{e}");
        assert!(Budget::machine().check_render(&s, (800, 600), 1, FIELDS).is_ok());
    }

    /// The limits agree: the largest image the renderer draws, MAX_IMAGE_SIDE², fits the
    /// read-back buffer and the default work budget (docs/format.md, README: Limits), with
    /// any memory that holds its 3 GB; one pixel more each way does not fit the buffer.
    #[test]
    fn the_largest_documented_image_fits_the_default_budget() {
        let s = scene(r#"{"type":"sphere","radius":1}"#);
        let budget = Budget { max_bytes: 4e9, max_work: crate::budget::DEFAULT_MAX_WORK };
        let side = MAX_IMAGE_SIDE;
        budget.check_render(&s, (side, side), 1, FIELDS).unwrap();
        let e = budget.check_render(&s, (side + 1, side + 1), 1, FIELDS).unwrap_err();
        assert!(e.message.contains("read-back buffer"), "{e}");
    }

    #[test]
    fn a_dense_object_is_blamed_on_the_objects_and_many_frames_on_the_frames() {
        let budget = Budget { max_bytes: 1e9, max_work: 1e10 };
        let dense = scene(r#"{"type":"scene","objects":[{"shape":{"type":"sphere","radius":1},"density":2048}]}"#);
        let e = budget.check_render(&dense, (800, 600), 1, FIELDS).unwrap_err();
        assert_eq!(e.path, "objects", "{e}");
        let light = scene(r#"{"type":"sphere","radius":1}"#);
        assert!(budget.check_render(&light, (800, 600), 1, FIELDS).is_ok());
        let e = budget.check_render(&light, (800, 600), 100_000, FIELDS).unwrap_err();
        assert_eq!(e.path, "frames", "{e}");
    }
}
