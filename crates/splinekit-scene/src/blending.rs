//! Blending-spline documents: `blending_spline` (curves) and `blending_spline_surface`,
//! with per-local `transforms` (rest frames) and an `animation` (tracks of motions evaluated
//! at a time T, see [`splinekit::blend::animation`]).

use std::sync::Arc;

use serde::{Deserialize, Serialize};
use serde_json::Value;
use splinekit::blend::{BlendingSplineCurve, BlendingSplineSurface, KnotSpacing, LocalKind, Motion, PatchKind, Track};
use splinekit::curve::Curve;
use splinekit::frame::Affine;
use splinekit::surface::Surface;

use crate::bfunctions::{BFunctionDoc, ErbsDoc};
use crate::curves::{CurveDocument, fields, kind};
use crate::defaults::*;
use crate::error::{DocumentError, Result};
use crate::surfaces::SurfaceDocument;
use crate::transforms::TransformDoc;

fn default_bfunction(value: &Option<Value>) -> Result<BFunctionDoc> {
    match value {
        Some(b) => BFunctionDoc::parse(b).map_err(|e| e.within("bfunction")),
        None => Ok(BFunctionDoc::Erbs(ErbsDoc { alpha: 1.0, beta: 1.0, gamma: 1.0, lambda: 0.5 })),
    }
}

// ---------------------------------------------------------------------------------------
// Motions and tracks.

/// `{"direction":[..],"amplitude":a,"frequency":f,"phase":φ}`.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct OscillateDoc {
    /// Direction of the translation.
    pub direction: Vec<f64>,
    /// Amplitude (default 1).
    #[serde(default = "one")]
    pub amplitude: f64,
    /// Frequency in hertz (default 1).
    #[serde(default = "one")]
    pub frequency: f64,
    /// Phase in radians (default 0).
    #[serde(default)]
    pub phase: f64,
}

/// `{"axis":[..],"speed":ω,"phase":φ,"pivot":[..]}`.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RotateMotionDoc {
    /// Axis (3-D).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub axis: Option<Vec<f64>>,
    /// Radians per second (default 2π: a turn a second).
    #[serde(default = "tau")]
    pub speed: f64,
    /// Phase in radians (default 0).
    #[serde(default)]
    pub phase: f64,
    /// A point on the axis (default: the local origin).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub pivot: Option<Vec<f64>>,
}

/// `{"axis":[..],"amplitude":a,"frequency":f,"phase":φ,"pivot":[..]}`.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SwingDoc {
    /// Axis (3-D).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub axis: Option<Vec<f64>>,
    /// Amplitude in radians.
    pub amplitude: f64,
    /// Frequency in hertz (default 1).
    #[serde(default = "one")]
    pub frequency: f64,
    /// Phase in radians (default 0).
    #[serde(default)]
    pub phase: f64,
    /// A point on the axis (default: the local origin).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub pivot: Option<Vec<f64>>,
}

/// `{"amplitude":a,"frequency":f,"phase":φ}`.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct PulseDoc {
    /// Amplitude (|a| < 1).
    pub amplitude: f64,
    /// Frequency in hertz (default 1).
    #[serde(default = "one")]
    pub frequency: f64,
    /// Phase in radians (default 0).
    #[serde(default)]
    pub phase: f64,
}

fn tau() -> f64 {
    std::f64::consts::TAU
}

/// One motion: `{"oscillate":{…}}`, `{"rotate":{…}}`, `{"swing":{…}}` or `{"pulse":{…}}`.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case", deny_unknown_fields)]
#[allow(missing_docs)]
pub enum MotionDoc {
    Oscillate(OscillateDoc),
    Rotate(RotateMotionDoc),
    Swing(SwingDoc),
    Pulse(PulseDoc),
}

impl MotionDoc {
    /// The kernel motion.
    pub fn motion(&self) -> Motion {
        match self.clone() {
            MotionDoc::Oscillate(d) => Motion::Oscillate {
                direction: d.direction,
                amplitude: d.amplitude,
                frequency: d.frequency,
                phase: d.phase,
            },
            MotionDoc::Rotate(d) => Motion::Rotate { axis: d.axis, speed: d.speed, phase: d.phase, pivot: d.pivot },
            MotionDoc::Swing(d) => Motion::Swing {
                axis: d.axis,
                amplitude: d.amplitude,
                frequency: d.frequency,
                phase: d.phase,
                pivot: d.pivot,
            },
            MotionDoc::Pulse(d) => Motion::Pulse { amplitude: d.amplitude, frequency: d.frequency, phase: d.phase },
        }
    }
}

/// `{"local": k (curves) or [k, l] (surfaces), "motions": [ … ]}`.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct TrackDoc<K> {
    /// Which local piece.
    pub local: K,
    /// Its motions, applied in order.
    pub motions: Vec<MotionDoc>,
}

fn tracks<K: Clone, const D: usize>(docs: &[TrackDoc<K>]) -> Result<Vec<Track<K>>> {
    docs.iter()
        .enumerate()
        .map(|(i, t)| {
            let motions: Vec<Motion> = t.motions.iter().map(MotionDoc::motion).collect();
            for (j, m) in motions.iter().enumerate() {
                m.validate::<D>().map_err(|e| {
                    DocumentError::new(
                        format!("animation[{i}].motions[{j}]"),
                        e.to_string().replacen("invalid ", "", 1),
                    )
                })?;
            }
            Ok(Track { local: t.local.clone(), motions })
        })
        .collect()
}

fn parse_list<T: serde::de::DeserializeOwned>(value: &Option<Value>, field: &str) -> Result<Vec<T>> {
    match value {
        None => Ok(Vec::new()),
        Some(Value::Array(list)) => list
            .iter()
            .enumerate()
            .map(|(i, t)| fields(t.clone()).map_err(|e| e.within(&format!("{field}[{i}]"))))
            .collect(),
        Some(other) => Err(DocumentError::new(field, format!("expected a list, got {}", kind(other)))),
    }
}

/// Per-local transforms: a list (one per local, in order) or an object keyed by index.
fn parse_transforms_by_index(value: &Option<Value>) -> Result<Vec<(usize, TransformDoc)>> {
    match value {
        None => Ok(Vec::new()),
        Some(Value::Array(list)) => list
            .iter()
            .enumerate()
            .map(|(i, t)| Ok((i, fields(t.clone()).map_err(|e| e.within(&format!("transforms[{i}]")))?)))
            .collect(),
        Some(Value::Object(map)) => map
            .iter()
            .map(|(k, t)| {
                let i: usize = k
                    .parse()
                    .map_err(|_| DocumentError::new(format!("transforms.{k}"), "keys must be local-curve indices"))?;
                Ok((i, fields(t.clone()).map_err(|e| e.within(&format!("transforms.{k}")))?))
            })
            .collect(),
        Some(other) => {
            Err(DocumentError::new("transforms", format!("expected a list or an object, got {}", kind(other))))
        }
    }
}

/// Per-patch transforms: rows (a list of n_u lists of n_v transforms) or an object keyed
/// by "k,l".
fn parse_transforms_by_pair(value: &Option<Value>) -> Result<Vec<((usize, usize), TransformDoc)>> {
    match value {
        None => Ok(Vec::new()),
        Some(Value::Array(rows)) => {
            let mut out = Vec::new();
            for (k, row) in rows.iter().enumerate() {
                let Value::Array(row) = row else {
                    return Err(DocumentError::new(
                        format!("transforms[{k}]"),
                        format!("expected a list of transforms (one row of patches), got {}", kind(row)),
                    ));
                };
                for (l, t) in row.iter().enumerate() {
                    out.push(((k, l), fields(t.clone()).map_err(|e| e.within(&format!("transforms[{k}][{l}]")))?));
                }
            }
            Ok(out)
        }
        Some(Value::Object(map)) => map
            .iter()
            .map(|(key, t)| {
                let pair = key
                    .split_once(',')
                    .and_then(|(a, b)| Some((a.trim().parse().ok()?, b.trim().parse().ok()?)))
                    .ok_or_else(|| {
                        DocumentError::new(format!("transforms.{key}"), "keys must be patch indices \"k,l\"")
                    })?;
                Ok((pair, fields(t.clone()).map_err(|e| e.within(&format!("transforms.{key}")))?))
            })
            .collect(),
        Some(other) => {
            Err(DocumentError::new("transforms", format!("expected a list of rows or an object, got {}", kind(other))))
        }
    }
}

// ---------------------------------------------------------------------------------------
// Curves.

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawBlendingSpline {
    #[serde(default)]
    model: Option<Value>,
    local_curves: Value,
    #[serde(default)]
    knots: Option<Vec<f64>>,
    #[serde(default)]
    knot_spacing: Option<KnotSpacingDoc>,
    #[serde(default)]
    local: Option<Value>,
    #[serde(default)]
    bfunction: Option<Value>,
    #[serde(default)]
    closed: Option<bool>,
    #[serde(default)]
    transforms: Option<Value>,
    #[serde(default)]
    animation: Option<Value>,
}

/// Where a model-based blending spline puts its knots.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize, Default)]
#[serde(rename_all = "snake_case")]
pub enum KnotSpacingDoc {
    /// Evenly in the model's parameter.
    #[default]
    Uniform,
    /// At equal chord length along the model.
    ChordLength,
}

/// The kind of local curves of a blending spline built from a model.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(tag = "type", rename_all = "snake_case", deny_unknown_fields)]
pub enum LocalDoc {
    /// Bézier locals of `degree` Hermite-fitted to the model's derivatives at the knots.
    Bezier {
        /// Degree d (default 3).
        #[serde(default = "three_usize")]
        degree: usize,
    },
    /// The model itself around each knot.
    SubCurve,
    /// The model's osculating circle arc at each knot.
    Arc,
}

fn three_usize() -> usize {
    3
}

/// Where the locals of a blending spline come from.
#[derive(Debug, Clone, PartialEq, Serialize)]
#[serde(untagged)]
pub enum BlendingSource {
    /// `model` + a count of `local_curves` of kind `local`.
    Model {
        /// The model curve.
        model: Box<CurveDocument>,
        /// Number of local curves.
        local_curves: usize,
        /// Kind of locals (default Bézier of degree 3).
        local: LocalDoc,
        /// Knot placement (default uniform).
        knot_spacing: KnotSpacingDoc,
    },
    /// Explicit `knots` and a list of `local_curves`, each mapped onto its support.
    Explicit {
        /// Open: one knot per local; closed: one more (the first plus the period).
        knots: Vec<f64>,
        /// The local curves.
        local_curves: Vec<CurveDocument>,
    },
}

/// `{"type":"blending_spline", "model":{…},"local_curves":n,"local":{…}` or
/// `"knots":[…],"local_curves":[{…},…]`, `"bfunction":{…},"closed":bool,"transforms":…,
/// "animation":[…]}`.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct BlendingSplineDoc {
    /// Where the locals come from.
    #[serde(flatten)]
    pub source: BlendingSource,
    /// The B-function (default ERBS).
    pub bfunction: BFunctionDoc,
    /// Closed (default: the model's; explicit locals: open).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub closed: Option<bool>,
    /// Per-local rest transforms, by index.
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub transforms: Vec<(usize, TransformDoc)>,
    /// Animation tracks.
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub animation: Vec<TrackDoc<usize>>,
    /// The time at which the animation is posed (`None`: the rest pose).
    #[serde(skip)]
    pub time: Option<f64>,
}

impl BlendingSplineDoc {
    pub(crate) fn parse(rest: Value) -> Result<Self> {
        let r: RawBlendingSpline = fields(rest)?;
        let source = match (&r.model, &r.knots) {
            (Some(model), None) => {
                let Some(count) = r.local_curves.as_u64() else {
                    return Err(DocumentError::new(
                        "local_curves",
                        format!("with a model, expected a count of local curves, got {}", kind(&r.local_curves)),
                    ));
                };
                let local = match &r.local {
                    Some(v) => fields::<LocalDoc>(v.clone()).map_err(|e| e.within("local"))?,
                    None => LocalDoc::Bezier { degree: 3 },
                };
                BlendingSource::Model {
                    model: CurveDocument::parse(model).map(Box::new).map_err(|e| e.within("model"))?,
                    local_curves: usize::try_from(count).unwrap_or(usize::MAX),
                    local,
                    knot_spacing: r.knot_spacing.unwrap_or_default(),
                }
            }
            (None, Some(knots)) => {
                let Value::Array(list) = &r.local_curves else {
                    return Err(DocumentError::new(
                        "local_curves",
                        format!("with explicit knots, expected a list of curves, got {}", kind(&r.local_curves)),
                    ));
                };
                if r.local.is_some() || r.knot_spacing.is_some() {
                    return Err(DocumentError::new(
                        if r.local.is_some() { "local" } else { "knot_spacing" },
                        "only for blending splines built from a model",
                    ));
                }
                let local_curves = list
                    .iter()
                    .enumerate()
                    .map(|(i, c)| CurveDocument::parse(c).map_err(|e| e.within(&format!("local_curves[{i}]"))))
                    .collect::<Result<_>>()?;
                BlendingSource::Explicit { knots: knots.clone(), local_curves }
            }
            (Some(_), Some(_)) => {
                return Err(DocumentError::new("knots", "give either a model or explicit knots, not both"));
            }
            (None, None) => {
                return Err(DocumentError::new(
                    "model",
                    "missing (give a model curve, or knots and a list of local curves)",
                ));
            }
        };
        Ok(BlendingSplineDoc {
            source,
            bfunction: default_bfunction(&r.bfunction)?,
            closed: r.closed,
            transforms: parse_transforms_by_index(&r.transforms)?,
            animation: parse_list(&r.animation, "animation")?,
            time: None,
        })
    }

    /// The dimension of the points.
    pub fn dimension(&self) -> Result<usize> {
        match &self.source {
            BlendingSource::Model { model, .. } => model.dimension().map_err(|e| e.within("model")),
            BlendingSource::Explicit { local_curves, .. } => {
                let first = local_curves
                    .first()
                    .ok_or_else(|| DocumentError::new("local_curves", "the list is empty"))?
                    .dimension()
                    .map_err(|e| e.within("local_curves[0]"))?;
                for (i, c) in local_curves.iter().enumerate().skip(1) {
                    let d = c.dimension().map_err(|e| e.within(&format!("local_curves[{i}]")))?;
                    if d != first {
                        return Err(DocumentError::new(
                            format!("local_curves[{i}]"),
                            format!("expected a curve of dimension {first} like local_curves[0], got {d}"),
                        ));
                    }
                }
                Ok(first)
            }
        }
    }

    /// Builds the curve in dimension D, posed at [`Self::time`].
    pub fn build_in<const D: usize>(&self) -> Result<BlendingSplineCurve<D>> {
        let b = self.bfunction.build().map_err(|e| e.within("bfunction"))?;
        let mut c = match &self.source {
            BlendingSource::Model { model, local_curves, local, knot_spacing } => {
                let model: Arc<dyn Curve<D>> = Arc::from(model.build_in::<D>().map_err(|e| e.within("model"))?);
                let closed = self.closed.unwrap_or_else(|| model.is_closed());
                let kind = match local {
                    LocalDoc::Bezier { degree } => LocalKind::Bezier(*degree),
                    LocalDoc::SubCurve => LocalKind::SubCurve,
                    LocalDoc::Arc => LocalKind::Arc,
                };
                let spacing = match knot_spacing {
                    KnotSpacingDoc::Uniform => KnotSpacing::Uniform,
                    KnotSpacingDoc::ChordLength => KnotSpacing::ChordLength,
                };
                BlendingSplineCurve::from_model_spaced(model, *local_curves, kind, b, closed, spacing)?
            }
            BlendingSource::Explicit { knots, local_curves } => {
                let locals = local_curves
                    .iter()
                    .enumerate()
                    .map(|(i, c)| c.build_in::<D>().map(Arc::from).map_err(|e| e.within(&format!("local_curves[{i}]"))))
                    .collect::<Result<Vec<Arc<dyn Curve<D>>>>>()?;
                BlendingSplineCurve::from_locals(knots.clone(), locals, b, self.closed.unwrap_or(false))?
            }
        };
        let n = c.local_count();
        for (i, t) in &self.transforms {
            if *i >= n {
                return Err(DocumentError::new(
                    "transforms",
                    format!("local curve {i} does not exist (there are {n})"),
                ));
            }
            let origin = c.origin(*i);
            c.set_transform(*i, t.build::<D>(&format!("transforms[{i}]"), &origin)?);
        }
        let tracks = tracks::<usize, D>(&self.animation)?;
        if let Some((i, t)) = tracks.iter().enumerate().find(|(_, t)| t.local >= n) {
            return Err(DocumentError::new(
                format!("animation[{i}].local"),
                format!("local curve {} does not exist (there are {n})", t.local),
            ));
        }
        if let Some(time) = self.time {
            let rest = c.transforms();
            c.animate(&rest, &tracks, time)?;
        }
        Ok(c)
    }
}

// ---------------------------------------------------------------------------------------
// Surfaces.

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawBlendingSurface {
    model: Value,
    local_surfaces: [usize; 2],
    #[serde(default)]
    local: Option<Value>,
    #[serde(default)]
    bfunction: Option<Value>,
    #[serde(default)]
    closed_u: Option<bool>,
    #[serde(default)]
    closed_v: Option<bool>,
    #[serde(default)]
    transforms: Option<Value>,
    #[serde(default)]
    animation: Option<Value>,
}

/// The kind of local patches.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(tag = "type", rename_all = "snake_case", deny_unknown_fields)]
pub enum LocalPatchDoc {
    /// Bézier patches of degrees [d_u, d_v] Hermite-fitted to the model's mixed partials.
    Bezier {
        /// [d_u, d_v] (default [3, 3]).
        #[serde(default = "bicubic")]
        degree: [usize; 2],
    },
    /// The model itself around each knot pair.
    SubSurface,
}

fn bicubic() -> [usize; 2] {
    [3, 3]
}

/// `{"type":"blending_spline_surface","model":{…},"local_surfaces":[n_u,n_v],"local":{…},
/// "bfunction":{…},"closed_u":…,"closed_v":…,"transforms":…,"animation":[…]}`.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct BlendingSplineSurfaceDoc {
    /// The model surface.
    pub model: Box<SurfaceDocument>,
    /// [n_u, n_v].
    pub local_surfaces: [usize; 2],
    /// Kind of patches (default bicubic Bézier).
    pub local: LocalPatchDoc,
    /// The B-function (default ERBS).
    pub bfunction: BFunctionDoc,
    /// Closed in u (default: the model's).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub closed_u: Option<bool>,
    /// Closed in v (default: the model's).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub closed_v: Option<bool>,
    /// Per-patch rest transforms.
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub transforms: Vec<((usize, usize), TransformDoc)>,
    /// Animation tracks (`local` is [k, l]).
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub animation: Vec<TrackDoc<(usize, usize)>>,
    /// The time at which the animation is posed (`None`: the rest pose).
    #[serde(skip)]
    pub time: Option<f64>,
}

impl BlendingSplineSurfaceDoc {
    pub(crate) fn parse(rest: Value) -> Result<Self> {
        let r: RawBlendingSurface = fields(rest)?;
        let local = match &r.local {
            Some(v) => fields::<LocalPatchDoc>(v.clone()).map_err(|e| e.within("local"))?,
            None => LocalPatchDoc::Bezier { degree: [3, 3] },
        };
        Ok(BlendingSplineSurfaceDoc {
            model: crate::surfaces::nested_surface(&r.model, "model")?,
            local_surfaces: r.local_surfaces,
            local,
            bfunction: default_bfunction(&r.bfunction)?,
            closed_u: r.closed_u,
            closed_v: r.closed_v,
            transforms: parse_transforms_by_pair(&r.transforms)?,
            animation: parse_list(&r.animation, "animation")?,
            time: None,
        })
    }

    /// Builds the surface in dimension D, posed at [`Self::time`].
    pub fn build_in<const D: usize>(&self) -> Result<BlendingSplineSurface<D>> {
        let model: Arc<dyn Surface<D>> = Arc::from(self.model.build_in::<D>().map_err(|e| e.within("model"))?);
        let closed = (
            self.closed_u.unwrap_or_else(|| model.is_closed_u()),
            self.closed_v.unwrap_or_else(|| model.is_closed_v()),
        );
        let kind = match self.local {
            LocalPatchDoc::Bezier { degree } => PatchKind::Bezier(degree[0], degree[1]),
            LocalPatchDoc::SubSurface => PatchKind::SubSurface,
        };
        let b = self.bfunction.build().map_err(|e| e.within("bfunction"))?;
        let counts = (self.local_surfaces[0], self.local_surfaces[1]);
        let mut s = BlendingSplineSurface::from_model(model, counts, kind, b, closed)?;
        let (nu, nv) = s.local_count();
        for ((k, l), t) in &self.transforms {
            if *k >= nu || *l >= nv {
                return Err(DocumentError::new(
                    "transforms",
                    format!("patch [{k}, {l}] does not exist (there are {nu}×{nv})"),
                ));
            }
            let origin = s.origin(*k, *l);
            s.set_transform(*k, *l, t.build::<D>(&format!("transforms[{k}][{l}]"), &origin)?);
        }
        let tracks = tracks::<(usize, usize), D>(&self.animation)?;
        if let Some((i, t)) = tracks.iter().enumerate().find(|(_, t)| t.local.0 >= nu || t.local.1 >= nv) {
            return Err(DocumentError::new(
                format!("animation[{i}].local"),
                format!("patch [{}, {}] does not exist (there are {nu}×{nv})", t.local.0, t.local.1),
            ));
        }
        if let Some(time) = self.time {
            let rest: Vec<Affine<D>> = s.transforms();
            s.animate(&rest, &tracks, time)?;
        }
        Ok(s)
    }
}

// ---------------------------------------------------------------------------------------
// Posing documents at a time.

impl CurveDocument {
    /// Poses every animated blending spline in the document (nested ones too) at `time`.
    pub fn set_time(&mut self, time: f64) {
        match self {
            CurveDocument::BlendingSpline(d) => {
                d.time = Some(time);
                match &mut d.source {
                    BlendingSource::Model { model, .. } => model.set_time(time),
                    BlendingSource::Explicit { local_curves, .. } => {
                        local_curves.iter_mut().for_each(|c| c.set_time(time))
                    }
                }
            }
            CurveDocument::Blend(d) => {
                d.first.set_time(time);
                d.second.set_time(time);
            }
            _ => {}
        }
    }
}

impl SurfaceDocument {
    /// Poses every animated blending spline in the document (nested ones too) at `time`.
    pub fn set_time(&mut self, time: f64) {
        match self {
            SurfaceDocument::BlendingSplineSurface(d) => {
                d.time = Some(time);
                d.model.set_time(time);
            }
            SurfaceDocument::Revolution(d) => d.curve.set_time(time),
            SurfaceDocument::Ruled(d) => {
                d.first.set_time(time);
                d.second.set_time(time);
            }
            SurfaceDocument::Extrusion(d) => d.curve.set_time(time),
            SurfaceDocument::Coons(d) => {
                for c in [&mut d.bottom, &mut d.top, &mut d.left, &mut d.right] {
                    c.set_time(time);
                }
            }
            SurfaceDocument::Sweep(d) => {
                d.profile.set_time(time);
                d.path.set_time(time);
            }
            SurfaceDocument::Trimmed(d) => d.surface.set_time(time),
            _ => {}
        }
    }
}
