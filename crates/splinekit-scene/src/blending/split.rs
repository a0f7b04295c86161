//! Splitting a knot of a blending-spline document: knot c_k of a `blending_spline` built
//! from a model is doubled and local k copied ([`BlendingSplineCurve::split_knot`], where
//! what the split keeps is stated), so that the two copies can be turned and scaled
//! independently about the joint: a C⁰ corner. This file writes the result back as a
//! document that builds the same curve:
//!
//! - `knots` become explicit with the value c_k twice (indices k and k + 1), the count
//!   grows by one, and `knot_spacing` goes;
//! - `transforms`, `animation` tracks and `local_control_points` past k move up by one;
//!   local k's transform and tracks are copied to k + 1, so the copy is posed as local k
//!   was at every time;
//! - an edited Bézier local k (`local_control_points`) gets its points on each copy's new
//!   support (the same polynomial, [`splinekit::blend::hermite::rebased`]); an unedited
//!   one is fitted to the model again on the new supports: a Taylor polynomial does not
//!   depend on the support, so both copies are the local as it was.
//!
//! - with Hermite data, local k's entry of `hermite` is copied to k + 1.
//!
//! Only splines built from a model or from Hermite data split: explicit local curves are each mapped onto their
//! support, which the split halves.
//!
//! [`BlendingSplineCurve::split_knot`]: splinekit::blend::BlendingSplineCurve::split_knot

use splinekit::curve::Curve;

use super::rebuilt::{local_points, model_built, rebuilt_doc};
use crate::curves::BlendingSplineDoc;
use crate::error::{DocumentError, Result};
use crate::registry::DocumentKind;
use crate::with_dimension;

/// `doc` with knot k split: the knot doubled and local k copied to k + 1. Errors name the
/// field: `k` for a knot that is not interior or is already double, `local_curves` for
/// explicit locals.
///
/// # Examples
///
/// ```
/// use splinekit_scene::blending::{BlendingSplineDoc, split_local_curve};
/// let doc: BlendingSplineDoc = serde_json::from_str(
///     r#"{"model": {"type": "heart"}, "local_curves": 10, "transforms": {"3": {"scale": 1.5}}}"#).unwrap();
/// let after = split_local_curve(&doc, 3).unwrap();
/// let knots = after.knots.clone().unwrap();
/// assert_eq!((knots.len(), knots[3]), (12, knots[4])); // closed: 11 locals, 12 knots
/// assert_eq!(after.transforms.iter().map(|(i, _)| *i).collect::<Vec<_>>(), [3, 4]);
/// assert!(split_local_curve(&after, 3).unwrap_err().to_string().contains("already double"));
/// ```
pub fn split_local_curve(doc: &BlendingSplineDoc, k: usize) -> Result<BlendingSplineDoc> {
    model_built(doc, "a knot is split only in", "which a split halves")?;
    let dim = doc.dimension()?;
    with_dimension!(dim, "model", D => split_in::<D>(doc, k))
}

/// The interior knot of `doc` nearest the parameter `t` that is not already double (for
/// a click on the curve), or an error naming `t` when there is none.
///
/// # Examples
///
/// ```
/// use splinekit_scene::blending::{BlendingSplineDoc, knot_to_split};
/// let doc: BlendingSplineDoc =
///     serde_json::from_str(r#"{"model": {"type": "helix"}, "local_curves": 5, "closed": false}"#).unwrap();
/// // Three turns of the helix, [0, 6π]: knots 3π/2 apart. 0.2 is nearest the end knot 0,
/// // which does not split: the nearest interior knot is knot 1.
/// assert_eq!(knot_to_split(&doc, 0.2).unwrap(), 1);
/// assert_eq!(knot_to_split(&doc, 9.0).unwrap(), 2);
/// ```
pub fn knot_to_split(doc: &BlendingSplineDoc, t: f64) -> Result<usize> {
    model_built(doc, "a knot is split only in", "which a split halves")?;
    let dim = doc.dimension()?;
    with_dimension!(dim, "model", D => nearest_in::<D>(doc, t))
}

fn nearest_in<const D: usize>(doc: &BlendingSplineDoc, t: f64) -> Result<usize> {
    let mut rest = doc.clone();
    rest.time = None;
    let c = rest.curve::<D>()?;
    let knots = c.knots().values();
    let last = if c.is_closed() { c.local_count() - 1 } else { c.local_count() - 2 };
    let single = |k: &usize| knots[k - 1] != knots[*k] && knots[k + 1] != knots[*k];
    let period = c.domain().length();
    // On a closed curve a click near the end of the domain is near knot 0 + P as well.
    let distance = |k: &usize| {
        let d = (knots[*k] - t).abs();
        if c.is_closed() { d.min(period - d).abs() } else { d }
    };
    (1..=last).filter(single).min_by(|a, b| distance(a).total_cmp(&distance(b))).ok_or_else(|| {
        DocumentError::new("t", format!("no interior knot left to split near {t}: every one is already double"))
    })
}

fn split_in<const D: usize>(doc: &BlendingSplineDoc, k: usize) -> Result<BlendingSplineDoc> {
    let (mut out, c, ()) = rebuilt_doc::<D, _>(doc, |c| c.split_knot(k))?;
    let up = |i: usize| if i > k { i + 1 } else { i };
    out.transforms = copied(&doc.transforms, k, up);
    let mut animation = Vec::with_capacity(doc.animation.len());
    for track in &doc.animation {
        let mut moved = track.clone();
        moved.local = up(track.local);
        animation.push(moved);
        if track.local == k {
            let mut copy = track.clone();
            copy.local = k + 1;
            animation.push(copy);
        }
    }
    out.animation = animation;
    if let Some(data) = &mut out.hermite {
        // Both copies interpolate local k's datum (the same Taylor polynomial).
        data.insert(k + 1, data[k].clone());
    }
    out.local_control_points = copied(&doc.local_control_points, k, up);
    for (i, entry) in out.local_control_points.iter_mut().filter(|(i, _)| *i == k || *i == k + 1) {
        if let Some(p) = local_points(&c, *i) {
            *entry = p;
        }
    }
    Ok(out)
}

/// `entries` (by local index) with indices moved by `up` and the entry of local k copied
/// to k + 1 right after it.
fn copied<T: Clone>(entries: &[(usize, T)], k: usize, up: impl Fn(usize) -> usize) -> Vec<(usize, T)> {
    let mut out = Vec::with_capacity(entries.len() + 1);
    for (i, v) in entries {
        out.push((up(*i), v.clone()));
        if *i == k {
            out.push((k + 1, v.clone()));
        }
    }
    out
}
