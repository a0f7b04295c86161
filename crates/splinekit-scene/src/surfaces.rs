//! Surface shape documents. The first index of a control net runs along u.

use serde::{Deserialize, Serialize};
use serde_json::Value;

use splinekit::Point;
use splinekit::surface::derived::{CoonsBlend, CoonsPatch, Extrusion, RevolvedSurface, RuledSurface, SweepSurface};
use splinekit::surface::model::{
    Apple, Cone, Cylinder, Enneper, HeartSurface, Helicoid, KleinBottle, MobiusStrip, Plane, Seashell, Sphere, Torus,
};
use splinekit::surface::{BSplineSurface, BezierSurface, NurbsSurface, Surface, TrimmedSurface};

use crate::curves::CurveDocument;

use crate::curves::fields;
use crate::defaults::*;
use crate::error::{DocumentError, Result};
use crate::points::{check_finite_list, dimension_of, to_point, to_points};
use crate::with_dimension;

/// `{"type":"bezier_surface","control_points":[[...row...],...]}`
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct BezierSurfaceDoc {
    /// Rows of control points (rows along u).
    pub control_points: Vec<Vec<Vec<f64>>>,
}

/// `{"type":"bspline_surface", ...}`
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct BSplineSurfaceDoc {
    /// Degree in u.
    pub degree_u: usize,
    /// Degree in v.
    pub degree_v: usize,
    /// n_u + degree_u + 1 knots.
    pub knots_u: Vec<f64>,
    /// n_v + degree_v + 1 knots.
    pub knots_v: Vec<f64>,
    /// n_u rows of n_v points.
    pub control_points: Vec<Vec<Vec<f64>>>,
    /// Closed in u with cyclic rows.
    #[serde(default, skip_serializing_if = "is_false")]
    pub periodic_u: bool,
    /// Closed in v with cyclic columns.
    #[serde(default, skip_serializing_if = "is_false")]
    pub periodic_v: bool,
}

/// `{"type":"nurbs_surface", ...bspline_surface fields..., "weights":[[...]]}`
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct NurbsSurfaceDoc {
    /// Degree in u.
    pub degree_u: usize,
    /// Degree in v.
    pub degree_v: usize,
    /// n_u + degree_u + 1 knots.
    pub knots_u: Vec<f64>,
    /// n_v + degree_v + 1 knots.
    pub knots_v: Vec<f64>,
    /// n_u rows of n_v points.
    pub control_points: Vec<Vec<Vec<f64>>>,
    /// n_u rows of n_v positive weights.
    pub weights: Vec<Vec<f64>>,
    /// Closed in u.
    #[serde(default, skip_serializing_if = "is_false")]
    pub periodic_u: bool,
    /// Closed in v.
    #[serde(default, skip_serializing_if = "is_false")]
    pub periodic_v: bool,
}

/// `{"type":"plane","origin":[0,0,0],"u_axis":[1,0,0],"v_axis":[0,1,0]}`
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct PlaneDoc {
    /// S(0, 0).
    #[serde(default = "origin")]
    pub origin: Vec<f64>,
    /// ∂S/∂u.
    #[serde(default = "x_axis")]
    pub u_axis: Vec<f64>,
    /// ∂S/∂v.
    #[serde(default = "y_axis")]
    pub v_axis: Vec<f64>,
}

/// `{"type":"cylinder","radius":1,"height":1}`
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RadiusHeightDoc {
    /// Radius (default 1).
    #[serde(default = "one")]
    pub radius: f64,
    /// Height (default 1).
    #[serde(default = "one")]
    pub height: f64,
}

/// `{"type":"cone","radius":1,"height":2}`
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ConeDoc {
    /// Base radius (default 1).
    #[serde(default = "one")]
    pub radius: f64,
    /// Height (default 2).
    #[serde(default = "two")]
    pub height: f64,
}

/// `{"type":"sphere","radius":1}`
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RadiusDoc {
    /// Radius (default 1).
    #[serde(default = "one")]
    pub radius: f64,
}

/// `{"type":"klein_bottle","radius":3}`
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct KleinDoc {
    /// Radius R (default 3).
    #[serde(default = "three")]
    pub radius: f64,
}

/// `{"type":"torus","major_radius":3,"minor_radius":1}`
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct TorusDoc {
    /// R (default 3).
    #[serde(default = "three")]
    pub major_radius: f64,
    /// r (default 1).
    #[serde(default = "one")]
    pub minor_radius: f64,
}

/// `{"type":"mobius","radius":1,"half_width":0.5}`
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct MobiusDoc {
    /// Centre radius (default 1).
    #[serde(default = "one")]
    pub radius: f64,
    /// Half-width (default 0.5).
    #[serde(default = "half")]
    pub half_width: f64,
}

/// `{"type":"enneper","extent":2}`
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct EnneperDoc {
    /// Half-extent of the square domain (default 2).
    #[serde(default = "two")]
    pub extent: f64,
}

/// `{"type":"helicoid","radius":1,"pitch":1,"turns":2}`
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct HelicoidDoc {
    /// Radius (default 1).
    #[serde(default = "one")]
    pub radius: f64,
    /// Rise per turn (default 1).
    #[serde(default = "one")]
    pub pitch: f64,
    /// Turns (default 2).
    #[serde(default = "two")]
    pub turns: f64,
}

/// `{"type":"seashell","a":1,"b":2,"c":0.1,"turns":2}`
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SeashellDoc {
    /// Tube radius (default 1).
    #[serde(default = "one")]
    pub a: f64,
    /// Height (default 2).
    #[serde(default = "two")]
    pub b: f64,
    /// Inner radius (default 0.1).
    #[serde(default = "tenth")]
    pub c: f64,
    /// Turns (default 2).
    #[serde(default = "two")]
    pub turns: f64,
}

/// `{"type":"apple","scale":1}` and `{"type":"heart_surface","scale":1}`.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SurfaceScaleDoc {
    /// Uniform scale (default 1).
    #[serde(default = "one")]
    pub scale: f64,
}

fn linear_blend() -> String {
    "linear".to_string()
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawRevolution {
    curve: Value,
    #[serde(default = "origin")]
    axis_point: Vec<f64>,
    #[serde(default = "z_axis")]
    axis: Vec<f64>,
    #[serde(default = "tau")]
    angle: f64,
}

/// `{"type":"revolution","curve":{…},"axis_point":[0,0,0],"axis":[0,0,1],"angle":2π}`:
/// the curve turned about the axis; u is the angle, v the curve's parameter.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct RevolutionDoc {
    /// The profile (a 3-D curve document).
    pub curve: Box<CurveDocument>,
    /// A point on the axis.
    pub axis_point: Vec<f64>,
    /// The axis direction.
    pub axis: Vec<f64>,
    /// The angle in radians (2π: closed).
    pub angle: f64,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawRuled {
    first: Value,
    second: Value,
}

/// `{"type":"ruled","first":{…},"second":{…}}`: (1 − v) first(u) + v second(u), both curves
/// reparametrised to [0, 1].
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct RuledDoc {
    /// The curve at v = 0.
    pub first: Box<CurveDocument>,
    /// The curve at v = 1.
    pub second: Box<CurveDocument>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawExtrusion {
    curve: Value,
    direction: Vec<f64>,
}

/// `{"type":"extrusion","curve":{…},"direction":[0,0,1]}`: curve(u) + v·direction.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ExtrusionDoc {
    /// The curve.
    pub curve: Box<CurveDocument>,
    /// The extrusion vector.
    pub direction: Vec<f64>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawCoons {
    bottom: Value,
    top: Value,
    left: Value,
    right: Value,
    #[serde(default = "linear_blend")]
    blend: String,
}

/// `{"type":"coons","bottom":{…},"top":{…},"left":{…},"right":{…},"blend":"linear"}`:
/// the Coons patch on [0, 1]² spanned by four boundary curves meeting at the corners;
/// `blend` is `linear` (bilinear) or `cubic`.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct CoonsDoc {
    /// S(u, 0).
    pub bottom: Box<CurveDocument>,
    /// S(u, 1).
    pub top: Box<CurveDocument>,
    /// S(0, v).
    pub left: Box<CurveDocument>,
    /// S(1, v).
    pub right: Box<CurveDocument>,
    /// `linear` or `cubic`.
    pub blend: String,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawSweep {
    profile: Value,
    path: Value,
}

/// `{"type":"sweep","profile":{…},"path":{…}}`: the profile (x, y in the path's normal
/// plane, z along the tangent) carried along the path by a rotation-minimising frame; u is
/// the profile's parameter, v the path's. Both curves are 3-D.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct SweepDoc {
    /// The cross-section.
    pub profile: Box<CurveDocument>,
    /// The spine.
    pub path: Box<CurveDocument>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawTrimmed {
    surface: Value,
    #[serde(default)]
    outer: Option<Value>,
    #[serde(default)]
    holes: Vec<Value>,
}

/// `{"type":"trimmed","surface":{…},"outer":{…},"holes":[{…}]}`: the surface restricted to
/// the inside of `outer` (default: the whole domain) and outside every hole; loops are
/// closed 2-D curves in the surface's (u, v) domain.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct TrimmedDoc {
    /// The underlying surface.
    pub surface: Box<SurfaceDocument>,
    /// The outer trimming loop.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub outer: Option<Box<CurveDocument>>,
    /// Holes.
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub holes: Vec<CurveDocument>,
}

pub(crate) fn nested_surface(value: &Value, field: &str) -> Result<Box<SurfaceDocument>> {
    let (ty, rest) = crate::curves::split_type(value).map_err(|e| e.within(field))?;
    SurfaceDocument::parse_typed(&ty, rest)
        .map_err(|e| e.within(field))?
        .map(Box::new)
        .ok_or_else(|| DocumentError::new(format!("{field}.type"), format!("expected a surface type, got \"{ty}\"")))
}

fn nested(value: &Value, field: &str) -> Result<Box<CurveDocument>> {
    CurveDocument::parse(value).map(Box::new).map_err(|e| e.within(field))
}

/// A surface shape document.
#[derive(Debug, Clone, PartialEq, Serialize)]
#[serde(tag = "type", rename_all = "snake_case")]
#[allow(missing_docs)]
pub enum SurfaceDocument {
    BezierSurface(BezierSurfaceDoc),
    BsplineSurface(BSplineSurfaceDoc),
    NurbsSurface(NurbsSurfaceDoc),
    Plane(PlaneDoc),
    Cylinder(RadiusHeightDoc),
    Cone(ConeDoc),
    Sphere(RadiusDoc),
    Torus(TorusDoc),
    Mobius(MobiusDoc),
    KleinBottle(KleinDoc),
    Enneper(EnneperDoc),
    Helicoid(HelicoidDoc),
    Seashell(SeashellDoc),
    Apple(SurfaceScaleDoc),
    HeartSurface(SurfaceScaleDoc),
    Revolution(RevolutionDoc),
    Ruled(RuledDoc),
    Extrusion(ExtrusionDoc),
    Coons(CoonsDoc),
    Sweep(SweepDoc),
    Trimmed(TrimmedDoc),
    BlendingSplineSurface(crate::blending::BlendingSplineSurfaceDoc),
}

/// The surface `type` names, for messages.
pub const SURFACE_TYPES: &[&str] = &[
    "bezier_surface",
    "bspline_surface",
    "nurbs_surface",
    "plane",
    "cylinder",
    "cone",
    "sphere",
    "torus",
    "mobius",
    "klein_bottle",
    "enneper",
    "helicoid",
    "seashell",
    "apple",
    "heart_surface",
    "revolution",
    "ruled",
    "extrusion",
    "coons",
    "sweep",
    "trimmed",
    "blending_spline_surface",
];

/// A surface of a dimension known only at run time.
#[allow(missing_docs)]
pub enum AnySurface {
    D1(Box<dyn Surface<1>>),
    D2(Box<dyn Surface<2>>),
    D3(Box<dyn Surface<3>>),
    D4(Box<dyn Surface<4>>),
}

/// Something to do with a surface of any dimension.
pub trait SurfaceVisitor {
    /// The result.
    type Output;
    /// Called with the surface at its dimension.
    fn visit<const D: usize>(self, surface: &dyn Surface<D>) -> Self::Output;
}

impl AnySurface {
    /// Calls `visitor` with the surface at its compile-time dimension.
    pub fn visit<V: SurfaceVisitor>(&self, visitor: V) -> V::Output {
        match self {
            AnySurface::D1(s) => visitor.visit(s.as_ref()),
            AnySurface::D2(s) => visitor.visit(s.as_ref()),
            AnySurface::D3(s) => visitor.visit(s.as_ref()),
            AnySurface::D4(s) => visitor.visit(s.as_ref()),
        }
    }
}

/// Wraps `Box<dyn Surface<D>>` into [`AnySurface`].
pub trait IntoAnySurface {
    /// The wrapped surface.
    fn into_any(self) -> AnySurface;
}
macro_rules! into_any_surface {
    ($d:literal, $v:ident) => {
        impl IntoAnySurface for Box<dyn Surface<$d>> {
            fn into_any(self) -> AnySurface {
                AnySurface::$v(self)
            }
        }
    };
}
into_any_surface!(1, D1);
into_any_surface!(2, D2);
into_any_surface!(3, D3);
into_any_surface!(4, D4);

fn net_dimension(field: &str, net: &[Vec<Vec<f64>>]) -> Result<usize> {
    let first = net.first().ok_or_else(|| DocumentError::new(field, "expected at least 1 row, got 0"))?;
    let d = dimension_of(&format!("{field}[0]"), first)?;
    for (i, row) in net.iter().enumerate() {
        let di = dimension_of(&format!("{field}[{i}]"), row)?;
        if di != d {
            return Err(DocumentError::new(
                format!("{field}[{i}]"),
                format!("expected points of {d} coordinates like the first row, got {di}"),
            ));
        }
    }
    Ok(d)
}

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

fn net_points<const D: usize>(net: &[Vec<Vec<f64>>]) -> Vec<Vec<Point<D>>> {
    net.iter().map(|r| to_points::<D>(r)).collect()
}

impl SurfaceDocument {
    /// Parses the fields of a document of type `ty`; `Ok(None)` if `ty` is not a surface.
    pub(crate) fn parse_typed(ty: &str, rest: Value) -> Result<Option<Self>> {
        use SurfaceDocument as S;
        Ok(Some(match ty {
            "bezier_surface" => S::BezierSurface(fields(rest)?),
            "bspline_surface" => S::BsplineSurface(fields(rest)?),
            "nurbs_surface" => S::NurbsSurface(fields(rest)?),
            "plane" => S::Plane(fields(rest)?),
            "cylinder" => S::Cylinder(fields(rest)?),
            "cone" => S::Cone(fields(rest)?),
            "sphere" => S::Sphere(fields(rest)?),
            "torus" => S::Torus(fields(rest)?),
            "mobius" => S::Mobius(fields(rest)?),
            "klein_bottle" => S::KleinBottle(fields(rest)?),
            "enneper" => S::Enneper(fields(rest)?),
            "helicoid" => S::Helicoid(fields(rest)?),
            "seashell" => S::Seashell(fields(rest)?),
            "apple" => S::Apple(fields(rest)?),
            "heart_surface" => S::HeartSurface(fields(rest)?),
            "revolution" => {
                let r: RawRevolution = fields(rest)?;
                S::Revolution(RevolutionDoc {
                    curve: nested(&r.curve, "curve")?,
                    axis_point: r.axis_point,
                    axis: r.axis,
                    angle: r.angle,
                })
            }
            "ruled" => {
                let r: RawRuled = fields(rest)?;
                S::Ruled(RuledDoc { first: nested(&r.first, "first")?, second: nested(&r.second, "second")? })
            }
            "extrusion" => {
                let r: RawExtrusion = fields(rest)?;
                S::Extrusion(ExtrusionDoc { curve: nested(&r.curve, "curve")?, direction: r.direction })
            }
            "coons" => {
                let r: RawCoons = fields(rest)?;
                if r.blend != "linear" && r.blend != "cubic" {
                    return Err(DocumentError::new(
                        "blend",
                        format!("expected \"linear\" or \"cubic\", got \"{}\"", r.blend),
                    ));
                }
                S::Coons(CoonsDoc {
                    bottom: nested(&r.bottom, "bottom")?,
                    top: nested(&r.top, "top")?,
                    left: nested(&r.left, "left")?,
                    right: nested(&r.right, "right")?,
                    blend: r.blend,
                })
            }
            "blending_spline_surface" => {
                S::BlendingSplineSurface(crate::blending::BlendingSplineSurfaceDoc::parse(rest)?)
            }
            "trimmed" => {
                let r: RawTrimmed = fields(rest)?;
                S::Trimmed(TrimmedDoc {
                    surface: nested_surface(&r.surface, "surface")?,
                    outer: r.outer.as_ref().map(|o| nested(o, "outer")).transpose()?,
                    holes: r
                        .holes
                        .iter()
                        .enumerate()
                        .map(|(i, h)| nested(h, &format!("holes[{i}]")).map(|b| *b))
                        .collect::<Result<_>>()?,
                })
            }
            "sweep" => {
                let r: RawSweep = fields(rest)?;
                S::Sweep(SweepDoc { profile: nested(&r.profile, "profile")?, path: nested(&r.path, "path")? })
            }
            _ => return Ok(None),
        }))
    }

    /// The document as JSON.
    pub fn to_value(&self) -> Value {
        serde_json::to_value(self).expect("documents serialise")
    }

    /// The dimension of the surface's points (3 for model surfaces).
    pub fn dimension(&self) -> Result<usize> {
        match self {
            SurfaceDocument::BezierSurface(d) => net_dimension("control_points", &d.control_points),
            SurfaceDocument::BsplineSurface(d) => net_dimension("control_points", &d.control_points),
            SurfaceDocument::NurbsSurface(d) => net_dimension("control_points", &d.control_points),
            SurfaceDocument::Ruled(d) => same_dimension(&[("first", &d.first), ("second", &d.second)]),
            SurfaceDocument::Trimmed(d) => d.surface.dimension().map_err(|e| e.within("surface")),
            SurfaceDocument::BlendingSplineSurface(d) => d.model.dimension().map_err(|e| e.within("model")),
            SurfaceDocument::Extrusion(d) => {
                let dim = d.curve.dimension().map_err(|e| e.within("curve"))?;
                if d.direction.len() != dim {
                    return Err(DocumentError::new(
                        "direction",
                        format!("expected {dim} coordinates like the curve, got {}", d.direction.len()),
                    ));
                }
                Ok(dim)
            }
            SurfaceDocument::Coons(d) => {
                same_dimension(&[("bottom", &d.bottom), ("top", &d.top), ("left", &d.left), ("right", &d.right)])
            }
            _ => Ok(3),
        }
    }

    /// Builds the surface.
    pub fn build(&self) -> Result<AnySurface> {
        let dim = self.dimension()?;
        with_dimension!(dim, "control_points", D => Ok(self.build_in::<D>()?.into_any()))
    }

    /// Builds the surface in dimension D (the document's).
    pub fn build_in<const D: usize>(&self) -> Result<Box<dyn Surface<D>>> {
        use SurfaceDocument as S;
        let s: Box<dyn Surface<D>> = match self {
            S::BezierSurface(d) => Box::new(BezierSurface::new(net_points::<D>(&d.control_points))?),
            S::BsplineSurface(d) => {
                check_finite_list("knots_u", &d.knots_u)?;
                check_finite_list("knots_v", &d.knots_v)?;
                Box::new(BSplineSurface::new(
                    (d.degree_u, d.degree_v),
                    d.knots_u.clone(),
                    d.knots_v.clone(),
                    net_points::<D>(&d.control_points),
                    (d.periodic_u, d.periodic_v),
                )?)
            }
            S::NurbsSurface(d) => {
                check_finite_list("knots_u", &d.knots_u)?;
                check_finite_list("knots_v", &d.knots_v)?;
                for (i, row) in d.weights.iter().enumerate() {
                    check_finite_list(&format!("weights[{i}]"), row)?;
                }
                Box::new(NurbsSurface::new(
                    (d.degree_u, d.degree_v),
                    d.knots_u.clone(),
                    d.knots_v.clone(),
                    net_points::<D>(&d.control_points),
                    d.weights.clone(),
                    (d.periodic_u, d.periodic_v),
                )?)
            }
            S::Trimmed(d) => {
                let loop2 = |c: &CurveDocument, field: &str| -> Result<Box<dyn splinekit::curve::Curve<2>>> {
                    if c.dimension().map_err(|e| e.within(field))? != 2 {
                        return Err(DocumentError::new(
                            field,
                            "a trimming loop must be a 2-D curve in the (u, v) domain",
                        ));
                    }
                    c.build_in::<2>().map_err(|e| e.within(field))
                };
                let outer = d.outer.as_ref().map(|o| loop2(o, "outer")).transpose()?;
                let holes: Vec<Box<dyn splinekit::curve::Curve<2>>> =
                    d.holes.iter().enumerate().map(|(i, h)| loop2(h, &format!("holes[{i}]"))).collect::<Result<_>>()?;
                let hole_refs: Vec<&dyn splinekit::curve::Curve<2>> = holes.iter().map(|h| h.as_ref()).collect();
                Box::new(TrimmedSurface::new(
                    d.surface.build_in::<D>().map_err(|e| e.within("surface"))?,
                    outer.as_deref(),
                    &hole_refs,
                )?)
            }
            S::BlendingSplineSurface(d) => Box::new(d.build_in::<D>()?),
            S::Ruled(d) => Box::new(RuledSurface::new(
                d.first.build_in::<D>().map_err(|e| e.within("first"))?,
                d.second.build_in::<D>().map_err(|e| e.within("second"))?,
            )?),
            S::Extrusion(d) => Box::new(Extrusion::new(
                d.curve.build_in::<D>().map_err(|e| e.within("curve"))?,
                to_point::<D>("direction", &d.direction)?,
            )?),
            S::Coons(d) => Box::new(CoonsPatch::new(
                d.bottom.build_in::<D>().map_err(|e| e.within("bottom"))?,
                d.top.build_in::<D>().map_err(|e| e.within("top"))?,
                d.left.build_in::<D>().map_err(|e| e.within("left"))?,
                d.right.build_in::<D>().map_err(|e| e.within("right"))?,
                if d.blend == "cubic" { CoonsBlend::Cubic } else { CoonsBlend::Linear },
            )?),
            model => {
                let three = |c: &CurveDocument, field: &str| -> Result<Box<dyn splinekit::curve::Curve<3>>> {
                    if c.dimension().map_err(|e| e.within(field))? != 3 {
                        return Err(DocumentError::new(field, "must be a 3-D curve"));
                    }
                    c.build_in::<3>().map_err(|e| e.within(field))
                };
                let s3: Box<dyn Surface<3>> = match model {
                    S::Sweep(d) => Box::new(SweepSurface::new(three(&d.profile, "profile")?, three(&d.path, "path")?)?),
                    S::Revolution(d) => {
                        if d.curve.dimension().map_err(|e| e.within("curve"))? != 3 {
                            return Err(DocumentError::new("curve", "the profile of a revolution must be a 3-D curve"));
                        }
                        Box::new(RevolvedSurface::new(
                            d.curve.build_in::<3>().map_err(|e| e.within("curve"))?,
                            to_point("axis_point", &d.axis_point)?,
                            to_point("axis", &d.axis)?,
                            d.angle,
                        )?)
                    }
                    S::Plane(d) => Box::new(Plane::new(
                        to_point("origin", &d.origin)?,
                        to_point("u_axis", &d.u_axis)?,
                        to_point("v_axis", &d.v_axis)?,
                    )?),
                    S::Cylinder(d) => Box::new(Cylinder::new(d.radius, d.height)?),
                    S::Cone(d) => Box::new(Cone::new(d.radius, d.height)?),
                    S::Sphere(d) => Box::new(Sphere::new(d.radius)?),
                    S::Torus(d) => Box::new(Torus::new(d.major_radius, d.minor_radius)?),
                    S::Mobius(d) => Box::new(MobiusStrip::new(d.radius, d.half_width)?),
                    S::KleinBottle(d) => Box::new(KleinBottle::new(d.radius)?),
                    S::Enneper(d) => Box::new(Enneper::new(d.extent)?),
                    S::Helicoid(d) => Box::new(Helicoid::new(d.radius, d.pitch, d.turns)?),
                    S::Seashell(d) => Box::new(Seashell::new(d.a, d.b, d.c, d.turns)?),
                    S::Apple(d) => Box::new(Apple::new(d.scale)?),
                    S::HeartSurface(d) => Box::new(HeartSurface::new(d.scale)?),
                    _ => unreachable!("handled above"),
                };
                let any: Box<dyn std::any::Any> = Box::new(s3);
                return any
                    .downcast::<Box<dyn Surface<D>>>()
                    .map(|b| *b)
                    .map_err(|_| DocumentError::new("type", "model surfaces are 3-D"));
            }
        };
        Ok(s)
    }
}
