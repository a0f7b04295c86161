//! Inserting a local piece into a blending-spline document: a local curve at a new knot t*
//! of a `blending_spline`, a row (column) of local patches at a new u-knot (v-knot) of a
//! `blending_spline_surface`. The kernel inserts ([`BlendingSplineCurve::insert_local`],
//! [`BlendingSplineSurface::insert_knot_line`], where the method and what it keeps are
//! stated); this file writes the result back as a document that builds the same shape:
//!
//! - `knots` (`knots_u`/`knots_v`) become explicit, the count grows by one, and a curve's
//!   `knot_spacing` goes (the knots say where the locals are);
//! - `transforms`, `animation` tracks and `local_control_points` keep their pieces: indices
//!   at or past the new one move up by one;
//! - with Bézier locals, the new piece's control points (fitted to the shape as it is) are
//!   written to `local_control_points`, and so are the edited neighbours' points, now on
//!   their shrunk supports (the same polynomials, [`splinekit::blend::hermite::rebased`]).
//!   Unedited neighbours are fitted to the model again on their new supports: a Taylor
//!   polynomial does not depend on the support, so they are the same curves.
//!
//! - with Hermite data (`hermite`), the new local's entry is the curve's value and first
//!   d derivatives at t* (the data its Bézier interpolates), inserted at its index.
//!
//! Only splines built from a model or from Hermite data take insertions: explicit local curves are each mapped
//! onto their support, so shrinking a support would stretch the neighbour.
//!
//! [`BlendingSplineCurve::insert_local`]: splinekit::blend::BlendingSplineCurve::insert_local
//! [`BlendingSplineSurface::insert_knot_line`]: splinekit::blend::BlendingSplineSurface::insert_knot_line

use splinekit::curve::Curve;
use splinekit::surface::{Direction, Surface};

use super::rebuilt::{local_points, model_built, rebuilt_doc};
use crate::curves::BlendingSplineDoc;
use crate::error::Result;
use crate::registry::DocumentKind;
use crate::surfaces::{BlendingSplineSurfaceDoc, LocalPatchDoc};
use crate::with_dimension;

/// `doc` with a local curve inserted at the new knot `t` (strictly inside a knot interval
/// of the domain), and the new local's index. Errors name the field: `t` off the domain or
/// on a knot, `local_curves` for explicit locals.
///
/// # Examples
///
/// ```
/// use splinekit_scene::blending::{BlendingSplineDoc, insert_local_curve};
/// let doc: BlendingSplineDoc = serde_json::from_str(
///     r#"{"model": {"type": "heart"}, "local_curves": 10, "local": {"type": "bezier", "degree": 3}}"#).unwrap();
/// let (after, k) = insert_local_curve(&doc, 1.0).unwrap();
/// assert_eq!(k, 2);
/// assert_eq!(after.knots.as_ref().map(Vec::len), Some(12)); // closed: 11 locals, 12 knots
/// assert_eq!(after.local_control_points[0].0, 2); // the new local's points
/// ```
pub fn insert_local_curve(doc: &BlendingSplineDoc, t: f64) -> Result<(BlendingSplineDoc, usize)> {
    model_built(doc, "a local curve is inserted only into", "and an insertion would stretch its neighbours")?;
    let dim = doc.dimension()?;
    with_dimension!(dim, "model", D => curve_in::<D>(doc, t))
}

fn curve_in<const D: usize>(doc: &BlendingSplineDoc, t: f64) -> Result<(BlendingSplineDoc, usize)> {
    let (mut out, c, k) = rebuilt_doc::<D, _>(doc, |c| c.insert_local(t))?;
    let up = |i: usize| if i >= k { i + 1 } else { i };
    out.transforms.iter_mut().for_each(|(i, _)| *i = up(*i));
    out.animation.iter_mut().for_each(|track| track.local = up(track.local));
    for (i, entry) in out.local_control_points.iter_mut() {
        *i = up(*i);
        if let Some(p) = local_points(&c, *i) {
            *entry = p;
        }
    }
    if let Some(data) = &mut out.hermite {
        // Hermite data: the new local's datum is the curve's value and first d derivatives
        // at t* before the insertion, which is what the kernel's new local interpolates.
        let mut values = vec![splinekit::Point::<D>::zeros(); data.first().map_or(2, Vec::len)];
        let mut rest = doc.clone();
        rest.time = None;
        rest.curve::<D>()?.eval(t, &mut values);
        data.insert(k, crate::points::from_points(&values));
    } else if let Some(p) = local_points(&c, k) {
        let at = out.local_control_points.iter().position(|(i, _)| *i > k).unwrap_or(out.local_control_points.len());
        out.local_control_points.insert(at, (k, p));
    }
    Ok((out, k))
}

/// `doc` with the knot line `direction` = `t` inserted (a u-knot for [`Direction::U`]: a
/// row of patches (k, ·); a v-knot: a column (·, k)), and the new row's (column's) index.
/// Errors name `u` or `v` for a parameter off the domain or on a knot.
///
/// # Examples
///
/// ```
/// use splinekit::surface::Direction;
/// use splinekit_scene::blending::{BlendingSplineSurfaceDoc, insert_knot_line};
/// let doc: BlendingSplineSurfaceDoc =
///     serde_json::from_str(r#"{"model": {"type": "torus"}, "local_surfaces": [6, 4]}"#).unwrap();
/// let (after, k) = insert_knot_line(&doc, Direction::V, 1.0).unwrap();
/// assert_eq!((k, after.local_surfaces), (1, Some([6, 5])));
/// assert_eq!(after.knots_v.as_ref().map(Vec::len), Some(6));
/// assert!(after.knots_u.is_none(), "u stays uniform");
/// assert_eq!(after.local_control_points.len(), 6, "one fitted net per new patch");
/// ```
pub fn insert_knot_line(
    doc: &BlendingSplineSurfaceDoc,
    direction: Direction,
    t: f64,
) -> Result<(BlendingSplineSurfaceDoc, usize)> {
    let dim = doc.dimension()?;
    with_dimension!(dim, "model", D => surface_in::<D>(doc, direction, t))
}

fn surface_in<const D: usize>(
    doc: &BlendingSplineSurfaceDoc,
    direction: Direction,
    t: f64,
) -> Result<(BlendingSplineSurfaceDoc, usize)> {
    let mut rest = doc.clone();
    rest.time = None;
    let mut s = rest.surface::<D>()?;
    let k = s.insert_knot_line(direction, t)?;
    let mut out = doc.clone();
    let along_u = direction == Direction::U;
    let (nu, nv) = s.local_count();
    if out.hermite.is_none() {
        out.local_surfaces = Some([nu, nv]);
    }
    if along_u {
        out.knots_u = Some(s.knots().0.values().to_vec());
    } else {
        out.knots_v = Some(s.knots().1.values().to_vec());
    }
    let up = |(a, b): (usize, usize)| match along_u {
        true if a >= k => (a + 1, b),
        false if b >= k => (a, b + 1),
        _ => (a, b),
    };
    out.transforms.iter_mut().for_each(|(i, _)| *i = up(*i));
    out.animation.iter_mut().for_each(|track| track.local = up(track.local));
    let net = |(a, b): (usize, usize)| -> Option<Vec<Vec<Vec<f64>>>> {
        let (net, (_, dv)) = s.bezier_rest_net(a, b)?;
        Some(net.chunks(dv + 1).map(|row| row.iter().map(|p| p.iter().copied().collect()).collect()).collect())
    };
    for (i, entry) in out.local_control_points.iter_mut() {
        *i = up(*i);
        if let Some(n) = net(*i) {
            *entry = n;
        }
    }
    if let Some(data) = &mut out.hermite {
        // Hermite data: the new patches' entries are the surface's partials at the new knot
        // pairs, which is what the kernel's new patches interpolate.
        let (Some(first), (ku, kv)) = (data.first().and_then(|r| r.first()), s.knots()) else {
            return Ok((out, k));
        };
        let (du, dv) = (first.len() - 1, first.first().map_or(1, Vec::len) - 1);
        // The partials were taken before the insertion: those of the surface as it was,
        // which the kernel's new patches interpolate (`rest` is that surface).
        let before = rest.surface::<D>()?;
        let entry = |u: f64, v: f64| {
            let mut g = vec![splinekit::Point::<D>::zeros(); (du + 1) * (dv + 1)];
            before.eval_partials(u, v, du, dv, &mut g);
            g.chunks(dv + 1).map(crate::points::from_points).collect::<Vec<_>>()
        };
        if along_u {
            let row = (0..nv).map(|l| entry(ku.centre(k), kv.centre(l))).collect();
            data.insert(k, row);
        } else {
            for (a, row) in data.iter_mut().enumerate() {
                row.insert(k, entry(ku.centre(a), kv.centre(k)));
            }
        }
    } else if matches!(doc.local, None | Some(LocalPatchDoc::Bezier { .. })) {
        let others = if along_u { nv } else { nu };
        for l in 0..others {
            let at = if along_u { (k, l) } else { (l, k) };
            if let Some(n) = net(at) {
                let lcp = &mut out.local_control_points;
                let place = lcp.iter().position(|(i, _)| *i > at).unwrap_or(lcp.len());
                lcp.insert(place, (at, n));
            }
        }
    }
    Ok((out, k))
}
