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
    /// The model surface.
    pub model: Box<SurfaceDocument>,
    /// [n_u, n_v].
    pub local_surfaces: [usize; 2],
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

impl BlendingSplineSurfaceDoc {
    /// The kernel surface in dimension D (the document's), posed at [`Self::time`].
    pub fn surface<const D: usize>(&self) -> Result<BlendingSplineSurface<D>> {
        let model: Arc<dyn Surface<D>> = Arc::from(self.model.build_in::<D>().map_err(|e| e.within("model"))?);
        let closed = (
            self.closed_u.unwrap_or_else(|| model.is_closed_u()),
            self.closed_v.unwrap_or_else(|| model.is_closed_v()),
        );
        let kind = match self.local.as_ref().unwrap_or(&BICUBIC_PATCHES) {
            LocalPatchDoc::Bezier { degree } => PatchKind::Bezier(degree[0], degree[1]),
            LocalPatchDoc::SubSurface => PatchKind::SubSurface,
        };
        let b = self.bfunction.as_ref().unwrap_or(&DEFAULT_BFUNCTION).build().map_err(|e| e.within("bfunction"))?;
        let counts = (self.local_surfaces[0], self.local_surfaces[1]);
        let options =
            BlendingSurfaceOptions { local: kind, bfunction: b, closed_u: Some(closed.0), closed_v: Some(closed.1) };
        let mut s = if self.knots_u.is_none() && self.knots_v.is_none() {
            BlendingSplineSurface::from_model(model, counts, &options)?
        } else {
            let knots = |given: &Option<Vec<f64>>, i: usize, field: &str, domain: Interval, closed: bool| {
                let knots = match given {
                    Some(k) => BlendKnots::new_as(k.clone(), closed, field)?,
                    None => {
                        BlendKnots::uniform(domain, self.local_surfaces[i], closed, &format!("local_surfaces[{i}]"))?
                    }
                };
                if knots.count() != self.local_surfaces[i] {
                    return Err(DocumentError::new(
                        format!("local_surfaces[{i}]"),
                        format!(
                            "expected {} patches for the {} {field} of a{} direction, got {}",
                            knots.count(),
                            knots.values().len(),
                            if closed { " closed" } else { "n open" },
                            self.local_surfaces[i]
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
    fn dimension(&self) -> Result<usize> {
        self.model.dimension().map_err(|e| e.within("model"))
    }
    /// The model, and per patch what making it costs (Bézier patches: the model's mixed
    /// partials up to (d_u, d_v) and a Hermite fit). A point evaluates four patches and
    /// two B-functions; sub-surface patches share one evaluation of the model (up to four
    /// where `closed_u`/`closed_v` force an open model shut, on the seam intervals).
    fn cost(&self) -> ShapeCost {
        let m = self.model.cost().within("model");
        let n = self.local_surfaces[0] as f64 * self.local_surfaces[1] as f64;
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
            model: Box::new(SurfaceDocument::Torus(TorusDoc::default())),
            local_surfaces: [6, 4],
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
        self.model.set_time(time);
    }
}
