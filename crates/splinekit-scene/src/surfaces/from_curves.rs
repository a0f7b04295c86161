//! Surfaces made from curve documents: revolution, ruled, extrusion, Coons patch, sweep,
//! Hermite surface of curves, loft.

use std::borrow::Cow;

use serde::{Deserialize, Deserializer, Serialize};
use splinekit::curve::{BSplineCurve, Curve};
use splinekit::fit::Parametrization;
use splinekit::surface::derived::{
    CoonsBlend, CoonsPatch, Extrusion, HermiteCurveSurface, RevolvedSurface, RuledSurface, SweepSurface,
};
use splinekit::surface::loft::{CurveLoft, LoftParameters};
use splinekit::surface::{BSplineSurface, Surface};

use super::{SurfaceDecoration, SurfaceForm, Surfaces};
use crate::budget::ShapeCost;
use crate::curves::{BezierDoc, CircleDoc, CurveDocument, LineDoc, TrefoilDoc};
use crate::defaults::{origin, tau, z_axis};
use crate::error::{DocumentError, Result};
use crate::points::{from_points, to_point};
use crate::registry::{DocumentKind, KindName, ModelFamily, approximated_kind_items, self_form_kind_items};
use crate::views::NetView;

/// The declarations the surfaces made from curve documents share, written inside their
/// `impl DocumentKind` with the fields that hold the curves: a scene draws nothing besides
/// the surface, and posing the document in time poses each curve.
macro_rules! made_of_curves_items {
    ($($curve:ident),+) => {
        fn decoration(&self) -> SurfaceDecoration<'_> {
            SurfaceDecoration::None
        }
        fn set_time(&mut self, time: f64) {
            $( self.$curve.set_time(time); )+
        }
    };
}

/// `{"type":"revolution","curve":{…},"axis_point":[0,0,0],"axis":[0,0,1],"angle":2π}`:
/// the curve turned about the axis; u is the angle, v the curve's parameter.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RevolutionDoc {
    /// The profile (a 3-D curve document).
    pub curve: Box<CurveDocument>,
    /// A point on the axis (default the origin).
    #[serde(default = "origin")]
    pub axis_point: Vec<f64>,
    /// The axis direction (default z).
    #[serde(default = "z_axis")]
    pub axis: Vec<f64>,
    /// The angle in radians (default 2π: closed).
    #[serde(default = "tau")]
    pub angle: f64,
}

impl DocumentKind for RevolutionDoc {
    type Family = Surfaces;
    self_form_kind_items!(NetView, SurfaceForm::Revolution);
    made_of_curves_items!(curve);
    fn dimension(&self) -> Result<usize> {
        Ok(3)
    }
    fn cost(&self) -> ShapeCost {
        self.curve.cost().within("curve")
    }
    fn build_in<const D: usize>(&self) -> Result<Box<dyn Surface<D>>> {
        Surfaces::model_in::<D>(Self::TYPE, || {
            if self.curve.dimension().map_err(|e| e.within("curve"))? != 3 {
                return Err(DocumentError::new("curve", "the profile of a revolution must be a 3-D curve"));
            }
            Ok(Box::new(RevolvedSurface::new(
                self.curve.build_in::<3>().map_err(|e| e.within("curve"))?,
                to_point("axis_point", &self.axis_point)?,
                to_point("axis", &self.axis)?,
                self.angle,
            )?))
        })
    }
    /// A quadratic Bézier arc in the xz-plane turned about z: a vase.
    fn example() -> Self {
        let profile = BezierDoc { control_points: vec![vec![1.0, 0.0, 0.0], vec![2.0, 0.0, 1.0], vec![1.0, 0.0, 2.0]] };
        RevolutionDoc {
            curve: Box::new(CurveDocument::Bezier(profile)),
            axis_point: origin(),
            axis: z_axis(),
            angle: tau(),
        }
    }
}

/// `{"type":"ruled","first":{…},"second":{…}}`: (1 − v) first(u) + v second(u), both curves
/// reparametrised to [0, 1].
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RuledDoc {
    /// The curve at v = 0.
    pub first: Box<CurveDocument>,
    /// The curve at v = 1.
    pub second: Box<CurveDocument>,
}

impl DocumentKind for RuledDoc {
    type Family = Surfaces;
    approximated_kind_items!(NetView, SurfaceForm);
    made_of_curves_items!(first, second);
    fn dimension(&self) -> Result<usize> {
        same_dimension(&[("first", &self.first), ("second", &self.second)])
    }
    fn cost(&self) -> ShapeCost {
        self.first.cost().within("first").and(self.second.cost().within("second"))
    }
    fn build_in<const D: usize>(&self) -> Result<Box<dyn Surface<D>>> {
        Ok(Box::new(RuledSurface::new(
            self.first.build_in::<D>().map_err(|e| e.within("first"))?,
            self.second.build_in::<D>().map_err(|e| e.within("second"))?,
        )?))
    }
    /// A parabola-like Bézier arc joined to a straight line above it.
    fn example() -> Self {
        let arc = BezierDoc { control_points: vec![vec![0.0, 0.0, 0.0], vec![1.0, 1.0, 0.0], vec![2.0, 0.0, 0.0]] };
        let line = LineDoc { from: vec![0.0, 0.0, 1.0], to: vec![2.0, 0.0, 1.0] };
        RuledDoc { first: Box::new(CurveDocument::Bezier(arc)), second: Box::new(CurveDocument::Line(line)) }
    }
}

/// `{"type":"extrusion","curve":{…},"direction":[0,0,1]}`: curve(u) + v·direction.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ExtrusionDoc {
    /// The curve.
    pub curve: Box<CurveDocument>,
    /// The extrusion vector.
    pub direction: Vec<f64>,
}

impl DocumentKind for ExtrusionDoc {
    type Family = Surfaces;
    self_form_kind_items!(NetView, SurfaceForm::Extrusion);
    made_of_curves_items!(curve);
    fn dimension(&self) -> Result<usize> {
        let dim = self.curve.dimension().map_err(|e| e.within("curve"))?;
        if self.direction.len() != dim {
            return Err(DocumentError::new(
                "direction",
                format!("expected {dim} coordinates like the curve, got {}", self.direction.len()),
            ));
        }
        Ok(dim)
    }
    fn cost(&self) -> ShapeCost {
        self.curve.cost().within("curve")
    }
    fn build_in<const D: usize>(&self) -> Result<Box<dyn Surface<D>>> {
        Ok(Box::new(Extrusion::new(
            self.curve.build_in::<D>().map_err(|e| e.within("curve"))?,
            to_point::<D>("direction", &self.direction)?,
        )?))
    }
    /// The unit circle extruded along z: a cylinder.
    fn example() -> Self {
        ExtrusionDoc { curve: Box::new(CurveDocument::Circle(CircleDoc::default())), direction: vec![0.0, 0.0, 1.0] }
    }
}

/// How a Coons patch blends its boundary curves: `"linear"` (bilinear) or `"cubic"`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Default)]
#[serde(rename_all = "lowercase")]
pub enum CoonsBlendDoc {
    /// Linear blending functions (the bilinearly blended Coons patch).
    #[default]
    Linear,
    /// Cubic Hermite blending functions 3s² − 2s³.
    Cubic,
}

impl<'de> Deserialize<'de> for CoonsBlendDoc {
    fn deserialize<D: Deserializer<'de>>(deserializer: D) -> std::result::Result<Self, D::Error> {
        match String::deserialize(deserializer)?.as_str() {
            "linear" => Ok(CoonsBlendDoc::Linear),
            "cubic" => Ok(CoonsBlendDoc::Cubic),
            other => Err(serde::de::Error::custom(format_args!("expected \"linear\" or \"cubic\", got \"{other}\""))),
        }
    }
}

/// `{"type":"coons","bottom":{…},"top":{…},"left":{…},"right":{…},"blend":"linear"}`:
/// the Coons patch on [0, 1]² spanned by four boundary curves meeting at the corners.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct CoonsDoc {
    /// S(u, 0).
    pub bottom: Box<CurveDocument>,
    /// S(u, 1).
    pub top: Box<CurveDocument>,
    /// S(0, v).
    pub left: Box<CurveDocument>,
    /// S(1, v).
    pub right: Box<CurveDocument>,
    /// The blending functions (default linear).
    #[serde(default)]
    pub blend: CoonsBlendDoc,
}

impl DocumentKind for CoonsDoc {
    type Family = Surfaces;
    approximated_kind_items!(NetView, SurfaceForm);
    made_of_curves_items!(bottom, top, left, right);
    fn dimension(&self) -> Result<usize> {
        same_dimension(&[("bottom", &self.bottom), ("top", &self.top), ("left", &self.left), ("right", &self.right)])
    }
    /// The four boundary curves, each evaluated twice per point (at u or v and at the corners).
    fn cost(&self) -> ShapeCost {
        let c = [("bottom", &self.bottom), ("top", &self.top), ("left", &self.left), ("right", &self.right)]
            .into_iter()
            .map(|(name, c)| c.cost().within(name))
            .reduce(ShapeCost::and)
            .expect("four curves");
        ShapeCost { eval: 2.0 * c.eval, ..c }
    }
    fn build_in<const D: usize>(&self) -> Result<Box<dyn Surface<D>>> {
        Ok(Box::new(CoonsPatch::new(
            self.bottom.build_in::<D>().map_err(|e| e.within("bottom"))?,
            self.top.build_in::<D>().map_err(|e| e.within("top"))?,
            self.left.build_in::<D>().map_err(|e| e.within("left"))?,
            self.right.build_in::<D>().map_err(|e| e.within("right"))?,
            match self.blend {
                CoonsBlendDoc::Linear => CoonsBlend::Linear,
                CoonsBlendDoc::Cubic => CoonsBlend::Cubic,
            },
        )?))
    }
    /// Three straight sides and one bulging Bézier side over the unit square.
    fn example() -> Self {
        let line =
            |from: [f64; 3], to: [f64; 3]| Box::new(CurveDocument::Line(LineDoc { from: from.into(), to: to.into() }));
        let bulge = BezierDoc { control_points: vec![vec![1.0, 0.0, 0.0], vec![1.2, 0.5, 1.0], vec![1.0, 1.0, 0.0]] };
        CoonsDoc {
            bottom: line([0.0, 0.0, 0.0], [1.0, 0.0, 0.0]),
            top: line([0.0, 1.0, 0.0], [1.0, 1.0, 0.0]),
            left: line([0.0, 0.0, 0.0], [0.0, 1.0, 0.0]),
            right: Box::new(CurveDocument::Bezier(bulge)),
            blend: CoonsBlendDoc::Cubic,
        }
    }
}

/// `{"type":"sweep","profile":{…},"path":{…}}`: the profile (x, y in the path's normal
/// plane, z along the tangent) carried along the path by a rotation-minimising frame; u is
/// the profile's parameter, v the path's. Both curves are 3-D.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SweepDoc {
    /// The cross-section.
    pub profile: Box<CurveDocument>,
    /// The spine.
    pub path: Box<CurveDocument>,
}

impl DocumentKind for SweepDoc {
    type Family = Surfaces;
    approximated_kind_items!(NetView, SurfaceForm);
    made_of_curves_items!(profile, path);
    fn dimension(&self) -> Result<usize> {
        Ok(3)
    }
    /// The profile and the path, and the rotation-minimising frames sampled along the path.
    fn cost(&self) -> ShapeCost {
        let mut c = self.profile.cost().within("profile").and(self.path.cost().within("path"));
        c.build.work += SWEEP_FRAMES * c.eval;
        c.build.bytes += SWEEP_FRAMES * 128.0;
        c
    }
    fn build_in<const D: usize>(&self) -> Result<Box<dyn Surface<D>>> {
        let three = |c: &CurveDocument, field: &str| -> Result<Box<dyn Curve<3>>> {
            if c.dimension().map_err(|e| e.within(field))? != 3 {
                return Err(DocumentError::new(field, "must be a 3-D curve"));
            }
            c.build_in::<3>().map_err(|e| e.within(field))
        };
        Surfaces::model_in::<D>(Self::TYPE, || {
            Ok(Box::new(SweepSurface::new(three(&self.profile, "profile")?, three(&self.path, "path")?)?))
        })
    }
    /// A thin tube along the trefoil knot.
    fn example() -> Self {
        SweepDoc {
            profile: Box::new(CurveDocument::Circle(CircleDoc { radius: 0.3 })),
            path: Box::new(CurveDocument::Trefoil(TrefoilDoc::default())),
        }
    }
}

/// Frames a sweep samples along its path (an upper estimate).
const SWEEP_FRAMES: f64 = 4096.0;

/// The common dimension of named curve documents, which must agree.
fn same_dimension(curves: &[(&str, &CurveDocument)]) -> Result<usize> {
    let d0 = curves[0].1.dimension().map_err(|e| e.within(curves[0].0))?;
    for (name, c) in &curves[1..] {
        let d = c.dimension().map_err(|e| e.within(name))?;
        if d != d0 {
            return Err(DocumentError::new(
                *name,
                format!("expected a curve of dimension {d0} like {}, got {d}", curves[0].0),
            ));
        }
    }
    Ok(d0)
}

/// `{"type":"hermite_curve_surface","bottom":{…},"top":{…},"bottom_derivative":{…},"top_derivative":{…}}`:
/// GMlib's `PHermiteCurveSurf`, cubic Hermite interpolation in v ∈ [0, 1] between two
/// boundary curves with two cross-derivative curves, on the curves' common domain in u.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct HermiteCurveSurfaceDoc {
    /// S(u, 0).
    pub bottom: Box<CurveDocument>,
    /// S(u, 1).
    pub top: Box<CurveDocument>,
    /// S_v(u, 0).
    pub bottom_derivative: Box<CurveDocument>,
    /// S_v(u, 1).
    pub top_derivative: Box<CurveDocument>,
}

impl HermiteCurveSurfaceDoc {
    fn named(&self) -> [(&'static str, &CurveDocument); 4] {
        [
            ("bottom", &self.bottom),
            ("top", &self.top),
            ("bottom_derivative", &self.bottom_derivative),
            ("top_derivative", &self.top_derivative),
        ]
    }
}

impl DocumentKind for HermiteCurveSurfaceDoc {
    type Family = Surfaces;
    approximated_kind_items!(NetView, SurfaceForm);
    made_of_curves_items!(bottom, top, bottom_derivative, top_derivative);
    fn dimension(&self) -> Result<usize> {
        same_dimension(&self.named())
    }
    /// The four curves, each evaluated once per point.
    fn cost(&self) -> ShapeCost {
        self.named().into_iter().map(|(name, c)| c.cost().within(name)).reduce(ShapeCost::and).expect("four curves")
    }
    fn build_in<const D: usize>(&self) -> Result<Box<dyn Surface<D>>> {
        let [a, b, c, d] = self.named().map(|(name, c)| c.build_in::<D>().map_err(|e| e.within(name)));
        Ok(Box::new(HermiteCurveSurface::new(a?, b?, c?, d?)?))
    }
    /// A band between two arcs of Bézier curves, leaving the bottom upwards and arriving
    /// at the top level.
    fn example() -> Self {
        let bezier = |points: &[[f64; 3]]| {
            Box::new(CurveDocument::Bezier(BezierDoc { control_points: points.iter().map(|p| p.to_vec()).collect() }))
        };
        HermiteCurveSurfaceDoc {
            bottom: bezier(&[[0.0, 0.0, 0.0], [1.0, -0.5, 0.0], [2.0, 0.0, 0.0]]),
            top: bezier(&[[0.0, 2.0, 0.5], [1.0, 2.5, 0.5], [2.0, 2.0, 0.5]]),
            bottom_derivative: bezier(&[[0.0, 1.0, 2.0], [0.0, 1.0, 3.0], [0.0, 1.0, 2.0]]),
            top_derivative: bezier(&[[0.0, 2.0, 0.0], [0.0, 2.0, -1.0], [0.0, 2.0, 0.0]]),
        }
    }
}

/// How a loft interpolates across its sections: `"bezier"` (one polynomial of degree
/// n − 1) or `"bspline"` (degree `degree_v`, default min(3, n − 1)).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum LoftCrossDoc {
    /// The Bézier (Lagrange) interpolant of degree n − 1.
    #[default]
    Bezier,
    /// The B-spline interpolant of degree `degree_v` on averaged knots.
    Bspline,
}

/// Where a loft's sections sit in v: a spacing name or the parameters themselves.
#[derive(Debug, Clone, PartialEq, Serialize)]
#[serde(untagged)]
pub enum LoftParametersDoc {
    /// `"chord_length"` (default), `"uniform"` or `"centripetal"`: on [0, 1] by the
    /// sections' mean distances apart.
    Spacing(String),
    /// Strictly increasing numbers, one per section.
    Given(Vec<f64>),
}

impl Default for LoftParametersDoc {
    fn default() -> Self {
        LoftParametersDoc::Spacing("chord_length".into())
    }
}

impl<'de> Deserialize<'de> for LoftParametersDoc {
    fn deserialize<De: Deserializer<'de>>(deserializer: De) -> std::result::Result<Self, De::Error> {
        match serde_json::Value::deserialize(deserializer)? {
            serde_json::Value::String(s) => Ok(LoftParametersDoc::Spacing(s)),
            v @ serde_json::Value::Array(_) => {
                serde_json::from_value(v).map(LoftParametersDoc::Given).map_err(serde::de::Error::custom)
            }
            other => Err(serde::de::Error::custom(format_args!(
                "expected \"chord_length\", \"uniform\", \"centripetal\" or a list of numbers, got {other}"
            ))),
        }
    }
}

/// `{"type":"loft","sections":[{…}, …],"cross":"bezier","parameters":"chord_length"}`:
/// the surface through n ≥ 2 curves (skinning), u along each section (reparametrised to
/// [0, 1]), v across them.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct LoftDoc {
    /// The section curves, of one dimension, all open or all closed.
    pub sections: Vec<CurveDocument>,
    /// The interpolation across (default Bézier).
    #[serde(default)]
    pub cross: LoftCrossDoc,
    /// The degree across for `"bspline"` (1 … n − 1, default min(3, n − 1)); for
    /// `"bezier"` it is n − 1 and may be left out.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub degree_v: Option<usize>,
    /// The sections' parameters in v (default chord length).
    #[serde(default)]
    pub parameters: LoftParametersDoc,
}

impl LoftDoc {
    /// The degree across, checked against the cross direction.
    fn degree(&self) -> Result<usize> {
        let n = self.sections.len();
        if n < 2 {
            return Err(DocumentError::new("sections", format!("expected at least 2 curves, got {n}")));
        }
        match (self.cross, self.degree_v) {
            (LoftCrossDoc::Bezier, None) => Ok(n - 1),
            (LoftCrossDoc::Bezier, Some(q)) if q == n - 1 => Ok(q),
            (LoftCrossDoc::Bezier, Some(q)) => Err(DocumentError::new(
                "degree_v",
                format!(
                    "a Bézier loft of {n} sections has degree {} across, got {q} (\"cross\": \"bspline\" takes another degree)",
                    n - 1
                ),
            )),
            (LoftCrossDoc::Bspline, None) => Ok((n - 1).min(3)),
            (LoftCrossDoc::Bspline, Some(q)) if (1..n).contains(&q) => Ok(q),
            (LoftCrossDoc::Bspline, Some(q)) => Err(DocumentError::new(
                "degree_v",
                format!("must be between 1 and {} for {n} sections, got {q}", n - 1),
            )),
        }
    }

    /// The kernel's placement of the sections.
    fn placement(&self) -> Result<LoftParameters> {
        Ok(match &self.parameters {
            LoftParametersDoc::Spacing(s) => LoftParameters::Spacing(match s.as_str() {
                "chord_length" => Parametrization::ChordLength,
                "uniform" => Parametrization::Uniform,
                "centripetal" => Parametrization::Centripetal,
                other => {
                    return Err(DocumentError::new(
                        "parameters",
                        format!(
                            "expected \"chord_length\", \"uniform\", \"centripetal\" or a list of numbers, got \"{other}\""
                        ),
                    ));
                }
            }),
            LoftParametersDoc::Given(v) => {
                crate::points::check_finite_list("parameters", v)?;
                LoftParameters::Given(v.clone())
            }
        })
    }

    fn loft<const D: usize>(&self) -> Result<CurveLoft<D>> {
        let degree = self.degree()?;
        let placement = self.placement()?;
        let sections = self
            .sections
            .iter()
            .enumerate()
            .map(|(k, c)| c.build_in::<D>().map_err(|e| e.within(&format!("sections[{k}]"))))
            .collect::<Result<Vec<_>>>()?;
        Ok(CurveLoft::new(sections, degree, &placement)?)
    }

    /// The B-spline sections when every one is a non-rational, non-periodic spline
    /// document (Bézier or B-spline), for the exact form.
    fn spline_sections<const D: usize>(&self) -> Option<Vec<BSplineCurve<D>>> {
        self.sections
            .iter()
            .map(|c| {
                let view = c.spline()?;
                if view.weights.is_some() || view.periodic {
                    return None;
                }
                match &view.knots {
                    Some(k) => view.bspline::<D>(k).ok(),
                    None => {
                        let p = view.degree;
                        let knots: Vec<f64> =
                            std::iter::repeat_n(0.0, p + 1).chain(std::iter::repeat_n(1.0, p + 1)).collect();
                        view.bspline::<D>(&knots).ok()
                    }
                }
            })
            .collect()
    }

    /// The spline form of a loft of spline sections: the B-spline loft at the parameters
    /// the curve loft chose.
    fn spline_form<const D: usize>(&self) -> Result<Option<NetView<'static>>> {
        let Some(sections) = self.spline_sections::<D>() else { return Ok(None) };
        let loft = self.loft::<D>()?;
        let s = BSplineSurface::loft_at(&sections, self.degree()?, loft.parameters())?;
        let (ku, kv) = s.knots();
        Ok(Some(NetView {
            degrees: s.degrees(),
            control_points: Cow::Owned(s.control_points().iter().map(|row| from_points(row)).collect()),
            knots: Some((Cow::Owned(ku.to_vec()), Cow::Owned(kv.to_vec()))),
            weights: None,
            periodic: (false, false),
        }))
    }
}

/// Samples a loft takes of each section to space them.
const LOFT_SPACING_SAMPLES: f64 = 33.0;

impl DocumentKind for LoftDoc {
    type Family = Surfaces;
    fn dimension(&self) -> Result<usize> {
        let named: Vec<(String, &CurveDocument)> =
            self.sections.iter().enumerate().map(|(k, c)| (format!("sections[{k}]"), c)).collect();
        if named.is_empty() {
            return Err(DocumentError::new("sections", "expected at least 2 curves, got 0"));
        }
        let refs: Vec<(&str, &CurveDocument)> = named.iter().map(|(n, c)| (n.as_str(), *c)).collect();
        same_dimension(&refs)
    }
    /// Every section per point and its cardinal function across; building samples every
    /// section and solves one interpolation per section (n² work).
    fn cost(&self) -> ShapeCost {
        let n = self.sections.len() as f64;
        let mut c = self
            .sections
            .iter()
            .enumerate()
            .map(|(k, s)| s.cost().within(&format!("sections[{k}]")))
            .reduce(ShapeCost::and)
            .unwrap_or_else(|| ShapeCost::new("sections", 0.0, 0.0, 0.0));
        c.build.work += LOFT_SPACING_SAMPLES * c.eval + 64.0 * n * n;
        c.build.bytes += 64.0 * n * n;
        c.eval += 32.0 * n;
        c
    }
    fn build_in<const D: usize>(&self) -> Result<Box<dyn Surface<D>>> {
        Ok(Box::new(self.loft::<D>()?))
    }
    /// Four sections of a vase: circles of changing radius, the B-spline loft through them.
    fn example() -> Self {
        let ring = |r: f64, z: f64| {
            // The circle of radius r at height z as a closed quadratic NURBS would need
            // weights; a Bézier quartic ring (open, nearly round) keeps the loft exact.
            let pts = [[r, 0.0, z], [r, r, z], [-r, r, z], [-r, -r, z], [r, -r, z], [r, 0.0, z]];
            CurveDocument::Bezier(BezierDoc { control_points: pts.iter().map(|p| p.to_vec()).collect() })
        };
        LoftDoc {
            sections: vec![ring(1.0, 0.0), ring(1.6, 1.0), ring(0.7, 2.2), ring(1.1, 3.0)],
            cross: LoftCrossDoc::Bspline,
            degree_v: Some(2),
            parameters: LoftParametersDoc::default(),
        }
    }
    fn decoration(&self) -> SurfaceDecoration<'_> {
        SurfaceDecoration::None
    }
    fn set_time(&mut self, time: f64) {
        for s in &mut self.sections {
            s.set_time(time);
        }
    }
    fn spline(&self) -> Option<NetView<'_>> {
        None
    }
    /// A B-spline surface when every section is a non-rational open spline (Bézier or
    /// B-spline document): the B-spline loft at the same parameters is the same surface.
    fn exact_form(&self) -> Result<SurfaceForm<'_>> {
        let form = crate::with_dimension!(self.dimension()?, "sections", D => self.spline_form::<D>())?;
        Ok(form.map_or(SurfaceForm::Approximate, SurfaceForm::Spline))
    }
    const BLENDING_MODEL: bool = false;
}
