//! Knot edits of blending-spline documents that change their topology but not their shape:
//! splitting a surface's knot line along the other direction
//! ([`BlendingSplineSurface::split_knot_line`], GMlib's `splitKnotAlong`) and turning a
//! curve open or closed ([`BlendingSplineCurve::set_closed`], GMlib's `toggleClose`). The
//! kernel edits the spline at rest; this file writes the result back as a document:
//!
//! - knots become explicit (`knots`, `knots_u`/`knots_v`), counts follow (`local_curves`,
//!   `local_surfaces`, or the entries of `hermite`), and a curve's `knot_spacing` goes;
//! - a copied piece (the split row or column; local 0 copied to the end when a curve is
//!   opened) gets the `transforms` entry, `animation` tracks, Hermite datum and edited
//!   control points of the piece it copies, the points re-expressed on the copy's support;
//! - a dropped piece (the last local when a closed curve's ends meet) takes its entries
//!   with it; indices past a copy move up by one.
//!
//! Explicit local curves refuse both (each is mapped onto its support, which they change).
//! A model-built curve is closed by dropping its last local in any case: a document's
//! knots span the model's domain, so the bridging interval the kernel adds where the ends
//! do not meet has no place in it; the closed spline then blends the last-but-one local
//! into local 0 as every model-built spline with `"closed": true` does.
//!
//! [`BlendingSplineSurface::split_knot_line`]: splinekit::blend::BlendingSplineSurface::split_knot_line
//! [`BlendingSplineCurve::set_closed`]: splinekit::blend::BlendingSplineCurve::set_closed

use splinekit::curve::Curve;
use splinekit::surface::Direction;

use super::rebuilt::{local_points, model_built, rebuilt_doc};
use crate::curves::{BlendingSource, BlendingSplineDoc, LocalCurves};
use crate::error::Result;
use crate::registry::DocumentKind;
use crate::surfaces::BlendingSplineSurfaceDoc;
use crate::with_dimension;

/// `doc` with the knot line `direction` = knot k split (u-knot for [`Direction::U`]: row
/// (k, ·) doubled; v-knot: column (·, k)). Errors name `k` for an end knot of an open
/// direction or a knot already double.
///
/// # Examples
///
/// ```
/// use splinekit::surface::Direction;
/// use splinekit_scene::blending::{BlendingSplineSurfaceDoc, split_knot_line};
/// let doc: BlendingSplineSurfaceDoc = serde_json::from_str(
///     r#"{"model": {"type": "torus"}, "local_surfaces": [6, 4], "transforms": {"2,1": {"scale": 1.2}}}"#).unwrap();
/// let after = split_knot_line(&doc, Direction::U, 2).unwrap();
/// assert_eq!(after.local_surfaces, Some([7, 4]));
/// let knots = after.knots_u.clone().unwrap();
/// assert_eq!(knots[2], knots[3]);
/// assert_eq!(after.transforms.iter().map(|(i, _)| *i).collect::<Vec<_>>(), [(2, 1), (3, 1)]);
/// ```
pub fn split_knot_line(
    doc: &BlendingSplineSurfaceDoc,
    direction: Direction,
    k: usize,
) -> Result<BlendingSplineSurfaceDoc> {
    let dim = doc.dimension()?;
    with_dimension!(dim, "model", D => split_line_in::<D>(doc, direction, k))
}

fn split_line_in<const D: usize>(
    doc: &BlendingSplineSurfaceDoc,
    direction: Direction,
    k: usize,
) -> Result<BlendingSplineSurfaceDoc> {
    let mut rest = doc.clone();
    rest.time = None;
    let mut s = rest.surface::<D>()?;
    s.split_knot_line(direction, k)?;
    let along_u = direction == Direction::U;
    let mut out = doc.clone();
    let (nu, nv) = s.local_count();
    if along_u {
        out.knots_u = Some(s.knots().0.values().to_vec());
    } else {
        out.knots_v = Some(s.knots().1.values().to_vec());
    }
    if let Some(data) = &mut out.hermite {
        if along_u {
            data.insert(k + 1, data[k].clone());
        } else {
            data.iter_mut().for_each(|row| row.insert(k + 1, row[k].clone()));
        }
    } else {
        out.local_surfaces = Some([nu, nv]);
    }
    // The index along the split direction, and the same index moved to j.
    let at = |(a, b): (usize, usize)| if along_u { a } else { b };
    let moved = |(a, b): (usize, usize), j: usize| if along_u { (j, b) } else { (a, j) };
    let up = |i: (usize, usize)| if at(i) > k { moved(i, at(i) + 1) } else { i };
    out.transforms = copied(&doc.transforms, |i| at(*i) == k, |i| up(*i), |i| moved(*i, k + 1));
    out.animation = Vec::with_capacity(doc.animation.len());
    for track in &doc.animation {
        let mut t = track.clone();
        t.local = up(track.local);
        out.animation.push(t);
        if at(track.local) == k {
            let mut copy = track.clone();
            copy.local = moved(track.local, k + 1);
            out.animation.push(copy);
        }
    }
    out.local_control_points = copied(&doc.local_control_points, |i| at(*i) == k, |i| up(*i), |i| moved(*i, k + 1));
    for (i, net) in out.local_control_points.iter_mut().filter(|(i, _)| at(*i) == k || at(*i) == k + 1) {
        if let Some((points, (_, dv))) = s.bezier_rest_net(i.0, i.1) {
            *net = points.chunks(dv + 1).map(crate::points::from_points).collect();
        }
    }
    Ok(out)
}

/// `doc` turned open (`closed` false) or closed, keeping its locals where it can (see the
/// module documentation and [`BlendingSplineCurve::set_closed`]); a document already so
/// comes back as it is (with `closed` written). Errors name `local_curves` for explicit
/// locals and `closed` when a closed curve would have fewer than three locals.
///
/// [`BlendingSplineCurve::set_closed`]: splinekit::blend::BlendingSplineCurve::set_closed
///
/// # Examples
///
/// ```
/// use splinekit_scene::blending::{BlendingSplineDoc, LocalCurves, set_closed};
/// let doc: BlendingSplineDoc =
///     serde_json::from_str(r#"{"model": {"type": "circle"}, "local_curves": 8, "transforms": {"0": {"scale": 2}}}"#).unwrap();
/// let open = set_closed(&doc, false).unwrap();
/// assert_eq!((open.closed, open.local_curves.clone()), (Some(false), Some(LocalCurves::Count(9))));
/// assert_eq!(open.transforms.iter().map(|(i, _)| *i).collect::<Vec<_>>(), [0, 8]);
/// let again = set_closed(&open, true).unwrap();
/// assert_eq!(again.local_curves, Some(LocalCurves::Count(8)));
/// ```
pub fn set_closed(doc: &BlendingSplineDoc, closed: bool) -> Result<BlendingSplineDoc> {
    model_built(doc, "open or closed is set only for", "which opening or closing changes")?;
    let dim = doc.dimension()?;
    with_dimension!(dim, "model", D => closed_in::<D>(doc, closed))
}

fn closed_in<const D: usize>(doc: &BlendingSplineDoc, closed: bool) -> Result<BlendingSplineDoc> {
    let mut rest = doc.clone();
    rest.time = None;
    let before = rest.curve::<D>()?;
    let n = before.local_count();
    if before.is_closed() == closed {
        let mut out = doc.clone();
        out.closed = Some(closed);
        return Ok(out);
    }
    let model = matches!(doc.source()?, BlendingSource::Model { .. });
    if closed && model {
        // A model-built spline closes by dropping its last local (its knots span the model).
        if n - 1 < 3 {
            return Err(splinekit::Error::invalid(
                "closed",
                format!("a closed blending spline needs at least 3 local curves, this one would have {}", n - 1),
            )
            .into());
        }
        let mut out = doc.clone();
        out.closed = Some(true);
        out.knots = Some(before.knots().values().to_vec());
        out.knot_spacing = None;
        out.local_curves = Some(LocalCurves::Count(n - 1));
        drop_last(&mut out, n - 1);
        return Ok(out);
    }
    let (mut out, c, ()) = rebuilt_doc::<D, _>(doc, |c| c.set_closed(closed))?;
    out.closed = Some(closed);
    let m = c.local_count();
    if m > n {
        // Opened: local n is local 0 one period on.
        if let Some(data) = &mut out.hermite {
            data.push(data[0].clone());
        }
        let copy = |i: &usize| *i == 0;
        out.transforms = copied(&doc.transforms, copy, |i| *i, |_| n);
        out.transforms.sort_by_key(|(i, _)| *i);
        let tracks: Vec<_> = doc.animation.iter().filter(|t| t.local == 0).cloned().collect();
        out.animation.extend(tracks.into_iter().map(|mut t| {
            t.local = n;
            t
        }));
        out.local_control_points = copied(&doc.local_control_points, copy, |i| *i, |_| n);
        out.local_control_points.sort_by_key(|(i, _)| *i);
        for (i, points) in out.local_control_points.iter_mut().filter(|(i, _)| *i == 0 || *i == n) {
            if let Some(p) = local_points(&c, *i) {
                *points = p;
            }
        }
    } else if m < n {
        // Closed where the ends meet: the last local, local 0 one period on, goes.
        drop_last(&mut out, m);
    }
    // (m == n: closed with a bridging interval; every local and entry stays.)
    Ok(out)
}

/// Removes the per-local entries of local `last` (the dropped last local).
fn drop_last(out: &mut BlendingSplineDoc, last: usize) {
    out.transforms.retain(|(i, _)| *i != last);
    out.animation.retain(|t| t.local != last);
    out.local_control_points.retain(|(i, _)| *i != last);
    if let Some(data) = &mut out.hermite {
        data.truncate(last);
    }
}

/// `entries` with each index mapped by `up`, and after each entry that `copy` picks a copy
/// of it at index `to`.
fn copied<K: Copy, T: Clone>(
    entries: &[(K, T)],
    copy: impl Fn(&K) -> bool,
    up: impl Fn(&K) -> K,
    to: impl Fn(&K) -> K,
) -> Vec<(K, T)> {
    let mut out = Vec::with_capacity(entries.len() + 1);
    for (i, v) in entries {
        out.push((up(i), v.clone()));
        if copy(i) {
            out.push((to(i), v.clone()));
        }
    }
    out
}
