//! Knot edits of B-spline, NURBS and Bézier curves from the window, each one undoable edit
//! of the object's whole `shape` made by the library's refinement
//! ([`splinekit_scene::refine`]): insert a knot where the user clicks on the curve (Boehm:
//! the curve does not change), remove the knot nearest the click where the curve moves by
//! at most a tolerance, raise the degree by one.
//!
//! The clicked parameter is that of the curve sample whose projection is nearest the
//! cursor (within twice the pick radius), among [`SAMPLES`] samples spread over the domain.

use splinekit::curve::Curve;
use splinekit_scene::refine::{Refinement, refine};
use splinekit_scene::{CurveDocument, Curves, DimensionVisitor, ShapeDocument};

use crate::edit::Edit;
use crate::error::StudioError;
use crate::view_caches::PICK_RADIUS;
use crate::view_camera::Projector;

/// Samples of a curve searched for the clicked parameter.
pub const SAMPLES: usize = 2000;

/// What the next click on the selected curve does.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum KnotTool {
    /// Insert a knot at the clicked parameter.
    Insert,
    /// Remove the knot nearest the clicked parameter (within the tolerance).
    Remove,
    /// Insert a local curve (on a blending surface, a row or column of local patches) at
    /// the clicked parameter of a blending spline ([`crate::local_insert`]).
    InsertLocal,
    /// Split the knot of a blending-spline curve nearest the clicked parameter
    /// ([`crate::knot_split`]).
    SplitKnot,
}

/// The curve document of object `object`'s shape, when it is one `refine` works on: one
/// whose kind declares a spline view.
fn refinable(shape: &ShapeDocument) -> Result<&CurveDocument, StudioError> {
    match shape {
        ShapeDocument::Curve(c) if c.spline().is_some() => Ok(c),
        ShapeDocument::Curve(c) => {
            let hint = if matches!(c.decoration(), splinekit_scene::Decoration::LocalCurves(_)) {
                " (on a blending spline, Insert local piece: L)"
            } else {
                ""
            };
            Err(StudioError::refused(format!(
                "knot edits work on bezier, rational_bezier, bspline and nurbs curves, not {}{hint}",
                c.type_name()
            )))
        }
        ShapeDocument::Surface(_) => Err("knot edits from the window work on curves".into()),
    }
}

/// `n` + 1 samples (t, world point; z = 0 for plane curves) spread over the curve's domain.
pub fn curve_samples(shape: &ShapeDocument, n: usize) -> Result<Vec<(f64, [f64; 3])>, StudioError> {
    struct Samples(usize);
    impl DimensionVisitor<Curves> for Samples {
        type Output = Vec<(f64, [f64; 3])>;
        fn visit<const D: usize>(self, c: &dyn Curve<D>) -> Self::Output {
            let domain = c.domain();
            (0..=self.0)
                .map(|i| {
                    let t = domain.lerp(i as f64 / self.0 as f64);
                    let p = c.point(t);
                    (t, [0, 1, 2].map(|k| if k < D { p[k] } else { 0.0 }))
                })
                .collect()
        }
    }
    match shape {
        ShapeDocument::Curve(c) => Ok(c.build()?.visit(Samples(n))),
        ShapeDocument::Surface(_) => Err("not a curve".into()),
    }
}

/// The parameter of the sample nearest `mouse` on screen, within twice the pick radius.
pub fn parameter_at(samples: &[(f64, [f64; 3])], projector: &Projector, mouse: [f64; 2]) -> Option<f64> {
    samples
        .iter()
        .filter_map(|&(t, p)| {
            let (s, _) = projector.project(p)?;
            Some((t, (s[0] - mouse[0]).hypot(s[1] - mouse[1])))
        })
        .filter(|&(_, d)| d <= 2.0 * PICK_RADIUS)
        .min_by(|a, b| a.1.total_cmp(&b.1))
        .map(|(t, _)| t)
}

fn whole_shape(object: usize, doc: &CurveDocument) -> Edit {
    Edit::Set { object, pointer: "/shape".into(), value: Some(doc.to_value()) }
}

/// The edit inserting knot `u` into object `object`'s curve.
pub fn insert(shape: &ShapeDocument, object: usize, u: f64) -> Result<Edit, StudioError> {
    let doc = refinable(shape)?;
    let out = refine(doc, &Refinement::Insert(vec![u]))?;
    Ok(whole_shape(object, &out.document))
}

/// The edit raising the degree of object `object`'s curve by one.
pub fn elevate(shape: &ShapeDocument, object: usize) -> Result<Edit, StudioError> {
    let doc = refinable(shape)?;
    let out = refine(doc, &Refinement::Elevate(1))?;
    Ok(whole_shape(object, &out.document))
}

/// The interior knots of a B-spline or NURBS curve document (those strictly inside the
/// first and last knot).
fn interior_knots(doc: &CurveDocument) -> Vec<f64> {
    let knots: Vec<f64> = match doc {
        CurveDocument::Bspline(d) => d.knots.clone(),
        CurveDocument::Nurbs(d) => d.knots.clone(),
        _ => Vec::new(),
    };
    match (knots.first(), knots.last()) {
        (Some(&a), Some(&b)) => knots.iter().copied().filter(|&k| k > a && k < b).collect(),
        _ => Vec::new(),
    }
}

/// The edit removing the interior knot nearest `u` from object `object`'s curve, where
/// the curve moves by at most `tolerance`; an error says when there is none or it cannot go.
pub fn remove(shape: &ShapeDocument, object: usize, u: f64, tolerance: f64) -> Result<Edit, StudioError> {
    let doc = refinable(shape)?;
    let knot = interior_knots(doc)
        .into_iter()
        .min_by(|a, b| (a - u).abs().total_cmp(&(b - u).abs()))
        .ok_or(StudioError::refused("remove knot: the curve has no interior knot"))?;
    let out = refine(doc, &Refinement::Remove { knots: vec![knot], tolerance })?;
    if out.removed == 0 {
        return Err(StudioError::refused(format!(
            "remove knot: knot {knot} cannot go without moving the curve by more than {tolerance}"
        )));
    }
    Ok(whole_shape(object, &out.document))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn quad() -> ShapeDocument {
        let v = serde_json::json!({"type": "bspline", "degree": 2, "knots": [0, 0, 0, 1, 2, 2, 2],
            "control_points": [[0, 0], [1, 2], [3, -1], [4, 1]]});
        ShapeDocument::from_value(v).expect("valid")
    }

    fn shape_of(edit: &Edit) -> ShapeDocument {
        let Edit::Set { value: Some(v), .. } = edit else { panic!("a set") };
        ShapeDocument::from_value(v.clone()).expect("valid")
    }

    fn same_curve(a: &ShapeDocument, b: &ShapeDocument, tol: f64) {
        let (sa, sb) = (curve_samples(a, 200).expect("a"), curve_samples(b, 200).expect("b"));
        for ((ta, pa), (tb, pb)) in sa.iter().zip(&sb) {
            assert_eq!(ta, tb);
            assert!((0..3).all(|k| (pa[k] - pb[k]).abs() <= tol), "{pa:?} vs {pb:?} at {ta}");
        }
    }

    #[test]
    fn inserting_keeps_the_curve_and_removing_takes_the_knot_back_out() {
        let before = quad();
        let inserted = shape_of(&insert(&before, 0, 0.5).expect("inserts"));
        same_curve(&before, &inserted, 1e-12);
        let value = |s: &ShapeDocument| match s {
            ShapeDocument::Curve(c) => c.to_value(),
            ShapeDocument::Surface(s) => s.to_value(),
        };
        let knots = |s: &ShapeDocument| value(s)["knots"].as_array().map(Vec::len);
        assert_eq!(knots(&inserted), Some(8));
        let removed = shape_of(&remove(&inserted, 0, 0.4, 1e-9).expect("removes"));
        assert_eq!(knots(&removed), Some(7));
        same_curve(&before, &removed, 1e-9);
        // Knot 1 of the original cannot go within 10⁻⁹: refused with the reason.
        let e = remove(&before, 0, 1.0, 1e-9).expect_err("not removable").to_string();
        assert!(e.contains("cannot go"), "{e}");
        let elevated = shape_of(&elevate(&before, 0).expect("elevates"));
        assert_eq!(value(&elevated)["degree"], serde_json::json!(3));
        same_curve(&before, &elevated, 1e-9);
    }
}
