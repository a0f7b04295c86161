//! Curve documents → STEP geometry: a spline's own B-spline form, lines, circles and
//! ellipses as their entities, polynomial blending splines as exact B-splines, anything
//! else a measured B-spline fit (see [`crate::approximate`]); and the helpers the surface
//! exporters share with it (the document's 3-D points, unrolled periodic knots). 2-D
//! documents lie in the plane z = 0.

use splinekit::Point;
use splinekit::basis::Side;
use splinekit::curve::bezier::bezier_knots;
use splinekit::curve::{Curve as KernelCurve, Interval};
use splinekit::query::extent::sampled_curve_box;
use splinekit_scene::bfunctions::BFunctionDoc;
use splinekit_scene::blending::{BlendingSource, BlendingSplineDoc, LocalDoc};
use splinekit_scene::{CurveDocument, CurveForm, SplineView};

use super::exported::{Exported, Form, ParamMap};
use crate::approximate::{hermite_curve, polynomial_curve};
use crate::error::{Result, StepError};
use crate::geometry::{Axes, Curve, Geometry, Item, SplineCurve};

pub(super) fn plain(field: &str, e: impl std::fmt::Display) -> StepError {
    StepError::plain(format!("{field}: {e}"))
}

pub(super) fn p3(p: &[f64]) -> Result<Vec<f64>> {
    match p.len() {
        3 => Ok(p.to_vec()),
        2 => Ok(vec![p[0], p[1], 0.0]),
        d => Err(StepError::plain(format!("control_points: STEP geometry is 2-D or 3-D, got {d} coordinates"))),
    }
}

/// Knots of the unrolled periodic spline: the n + p + 1 given ones and p more,
/// t_{i} = t_{i−n} + T (as the kernel evaluates them).
pub(super) fn unrolled_knots(knots: &[f64], n: usize, p: usize) -> Vec<f64> {
    let period = knots[n + p] - knots[p];
    let mut ext = knots.to_vec();
    for i in n + p + 1..n + 2 * p + 1 {
        let v = ext[i - n] + period;
        ext.push(v);
    }
    ext
}

pub(super) fn spline_curve(
    degree: usize,
    knots: &[f64],
    points: &[Vec<f64>],
    weights: Option<&[f64]>,
    periodic: bool,
) -> Result<SplineCurve> {
    let n = points.len();
    let pts: Vec<Vec<f64>> = points.iter().map(|p| p3(p)).collect::<Result<_>>()?;
    if !periodic {
        return Ok(SplineCurve {
            degree,
            knots: knots.to_vec(),
            points: pts,
            weights: weights.map(<[f64]>::to_vec),
            closed: false,
        });
    }
    let count = n + degree;
    Ok(SplineCurve {
        degree,
        knots: unrolled_knots(knots, n, degree),
        points: (0..count).map(|i| pts[i % n].clone()).collect(),
        weights: weights.map(|w| (0..count).map(|i| w[i % n]).collect()),
        closed: true,
    })
}

/// The polynomial degree of a B-function, if it is a polynomial.
pub(super) fn bfunction_degree(b: &BFunctionDoc) -> Option<usize> {
    match b {
        BFunctionDoc::Linear(_) => Some(1),
        BFunctionDoc::Polynomial(p) => Some(2 * p.smoothness + 1),
        BFunctionDoc::Beta(b) => Some(b.a + b.b + 1),
        _ => None,
    }
}

/// The degree of a local curve document that is a polynomial in its parameter.
pub(super) fn polynomial_local_degree(c: &CurveDocument) -> Option<usize> {
    match c.exact_form().ok()? {
        CurveForm::Spline(v) if v.knots.is_none() && v.weights.is_none() => Some(v.degree),
        CurveForm::Line { .. } => Some(1),
        _ => None,
    }
}

/// The piece degree of a blending spline that is a piecewise polynomial: Bézier (or line)
/// locals of degree d and a polynomial B-function of degree β give degree d + β.
pub(super) fn blending_polynomial_degree(d: &BlendingSplineDoc) -> Option<usize> {
    let beta = bfunction_degree(d.bfunction.as_ref()?)?;
    let local = match d.source().ok()? {
        BlendingSource::Model { local: LocalDoc::Bezier { degree }, .. } => *degree,
        BlendingSource::Hermite { data, .. } => data.first()?.len().checked_sub(1)?,
        BlendingSource::Explicit { local_curves, .. } => {
            local_curves.iter().map(polynomial_local_degree).collect::<Option<Vec<_>>>()?.into_iter().max()?
        }
        _ => return None,
    };
    Some(local + beta)
}

/// A 2-D curve seen in the plane z = 0.
struct Lifted(Box<dyn KernelCurve<2>>);

impl KernelCurve<3> for Lifted {
    fn domain(&self) -> Interval {
        self.0.domain()
    }
    fn is_closed(&self) -> bool {
        self.0.is_closed()
    }
    fn eval_side(&self, t: f64, side: Side, out: &mut [Point<3>]) {
        let mut tmp = vec![Point::<2>::zeros(); out.len()];
        self.0.eval_side(t, side, &mut tmp);
        for (o, p) in out.iter_mut().zip(&tmp) {
            *o = Point::<3>::new(p[0], p[1], 0.0);
        }
    }
    fn breakpoints(&self) -> Vec<f64> {
        self.0.breakpoints()
    }
}

pub(super) fn kernel_curve(doc: &CurveDocument) -> Result<Box<dyn KernelCurve<3>>> {
    match doc.dimension().map_err(|e| plain("document", e))? {
        3 => doc.build_in::<3>().map_err(|e| plain("document", e)),
        2 => Ok(Box::new(Lifted(doc.build_in::<2>().map_err(|e| plain("document", e))?))),
        d => Err(StepError::plain(format!("document: STEP geometry is 2-D or 3-D, got a {d}-D curve"))),
    }
}

/// The size a relative tolerance refers to: the diagonal of the box of 257 regular samples
/// ([`sampled_curve_box`]; the tolerances, so the files, are defined by that sample set).
fn curve_size(c: &dyn KernelCurve<3>) -> f64 {
    sampled_curve_box(c, 256).diagonal().max(f64::MIN_POSITIVE)
}

/// Exports a curve document; `relative_tolerance` scales with the curve's size.
pub fn export_curve(doc: &CurveDocument, name: &str, relative_tolerance: f64) -> Result<Exported> {
    let kernel = kernel_curve(doc)?;
    let tolerance = relative_tolerance * curve_size(kernel.as_ref());
    let domain = (kernel.domain(), Interval::new(0.0, 0.0));
    let exact = |curve: Curve| Exported {
        item: Item { name: name.to_string(), geometry: Geometry::Curve(curve) },
        form: Form::Exact,
        max_deviation: 0.0,
        tolerance,
        map: ParamMap::IDENTITY,
        domain,
    };
    let spline = |view: &SplineView<'_>| {
        let knots = view.knots.as_deref().map_or_else(|| bezier_knots(view.degree), <[f64]>::to_vec);
        let curve = spline_curve(view.degree, &knots, &view.control_points, view.weights.as_deref(), view.periodic)?;
        Ok::<_, StepError>(exact(Curve::Spline(curve)))
    };
    Ok(match doc.exact_form().map_err(|e| plain("document", e))? {
        CurveForm::Spline(view) => spline(&view)?,
        CurveForm::Line { from, to } => {
            let (from, to) = (p3(from)?, p3(to)?);
            // A unit direction, trimmed by length: readers (OpenCASCADE) parametrise lines
            // by arc length whatever the VECTOR's magnitude, so t' = |to − from| t.
            let d: Vec<f64> = (0..3).map(|k| to[k] - from[k]).collect();
            let len = Point::<3>::new(d[0], d[1], d[2]).norm();
            let direction = d.iter().map(|c| c / len).collect();
            let mut e = exact(Curve::Trimmed {
                basis: Box::new(Curve::Line { origin: from, direction }),
                start: 0.0,
                end: len,
            });
            e.map = ParamMap { u: (len, 0.0), v: (1.0, 0.0) };
            e
        }
        CurveForm::Circle { radius } => exact(Curve::Circle { axes: Axes::WORLD, radius }),
        CurveForm::Ellipse { a, b } => exact(Curve::Ellipse { axes: Axes::WORLD, a, b }),
        form @ (CurveForm::BlendingSpline(_) | CurveForm::Approximate) => {
            let (fitted, form) = match form {
                CurveForm::BlendingSpline(b) if blending_polynomial_degree(b).is_some() => {
                    let m = blending_polynomial_degree(b).expect("checked");
                    (
                        polynomial_curve(kernel.as_ref(), &kernel.breakpoints(), m)?,
                        Form::ExactPolynomial { degree: (m, 0) },
                    )
                }
                _ => (hermite_curve(kernel.as_ref(), tolerance)?, Form::Approximated),
            };
            Exported {
                item: Item { name: name.to_string(), geometry: Geometry::Curve(Curve::Spline(fitted.spline)) },
                form,
                max_deviation: fitted.max_deviation,
                tolerance,
                map: ParamMap::IDENTITY,
                domain,
            }
        }
    })
}

pub(super) fn curve_exports_exactly(doc: &CurveDocument) -> bool {
    match doc.exact_form() {
        Err(_) | Ok(CurveForm::Approximate) => false,
        Ok(CurveForm::Spline(_) | CurveForm::Line { .. } | CurveForm::Circle { .. } | CurveForm::Ellipse { .. }) => {
            true
        }
        Ok(CurveForm::BlendingSpline(b)) => blending_polynomial_degree(b).is_some(),
    }
}
