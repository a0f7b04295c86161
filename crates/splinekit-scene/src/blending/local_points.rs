//! `local_control_points` of blending splines with Bézier locals: edited control points of
//! some local curves (patches), overriding the Hermite-fitted ones, in the local's rest
//! frame (the model's coordinates, before the local's `transforms` entry is applied).
//!
//! Curves: `{"k": [[x, y, …], …]}`, d + 1 points for local k of degree d. Surfaces:
//! `{"k,l": [[[x, y, z], …], …]}`, d_u + 1 rows of d_v + 1 points for patch (k, l) (the
//! first index along u, as in every net). Read from and written as an object keyed by the
//! local's index; the entries are applied before the transforms and the animation.

use serde::Deserializer;
use serde_json::Value;
use splinekit::Point;

use crate::error::{DocumentError, Result};
use crate::json::{kind, nested};
use crate::keyed;

/// Edited control points of a blending-spline curve's Bézier locals, by local index.
pub type LocalControlPoints = Vec<(usize, Vec<Vec<f64>>)>;

/// Edited control nets of a blending-spline surface's Bézier patches, by (k, l).
pub type PatchControlPoints = Vec<((usize, usize), Vec<Vec<Vec<f64>>>)>;

/// The field's name in documents and messages.
pub const FIELD: &str = "local_control_points";

fn object(value: Value, what: &str) -> Result<Option<serde_json::Map<String, Value>>> {
    match value {
        Value::Null => Ok(None),
        Value::Object(map) => Ok(Some(map)),
        other => Err(DocumentError::new("", format!("expected an object keyed by {what}, got {}", kind(&other)))),
    }
}

/// `with` module for curves' `local_control_points`: an object keyed by local index.
pub mod by_index {
    use super::*;

    pub(crate) use crate::keyed::serialize;

    /// Reads `local_control_points`.
    pub fn deserialize<'de, D: Deserializer<'de>>(d: D) -> std::result::Result<LocalControlPoints, D::Error> {
        nested(d, |value| {
            let Some(map) = object(value, "local-curve index")? else { return Ok(Vec::new()) };
            keyed::entries(map, "keys must be local-curve indices (\"3\")")
        })
    }
}

/// `with` module for surfaces' `local_control_points`: an object keyed by `"k,l"`.
pub mod by_pair {
    use super::*;

    pub(crate) use crate::keyed::serialize;

    /// Reads `local_control_points`.
    pub fn deserialize<'de, D: Deserializer<'de>>(d: D) -> std::result::Result<PatchControlPoints, D::Error> {
        nested(d, |value| {
            let Some(map) = object(value, "patch index \"k,l\"")? else { return Ok(Vec::new()) };
            keyed::entries(map, "keys must be patch indices \"k,l\"")
        })
    }
}

/// The d + 1 points of local k's entry as points of dimension D (field `local_control_points.k`).
pub fn curve_points<const D: usize>(k: usize, points: &[Vec<f64>], degree: usize) -> Result<Vec<Point<D>>> {
    let field = format!("{FIELD}.{k}");
    if points.len() != degree + 1 {
        return Err(DocumentError::new(
            field,
            format!(
                "expected {} control points for a Bézier local of degree {degree}, got {}",
                degree + 1,
                points.len()
            ),
        ));
    }
    points.iter().enumerate().map(|(i, p)| crate::points::to_point::<D>(&format!("{field}[{i}]"), p)).collect()
}

/// The (d_u + 1) × (d_v + 1) net of patch (k, l)'s entry, row-major (field
/// `local_control_points.k,l`).
pub fn patch_net<const D: usize>(
    (k, l): (usize, usize),
    net: &[Vec<Vec<f64>>],
    (du, dv): (usize, usize),
) -> Result<Vec<Point<D>>> {
    let field = format!("{FIELD}.{k},{l}");
    if net.len() != du + 1 {
        return Err(DocumentError::new(
            field,
            format!("expected {} rows (d_u + 1 for degrees [{du}, {dv}]), got {}", du + 1, net.len()),
        ));
    }
    let mut out = Vec::with_capacity((du + 1) * (dv + 1));
    for (a, row) in net.iter().enumerate() {
        if row.len() != dv + 1 {
            return Err(DocumentError::new(
                format!("{field}[{a}]"),
                format!("expected {} points (d_v + 1 for degrees [{du}, {dv}]), got {}", dv + 1, row.len()),
            ));
        }
        for (b, p) in row.iter().enumerate() {
            out.push(crate::points::to_point::<D>(&format!("{field}[{a}][{b}]"), p)?);
        }
    }
    Ok(out)
}

/// The error for `local_control_points` on locals that are not Bézier curves (patches).
pub fn not_bezier(what: &str) -> DocumentError {
    DocumentError::new(
        FIELD,
        format!("only for Bézier locals made from a model (\"local\": {{\"type\": \"bezier\"}}), not {what}"),
    )
}
