//! Surfaces made from curve documents: revolution, ruled, extrusion, Coons patch, sweep.

use serde::{Deserialize, Deserializer, Serialize};
use splinekit::curve::Curve;
use splinekit::surface::Surface;
use splinekit::surface::derived::{CoonsBlend, CoonsPatch, Extrusion, RevolvedSurface, RuledSurface, SweepSurface};

use super::{SurfaceDecoration, SurfaceForm, Surfaces};
use crate::budget::ShapeCost;
use crate::curves::{BezierDoc, CircleDoc, CurveDocument, LineDoc, TrefoilDoc};
use crate::defaults::{origin, tau, z_axis};
use crate::error::{DocumentError, Result};
use crate::points::to_point;
use crate::registry::{DocumentKind, KindName, ModelFamily, approximated_kind_items, self_form_kind_items};

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
