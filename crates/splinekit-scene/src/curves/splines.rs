//! Documents of curves given by points: Bézier, rational Bézier, B-spline, NURBS,
//! Hermite, Catmull–Rom and the line segment, in any dimension 1 … 4.

use serde::{Deserialize, Serialize};
use splinekit::curve::model::Line;
use splinekit::curve::{
    BSplineCurve, BezierCurve, CatmullRomCurve, Curve, HermiteCurve, NurbsCurve, RationalBezierCurve,
};

use super::{CurveDecoration, CurveForm, Curves};
use crate::budget::{ShapeCost, check_degree, spline_cost};
use crate::defaults::is_false;
use crate::error::{DocumentError, Result};
use crate::points::{check_finite_list, dimension_of, to_point, to_points};
use crate::registry::{DocumentKind, approximated_kind_items, spline_kind_items};
use crate::views::SplineView;

/// `{"type":"bezier","control_points":[[x,y],...]}`
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct BezierDoc {
    /// Control points P_0 … P_n.
    pub control_points: Vec<Vec<f64>>,
}

impl DocumentKind for BezierDoc {
    type Family = Curves;
    fn spline(&self) -> Option<SplineView<'_>> {
        Some(SplineView::bezier(&self.control_points, None))
    }
    spline_kind_items!(CurveForm, dimension_of, control_polygon);
    /// De Casteljau's triangle: n²/2 interpolations of D coordinates per point.
    fn cost(&self) -> ShapeCost {
        bezier_cost(&self.control_points, 0)
    }
    fn build_in<const D: usize>(&self) -> Result<Box<dyn Curve<D>>> {
        check_bezier_degree(&self.control_points)?;
        Ok(Box::new(BezierCurve::new(to_points::<D>(&self.control_points))?))
    }
    fn example() -> Self {
        BezierDoc { control_points: vec![vec![0.0, 0.0], vec![1.0, 2.0], vec![3.0, 2.0], vec![4.0, 0.0]] }
    }
}

/// `{"type":"rational_bezier","control_points":[...],"weights":[...]}`
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RationalBezierDoc {
    /// Control points.
    pub control_points: Vec<Vec<f64>>,
    /// One positive weight per control point.
    pub weights: Vec<f64>,
}

impl DocumentKind for RationalBezierDoc {
    type Family = Curves;
    fn spline(&self) -> Option<SplineView<'_>> {
        Some(SplineView::bezier(&self.control_points, Some(&self.weights)))
    }
    spline_kind_items!(CurveForm, dimension_of, control_polygon);
    /// De Casteljau's triangle in homogeneous coordinates (one more than the points').
    fn cost(&self) -> ShapeCost {
        bezier_cost(&self.control_points, 1)
    }
    fn build_in<const D: usize>(&self) -> Result<Box<dyn Curve<D>>> {
        check_bezier_degree(&self.control_points)?;
        check_finite_list("weights", &self.weights)?;
        Ok(Box::new(RationalBezierCurve::new(to_points::<D>(&self.control_points), self.weights.clone())?))
    }
    /// A quarter of the unit circle.
    fn example() -> Self {
        RationalBezierDoc {
            control_points: vec![vec![1.0, 0.0], vec![1.0, 1.0], vec![0.0, 1.0]],
            weights: vec![1.0, std::f64::consts::FRAC_1_SQRT_2, 1.0],
        }
    }
}

/// `{"type":"bspline","degree":p,"knots":[...],"control_points":[...],"periodic":false}`
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct BSplineDoc {
    /// Degree p.
    pub degree: usize,
    /// n + p + 1 knots.
    pub knots: Vec<f64>,
    /// n control points.
    pub control_points: Vec<Vec<f64>>,
    /// Closed, with cyclic control points (see `splinekit::curve::BSplineCurve::new_periodic`).
    #[serde(default, skip_serializing_if = "is_false")]
    pub periodic: bool,
}

impl BSplineDoc {
    /// The kernel curve in dimension D (the document's).
    pub fn curve<const D: usize>(&self) -> Result<BSplineCurve<D>> {
        self.spline().expect("a spline kind").bspline(&self.knots)
    }
}

impl DocumentKind for BSplineDoc {
    type Family = Curves;
    fn spline(&self) -> Option<SplineView<'_>> {
        Some(SplineView::borrowed(self.degree, &self.control_points, Some(&self.knots), None, self.periodic))
    }
    spline_kind_items!(CurveForm, dimension_of, control_polygon);
    fn cost(&self) -> ShapeCost {
        spline_cost(self.degree, self.control_points.len(), coordinates(&self.control_points))
    }
    fn build_in<const D: usize>(&self) -> Result<Box<dyn Curve<D>>> {
        Ok(Box::new(self.curve::<D>()?))
    }
    /// A clamped cubic through eight points.
    fn example() -> Self {
        BSplineDoc {
            degree: 3,
            knots: vec![0.0, 0.0, 0.0, 0.0, 1.0, 2.0, 3.0, 4.0, 5.0, 5.0, 5.0, 5.0],
            control_points: plane_points(&[
                [0.0, 0.0],
                [1.0, 2.0],
                [2.0, -1.0],
                [3.0, 1.0],
                [4.0, 0.0],
                [5.0, 2.0],
                [6.0, -1.0],
                [7.0, 0.0],
            ]),
            periodic: false,
        }
    }
}

/// `{"type":"nurbs", ...bspline fields..., "weights":[...]}`
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct NurbsDoc {
    /// Degree p.
    pub degree: usize,
    /// n + p + 1 knots.
    pub knots: Vec<f64>,
    /// n control points.
    pub control_points: Vec<Vec<f64>>,
    /// n positive weights.
    pub weights: Vec<f64>,
    /// Closed, with cyclic control points.
    #[serde(default, skip_serializing_if = "is_false")]
    pub periodic: bool,
}

impl NurbsDoc {
    /// The kernel curve in dimension D (the document's).
    pub fn curve<const D: usize>(&self) -> Result<NurbsCurve<D>> {
        self.spline().expect("a spline kind").nurbs(&self.knots, &self.weights)
    }
}

impl DocumentKind for NurbsDoc {
    type Family = Curves;
    fn spline(&self) -> Option<SplineView<'_>> {
        let (knots, weights) = (Some(self.knots.as_slice()), Some(self.weights.as_slice()));
        Some(SplineView::borrowed(self.degree, &self.control_points, knots, weights, self.periodic))
    }
    spline_kind_items!(CurveForm, dimension_of, control_polygon);
    fn cost(&self) -> ShapeCost {
        spline_cost(self.degree, self.control_points.len(), coordinates(&self.control_points) + 1)
    }
    fn build_in<const D: usize>(&self) -> Result<Box<dyn Curve<D>>> {
        Ok(Box::new(self.curve::<D>()?))
    }
    /// The exact unit circle: nine points of a square, quadratic, weights 1 and 1/√2.
    fn example() -> Self {
        let w = std::f64::consts::FRAC_1_SQRT_2;
        NurbsDoc {
            degree: 2,
            knots: vec![0.0, 0.0, 0.0, 0.25, 0.25, 0.5, 0.5, 0.75, 0.75, 1.0, 1.0, 1.0],
            control_points: plane_points(&[
                [1.0, 0.0],
                [1.0, 1.0],
                [0.0, 1.0],
                [-1.0, 1.0],
                [-1.0, 0.0],
                [-1.0, -1.0],
                [0.0, -1.0],
                [1.0, -1.0],
                [1.0, 0.0],
            ]),
            weights: vec![1.0, w, 1.0, w, 1.0, w, 1.0, w, 1.0],
            periodic: false,
        }
    }
}

/// The declarations the curves through `points` (Hermite, Catmull–Rom) share, written
/// inside their `impl DocumentKind`: the points are data, not a spline's control points,
/// so exporters approximate the curve; they give its dimension (checking them), it costs
/// one cubic piece per point ([`piecewise_cubic_cost`]), and it has nothing to pose in time.
macro_rules! interpolating_cubic_items {
    () => {
        approximated_kind_items!(SplineView, CurveForm);
        fn dimension(&self) -> Result<usize> {
            dimension_of("points", &self.points)
        }
        fn cost(&self) -> ShapeCost {
            piecewise_cubic_cost("points", &self.points)
        }
        fn set_time(&mut self, _time: f64) {}
    };
}

/// `{"type":"hermite","points":[...],"tangents":[...],"params":[...]}`
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct HermiteDoc {
    /// Interpolated points.
    pub points: Vec<Vec<f64>>,
    /// First derivatives at the points.
    pub tangents: Vec<Vec<f64>>,
    /// Strictly increasing parameters (default 0, 1, 2, …).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub params: Option<Vec<f64>>,
}

impl DocumentKind for HermiteDoc {
    type Family = Curves;
    interpolating_cubic_items!();
    fn build_in<const D: usize>(&self) -> Result<Box<dyn Curve<D>>> {
        if self.tangents.len() != self.points.len() {
            return Err(DocumentError::new(
                "tangents",
                format!("expected {} tangents, one per point, got {}", self.points.len(), self.tangents.len()),
            ));
        }
        let dt = dimension_of("tangents", &self.tangents)?;
        if dt != D {
            return Err(DocumentError::new("tangents", format!("expected {D} coordinates like the points, got {dt}")));
        }
        let (points, tangents) = (to_points::<D>(&self.points), to_points::<D>(&self.tangents));
        Ok(Box::new(HermiteCurve::new(points, tangents, self.params.clone())?))
    }
    fn example() -> Self {
        HermiteDoc {
            points: vec![vec![0.0, 0.0], vec![2.0, 1.0], vec![4.0, 0.0]],
            tangents: vec![vec![1.0, 1.0], vec![1.0, 0.0], vec![1.0, -1.0]],
            params: Some(vec![0.0, 1.0, 3.0]),
        }
    }
    fn decoration(&self) -> CurveDecoration<'_> {
        CurveDecoration::ControlPolygon { points: &self.points, field: "points", closed: false }
    }
}

/// `{"type":"catmull_rom","points":[...],"alpha":0,"closed":false}`
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct CatmullRomDoc {
    /// Interpolated points.
    pub points: Vec<Vec<f64>>,
    /// 0 uniform (default), 0.5 centripetal, 1 chordal.
    #[serde(default)]
    pub alpha: f64,
    /// Closed loop through the points.
    #[serde(default, skip_serializing_if = "is_false")]
    pub closed: bool,
}

impl DocumentKind for CatmullRomDoc {
    type Family = Curves;
    interpolating_cubic_items!();
    fn build_in<const D: usize>(&self) -> Result<Box<dyn Curve<D>>> {
        Ok(Box::new(CatmullRomCurve::new(to_points::<D>(&self.points), self.alpha, self.closed)?))
    }
    /// A centripetal spline through four points.
    fn example() -> Self {
        CatmullRomDoc {
            points: vec![vec![0.0, 0.0], vec![1.0, 1.0], vec![3.0, 1.0], vec![4.0, 0.0]],
            alpha: 0.5,
            closed: false,
        }
    }
    fn decoration(&self) -> CurveDecoration<'_> {
        CurveDecoration::ControlPolygon { points: &self.points, field: "points", closed: self.closed }
    }
}

/// `{"type":"line","from":[...],"to":[...]}`, t ∈ [0, 1].
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct LineDoc {
    /// c(0).
    pub from: Vec<f64>,
    /// c(1).
    pub to: Vec<f64>,
}

impl DocumentKind for LineDoc {
    type Family = Curves;
    fn spline(&self) -> Option<SplineView<'_>> {
        None
    }
    fn exact_form(&self) -> crate::Result<CurveForm<'_>> {
        Ok(CurveForm::Line { from: &self.from, to: &self.to })
    }
    const BLENDING_MODEL: bool = false;
    fn dimension(&self) -> Result<usize> {
        dimension_of("from", std::slice::from_ref(&self.from))
    }
    fn cost(&self) -> ShapeCost {
        ShapeCost::new("from", 64.0, 0.0, 10.0)
    }
    fn build_in<const D: usize>(&self) -> Result<Box<dyn Curve<D>>> {
        Ok(Box::new(Line::new(to_point::<D>("from", &self.from)?, to_point::<D>("to", &self.to)?)?))
    }
    fn example() -> Self {
        LineDoc { from: vec![0.0, 0.0, 0.0], to: vec![1.0, 2.0, 0.0] }
    }
    fn decoration(&self) -> CurveDecoration<'_> {
        CurveDecoration::None
    }
    fn set_time(&mut self, _time: f64) {}
}

/// Plane points as a document holds them (for the examples).
fn plane_points(points: &[[f64; 2]]) -> Vec<Vec<f64>> {
    points.iter().map(|p| p.to_vec()).collect()
}

/// Coordinates per point (of the first point; the dimension is checked when building).
fn coordinates(points: &[Vec<f64>]) -> usize {
    points.first().map_or(1, Vec::len).max(1)
}

/// A Bézier curve of n + 1 points: n + 1 points of D (+ `extra`) coordinates, and de
/// Casteljau's n(n + 1)/2 interpolations per point.
fn bezier_cost(points: &[Vec<f64>], extra: usize) -> ShapeCost {
    let (n, d) = (points.len() as f64, (coordinates(points) + extra) as f64);
    // Degrees above the limit are refused when built (check_bezier_degree).
    let order = n.min(crate::budget::MAX_DEGREE as f64 + 1.0);
    ShapeCost::new("control_points", n * d * crate::budget::F64, n * d, order * order * d)
}

/// Refuses Bézier curves above [`crate::budget::MAX_DEGREE`], naming the points.
fn check_bezier_degree(points: &[Vec<f64>]) -> Result<()> {
    check_degree("control_points", points.len().saturating_sub(1)).map_err(|e| {
        DocumentError::new(e.path, format!("{} points make a Bézier curve of {}", points.len(), e.message))
    })
}

/// Piecewise cubic curves through points: a span search and one cubic per point.
fn piecewise_cubic_cost(field: &str, points: &[Vec<f64>]) -> ShapeCost {
    let (n, d) = (points.len() as f64, coordinates(points) as f64);
    ShapeCost::new(field, 3.0 * n * d * crate::budget::F64, 10.0 * n * d, 20.0 * d + n.max(2.0).log2())
}

/// What a scene draws besides a spline kind: its control polygon (`control_points`),
/// closed where the spline wraps around.
fn control_polygon<'a>(points: &'a [Vec<f64>], spline: &SplineView<'_>) -> CurveDecoration<'a> {
    CurveDecoration::ControlPolygon { points, field: "control_points", closed: spline.periodic }
}
