//! `blending_spline_surface` documents: tensor-product blending splines of local patches
//! made from a model surface, with rest transforms and an animation.

use std::sync::Arc;

use serde::{Deserialize, Serialize};
use splinekit::Interval;
use splinekit::blend::{BlendKnots, BlendingSplineSurface, BlendingSurfaceOptions, PatchKind};
use splinekit::frame::Affine;
use splinekit::surface::Surface;

use super::{SurfaceDecoration, SurfaceDocument, SurfaceForm, Surfaces, TorusDoc};
use crate::bfunctions::{BFunctionDoc, DEFAULT_BFUNCTION};
use crate::blending::local_points::{self, PatchControlPoints};
use crate::blending::{TrackDoc, tracks};
use crate::budget::{BFUNCTION_EVALUATION, F64, LOCAL_PIECE, ShapeCost};
use crate::error::{DocumentError, Result};
use crate::points::{dimension_of, to_point};
use crate::registry::{DocumentKind, self_form_kind_items};
use crate::transforms::PatchTransforms;

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

const BICUBIC_PATCHES: LocalPatchDoc = LocalPatchDoc::Bezier { degree: [3, 3] };

/// `{"type":"blending_spline_surface","model":{…},"local_surfaces":[n_u,n_v],"knots_u":[…],"knots_v":[…],"local":{…},
/// "bfunction":{…},"closed_u":…,"closed_v":…,"transforms":…,"animation":[…]}`.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct BlendingSplineSurfaceDoc {
    /// The model surface (absent with `hermite`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub model: Option<Box<SurfaceDocument>>,
    /// [n_u, n_v] (with a model; with `hermite` the knots give them).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub local_surfaces: Option<[usize; 2]>,
    /// Hermite data, `hermite[k][l][i][j]` = ∂^{i+j}S/∂u^i∂v^j at the knot pair
    /// (u_k, v_l), i ≤ d_u, j ≤ d_v, the same (d_u + 1) × (d_v + 1) at every pair (with
    /// `knots_u` and `knots_v`, without `model` and `local`). Each patch is the Bézier patch
    /// of degrees (d_u, d_v) with those partials at its knot pair (GMlib's
    /// `PERBSSurf(DMatrix<DMatrix<Vector>>, u, v)`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub hermite: Option<Vec<Vec<HermitePartials>>>,
    /// Kind of patches (default bicubic Bézier).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub local: Option<LocalPatchDoc>,
    /// The B-function (default ERBS).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub bfunction: Option<BFunctionDoc>,
    /// The knots in u (n_u values, one more when closed in u), spanning the model's
    /// u-domain; default: uniform. Written by knot-line insertion.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub knots_u: Option<Vec<f64>>,
    /// The knots in v, as `knots_u`.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub knots_v: Option<Vec<f64>>,
    /// Closed in u (default: the model's).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub closed_u: Option<bool>,
    /// Closed in v (default: the model's).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub closed_v: Option<bool>,
    /// Per-patch rest transforms.
    #[serde(default, with = "crate::transforms::by_pair", skip_serializing_if = "Vec::is_empty")]
    pub transforms: PatchTransforms,
    /// Edited control nets of Bézier patches, by `"k,l"`, in each patch's rest frame
    /// (overriding the Hermite-fitted ones; see [`crate::blending::local_points`]).
    #[serde(default, with = "crate::blending::local_points::by_pair", skip_serializing_if = "Vec::is_empty")]
    pub local_control_points: PatchControlPoints,
    /// Animation tracks (`local` is [k, l]).
    #[serde(default, deserialize_with = "crate::json::list", skip_serializing_if = "Vec::is_empty")]
    pub animation: Vec<TrackDoc<(usize, usize)>>,
    /// The time at which the animation is posed (`None`: the rest pose).
    #[serde(skip)]
    pub time: Option<f64>,
}

/// The partials at one knot pair: rows i = 0 … d_u of points j = 0 … d_v.
pub type HermitePartials = Vec<Vec<Vec<f64>>>;

/// Hermite data as kernel points, one list of partials per knot pair, with the degrees.
type HermiteGrid<const D: usize> = (Vec<Vec<splinekit::Point<D>>>, (usize, usize));

/// Where the patches of a blending-spline surface come from (a checked view of the document).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum SurfaceSource<'a> {
    /// [n_u, n_v] patches made from a model.
    Model {
        /// The model surface.
        model: &'a SurfaceDocument,
        /// [n_u, n_v].
        local_surfaces: [usize; 2],
    },
    /// Bézier patches of Hermite data at the knot pairs.
    Hermite {
        /// The knots in u and in v.
        knots: (&'a [f64], &'a [f64]),
        /// `data[k][l][i][j]`, the partial ∂^{i,j} at (u_k, v_l).
        data: &'a [Vec<HermitePartials>],
    },
}

impl BlendingSplineSurfaceDoc {
    /// The source of the patches: a model with counts, or knots with Hermite data.
    pub fn source(&self) -> Result<SurfaceSource<'_>> {
        match (&self.hermite, &self.model) {
            (Some(data), _) => {
                let clash = [
                    ("model", self.model.is_some()),
                    ("local_surfaces", self.local_surfaces.is_some()),
                    ("local", self.local.is_some()),
                ];
                if let Some((field, _)) = clash.iter().find(|(_, given)| *given) {
                    return Err(DocumentError::new(
                        *field,
                        "not with hermite data (each entry of hermite is the data of one Bézier patch at its knot pair)",
                    ));
                }
                let (Some(ku), Some(kv)) = (&self.knots_u, &self.knots_v) else {
                    let missing = if self.knots_u.is_none() { "knots_u" } else { "knots_v" };
                    return Err(DocumentError::new(missing, "missing (hermite data is given at the knot pairs)"));
                };
                Ok(SurfaceSource::Hermite { knots: (ku, kv), data })
            }
            (None, None) => {
                Err(DocumentError::new("model", "missing (give a model surface, or knots and hermite data)"))
            }
            (None, Some(model)) => {
                let local_surfaces = self.local_surfaces.ok_or_else(|| {
                    DocumentError::new(
                        "local_surfaces",
                        "missing (the counts [n_u, n_v] of patches made from the model)",
                    )
                })?;
                Ok(SurfaceSource::Model { model, local_surfaces })
            }
        }
    }

    /// The patch counts [n_u, n_v]: the document's, or those of its Hermite data.
    pub fn counts(&self) -> Result<[usize; 2]> {
        match self.source()? {
            SurfaceSource::Model { local_surfaces, .. } => Ok(local_surfaces),
            SurfaceSource::Hermite { data, .. } => Ok([data.len(), data.first().map_or(0, Vec::len)]),
        }
    }

    /// The Hermite data as points of dimension D, row-major (k·n_v + l, then i·(d_v + 1) + j),
    /// with the degrees (d_u, d_v): every entry checked to have n_v pairs and the shape of
    /// `hermite[0][0]` (errors name the entry).
    fn hermite_points<const D: usize>(data: &[Vec<HermitePartials>]) -> Result<HermiteGrid<D>> {
        let first = data
            .first()
            .and_then(|r| r.first())
            .ok_or_else(|| DocumentError::new("hermite", "expected at least one knot pair's partials"))?;
        let rows = first.len();
        let cols = first.first().map_or(0, Vec::len);
        if rows < 2 || cols < 2 {
            return Err(DocumentError::new(
                "hermite[0][0]",
                format!("expected at least 2 × 2 partials (S, S_v; S_u, S_uv), got {rows} × {cols}"),
            ));
        }
        let nv = data[0].len();
        let mut out = Vec::with_capacity(data.len() * nv);
        for (k, row) in data.iter().enumerate() {
            if row.len() != nv {
                return Err(DocumentError::new(
                    format!("hermite[{k}]"),
                    format!("expected {nv} knot pairs like hermite[0], got {}", row.len()),
                ));
            }
            for (l, partials) in row.iter().enumerate() {
                let field = format!("hermite[{k}][{l}]");
                if partials.len() != rows {
                    return Err(DocumentError::new(
                        field,
                        format!("expected {rows} rows of partials like hermite[0][0], got {}", partials.len()),
                    ));
                }
                let mut g = Vec::with_capacity(rows * cols);
                for (i, line) in partials.iter().enumerate() {
                    if line.len() != cols {
                        return Err(DocumentError::new(
                            format!("{field}[{i}]"),
                            format!("expected {cols} partials like hermite[0][0][0], got {}", line.len()),
                        ));
                    }
                    for (j, p) in line.iter().enumerate() {
                        g.push(to_point::<D>(&format!("{field}[{i}][{j}]"), p)?);
                    }
                }
                out.push(g);
            }
        }
        Ok((out, (rows - 1, cols - 1)))
    }

    /// The kernel surface in dimension D (the document's), posed at [`Self::time`].
    pub fn surface<const D: usize>(&self) -> Result<BlendingSplineSurface<D>> {
        let (model, local_surfaces) = match self.source()? {
            SurfaceSource::Model { model, local_surfaces } => (model, local_surfaces),
            SurfaceSource::Hermite { knots: (ku, kv), data } => {
                let (points, degrees) = Self::hermite_points::<D>(data)?;
                let b =
                    self.bfunction.as_ref().unwrap_or(&DEFAULT_BFUNCTION).build().map_err(|e| e.within("bfunction"))?;
                let knots = (
                    BlendKnots::new_as(ku.to_vec(), self.closed_u.unwrap_or(false), "knots_u")?,
                    BlendKnots::new_as(kv.to_vec(), self.closed_v.unwrap_or(false), "knots_v")?,
                );
                let counts = (knots.0.count(), knots.1.count());
                if (data.len(), data[0].len()) != counts {
                    return Err(DocumentError::new(
                        "hermite",
                        format!(
                            "expected {}×{} knot pairs for the knots ({} in u, {} in v), got {}×{}",
                            counts.0,
                            counts.1,
                            ku.len(),
                            kv.len(),
                            data.len(),
                            data[0].len()
                        ),
                    ));
                }
                let mut s = BlendingSplineSurface::from_hermite(knots, points, degrees, b)?;
                self.edit_patches(&mut s, PatchKind::Bezier(degrees.0, degrees.1))?;
                self.pose(&mut s)?;
                return Ok(s);
            }
        };
        let model: Arc<dyn Surface<D>> = Arc::from(model.build_in::<D>().map_err(|e| e.within("model"))?);
        let closed = (
            self.closed_u.unwrap_or_else(|| model.is_closed_u()),
            self.closed_v.unwrap_or_else(|| model.is_closed_v()),
        );
        let kind = match self.local.as_ref().unwrap_or(&BICUBIC_PATCHES) {
            LocalPatchDoc::Bezier { degree } => PatchKind::Bezier(degree[0], degree[1]),
            LocalPatchDoc::SubSurface => PatchKind::SubSurface,
        };
        let b = self.bfunction.as_ref().unwrap_or(&DEFAULT_BFUNCTION).build().map_err(|e| e.within("bfunction"))?;
        let counts = (local_surfaces[0], local_surfaces[1]);
        let options =
            BlendingSurfaceOptions { local: kind, bfunction: b, closed_u: Some(closed.0), closed_v: Some(closed.1) };
        let mut s = if self.knots_u.is_none() && self.knots_v.is_none() {
            BlendingSplineSurface::from_model(model, counts, &options)?
        } else {
            let knots = |given: &Option<Vec<f64>>, i: usize, field: &str, domain: Interval, closed: bool| {
                let knots = match given {
                    Some(k) => BlendKnots::new_as(k.clone(), closed, field)?,
                    None => BlendKnots::uniform(domain, local_surfaces[i], closed, &format!("local_surfaces[{i}]"))?,
                };
                if knots.count() != local_surfaces[i] {
                    return Err(DocumentError::new(
                        format!("local_surfaces[{i}]"),
                        format!(
                            "expected {} patches for the {} {field} of a{} direction, got {}",
                            knots.count(),
                            knots.values().len(),
                            if closed { " closed" } else { "n open" },
                            local_surfaces[i]
                        ),
                    ));
                }
                Ok(knots)
            };
            let ku = knots(&self.knots_u, 0, "knots_u", model.domain_u(), closed.0)?;
            let kv = knots(&self.knots_v, 1, "knots_v", model.domain_v(), closed.1)?;
            BlendingSplineSurface::from_model_with_knots(model, (ku, kv), &options)?
        };
        self.edit_patches(&mut s, kind)?;
        self.pose(&mut s)?;
        Ok(s)
    }

    /// Sets the edited nets of `local_control_points` (Bézier patches only).
    fn edit_patches<const D: usize>(&self, s: &mut BlendingSplineSurface<D>, kind: PatchKind) -> Result<()> {
        if self.local_control_points.is_empty() {
            return Ok(());
        }
        let PatchKind::Bezier(du, dv) = kind else {
            return Err(local_points::not_bezier("sub-surface patches"));
        };
        let (nu, nv) = s.local_count();
        for ((k, l), net) in &self.local_control_points {
            if *k >= nu || *l >= nv {
                return Err(DocumentError::new(
                    format!("{}.{k},{l}", local_points::FIELD),
                    format!("patch [{k}, {l}] does not exist (there are {nu}×{nv})"),
                ));
            }
            let net = local_points::patch_net::<D>((*k, *l), net, (du, dv))?;
            s.set_bezier_net(*k, *l, net)?;
        }
        Ok(())
    }

    /// Applies the rest transforms and, at [`Self::time`], the animation.
    fn pose<const D: usize>(&self, s: &mut BlendingSplineSurface<D>) -> Result<()> {
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
        Ok(())
    }
}

impl DocumentKind for BlendingSplineSurfaceDoc {
    type Family = Surfaces;
    self_form_kind_items!(NetView, SurfaceForm::BlendingSpline);
    /// The fields, then [`BlendingSplineSurfaceDoc::source`].
    fn from_fields(fields: serde_json::Value) -> Result<Self> {
        let doc: Self = crate::json::fields(fields)?;
        doc.source()?;
        Ok(doc)
    }
    fn dimension(&self) -> Result<usize> {
        match self.source()? {
            SurfaceSource::Model { model, .. } => model.dimension().map_err(|e| e.within("model")),
            SurfaceSource::Hermite { data, .. } => {
                let mut dim = None;
                for (k, row) in data.iter().enumerate() {
                    for (l, partials) in row.iter().enumerate() {
                        for (i, line) in partials.iter().enumerate() {
                            let field = format!("hermite[{k}][{l}][{i}]");
                            let d = dimension_of(&field, line)?;
                            if *dim.get_or_insert(d) != d {
                                return Err(DocumentError::new(
                                    field,
                                    format!(
                                        "expected points of dimension {} like hermite[0][0][0], got {d}",
                                        dim.unwrap_or(d)
                                    ),
                                ));
                            }
                        }
                    }
                }
                dim.ok_or_else(|| DocumentError::new("hermite", "expected at least one knot pair's partials"))
            }
        }
    }
    /// The model, and per patch what making it costs (Bézier patches: the model's mixed
    /// partials up to (d_u, d_v) and a Hermite fit). A point evaluates four patches and
    /// two B-functions; sub-surface patches share one evaluation of the model (up to four
    /// where `closed_u`/`closed_v` force an open model shut, on the seam intervals).
    /// Hermite data: as Bézier patches made from a model, with the data in its place.
    fn cost(&self) -> ShapeCost {
        let (model, local_surfaces) = match self.source() {
            Ok(SurfaceSource::Model { model, local_surfaces }) => (model, local_surfaces),
            Ok(SurfaceSource::Hermite { data, .. }) => {
                let n = data.iter().map(Vec::len).sum::<usize>() as f64;
                let first = data.first().and_then(|r| r.first());
                let q = first.map_or(1, |g| g.len() * g.first().map_or(1, Vec::len)) as f64;
                let d = 4.0;
                return ShapeCost::new(
                    "hermite",
                    n * LOCAL_PIECE + 3.0 * n * q * d * F64,
                    n * q * q * d,
                    16.0 * q * d + 2.0 * BFUNCTION_EVALUATION + 100.0,
                );
            }
            Err(_) => return ShapeCost::new("local_surfaces", 0.0, 0.0, 0.0),
        };
        let m = model.cost().within("model");
        let n = local_surfaces[0] as f64 * local_surfaces[1] as f64;
        let d = 4.0;
        let (bytes, build, eval) = match self.local.as_ref().unwrap_or(&BICUBIC_PATCHES) {
            LocalPatchDoc::Bezier { degree } => {
                let q = (degree[0] as f64 + 1.0) * (degree[1] as f64 + 1.0);
                (2.0 * n * q * d * F64, n * (m.eval * q + q * q * d), 4.0 * q * d * 4.0)
            }
            LocalPatchDoc::SubSurface => {
                let forced = |c: Option<bool>| if c == Some(true) { 2.0 } else { 1.0 };
                (0.0, n, forced(self.closed_u) * forced(self.closed_v) * m.eval)
            }
        };
        let own = ShapeCost::new("local_surfaces", n * LOCAL_PIECE + bytes, build, 0.0);
        let mut cost = own.and(m);
        cost.eval = eval + 2.0 * BFUNCTION_EVALUATION + 100.0;
        cost
    }
    fn build_in<const D: usize>(&self) -> Result<Box<dyn Surface<D>>> {
        Ok(Box::new(self.surface::<D>()?))
    }
    /// 6 × 4 bicubic patches on the torus.
    fn example() -> Self {
        BlendingSplineSurfaceDoc {
            model: Some(Box::new(SurfaceDocument::Torus(TorusDoc::default()))),
            local_surfaces: Some([6, 4]),
            hermite: None,
            knots_u: None,
            knots_v: None,
            local: None,
            bfunction: None,
            closed_u: None,
            closed_v: None,
            transforms: Vec::new(),
            local_control_points: Vec::new(),
            animation: Vec::new(),
            time: None,
        }
    }
    fn decoration(&self) -> SurfaceDecoration<'_> {
        SurfaceDecoration::LocalPatches(self)
    }
    fn set_time(&mut self, time: f64) {
        self.time = Some(time);
        if let Some(model) = &mut self.model {
            model.set_time(time);
        }
    }
}
