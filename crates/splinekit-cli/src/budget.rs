//! The budget of one command: the limits set by `--max-memory` and `--max-work` (or
//! `SPLINEKIT_MAX_MEMORY`, `SPLINEKIT_MAX_WORK`, or half the physical memory and about ten
//! seconds of work), and the checks every command makes before it allocates: the size of
//! its input, the cost of the document it built (see [`splinekit_scene::budget`]) and the
//! cost of what its options ask for.

use std::sync::OnceLock;

use anyhow::Result;
use splinekit_scene::budget::{Budget, Bytes, Cost, ShapeCost};

static BUDGET: OnceLock<Budget> = OnceLock::new();

/// Sets the budget of this run (once, from the command line).
pub fn set(budget: Budget) {
    let _ = BUDGET.set(budget);
}

/// The budget of this run.
pub fn current() -> Budget {
    *BUDGET.get_or_init(Budget::machine)
}

/// Bytes of memory that parsing takes per byte of JSON text at its peak: the text, the
/// JSON value tree and the document (measured: about 10 on a 128 MB list of 2-D points).
pub const PARSE_BYTES_PER_INPUT_BYTE: f64 = 12.0;

/// Work of parsing one byte of JSON text.
pub const PARSE_WORK_PER_INPUT_BYTE: f64 = 30.0;

/// Work of formatting one number of output (shortest round-trip digits).
pub const FORMAT_WORK_PER_NUMBER: f64 = 60.0;

/// The most bytes of input text `field` may have so that parsing it stays in the budget.
pub fn max_input_bytes() -> f64 {
    current().max_bytes / PARSE_BYTES_PER_INPUT_BYTE
}

/// Refuses input text of `len` bytes whose parsing would not fit the budget.
pub fn check_input(field: &str, len: f64) -> Result<()> {
    let cost = Cost::new(len * PARSE_BYTES_PER_INPUT_BYTE, len * PARSE_WORK_PER_INPUT_BYTE);
    Ok(current().check(field, &format!("{} of JSON", Bytes(len)), cost)?)
}

/// The error for input text that grew past [`max_input_bytes`] while being read.
pub fn input_too_large(field: &str) -> anyhow::Error {
    anyhow::anyhow!(
        "{field}: more than {} of JSON, the most that parsing can hold within the memory limit of {} (raise it with --max-memory or {})",
        Bytes(max_input_bytes()),
        Bytes(current().max_bytes),
        splinekit_scene::budget::MEMORY_VARIABLE
    )
}

/// Refuses a document whose building (and one evaluation) would not fit the budget.
pub fn check_shape(cost: &ShapeCost) -> Result<()> {
    Ok(current().check_shape(cost)?)
}

/// Refuses a request (the document's building `shape` plus `request`) that would not fit
/// the budget, naming `field` (the flag that asks for the most) and saying `what` it asks.
pub fn check_request(field: &str, what: &str, shape: &ShapeCost, request: Cost) -> Result<()> {
    Ok(current().check(field, what, shape.build + request)?)
}

/// The cost of writing `numbers` numbers of output held in memory as `f64`s.
pub fn output(numbers: f64) -> Cost {
    Cost::new(numbers * 8.0, numbers * FORMAT_WORK_PER_NUMBER)
}

pub use splinekit_scene::budget::regular_mesh;

/// The most cells an adaptive mesh of a shape (built at `shape`) may have within the
/// budget of this run (see [`Budget::adaptive_cells`]).
pub fn adaptive_cells(shape: &ShapeCost) -> usize {
    current().adaptive_cells(shape)
}

/// The cost of composing one frame of a scene (every object's document checked on its
/// own first, named `objects[i].shape.…`): surfaces as meshes of their style's density
/// (default 64), curves as polylines of their density (default: adaptive, up to 200 000
/// points).
pub fn scene_frame(scene: &splinekit_scene::SceneDocument) -> Result<Cost> {
    let mut total = Cost::ZERO;
    for (i, object) in scene.objects.iter().enumerate() {
        let cost = object.shape.cost();
        current().check_shape(&cost).map_err(|e| e.within(&format!("objects[{i}].shape")))?;
        let drawn = match &object.shape {
            splinekit_scene::ShapeDocument::Surface(_) => regular_mesh(object.style.density.unwrap_or(64), cost.eval),
            splinekit_scene::ShapeDocument::Curve(_) => {
                let points = object.style.density.map_or(200_000.0, |n| n as f64 + 1.0);
                Cost::new(points * 64.0, points * (3.0 * cost.eval + 100.0))
            }
        };
        total = total + cost.build + drawn;
    }
    Ok(total)
}

/// Bytes the renderer holds per pixel of an image: 4× multisampled colour and depth,
/// the resolved image, its read-back copy and the image kept.
pub const RENDER_BYTES_PER_PIXEL: f64 = 4.0 * 4.0 + 4.0 * 4.0 + 4.0 + 4.0 + 4.0;
/// Work of one pixel of a software render (rasterising, resolving, encoding).
pub const RENDER_WORK_PER_PIXEL: f64 = 200.0;
/// The largest buffer the renderer's device accepts (wgpu's default limit, 256 MiB): the
/// read-back of one image must fit it.
pub const MAX_RENDER_BUFFER: f64 = 256.0 * 1024.0 * 1024.0;

/// Refuses `frames` renders of a scene at `size` that would not fit the budget or the
/// renderer's buffers, naming `objects` (the scene's meshes and polylines too large),
/// `--size` (the image too large) or `flag` (too many frames);
/// every rendered frame is kept until the file is written (GIF frames: one byte a pixel
/// after quantisation, counted at four).
pub fn check_render(scene: &splinekit_scene::SceneDocument, size: (u32, u32), frames: usize, flag: &str) -> Result<()> {
    let pixels = size.0 as f64 * size.1 as f64;
    let row = (size.0 as f64 * 4.0 / 256.0).ceil() * 256.0;
    if row * size.1 as f64 > MAX_RENDER_BUFFER {
        anyhow::bail!(
            "--size: a {}x{} image needs a read-back buffer of {}, more than the renderer's limit of {} (at most about 8000x8000 pixels)",
            size.0,
            size.1,
            Bytes(row * size.1 as f64),
            Bytes(MAX_RENDER_BUFFER)
        );
    }
    let frame = scene_frame(scene)?;
    let drawing = format!("drawing {} objects", scene.objects.len());
    current().check("objects", &drawing, frame)?;
    let image = Cost::new(pixels * RENDER_BYTES_PER_PIXEL, pixels * RENDER_WORK_PER_PIXEL);
    let rendering = format!("rendering {}x{}", size.0, size.1);
    current().check("--size", &rendering, image)?;
    // Each fits alone: the larger part of the two is the one to blame.
    let one = image + frame;
    let b = current();
    let share = |c: Cost| (c.bytes / b.max_bytes).max(c.work / b.max_work);
    let blamed = if share(frame) > share(image) { "objects" } else { "--size" };
    b.check(blamed, &format!("{drawing}, {rendering}"), one)?;
    let n = frames as f64;
    let all = Cost::new(one.bytes + n * pixels * 4.0, n * one.work);
    Ok(current().check(flag, &format!("{frames} frames of {}x{}", size.0, size.1), all)?)
}
