//! What knot insertion and knot splitting share on a `blending_spline` document: both
//! refuse explicit local curves, edit the kernel curve at rest and write the edited curve's
//! knots back ([`rebuilt_doc`]); the callers then move the per-local fields.

use splinekit::blend::BlendingSplineCurve;

use crate::curves::{BlendingSource, BlendingSplineDoc, LocalCurves};
use crate::error::{DocumentError, Result};

/// Refuses explicit local curves (an error at `local_curves`): each is mapped onto its
/// support, which an edit of the knots changes. The message reads `"{edit} a blending spline
/// built from a model (explicit local curves are mapped onto their supports, {why})"`.
pub(super) fn model_built(doc: &BlendingSplineDoc, edit: &str, why: &str) -> Result<()> {
    if let BlendingSource::Explicit { .. } = doc.source()? {
        return Err(DocumentError::new(
            "local_curves",
            format!(
                "{edit} a blending spline built from a model (explicit local curves are mapped onto their supports, \
                 {why})"
            ),
        ));
    }
    Ok(())
}

/// `doc` after `edit` of its curve in dimension D, built at rest (the animation not
/// posed): a copy whose `knots` are the edited curve's, explicit (`knot_spacing` goes),
/// with its count of locals; returned with the edited curve and what `edit` gave, for the
/// caller to move the per-local fields (`transforms`, `animation`, `local_control_points`).
pub(super) fn rebuilt_doc<const D: usize, R>(
    doc: &BlendingSplineDoc,
    edit: impl FnOnce(&mut BlendingSplineCurve<D>) -> splinekit::Result<R>,
) -> Result<(BlendingSplineDoc, BlendingSplineCurve<D>, R)> {
    let mut rest = doc.clone();
    rest.time = None;
    let mut c = rest.curve::<D>()?;
    let edited = edit(&mut c)?;
    let mut out = doc.clone();
    out.knots = Some(c.knots().values().to_vec());
    out.knot_spacing = None;
    if out.hermite.is_none() {
        out.local_curves = Some(LocalCurves::Count(c.local_count()));
    }
    Ok((out, c, edited))
}

/// The control points of local i of `c`, as a document's `local_control_points` entry
/// holds them; `None` unless local i is a Bézier curve.
pub(super) fn local_points<const D: usize>(c: &BlendingSplineCurve<D>, i: usize) -> Option<Vec<Vec<f64>>> {
    Some(c.local_bezier_points(i)?.iter().map(|p| p.iter().copied().collect()).collect())
}
