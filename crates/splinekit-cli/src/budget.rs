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

/// The cost of composing one frame of a scene (see [`Budget::scene_frame`]).
pub fn scene_frame(scene: &splinekit_scene::SceneDocument) -> Result<Cost> {
    Ok(current().scene_frame(scene)?)
}

/// Refuses `frames` renders of a scene at `size` that would not fit the budget or the
/// renderer's buffers (see [`Budget::check_render`]), naming `objects`, `--size` or
/// `flag` (too many frames).
pub fn check_render(scene: &splinekit_scene::SceneDocument, size: (u32, u32), frames: usize, flag: &str) -> Result<()> {
    let fields = splinekit_scene::budget::RenderFields { size: "--size", frames: flag };
    Ok(current().check_render(scene, size, frames, fields)?)
}
