//! Refinement of spline documents: knot insertion, degree elevation, knot removal. The
//! result is a document of the same curve.

use splinekit::curve::bezier::bezier_knots;
use splinekit::curve::{BSplineCurve, BezierCurve, NurbsCurve, RationalBezierCurve};
use splinekit::surface::BSplineSurface;

use crate::curves::{BSplineDoc, BezierDoc, CurveDocument, NurbsDoc, RationalBezierDoc};
use crate::error::{DocumentError, Result};
use crate::points::{from_points, to_points};
use crate::surfaces::{BSplineSurfaceDoc, SurfaceDocument};
use crate::with_dimension;

/// What to do to the curve.
#[derive(Debug, Clone, PartialEq)]
pub enum Refinement {
    /// Insert each knot once (repeat a value to insert it several times).
    Insert(Vec<f64>),
    /// Raise the degree by this much.
    Elevate(usize),
    /// Remove each knot once where the curve moves by at most `tolerance`.
    Remove {
        /// Knots to remove.
        knots: Vec<f64>,
        /// Largest allowed deviation of the curve.
        tolerance: f64,
    },
}

/// The refined document and, for removal, how many knots could be removed.
#[derive(Debug, Clone, PartialEq)]
pub struct Refined {
    /// The document of the same curve.
    pub document: CurveDocument,
    /// Knots actually removed (removal only).
    pub removed: usize,
}

/// The document of a B-spline curve.
pub fn bspline_doc<const D: usize>(c: &BSplineCurve<D>) -> CurveDocument {
    CurveDocument::Bspline(BSplineDoc {
        degree: c.degree(),
        knots: c.knots().to_vec(),
        control_points: from_points(c.control_points()),
        periodic: c.is_periodic(),
    })
}

/// The document of a B-spline surface.
pub fn bspline_surface_doc(s: &BSplineSurface<3>) -> SurfaceDocument {
    let ((degree_u, degree_v), (ku, kv), (periodic_u, periodic_v)) = (s.degrees(), s.knots(), s.periodic());
    SurfaceDocument::BsplineSurface(BSplineSurfaceDoc {
        degree_u,
        degree_v,
        knots_u: ku.to_vec(),
        knots_v: kv.to_vec(),
        control_points: s.control_points().iter().map(|row| from_points(row)).collect(),
        periodic_u,
        periodic_v,
    })
}

/// The document of a NURBS curve.
pub fn nurbs_doc<const D: usize>(c: &NurbsCurve<D>) -> CurveDocument {
    CurveDocument::Nurbs(NurbsDoc {
        degree: c.degree(),
        knots: c.knots().to_vec(),
        control_points: from_points(c.control_points()),
        weights: c.weights().to_vec(),
        periodic: c.is_periodic(),
    })
}

/// The knot operations B-spline and NURBS curves share.
trait KnotOperations: Sized {
    fn refine(&self, knots: &[f64]) -> splinekit::Result<Self>;
    fn elevate_degree(&self, t: usize) -> splinekit::Result<Self>;
    fn remove_knot(&self, u: f64, times: usize, tolerance: f64) -> splinekit::Result<(Self, usize)>;
}

macro_rules! knot_operations {
    ($ty:ident) => {
        impl<const D: usize> KnotOperations for $ty<D> {
            fn refine(&self, knots: &[f64]) -> splinekit::Result<Self> {
                $ty::refine(self, knots)
            }
            fn elevate_degree(&self, t: usize) -> splinekit::Result<Self> {
                $ty::elevate_degree(self, t)
            }
            fn remove_knot(&self, u: f64, times: usize, tolerance: f64) -> splinekit::Result<(Self, usize)> {
                $ty::remove_knot(self, u, times, tolerance)
            }
        }
    };
}
knot_operations!(BSplineCurve);
knot_operations!(NurbsCurve);

/// Applies the refinement; returns the new curve and the number of knots removed.
fn apply<C: KnotOperations>(c: C, r: &Refinement) -> Result<(C, usize)> {
    Ok(match r {
        Refinement::Insert(k) => (c.refine(k)?, 0),
        Refinement::Elevate(t) => (c.elevate_degree(*t)?, 0),
        Refinement::Remove { knots, tolerance } => {
            let (mut c, mut removed) = (c, 0);
            for &u in knots {
                let (next, n) = c.remove_knot(u, 1, *tolerance)?;
                removed += n;
                c = next;
            }
            (c, removed)
        }
    })
}

fn refine_bspline<const D: usize>(c: BSplineCurve<D>, r: &Refinement) -> Result<Refined> {
    let (out, removed) = apply(c, r)?;
    Ok(Refined { document: bspline_doc(&out), removed })
}

fn refine_nurbs<const D: usize>(c: NurbsCurve<D>, r: &Refinement) -> Result<Refined> {
    let (out, removed) = apply(c, r)?;
    Ok(Refined { document: nurbs_doc(&out), removed })
}

fn check_request(r: &Refinement) -> Result<()> {
    match r {
        Refinement::Insert(k) | Refinement::Remove { knots: k, .. } => {
            if let Some((i, v)) = k.iter().enumerate().find(|(_, v)| !v.is_finite()) {
                return Err(DocumentError::new(format!("knot {i}"), format!("not finite ({v})")));
            }
            if k.len() > 1_000_000 {
                return Err(DocumentError::new(
                    "knots",
                    format!("{} knots at once is more than the limit of 1000000", k.len()),
                ));
            }
        }
        Refinement::Elevate(t) => {
            if *t > 64 {
                return Err(DocumentError::new(
                    "elevate",
                    format!("raising the degree by {t} is more than the limit of 64"),
                ));
            }
        }
    }
    Ok(())
}

/// Refines a `bezier`, `rational_bezier`, `bspline` or `nurbs` document. Bézier curves
/// stay Bézier under elevation and become clamped B-splines (NURBS) under insertion or
/// removal.
pub fn refine(doc: &CurveDocument, r: &Refinement) -> Result<Refined> {
    check_request(r)?;
    let dim = doc.dimension()?;
    with_dimension!(dim, "control_points", D => refine_in::<D>(doc, r))
}

fn refine_in<const D: usize>(doc: &CurveDocument, r: &Refinement) -> Result<Refined> {
    let Some(view) = doc.spline() else {
        return Err(DocumentError::new(
            "type",
            format!("refine works on bezier, rational_bezier, bspline and nurbs documents, not {}", doc.type_name()),
        ));
    };
    match (&view.knots, &view.weights) {
        (Some(knots), None) => refine_bspline(view.bspline::<D>(knots)?, r),
        (Some(knots), Some(weights)) => refine_nurbs(view.nurbs::<D>(knots, weights)?, r),
        (None, None) => {
            let b = BezierCurve::new(to_points::<D>(&view.control_points))?;
            if let Refinement::Elevate(t) = r {
                let mut e = b;
                for _ in 0..*t {
                    e = e.elevate();
                }
                return Ok(Refined {
                    document: CurveDocument::Bezier(BezierDoc { control_points: from_points(e.control_points()) }),
                    removed: 0,
                });
            }
            refine_bspline(BSplineCurve::clamped_uniform(b.degree(), b.control_points().to_vec())?, r)
        }
        (None, Some(weights)) => {
            let b = RationalBezierCurve::new(to_points::<D>(&view.control_points), weights.to_vec())?;
            let p = b.degree();
            let n = NurbsCurve::new(p, bezier_knots(p), b.control_points().to_vec(), b.weights().to_vec())?;
            let out = refine_nurbs(n, r)?;
            match (r, out.document) {
                // A single elevated segment is still one rational Bézier curve.
                (Refinement::Elevate(_), CurveDocument::Nurbs(nd)) => Ok(Refined {
                    document: CurveDocument::RationalBezier(RationalBezierDoc {
                        control_points: nd.control_points,
                        weights: nd.weights,
                    }),
                    removed: 0,
                }),
                (_, document) => Ok(Refined { document, removed: out.removed }),
            }
        }
    }
}
