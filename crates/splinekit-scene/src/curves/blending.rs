//! `blending_spline` documents: blending-spline curves from a model curve or from explicit
//! local curves, with rest transforms and an animation.

use std::sync::Arc;

use serde::{Deserialize, Deserializer, Serialize};
use serde_json::Value;
use splinekit::Point;
use splinekit::blend::{BlendKnots, BlendingCurveOptions, BlendingSplineCurve, KnotSpacing, LocalKind};
use splinekit::curve::Curve;

use super::{CurveDecoration, CurveDocument, CurveForm, Curves, HeartDoc};
use crate::bfunctions::{BFunctionDoc, DEFAULT_BFUNCTION};
use crate::blending::local_points::{self, LocalControlPoints};
use crate::blending::{TrackDoc, tracks};
use crate::budget::{BFUNCTION_EVALUATION, F64, LOCAL_PIECE, ShapeCost};
use crate::error::{DocumentError, Result};
use crate::json::{kind, nested};
use crate::points::{dimension_of, to_point};
use crate::registry::{DocumentKind, self_form_kind_items};
use crate::transforms::LocalTransforms;

/// Where a model-based blending spline puts its knots.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize, Default)]
#[serde(rename_all = "snake_case")]
pub enum KnotSpacingDoc {
    /// Evenly in the model's parameter.
    #[default]
    Uniform,
    /// At equal chord length along the model.
    ChordLength,
    /// At equal arc length along the model, by quadrature (GMlib's `generateCuLenKnotVector`).
    ArcLength,
}

/// The kind of local curves of a blending spline built from a model.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(tag = "type", rename_all = "snake_case", deny_unknown_fields)]
pub enum LocalDoc {
    /// Bézier locals of `degree` Hermite-fitted to the model's derivatives at the knots.
    Bezier {
        /// Degree d (default 3).
        #[serde(default = "three")]
        degree: usize,
    },
    /// The model itself around each knot.
    SubCurve,
    /// The model's osculating circle arc at each knot.
    Arc,
}

fn three() -> usize {
    3
}

/// The `local_curves` of a blending spline: a count (with a `model`) or a list of curve
/// documents (with explicit `knots`).
#[derive(Debug, Clone, PartialEq, Serialize)]
#[serde(untagged)]
pub enum LocalCurves {
    /// Number of local curves made from the model.
    Count(usize),
    /// The local curves themselves.
    List(Vec<CurveDocument>),
}

impl<'de> Deserialize<'de> for LocalCurves {
    fn deserialize<D: Deserializer<'de>>(deserializer: D) -> std::result::Result<Self, D::Error> {
        nested(deserializer, |value| match value {
            Value::Array(list) => list
                .into_iter()
                .enumerate()
                .map(|(i, c)| CurveDocument::from_value(c).map_err(|e| e.within(&format!("[{i}]"))))
                .collect::<Result<_>>()
                .map(LocalCurves::List),
            other => {
                other.as_u64().map(|n| LocalCurves::Count(usize::try_from(n).unwrap_or(usize::MAX))).ok_or_else(|| {
                    DocumentError::new(
                        "",
                        format!("expected a count of local curves or a list of curves, got {}", kind(&other)),
                    )
                })
            }
        })
    }
}

/// `{"type":"blending_spline", "model":{…},"local_curves":n,"local":{…}` or
/// `"knots":[…],"local_curves":[{…},…]`, `"bfunction":{…},"closed":bool,"transforms":…,
/// "animation":[…]}`. The fields that depend on each other are checked by
/// [`BlendingSplineDoc::source`].
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct BlendingSplineDoc {
    /// The model curve (with a count of local curves).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub model: Option<Box<CurveDocument>>,
    /// A count (with a model) or the local curves (with knots); absent with `hermite`.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub local_curves: Option<LocalCurves>,
    /// Hermite data, one entry per knot: [c(c_k), c′(c_k), …, c^{(d)}(c_k)], the same count
    /// d + 1 ≥ 2 at every knot (with `knots`, without `model` and `local_curves`). Each local
    /// is the Bézier of degree d with those derivatives at its knot (GMlib's
    /// `PERBSCurve(DVector<DVector<Vector>>, t)`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub hermite: Option<Vec<Vec<Vec<f64>>>>,
    /// Knots: open, one per local; closed, one more. With a list of local curves, required;
    /// with a model, optional (default: spaced by `knot_spacing`; given, e.g. after a local
    /// was inserted or a knot split, they must span the model's domain). Non-decreasing; an
    /// interior value may appear twice (a split knot: a C⁰ joint).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub knots: Option<Vec<f64>>,
    /// Knot placement along a model (default uniform).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub knot_spacing: Option<KnotSpacingDoc>,
    /// Kind of locals made from a model (default Bézier of degree 3).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub local: Option<LocalDoc>,
    /// The B-function (default ERBS).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub bfunction: Option<BFunctionDoc>,
    /// Closed (default: the model's; explicit locals: open).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub closed: Option<bool>,
    /// Per-local rest transforms, by index.
    #[serde(default, with = "crate::transforms::by_index", skip_serializing_if = "Vec::is_empty")]
    pub transforms: LocalTransforms,
    /// Edited control points of Bézier locals, by index, in each local's rest frame
    /// (overriding the Hermite-fitted ones; see [`crate::blending::local_points`]).
    #[serde(default, with = "crate::blending::local_points::by_index", skip_serializing_if = "Vec::is_empty")]
    pub local_control_points: LocalControlPoints,
    /// Animation tracks.
    #[serde(default, deserialize_with = "crate::json::list", skip_serializing_if = "Vec::is_empty")]
    pub animation: Vec<TrackDoc<usize>>,
    /// The time at which the animation is posed (`None`: the rest pose).
    #[serde(skip)]
    pub time: Option<f64>,
}

/// Where the locals of a blending spline come from (a checked view of the document).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum BlendingSource<'a> {
    /// `local_curves` locals of kind `local` made from `model` at `knots`, or at knots
    /// spaced by `knot_spacing`.
    Model {
        /// The model curve.
        model: &'a CurveDocument,
        /// Number of local curves.
        local_curves: usize,
        /// Kind of locals.
        local: &'a LocalDoc,
        /// Knot placement (when `knots` is `None`).
        knot_spacing: KnotSpacingDoc,
        /// The knots themselves, when given.
        knots: Option<&'a [f64]>,
    },
    /// Bézier locals of Hermite data at the knots.
    Hermite {
        /// Open: one knot per entry; closed: one more (the first plus the period).
        knots: &'a [f64],
        /// Per knot, the position and its first d derivatives.
        data: &'a [Vec<Vec<f64>>],
    },
    /// Explicit knots and local curves, each mapped onto its support.
    Explicit {
        /// Open: one knot per local; closed: one more (the first plus the period).
        knots: &'a [f64],
        /// The local curves.
        local_curves: &'a [CurveDocument],
    },
}

const BEZIER_LOCALS: LocalDoc = LocalDoc::Bezier { degree: 3 };

impl BlendingSplineDoc {
    /// The source of the locals: a model with a count, knots with a list of curves, or
    /// knots with Hermite data.
    pub fn source(&self) -> Result<BlendingSource<'_>> {
        if let Some(data) = &self.hermite {
            let clash = [
                ("model", self.model.is_some()),
                ("local_curves", self.local_curves.is_some()),
                ("local", self.local.is_some()),
                ("knot_spacing", self.knot_spacing.is_some()),
            ];
            if let Some((field, _)) = clash.iter().find(|(_, given)| *given) {
                return Err(DocumentError::new(
                    *field,
                    "not with hermite data (each entry of hermite is the data of one Bézier local at its knot)",
                ));
            }
            let knots = self.knots.as_deref().ok_or_else(|| {
                DocumentError::new(
                    "knots",
                    "missing (hermite data is given at knots: one per entry, one more when closed)",
                )
            })?;
            return Ok(BlendingSource::Hermite { knots, data });
        }
        let Some(local_curves) = &self.local_curves else {
            return Err(DocumentError::new(
                "local_curves",
                "missing (a count with a model, a list of curves with knots; or hermite data with knots)",
            ));
        };
        match (&self.model, &self.knots, local_curves) {
            (None, None, _) => Err(DocumentError::new(
                "model",
                "missing (give a model curve, or knots and a list of local curves, or knots and hermite data)",
            )),
            (Some(_), Some(_), _) if self.knot_spacing.is_some() => {
                Err(DocumentError::new("knot_spacing", "not with explicit knots (they are where the locals go)"))
            }
            (Some(model), knots, LocalCurves::Count(n)) => Ok(BlendingSource::Model {
                model,
                local_curves: *n,
                local: self.local.as_ref().unwrap_or(&BEZIER_LOCALS),
                knot_spacing: self.knot_spacing.unwrap_or_default(),
                knots: knots.as_deref(),
            }),
            (Some(_), _, LocalCurves::List(_)) => Err(local_curves_kind(true, "an array")),
            (None, Some(_), LocalCurves::Count(_)) => Err(local_curves_kind(false, "a number")),
            (None, Some(knots), LocalCurves::List(list)) => {
                if self.local.is_some() || self.knot_spacing.is_some() {
                    return Err(DocumentError::new(
                        if self.local.is_some() { "local" } else { "knot_spacing" },
                        "only for blending splines built from a model",
                    ));
                }
                Ok(BlendingSource::Explicit { knots, local_curves: list })
            }
        }
    }

    /// The Hermite data of `hermite` as points of dimension D, checked: the same count of
    /// values at every knot (errors name `hermite[k]` and `hermite[k][j]`).
    pub fn hermite_points<const D: usize>(data: &[Vec<Vec<f64>>]) -> Result<Vec<Vec<Point<D>>>> {
        let order = data.first().map_or(0, Vec::len);
        data.iter()
            .enumerate()
            .map(|(k, values)| {
                if values.len() != order {
                    return Err(DocumentError::new(
                        format!("hermite[{k}]"),
                        format!(
                            "expected {order} values (a position and its derivatives) like hermite[0], got {}",
                            values.len()
                        ),
                    ));
                }
                values.iter().enumerate().map(|(j, p)| to_point::<D>(&format!("hermite[{k}][{j}]"), p)).collect()
            })
            .collect()
    }

    /// The kernel curve in dimension D (the document's), posed at [`Self::time`].
    pub fn curve<const D: usize>(&self) -> Result<BlendingSplineCurve<D>> {
        let b = self.bfunction.as_ref().unwrap_or(&DEFAULT_BFUNCTION).build().map_err(|e| e.within("bfunction"))?;
        let mut bezier_degree = None;
        let mut c = match self.source()? {
            BlendingSource::Model { model, local_curves, local, knot_spacing, knots } => {
                let model: Arc<dyn Curve<D>> = Arc::from(model.build_in::<D>().map_err(|e| e.within("model"))?);
                let closed = self.closed.unwrap_or_else(|| model.is_closed());
                let kind = match local {
                    LocalDoc::Bezier { degree } => {
                        bezier_degree = Some(*degree);
                        LocalKind::Bezier(*degree)
                    }
                    LocalDoc::SubCurve => LocalKind::SubCurve,
                    LocalDoc::Arc => LocalKind::Arc,
                };
                let spacing = match knot_spacing {
                    KnotSpacingDoc::Uniform => KnotSpacing::Uniform,
                    KnotSpacingDoc::ChordLength => KnotSpacing::ChordLength,
                    KnotSpacingDoc::ArcLength => KnotSpacing::ArcLength,
                };
                let options = BlendingCurveOptions { local: kind, bfunction: b, closed: Some(closed), spacing };
                match knots {
                    None => BlendingSplineCurve::from_model(model, local_curves, &options)?,
                    Some(knots) => {
                        let knots = BlendKnots::new(knots.to_vec(), closed)?;
                        if knots.count() != local_curves {
                            return Err(DocumentError::new(
                                "local_curves",
                                format!(
                                    "expected {} local curves for the {} knots of a{} curve, got {local_curves}",
                                    knots.count(),
                                    knots.values().len(),
                                    if closed { " closed" } else { "n open" }
                                ),
                            ));
                        }
                        BlendingSplineCurve::from_model_with_knots(model, knots, &options)?
                    }
                }
            }
            BlendingSource::Hermite { knots, data } => {
                let points = Self::hermite_points::<D>(data)?;
                bezier_degree = Some(points.first().map_or(0, Vec::len).saturating_sub(1));
                let knots = BlendKnots::new(knots.to_vec(), self.closed.unwrap_or(false))?;
                BlendingSplineCurve::from_hermite(knots, points, b)?
            }
            BlendingSource::Explicit { knots, local_curves } => {
                let locals = local_curves
                    .iter()
                    .enumerate()
                    .map(|(i, c)| c.build_in::<D>().map(Arc::from).map_err(|e| e.within(&format!("local_curves[{i}]"))))
                    .collect::<Result<Vec<Arc<dyn Curve<D>>>>>()?;
                BlendingSplineCurve::from_locals(
                    BlendKnots::new(knots.to_vec(), self.closed.unwrap_or(false))?,
                    locals,
                    b,
                )?
            }
        };
        self.edit_locals(&mut c, bezier_degree)?;
        self.pose(&mut c)?;
        Ok(c)
    }

    /// Sets the edited control points of `local_control_points` (Bézier locals of
    /// `degree` only).
    fn edit_locals<const D: usize>(&self, c: &mut BlendingSplineCurve<D>, degree: Option<usize>) -> Result<()> {
        if self.local_control_points.is_empty() {
            return Ok(());
        }
        let Some(degree) = degree else {
            return Err(local_points::not_bezier(match self.local {
                _ if self.model.is_none() => "explicit local curves",
                Some(LocalDoc::SubCurve) => "sub-curve locals",
                _ => "arc locals",
            }));
        };
        let n = c.local_count();
        for (k, points) in &self.local_control_points {
            if *k >= n {
                return Err(DocumentError::new(
                    format!("{}.{k}", local_points::FIELD),
                    format!("local curve {k} does not exist (there are {n})"),
                ));
            }
            let points = local_points::curve_points::<D>(*k, points, degree)?;
            c.set_local_bezier_points(*k, points)?;
        }
        Ok(())
    }

    /// Applies the rest transforms and, at [`Self::time`], the animation.
    fn pose<const D: usize>(&self, c: &mut BlendingSplineCurve<D>) -> Result<()> {
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
        Ok(())
    }
}

/// The error for `local_curves` of the wrong JSON kind for the source.
fn local_curves_kind(with_model: bool, got: &str) -> DocumentError {
    let expected = if with_model {
        "with a model, expected a count of local curves"
    } else {
        "with explicit knots, expected a list of curves"
    };
    DocumentError::new("local_curves", format!("{expected}, got {got}"))
}

impl DocumentKind for BlendingSplineDoc {
    type Family = Curves;
    self_form_kind_items!(SplineView, CurveForm::BlendingSpline);

    /// Checks `local_curves` against `model`/`knots` on the JSON first (the message names
    /// its JSON kind), then the fields, then [`BlendingSplineDoc::source`].
    fn from_fields(fields: Value) -> Result<Self> {
        let given = |key: &str| fields.get(key).is_some_and(|v| !v.is_null());
        if let (Some(local_curves), false) = (fields.get("local_curves"), given("hermite")) {
            match (given("model"), given("knots")) {
                (true, false) if local_curves.as_u64().is_none() => {
                    return Err(local_curves_kind(true, kind(local_curves)));
                }
                (false, true) if !local_curves.is_array() => return Err(local_curves_kind(false, kind(local_curves))),
                _ => {}
            }
        }
        let doc: Self = crate::json::fields(fields)?;
        doc.source()?;
        Ok(doc)
    }
    fn dimension(&self) -> Result<usize> {
        match self.source()? {
            BlendingSource::Model { model, .. } => model.dimension().map_err(|e| e.within("model")),
            BlendingSource::Hermite { data, .. } => {
                let first = dimension_of("hermite[0]", data.first().map_or(&[][..], Vec::as_slice)).map_err(|e| {
                    if data.is_empty() { DocumentError::new("hermite", "the list is empty") } else { e }
                })?;
                for (k, values) in data.iter().enumerate().skip(1) {
                    let d = dimension_of(&format!("hermite[{k}]"), values)?;
                    if d != first {
                        return Err(DocumentError::new(
                            format!("hermite[{k}]"),
                            format!("expected points of dimension {first} like hermite[0], got {d}"),
                        ));
                    }
                }
                Ok(first)
            }
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
    /// Built from a model: the model, and per local what making it costs (Bézier locals:
    /// the model's first d derivatives and a Hermite fit; arcs: two derivatives). A point
    /// evaluates two locals and the B-function; sub-curve locals share one evaluation of
    /// the model (two where `closed` forces an open model shut, on the seam interval).
    /// Explicit locals: each local's cost, and a point evaluates the costliest two.
    fn cost(&self) -> ShapeCost {
        let blend = BFUNCTION_EVALUATION + 50.0;
        match self.source() {
            Err(_) => ShapeCost::new("local_curves", 0.0, 0.0, 0.0),
            Ok(BlendingSource::Model { model, local_curves, local, knot_spacing, .. }) => {
                let m = model.cost().within("model");
                let n = local_curves as f64;
                let d = 4.0;
                let (bytes, build, eval) = match local {
                    LocalDoc::Bezier { degree } => {
                        let q = *degree as f64 + 1.0;
                        (2.0 * n * q * d * F64, n * (m.eval * q + q * q * d), 2.0 * q * q * d)
                    }
                    LocalDoc::SubCurve => {
                        let twice = if self.closed == Some(true) { 2.0 } else { 1.0 };
                        (0.0, n, twice * m.eval)
                    }
                    LocalDoc::Arc => (n * 8.0 * d * F64, n * 3.0 * m.eval, 100.0),
                };
                let spacing = match knot_spacing {
                    KnotSpacingDoc::Uniform => 0.0,
                    KnotSpacingDoc::ChordLength => 256.0 * n * m.eval,
                    // The length table (64 pieces of adaptive Gauss–Legendre) and a Newton
                    // inversion per knot, each a few quadratures.
                    KnotSpacingDoc::ArcLength => (64.0 * 60.0 + n * 600.0) * m.eval,
                };
                let own = ShapeCost::new("local_curves", n * LOCAL_PIECE + bytes, build + spacing, 0.0);
                let mut cost = own.and(m);
                cost.eval = eval + blend;
                cost
            }
            Ok(BlendingSource::Hermite { data, .. }) => {
                // As Bézier locals made from a model, with the data in place of the model.
                let (n, d) = (data.len() as f64, 4.0);
                let q = data.first().map_or(1, Vec::len) as f64;
                let bytes = 3.0 * n * q * d * F64;
                ShapeCost::new("hermite", n * LOCAL_PIECE + bytes, n * q * q * d, 2.0 * q * q * d + blend)
            }
            Ok(BlendingSource::Explicit { local_curves, .. }) => {
                let n = local_curves.len() as f64;
                let own = ShapeCost::new("local_curves", n * LOCAL_PIECE, n, 0.0);
                let (cost, costliest) = local_curves.iter().enumerate().fold((own, 0.0f64), |(acc, most), (i, c)| {
                    let c = c.cost().within(&format!("local_curves[{i}]"));
                    let eval = c.eval;
                    (acc.and(c), most.max(eval))
                });
                ShapeCost { eval: 2.0 * costliest + blend, ..cost }
            }
        }
    }
    fn build_in<const D: usize>(&self) -> Result<Box<dyn Curve<D>>> {
        Ok(Box::new(self.curve::<D>()?))
    }
    /// Ten cubic Bézier locals on the heart curve.
    fn example() -> Self {
        BlendingSplineDoc {
            model: Some(Box::new(CurveDocument::Heart(HeartDoc::default()))),
            local_curves: Some(LocalCurves::Count(10)),
            hermite: None,
            knots: None,
            knot_spacing: None,
            local: None,
            bfunction: None,
            closed: None,
            transforms: Vec::new(),
            local_control_points: Vec::new(),
            animation: Vec::new(),
            time: None,
        }
    }
    fn decoration(&self) -> CurveDecoration<'_> {
        CurveDecoration::LocalCurves(self)
    }
    fn set_time(&mut self, time: f64) {
        self.time = Some(time);
        if let Some(model) = &mut self.model {
            model.set_time(time);
        }
        if let Some(LocalCurves::List(list)) = &mut self.local_curves {
            list.iter_mut().for_each(|c| c.set_time(time));
        }
    }
}
