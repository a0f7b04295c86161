//! Curve shape documents: one struct per `type`, parsed with exact field paths in errors
//! and unknown fields refused.

use serde::de::DeserializeOwned;
use serde::{Deserialize, Serialize};
use serde_json::Value;

pub use crate::blending::{BlendingSplineDoc, LocalDoc};
use crate::defaults::*;
use crate::error::{DocumentError, Result};

/// `{"type":"bezier","control_points":[[x,y],...]}`
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct BezierDoc {
    /// Control points P_0 … P_n.
    pub control_points: Vec<Vec<f64>>,
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

/// `{"type":"line","from":[...],"to":[...]}`, t ∈ [0, 1].
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct LineDoc {
    /// c(0).
    pub from: Vec<f64>,
    /// c(1).
    pub to: Vec<f64>,
}

/// `{"type":"circle","radius":1}`: (r cos t, r sin t, 0), t ∈ [0, 2π].
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct CircleDoc {
    /// Radius r (default 1).
    #[serde(default = "one")]
    pub radius: f64,
}

/// `{"type":"ellipse","a":2,"b":1}`: (a cos t, b sin t, 0), t ∈ [0, 2π].
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct EllipseDoc {
    /// Semi-axis along x (default 2).
    #[serde(default = "two")]
    pub a: f64,
    /// Semi-axis along y (default 1).
    #[serde(default = "one")]
    pub b: f64,
}

/// `{"type":"helix","radius":1,"pitch":1,"turns":3}`: (r cos t, r sin t, pitch·t/2π).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct HelixDoc {
    /// Radius (default 1).
    #[serde(default = "one")]
    pub radius: f64,
    /// Rise per turn (default 1).
    #[serde(default = "one")]
    pub pitch: f64,
    /// Number of turns; t ∈ [0, 2π·turns] (default 3).
    #[serde(default = "three")]
    pub turns: f64,
}

/// Curves with only a `scale` (default 1): heart, trefoil, butterfly.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ScaleDoc {
    /// Uniform scale (default 1).
    #[serde(default = "one")]
    pub scale: f64,
}

/// `{"type":"rose","radius":1,"n":4,"planar":false}`.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RoseDoc {
    /// Radius r (default 1).
    #[serde(default = "one")]
    pub radius: f64,
    /// Petal parameter n (default 4).
    #[serde(default = "four")]
    pub n: f64,
    /// Drop z = r sin(nt) (default false: the 3-D rose).
    #[serde(default, skip_serializing_if = "is_false")]
    pub planar: bool,
}

/// `{"type":"lissajous","amplitudes":[1,1,0],"frequencies":[3,2,0],"delta":π/2}`.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct LissajousDoc {
    /// (A, B, C) (default [1, 1, 0]).
    #[serde(default = "lissajous_amplitudes")]
    pub amplitudes: [f64; 3],
    /// (a, b, c) (default [3, 2, 0]).
    #[serde(default = "lissajous_frequencies")]
    pub frequencies: [f64; 3],
    /// Phase of x (default π/2).
    #[serde(default = "half_pi")]
    pub delta: f64,
}
fn lissajous_amplitudes() -> [f64; 3] {
    [1.0, 1.0, 0.0]
}
fn lissajous_frequencies() -> [f64; 3] {
    [3.0, 2.0, 0.0]
}

/// `{"type":"bfunction","bfunction":{…}}`: the B-function as a 1-D curve on [0, 1].
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct BFunctionShapeDoc {
    /// The B-function.
    pub bfunction: crate::bfunctions::BFunctionDoc,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawBFunctionShape {
    bfunction: Value,
}

/// `{"type":"blend","first":{…},"second":{…},"overlap":x,"bfunction":{…}}`: the two-curve
/// blend on [0, 1 + x] (B-function default: polynomial smoothness 1, i.e. 3t² − 2t³).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct BlendDoc {
    /// The curve before the overlap.
    pub first: Box<CurveDocument>,
    /// The curve after it.
    pub second: Box<CurveDocument>,
    /// x ∈ (0, 1).
    pub overlap: f64,
    /// The B-function.
    pub bfunction: crate::bfunctions::BFunctionDoc,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawBlend {
    first: Value,
    second: Value,
    overlap: f64,
    #[serde(default)]
    bfunction: Option<Value>,
}

/// A curve shape document.
#[derive(Debug, Clone, PartialEq, Serialize)]
#[serde(tag = "type", rename_all = "snake_case")]
#[allow(missing_docs)]
pub enum CurveDocument {
    Bezier(BezierDoc),
    RationalBezier(RationalBezierDoc),
    Bspline(BSplineDoc),
    Nurbs(NurbsDoc),
    Hermite(HermiteDoc),
    CatmullRom(CatmullRomDoc),
    Line(LineDoc),
    Circle(CircleDoc),
    Ellipse(EllipseDoc),
    Helix(HelixDoc),
    Heart(ScaleDoc),
    Rose(RoseDoc),
    Lissajous(LissajousDoc),
    Trefoil(ScaleDoc),
    Butterfly(ScaleDoc),
    Bfunction(BFunctionShapeDoc),
    Blend(BlendDoc),
    BlendingSpline(BlendingSplineDoc),
}

/// The curve `type` names, for messages.
pub const CURVE_TYPES: &[&str] = &[
    "bezier",
    "rational_bezier",
    "bspline",
    "nurbs",
    "hermite",
    "catmull_rom",
    "line",
    "circle",
    "ellipse",
    "helix",
    "heart",
    "rose",
    "lissajous",
    "trefoil",
    "butterfly",
];

/// Deserialises `value` (an object without its `type`) into `T`, locating errors.
pub(crate) fn fields<T: DeserializeOwned>(value: Value) -> Result<T> {
    serde_path_to_error::deserialize::<_, T>(value).map_err(|e| {
        let path = e.path().to_string();
        let path = if path == "." { String::new() } else { path };
        DocumentError::new(path, e.into_inner().to_string())
    })
}

/// Splits a document object into its `type` and the remaining fields.
pub(crate) fn split_type(value: &Value) -> Result<(String, Value)> {
    let Value::Object(map) = value else {
        return Err(DocumentError::new(
            "",
            format!("expected a JSON object with a \"type\" field, got {}", kind(value)),
        ));
    };
    let mut map = map.clone();
    let ty = match map.remove("type") {
        Some(Value::String(s)) => s,
        Some(other) => return Err(DocumentError::new("type", format!("expected a string, got {}", kind(&other)))),
        None => return Err(DocumentError::new("type", "missing (every shape document needs a \"type\")")),
    };
    Ok((ty, Value::Object(map)))
}

/// JSON kind of a value, for messages.
pub(crate) fn kind(v: &Value) -> &'static str {
    match v {
        Value::Null => "null",
        Value::Bool(_) => "a boolean",
        Value::Number(_) => "a number",
        Value::String(_) => "a string",
        Value::Array(_) => "an array",
        Value::Object(_) => "an object",
    }
}

impl CurveDocument {
    /// Parses a curve document.
    pub fn parse(value: &Value) -> Result<Self> {
        let (ty, rest) = split_type(value)?;
        Self::parse_typed(&ty, rest)?.ok_or_else(|| {
            DocumentError::new(
                "type",
                format!("unknown curve type \"{ty}\" (expected one of {})", CURVE_TYPES.join(", ")),
            )
        })
    }

    /// Parses the fields of a document of type `ty`; `Ok(None)` if `ty` is not a curve.
    pub(crate) fn parse_typed(ty: &str, rest: Value) -> Result<Option<Self>> {
        use CurveDocument as C;
        Ok(Some(match ty {
            "bezier" => C::Bezier(fields(rest)?),
            "rational_bezier" => C::RationalBezier(fields(rest)?),
            "bspline" => C::Bspline(fields(rest)?),
            "nurbs" => C::Nurbs(fields(rest)?),
            "hermite" => C::Hermite(fields(rest)?),
            "catmull_rom" => C::CatmullRom(fields(rest)?),
            "line" => C::Line(fields(rest)?),
            "circle" => C::Circle(fields(rest)?),
            "ellipse" => C::Ellipse(fields(rest)?),
            "helix" => C::Helix(fields(rest)?),
            "heart" => C::Heart(fields(rest)?),
            "rose" => C::Rose(fields(rest)?),
            "lissajous" => C::Lissajous(fields(rest)?),
            "trefoil" => C::Trefoil(fields(rest)?),
            "butterfly" => C::Butterfly(fields(rest)?),
            "bfunction" => {
                let r: RawBFunctionShape = fields(rest)?;
                C::Bfunction(BFunctionShapeDoc {
                    bfunction: crate::bfunctions::BFunctionDoc::parse(&r.bfunction)
                        .map_err(|e| e.within("bfunction"))?,
                })
            }
            "blending_spline" => C::BlendingSpline(BlendingSplineDoc::parse(rest)?),
            "blend" => {
                let r: RawBlend = fields(rest)?;
                let nested = |v: &Value, f: &str| CurveDocument::parse(v).map(Box::new).map_err(|e| e.within(f));
                let bfunction = match &r.bfunction {
                    Some(b) => crate::bfunctions::BFunctionDoc::parse(b).map_err(|e| e.within("bfunction"))?,
                    None => {
                        crate::bfunctions::BFunctionDoc::Polynomial(crate::bfunctions::PolynomialDoc { smoothness: 1 })
                    }
                };
                C::Blend(BlendDoc {
                    first: nested(&r.first, "first")?,
                    second: nested(&r.second, "second")?,
                    overlap: r.overlap,
                    bfunction,
                })
            }
            _ => return Ok(None),
        }))
    }

    /// The document as JSON.
    pub fn to_value(&self) -> Value {
        serde_json::to_value(self).expect("documents serialise")
    }
}
