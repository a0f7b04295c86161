//! Budgets: what a request will cost, estimated from the document and the options before
//! any work starts, and the limits it must stay within.
//!
//! A [`Cost`] counts bytes of memory and units of work (one unit ≈ one floating-point
//! operation; this machine does about 10⁹ of them a second on the paths measured). Every
//! document kind estimates its own [`ShapeCost`] (see
//! [`DocumentKind::cost`](crate::registry::DocumentKind::cost)): the memory and work of
//! building its kernel object and the work of evaluating one point, from its counts,
//! degrees and nesting. Commands add what their options ask for (samples, grids, steps)
//! and check the sum against a [`Budget`] before they allocate: a request over the budget
//! is refused at once with one line naming the flag or field, the estimate and the limit.
//!
//! The estimates are in `f64` so that products of huge counts cannot wrap around: an
//! overflowing estimate is infinite and over every limit.

use std::fmt;

use crate::error::{DocumentError, Result};

mod render;

pub use render::{
    MAX_DRAWN_CURVE_POINTS, MAX_IMAGE_SIDE, MAX_RENDER_BUFFER, RENDER_BYTES_PER_PIXEL, RENDER_WORK_PER_PIXEL,
    RenderFields,
};

/// Memory in bytes and work in operations.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Cost {
    /// Bytes of memory held at the peak.
    pub bytes: f64,
    /// Operations (≈ floating-point operations).
    pub work: f64,
}

impl Cost {
    /// Nothing.
    pub const ZERO: Cost = Cost { bytes: 0.0, work: 0.0 };

    /// A cost of `bytes` and `work`.
    pub fn new(bytes: f64, work: f64) -> Self {
        Cost { bytes, work }
    }

    /// `count` copies of this cost (memory and work both scale).
    pub fn times(self, count: f64) -> Self {
        Cost { bytes: self.bytes * count, work: self.work * count }
    }
}

impl std::ops::Add for Cost {
    type Output = Cost;
    fn add(self, other: Cost) -> Cost {
        Cost { bytes: self.bytes + other.bytes, work: self.work + other.work }
    }
}

/// Bytes of one stored coordinate or knot.
pub const F64: f64 = 8.0;

/// Operations of one evaluation of a model curve or surface given by a formula (a few
/// dozen trigonometric calls with their derivatives).
pub const MODEL_EVALUATION: f64 = 100.0;

/// Operations of one evaluation of a B-function with a few derivatives.
pub const BFUNCTION_EVALUATION: f64 = 100.0;

/// Bytes of one local piece's frame and bookkeeping in a blending spline.
pub const LOCAL_PIECE: f64 = 256.0;

/// Largest magnitude of a coordinate, knot, weight or model parameter in a document:
/// about the square root of the largest double (1.8·10³⁰⁸), so that squared distances,
/// normal equations and products of two coordinates cannot overflow.
pub const MAX_MAGNITUDE: f64 = 1e150;

/// Highest degree of Bézier, B-spline and NURBS curves and surfaces (per direction) that
/// documents may ask for. De Casteljau's and Cox–de Boor's algorithms cost O(p²) per point;
/// at p = 1024 that is about a million operations per point, and polynomials of such degree
/// carry no information that a B-spline of lower degree with more knots would not.
pub const MAX_DEGREE: usize = 1024;

/// Deepest nesting of documents inside documents (blends of blends, blending splines of
/// blending splines, …). Each level adds at least one evaluation of the level below.
pub const MAX_NESTING: usize = 64;

/// The cost of a shape document: building its kernel object, and evaluating one point.
#[derive(Debug, Clone, PartialEq)]
pub struct ShapeCost {
    /// Memory and work of building the kernel object from the document.
    pub build: Cost,
    /// Operations of one evaluation of the point at one parameter (derivatives of order k
    /// cost about k + 1 times this).
    pub eval: f64,
    /// Levels of documents nested inside this one (0 for a document with no sub-documents).
    pub depth: usize,
    /// The field that makes most of the cost (`control_points`, `model.local_curves`), for
    /// messages.
    pub field: String,
}

impl ShapeCost {
    /// A shape of `bytes` and `build` work whose points cost `eval`, its cost driven by
    /// `field`.
    pub fn new(field: &str, bytes: f64, build: f64, eval: f64) -> Self {
        ShapeCost { build: Cost::new(bytes, build), eval, depth: 0, field: field.to_string() }
    }

    /// A model curve or surface given by a formula: nothing to store, a fixed cost per point.
    pub fn model() -> Self {
        ShapeCost::new("type", 64.0, 0.0, MODEL_EVALUATION)
    }

    /// The same cost seen from the parent field `prefix` (one more level of nesting).
    pub fn within(mut self, prefix: &str) -> Self {
        self.field = DocumentError::new(std::mem::take(&mut self.field), "").within(prefix).path;
        self.depth += 1;
        self
    }

    /// Both costs together (a document made of two others); the field is the costlier one's.
    pub fn and(self, other: ShapeCost) -> Self {
        let weight = |c: &ShapeCost| c.build.bytes + c.build.work + c.eval;
        let field = if weight(&other) > weight(&self) { other.field } else { self.field };
        ShapeCost {
            build: self.build + other.build,
            eval: self.eval + other.eval,
            depth: self.depth.max(other.depth),
            field,
        }
    }

    /// Work of evaluating `points` parameters with derivatives up to order `order`.
    pub fn evaluations(&self, points: f64, order: usize) -> f64 {
        points * self.eval * (order as f64 + 1.0)
    }
}

/// A B-spline of `degree` p with n control points of `coordinates` numbers each (one more
/// for NURBS): the points and n + p + 1 knots stored, and per point a span search and
/// Cox–de Boor's (p + 1)² basis operations plus the (p + 1)·D combination.
/// Degrees above [`MAX_DEGREE`] are counted as MAX_DEGREE + 1: such documents are refused
/// by [`check_degree`] when built, with a message about their degree.
pub fn spline_cost(degree: usize, n: usize, coordinates: usize) -> ShapeCost {
    let (p, n, d) = (degree.min(MAX_DEGREE + 1) as f64, n as f64, coordinates as f64);
    let stored = n * d + n + p + 1.0;
    let eval = (p + 1.0) * (p + 1.0) + (p + 1.0) * d + (n + p).max(2.0).log2();
    ShapeCost::new(if p > n { "degree" } else { "control_points" }, stored * F64, stored, eval)
}

/// Checks a degree against [`MAX_DEGREE`], naming `field`.
pub fn check_degree(field: &str, degree: usize) -> Result<()> {
    if degree > MAX_DEGREE {
        return Err(DocumentError::new(
            field,
            format!("degree {degree} is more than the limit of {MAX_DEGREE} (see Limits in docs/format.md)"),
        ));
    }
    Ok(())
}

/// Bytes of one vertex of a triangle mesh held for output: position, normal and (u, v)
/// in f64, their f32 copies, and the samples they came from.
pub const MESH_VERTEX_BYTES: f64 = 160.0;
/// Bytes of one vertex written as text (OBJ/PLY lines) or binary (STL, glTF).
pub const MESH_VERTEX_OUTPUT_BYTES: f64 = 120.0;
/// Work of one mesh vertex besides evaluating the surface: normals, welding, writing.
pub const MESH_VERTEX_WORK: f64 = 400.0;
/// Bytes of one cell of an adaptive quad-tree: its leaf, its cached samples and the
/// vertex and two triangles it becomes.
pub const ADAPTIVE_CELL_BYTES: f64 = 600.0;

/// A regular mesh of n × n cells of a shape whose points cost `eval`: (n + 1)² vertices
/// (each a point and its partials), held and written.
pub fn regular_mesh(n: usize, eval: f64) -> Cost {
    let vertices = (n as f64 + 1.0).powi(2);
    Cost::new(vertices * (MESH_VERTEX_BYTES + MESH_VERTEX_OUTPUT_BYTES), vertices * (4.0 * eval + MESH_VERTEX_WORK))
}

/// A polyline of `points` points of a curve whose points cost `eval`: each point, its
/// derivatives for the adaptive refinement, and its copy for output.
pub fn polyline(points: f64, eval: f64) -> Cost {
    Cost::new(points * 160.0, points * (4.0 * eval + 300.0))
}

/// The most an offset of a curve may ask for: at most
/// [`MAX_TOTAL_PIECES`](splinekit::query::offset::hermite_fit::MAX_TOTAL_PIECES) pieces of
/// 8 samples (each a point and two derivatives) over all the approximations of the offset,
/// all of them held at the most; `eval` is one evaluation of the curve.
pub fn offset_curve(eval: f64) -> Cost {
    let pieces = splinekit::query::offset::hermite_fit::MAX_TOTAL_PIECES as f64;
    Cost::new(pieces * 200.0, pieces * 8.0 * 3.0 * eval)
}

/// The most an offset of a surface may ask for: the last grid of
/// [`MAX_GRID_POINTS`](splinekit::query::offset::surface_offset::MAX_GRID_POINTS) and those
/// before it (a third more), at its nodes and midpoints, each a point and a normal (up to
/// nine evaluations at a singular point); `eval` is one evaluation of the surface.
pub fn offset_surface(eval: f64) -> Cost {
    let samples = 4.0 * 1.34 * splinekit::query::offset::surface_offset::MAX_GRID_POINTS as f64;
    Cost::new(samples * 200.0, samples * 12.0 * eval)
}

/// A least-squares fit of `points` data points of `dimension` coordinates by a B-spline of
/// `degree` p with `control_points` n (the kernel's banded QR, `splinekit::fit`): the
/// data, its parameters, sort order and fitted values held (≈ 2D + 3 numbers a point)
/// and the band of R with its right-hand sides (2p + 2 + D numbers a control point); per
/// point the basis ((p + 1)²) and the Givens rotations of its p + 1 entries across a row
/// of R and its right-hand sides (3 (p + 1)(p + 1 + D)).
pub fn least_squares_fit(points: f64, control_points: f64, degree: usize, dimension: usize) -> Cost {
    let (p, d) = (degree.min(MAX_DEGREE + 1) as f64, dimension as f64);
    let bytes = points * (2.0 * d + 3.0) * F64 + control_points * (2.0 * p + 2.0 + d) * F64;
    let per_point = (p + 1.0) * (p + 1.0) + 3.0 * (p + 1.0) * (p + 1.0 + d);
    Cost::new(bytes, points * per_point)
}

/// The limits a request must stay within.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Budget {
    /// Most bytes of memory.
    pub max_bytes: f64,
    /// Most operations.
    pub max_work: f64,
}

/// The environment variable that sets the memory limit (bytes, or with a suffix K, M, G, T).
pub const MEMORY_VARIABLE: &str = "SPLINEKIT_MAX_MEMORY";
/// The environment variable that sets the work limit (operations, e.g. `2e10`).
pub const WORK_VARIABLE: &str = "SPLINEKIT_MAX_WORK";
/// Default work limit: about ten seconds of computing on this machine.
pub const DEFAULT_MAX_WORK: f64 = 1e10;
/// Share of the physical memory a request may use by default.
pub const DEFAULT_MEMORY_SHARE: f64 = 0.5;

impl Budget {
    /// The default budget: half of the physical memory, [`DEFAULT_MAX_WORK`] operations.
    pub fn machine() -> Self {
        Budget { max_bytes: physical_memory() * DEFAULT_MEMORY_SHARE, max_work: DEFAULT_MAX_WORK }
    }

    /// The budget set by the flags `--max-memory` and `--max-work` (given as text), else by
    /// the environment variables [`MEMORY_VARIABLE`] and [`WORK_VARIABLE`], else
    /// [`Budget::machine`].
    pub fn from_options(max_memory: Option<&str>, max_work: Option<&str>) -> Result<Self> {
        let mut budget = Budget::machine();
        let memory = match max_memory {
            Some(text) => Some(("--max-memory", text.to_string())),
            None => std::env::var(MEMORY_VARIABLE).ok().map(|v| (MEMORY_VARIABLE, v)),
        };
        if let Some((name, text)) = memory {
            budget.max_bytes = parse_amount(name, &text, true)?;
        }
        let work = match max_work {
            Some(text) => Some(("--max-work", text.to_string())),
            None => std::env::var(WORK_VARIABLE).ok().map(|v| (WORK_VARIABLE, v)),
        };
        if let Some((name, text)) = work {
            budget.max_work = parse_amount(name, &text, false)?;
        }
        Ok(budget)
    }

    /// Refuses `cost` if it is over the budget, in a message that names `field` and says
    /// what the cost is `for` (e.g. "10⁹ samples").
    pub fn check(&self, field: &str, what: &str, cost: Cost) -> Result<()> {
        if cost.bytes.is_nan() || cost.bytes > self.max_bytes {
            return Err(DocumentError::budget(
                field,
                format!(
                    "{what} would need about {} of memory, more than the limit of {} (raise it with --max-memory or {MEMORY_VARIABLE})",
                    Bytes(cost.bytes),
                    Bytes(self.max_bytes)
                ),
            ));
        }
        if cost.work.is_nan() || cost.work > self.max_work {
            return Err(DocumentError::budget(
                field,
                format!(
                    "{what} would need about {:.1e} operations, more than the limit of {:.1e} (raise it with --max-work or {WORK_VARIABLE})",
                    cost.work, self.max_work
                ),
            ));
        }
        Ok(())
    }

    /// The most cells an adaptive mesh of a shape (built at `shape`) may have within this
    /// budget: its memory and its work (about five samples of the surface per cell).
    pub fn adaptive_cells(&self, shape: &ShapeCost) -> usize {
        let by_memory = (self.max_bytes - shape.build.bytes) / ADAPTIVE_CELL_BYTES;
        let by_work = (self.max_work - shape.build.work) / (5.0 * 4.0 * shape.eval + MESH_VERTEX_WORK);
        by_memory.min(by_work).max(1.0) as usize
    }

    /// Refuses a document whose own cost (building it, and a first evaluation) is over the
    /// budget or nests deeper than [`MAX_NESTING`], naming the field that drives the cost.
    pub fn check_shape(&self, cost: &ShapeCost) -> Result<()> {
        if cost.depth > MAX_NESTING {
            return Err(DocumentError::budget(
                cost.field.as_str(),
                format!("documents nested {} deep, more than the limit of {MAX_NESTING}", cost.depth),
            ));
        }
        self.check(
            &cost.field,
            "building this document and evaluating one point",
            cost.build + Cost::new(0.0, cost.eval),
        )
    }
}

/// Bytes written for people: `1.5 GB`.
#[derive(Debug, Clone, Copy)]
pub struct Bytes(pub f64);

impl fmt::Display for Bytes {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let b = self.0;
        if !b.is_finite() {
            return write!(f, "more than any machine has");
        }
        let units = [("TB", 1e12), ("GB", 1e9), ("MB", 1e6), ("kB", 1e3)];
        for (unit, size) in units {
            if b >= size {
                return write!(f, "{:.1} {unit}", b / size);
            }
        }
        write!(f, "{b:.0} bytes")
    }
}

/// Parses a limit: a positive number, for memory with an optional suffix K, M, G or T
/// (powers of 1024) or KB, MB, GB, TB (powers of 1000).
fn parse_amount(name: &str, text: &str, memory: bool) -> Result<f64> {
    let t = text.trim();
    let (number, scale) = if memory {
        let upper = t.to_ascii_uppercase();
        let suffixes = [
            ("KB", 1e3),
            ("MB", 1e6),
            ("GB", 1e9),
            ("TB", 1e12),
            ("K", 1024.0),
            ("M", 1024.0 * 1024.0),
            ("G", 1024.0 * 1024.0 * 1024.0),
            ("T", 1024.0f64.powi(4)),
            ("B", 1.0),
        ];
        match suffixes.iter().find(|(s, _)| upper.ends_with(s)) {
            Some((s, scale)) => (&t[..t.len() - s.len()], *scale),
            None => (t, 1.0),
        }
    } else {
        (t, 1.0)
    };
    let value: f64 = number.trim().parse().map_err(|_| {
        DocumentError::new(
            name,
            if memory {
                format!("expected bytes like 4G, 512M or 2e9, got '{text}'")
            } else {
                format!("expected a number of operations like 2e10, got '{text}'")
            },
        )
    })?;
    let amount = value * scale;
    if !(amount.is_finite() && amount > 0.0) {
        return Err(DocumentError::new(name, format!("must be positive and finite, got '{text}'")));
    }
    Ok(amount)
}

/// Physical memory in bytes (`MemTotal` of /proc/meminfo; 4 GiB where it cannot be read).
pub fn physical_memory() -> f64 {
    const FALLBACK: f64 = 4.0 * 1024.0 * 1024.0 * 1024.0;
    std::fs::read_to_string("/proc/meminfo")
        .ok()
        .and_then(|text| {
            let line = text.lines().find(|l| l.starts_with("MemTotal:"))?;
            let kib: f64 = line.split_whitespace().nth(1)?.parse().ok()?;
            Some(kib * 1024.0)
        })
        .unwrap_or(FALLBACK)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn amounts_parse_with_suffixes() {
        assert_eq!(parse_amount("m", "512M", true).unwrap(), 512.0 * 1024.0 * 1024.0);
        assert_eq!(parse_amount("m", "2GB", true).unwrap(), 2e9);
        assert_eq!(parse_amount("m", "1e6", true).unwrap(), 1e6);
        assert_eq!(parse_amount("w", "2e10", false).unwrap(), 2e10);
        assert!(parse_amount("m", "-1G", true).is_err());
        assert!(parse_amount("w", "lots", false).unwrap_err().to_string().starts_with("w: expected"));
        assert!(parse_amount("w", "inf", false).is_err());
    }

    #[test]
    fn over_budget_names_the_field_and_both_numbers() {
        let budget = Budget { max_bytes: 1e9, max_work: 1e10 };
        let e = budget.check("--samples", "10⁹ samples", Cost::new(8.8e11, 1.0)).unwrap_err();
        assert_eq!(e.path, "--samples");
        assert!(e.message.contains("880.0 GB") && e.message.contains("1.0 GB"), "{e}");
        let e = budget.check("--grid", "a grid", Cost::new(1.0, 2e10)).unwrap_err();
        assert!(e.message.contains("2.0e10") && e.message.contains("1.0e10"), "{e}");
        assert!(budget.check("x", "y", Cost::new(1e9, 1e10)).is_ok());
        assert!(budget.check("x", "y", Cost::new(f64::INFINITY, 0.0)).is_err());
        assert!(budget.check("x", "y", Cost::new(f64::NAN, 0.0)).is_err());
    }

    #[test]
    fn nested_costs_name_the_inner_field_and_count_levels() {
        let inner = ShapeCost::new("control_points", 100.0, 10.0, 5.0).within("model");
        let outer = ShapeCost::new("local_curves", 10.0, 1.0, 1.0).and(inner).within("first");
        assert_eq!(outer.field, "first.model.control_points");
        assert_eq!(outer.depth, 2);
        assert_eq!(outer.build, Cost::new(110.0, 11.0));
        let deep = (0..=MAX_NESTING).fold(ShapeCost::model(), |c, _| c.within("model"));
        assert!(Budget::machine().check_shape(&deep).unwrap_err().message.contains("nested"));
    }
}
