//! Blending-spline (GERBS/ERBS) surfaces: S(u, v) = Σ_{k,l} B∘w_k(u) B∘w_l(v) s_{kl}(u, v)
//! over a tensor grid of local surfaces.
//!
//! In the cell [u_k, u_{k+1}) × [v_l, v_{l+1}) the four patches s_ab (a ∈ {k, k+1},
//! b ∈ {l, l+1}) are active, with β₀ = 1 − B(w_u), β₁ = B(w_u), γ₀ = 1 − B(w_v), γ₁ = B(w_v):
//! S = Σ β_a γ_b s_ab, and every partial follows by Leibniz in each direction,
//! ∂^{i,j}S = Σ_{a,b} Σ_{p≤i} Σ_{q≤j} C(i,p) C(j,q) β_a^{(p)} γ_b^{(q)} ∂^{i−p, j−q} s_ab,
//! computed as a blend in u of each v-row followed by a blend in v.
//!
//! Local patches are evaluated at the global (u, v): sub-surfaces of the model, or Bézier
//! patches of degrees (d_u, d_v) on the support [u_{k−1}, u_{k+1}] × [v_{l−1}, v_{l+1}] whose
//! net C = H_u⁻¹ G H_v⁻ᵀ matches the model's mixed partials G_ij = ∂^{i+j}g(u_k, v_l),
//! i ≤ d_u, j ≤ d_v (so with ERBS the surface reproduces all of them at every knot pair).
//! Closed directions have n locals on n intervals (indices wrap; no patch is aliased).
//!
//! Every patch has an affine frame about its origin g(u_k, v_l); a Bézier patch's frame is
//! applied to its net (Bézier patches are affine invariant), a sub-surface's to its values.
//! Moving patch (k, l) changes S only on (u_{k−1}, u_{k+1}) × (v_{l−1}, v_{l+1})
//! ([`BlendingSplineSurface::affected_rects`]).

use std::sync::Arc;

use smallvec::{SmallVec, smallvec};

use super::animation::Track;
use super::hermite::inverse_hermite_matrix;
use super::knots::{BlendKnots, BlendSpan};
use super::leibniz::{blend_derivatives, blend_derivatives_strided};
pub use crate::ParamRect;
use crate::Point;
use crate::basis::{BFunction, Side, bernstein_derivatives};
use crate::curve::Interval;
use crate::error::{Error, Result};
use crate::frame::Affine;
use crate::surface::{Surface, unit_normal};

/// How local patches are made from a model surface.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum PatchKind {
    /// The model itself around the knot pair.
    SubSurface,
    /// The Bézier patch of degrees (d_u, d_v) matching the model's mixed partials up to
    /// those orders at the knot pair.
    Bezier(usize, usize),
}

/// How [`BlendingSplineSurface::from_model`] makes a surface from a model. The defaults
/// are the shape documents': bicubic Bézier patches, the default ERBS and the model's own
/// closedness in each direction.
#[derive(Debug, Clone, PartialEq)]
pub struct BlendingSurfaceOptions {
    /// How each local patch is made from the model.
    pub local: PatchKind,
    /// The B-function blending neighbouring patches (in u and in v).
    pub bfunction: BFunction,
    /// Closed in u (n_u patches on n_u intervals) or open; `None`: as the model is.
    pub closed_u: Option<bool>,
    /// Closed in v; `None`: as the model is.
    pub closed_v: Option<bool>,
}

impl Default for BlendingSurfaceOptions {
    fn default() -> Self {
        BlendingSurfaceOptions {
            local: PatchKind::Bezier(3, 3),
            bfunction: BFunction::erbs_default(),
            closed_u: None,
            closed_v: None,
        }
    }
}

/// A Bézier patch on its support in the global parameters.
#[derive(Clone)]
pub(super) struct HermitePatch<const D: usize> {
    pub(super) degrees: (usize, usize),
    /// The net as fitted (row-major, u first), in the model's coordinates.
    pub(super) net: Vec<Point<D>>,
    /// The net with the frame applied.
    pub(super) world: Vec<Point<D>>,
    pub(super) support: ParamRect,
}

#[derive(Clone)]
pub(super) enum PatchShape<const D: usize> {
    Shared(Arc<dyn Surface<D>>),
    Bezier(HermitePatch<D>),
}

#[derive(Clone)]
pub(super) struct LocalPatch<const D: usize> {
    pub(super) shape: PatchShape<D>,
    pub(super) origin: Point<D>,
    pub(super) transform: Affine<D>,
}

impl<const D: usize> LocalPatch<D> {
    /// Partials ∂^{i,j} for i ≤ du, j ≤ dv at (u, v), frame applied.
    fn eval(&self, u: f64, v: f64, du: usize, dv: usize, out: &mut [Point<D>]) {
        match &self.shape {
            PatchShape::Bezier(p) => {
                let (nu, nv) = (p.degrees.0 + 1, p.degrees.1 + 1);
                let mut bu: SmallVec<[f64; 32]> = smallvec![0.0; (du + 1) * nu];
                let mut bv: SmallVec<[f64; 32]> = smallvec![0.0; (dv + 1) * nv];
                scaled_bernstein(p.degrees.0, p.support.u, u, du, &mut bu);
                scaled_bernstein(p.degrees.1, p.support.v, v, dv, &mut bv);
                let mut row: SmallVec<[Point<D>; 32]> = smallvec![Point::<D>::zeros(); (dv + 1) * nu];
                for a in 0..nu {
                    for j in 0..=dv {
                        row[j * nu + a] =
                            (0..nv).fold(Point::<D>::zeros(), |acc, b| acc + p.world[a * nv + b] * bv[j * nv + b]);
                    }
                }
                for i in 0..=du {
                    for j in 0..=dv {
                        out[i * (dv + 1) + j] =
                            (0..nu).fold(Point::<D>::zeros(), |acc, a| acc + row[j * nu + a] * bu[i * nu + a]);
                    }
                }
            }
            PatchShape::Shared(s) => {
                s.eval_partials(u, v, du, dv, out);
                self.transform.apply_derivatives_about(&self.origin, &mut out[..(du + 1) * (dv + 1)]);
            }
        }
    }
    /// Applies the frame to the model's values: o + T(S − o), T's linear part for partials.
    fn to_world(&self, out: &mut [Point<D>]) {
        self.transform.apply_derivatives_about(&self.origin, out);
    }
    pub(super) fn set_transform(&mut self, t: Affine<D>) {
        self.transform = t;
        if let PatchShape::Bezier(p) = &mut self.shape {
            for (w, c) in p.world.iter_mut().zip(&p.net) {
                *w = t.apply_point_about(&self.origin, c);
            }
        }
    }
}

/// Bernstein derivatives of degree d on `support` at x, with respect to x.
fn scaled_bernstein(d: usize, support: Interval, x: f64, order: usize, out: &mut [f64]) {
    let l = support.length();
    bernstein_derivatives(d, (x - support.start) / l, order, out);
    let mut f = 1.0;
    for r in 1..=order {
        f /= l;
        out[r * (d + 1)..(r + 1) * (d + 1)].iter_mut().for_each(|x| *x *= f);
    }
}

/// A blending-spline surface.
#[derive(Clone)]
pub struct BlendingSplineSurface<const D: usize> {
    /// Patch (k, l) at index k·n_v + l.
    pub(super) patches: Vec<LocalPatch<D>>,
    pub(super) knots_u: BlendKnots,
    pub(super) knots_v: BlendKnots,
    bfunction: BFunction,
    /// The model the patches were made from; `None` for Hermite data.
    pub(super) model: Option<Arc<dyn Surface<D>>>,
    pub(super) kind: PatchKind,
}

impl<const D: usize> BlendingSplineSurface<D> {
    /// `counts` = (n_u, n_v) local patches made from `model` at uniform knots over its
    /// domain as `options` say.
    ///
    /// # Examples
    ///
    /// ```
    /// use std::sync::Arc;
    /// use splinekit::blend::{BlendingSplineSurface, BlendingSurfaceOptions};
    /// use splinekit::surface::Surface;
    /// use splinekit::surface::model::Torus;
    /// // 8×6 bicubic patches on the torus, closed both ways like the model; at every knot
    /// // pair the surface passes through the torus.
    /// let torus = Arc::new(Torus::new(3.0, 1.0).unwrap());
    /// let s = BlendingSplineSurface::from_model(torus.clone(), (8, 6), &BlendingSurfaceOptions::default()).unwrap();
    /// assert!(s.is_closed_u() && s.is_closed_v());
    /// let (u, v) = (s.knots().0.centre(3), s.knots().1.centre(2));
    /// assert!((s.point(u, v) - torus.point(u, v)).norm() < 1e-13);
    /// ```
    pub fn from_model(
        model: Arc<dyn Surface<D>>,
        counts: (usize, usize),
        options: &BlendingSurfaceOptions,
    ) -> Result<Self> {
        let (kind, bfunction) = (options.local, options.bfunction.clone());
        let closed = (
            options.closed_u.unwrap_or_else(|| model.is_closed_u()),
            options.closed_v.unwrap_or_else(|| model.is_closed_v()),
        );
        let knots_u = BlendKnots::uniform(model.domain_u(), counts.0, closed.0, "local_surfaces[0]")?;
        let knots_v = BlendKnots::uniform(model.domain_v(), counts.1, closed.1, "local_surfaces[1]")?;
        Self::built(model, (knots_u, knots_v), kind, bfunction)
    }

    /// Patches made from `model` as `options` say at the given knots in u and v (uneven
    /// ones, as [`Self::insert_knot_line`] leaves them; closedness is the knots' own, and
    /// `options.closed_u`/`closed_v` are not read). Each knot vector must span the model's
    /// domain in its direction (its first and last value the ends, to 10⁻¹² times
    /// max(length, 1)); errors name `knots_u` or `knots_v` and the numbers.
    ///
    /// # Examples
    ///
    /// ```
    /// use std::sync::Arc;
    /// use splinekit::blend::{BlendKnots, BlendingSplineSurface, BlendingSurfaceOptions};
    /// use splinekit::surface::Surface;
    /// use splinekit::surface::model::Plane;
    /// use splinekit::Point;
    /// let plane: Arc<dyn Surface<3>> = Arc::new(Plane::new(Point::<3>::zeros(), Point::<3>::x(), Point::<3>::y()).unwrap());
    /// let (du, dv) = (plane.domain_u(), plane.domain_v());
    /// let ku = BlendKnots::new(vec![du.start, du.lerp(0.2), du.end], false).unwrap();
    /// let kv = BlendKnots::new(vec![dv.start, dv.end], false).unwrap();
    /// let s = BlendingSplineSurface::from_model_with_knots(plane.clone(), (ku, kv), &BlendingSurfaceOptions::default()).unwrap();
    /// assert_eq!(s.local_count(), (3, 2));
    /// let (u, v) = (du.lerp(0.3), dv.lerp(0.6));
    /// assert!((s.point(u, v) - plane.point(u, v)).norm() < 1e-12);
    /// ```
    pub fn from_model_with_knots(
        model: Arc<dyn Surface<D>>,
        (knots_u, knots_v): (BlendKnots, BlendKnots),
        options: &BlendingSurfaceOptions,
    ) -> Result<Self> {
        knots_u.check_spans(model.domain_u(), "knots_u")?;
        knots_v.check_spans(model.domain_v(), "knots_v")?;
        Self::built(model, (knots_u, knots_v), options.local, options.bfunction.clone())
    }

    /// The blending-spline surface of Hermite data (GMlib's `PERBSSurf(DMatrix<DMatrix<Vector>>,
    /// u, v)`): `data[k·n_v + l]` holds the mixed partials ∂^{i+j}S/∂u^i∂v^j at the knot
    /// pair (u_k, v_l), i ≤ d_u, j ≤ d_v, row-major (i first, (d_u + 1)(d_v + 1) points), with
    /// `degrees` = (d_u, d_v), each 1 to 12. Patch (k, l) is the Bézier patch of those degrees
    /// on its support whose partials at (u_k, v_l) are the data (C = H_u⁻¹ G H_v⁻ᵀ), its
    /// frame's origin the position ∂^{0,0}. With ERBS the surface reproduces every datum at
    /// every knot pair; with a polynomial B-function the partials up to its smoothness in
    /// each direction. Errors name `hermite` (counts, non-finite values).
    ///
    /// # Examples
    ///
    /// ```
    /// use splinekit::Point;
    /// use splinekit::basis::BFunction;
    /// use splinekit::blend::{BlendKnots, BlendingSplineSurface};
    /// use splinekit::surface::Surface;
    /// // The saddle (u, v, uv) from its value, S_u, S_v, S_uv at the corners of [0, 1]².
    /// let partials = |u: f64, v: f64| vec![
    ///     Point::<3>::new(u, v, u * v), Point::<3>::new(0.0, 1.0, u),
    ///     Point::<3>::new(1.0, 0.0, v), Point::<3>::new(0.0, 0.0, 1.0),
    /// ];
    /// let data = vec![partials(0.0, 0.0), partials(0.0, 1.0), partials(1.0, 0.0), partials(1.0, 1.0)];
    /// let knots = (BlendKnots::new(vec![0.0, 1.0], false).unwrap(), BlendKnots::new(vec![0.0, 1.0], false).unwrap());
    /// let s = BlendingSplineSurface::from_hermite(knots, data, (1, 1), BFunction::erbs_default()).unwrap();
    /// assert!((s.point(0.3, 0.6) - Point::<3>::new(0.3, 0.6, 0.18)).norm() < 1e-14);
    /// ```
    pub fn from_hermite(
        (knots_u, knots_v): (BlendKnots, BlendKnots),
        data: Vec<Vec<Point<D>>>,
        (du, dv): (usize, usize),
        bfunction: BFunction,
    ) -> Result<Self> {
        let (nu, nv) = (knots_u.count(), knots_v.count());
        if nu * nv > MAX_PATCHES {
            return Err(Error::invalid("hermite", format!("at most 10⁶ patches, got {}", nu * nv)));
        }
        if !((1..=12).contains(&du) && (1..=12).contains(&dv)) {
            return Err(Error::invalid(
                "hermite",
                format!("the orders of the partials must be between 1 and 12 in each direction, got [{du}, {dv}]"),
            ));
        }
        if data.len() != nu * nv {
            return Err(Error::invalid(
                "hermite",
                format!("expected {nu}×{nv} entries, one per knot pair, got {}", data.len()),
            ));
        }
        let mut patches = Vec::with_capacity(nu * nv);
        for (i, g) in data.iter().enumerate() {
            let (k, l) = (i / nv, i % nv);
            if g.len() != (du + 1) * (dv + 1) {
                return Err(Error::invalid(
                    format!("hermite[{k}][{l}]"),
                    format!("expected {}×{} partials, got {}", du + 1, dv + 1, g.len()),
                ));
            }
            if let Some(j) = g.iter().position(|p| !p.iter().all(|x| x.is_finite())) {
                return Err(Error::invalid(
                    format!("hermite[{k}][{l}][{}][{}]", j / (dv + 1), j % (dv + 1)),
                    "must be finite",
                ));
            }
            let (uc, vc) = (knots_u.centre(k), knots_v.centre(l));
            let support = ParamRect::new(knots_u.support(k), knots_v.support(l));
            let patch = hermite_patch(g, (du, dv), support, (uc, vc), "the data's").map_err(|e| {
                Error::invalid(
                    format!("hermite[{k}][{l}]"),
                    format!(
                        "no Bézier patch of these data on the support [{}, {}] × [{}, {}] ({e})",
                        support.u.start, support.u.end, support.v.start, support.v.end
                    ),
                )
            })?;
            patches.push(LocalPatch { shape: PatchShape::Bezier(patch), origin: g[0], transform: Affine::identity() });
        }
        Ok(BlendingSplineSurface { patches, knots_u, knots_v, bfunction, model: None, kind: PatchKind::Bezier(du, dv) })
    }

    fn built(
        model: Arc<dyn Surface<D>>,
        (knots_u, knots_v): (BlendKnots, BlendKnots),
        kind: PatchKind,
        bfunction: BFunction,
    ) -> Result<Self> {
        let counts = (knots_u.count(), knots_v.count());
        if counts.0 * counts.1 > MAX_PATCHES {
            return Err(Error::invalid("local_surfaces", format!("at most 10⁶ patches, got {}", counts.0 * counts.1)));
        }
        if let PatchKind::Bezier(du, dv) = kind
            && !((1..=12).contains(&du) && (1..=12).contains(&dv))
        {
            return Err(Error::invalid("local", format!("Bézier degrees must be between 1 and 12, got [{du}, {dv}]")));
        }
        let mut patches = Vec::with_capacity(counts.0 * counts.1);
        for k in 0..counts.0 {
            for l in 0..counts.1 {
                patches.push(make_patch(&model, kind, &knots_u, &knots_v, k, l)?);
            }
        }
        Ok(BlendingSplineSurface { patches, knots_u, knots_v, bfunction, model: Some(model), kind })
    }

    /// The same surface rebuilt from its model with other counts or patch kind (frames
    /// are reset). An error for surfaces of Hermite data, which have no model.
    pub fn rebuilt(&self, counts: (usize, usize), kind: PatchKind) -> Result<Self> {
        let model = self.model.clone().ok_or_else(|| {
            Error::invalid("local_surfaces", "this blending-spline surface was built from Hermite data, not a model")
        })?;
        let options = BlendingSurfaceOptions {
            local: kind,
            bfunction: self.bfunction.clone(),
            closed_u: Some(self.knots_u.is_closed()),
            closed_v: Some(self.knots_v.is_closed()),
        };
        Self::from_model(model, counts, &options)
    }
    /// Replaces the B-function.
    pub fn set_bfunction(&mut self, bfunction: BFunction) {
        self.bfunction = bfunction;
    }
    /// The B-function.
    pub fn bfunction(&self) -> &BFunction {
        &self.bfunction
    }
    /// (n_u, n_v).
    pub fn local_count(&self) -> (usize, usize) {
        (self.knots_u.count(), self.knots_v.count())
    }
    /// The knots in u and in v.
    pub fn knots(&self) -> (&BlendKnots, &BlendKnots) {
        (&self.knots_u, &self.knots_v)
    }
    /// The patch kind.
    pub fn kind(&self) -> PatchKind {
        self.kind
    }
    fn index(&self, k: usize, l: usize) -> usize {
        k * self.knots_v.count() + l
    }
    /// The origin g(u_k, v_l) of patch (k, l).
    pub fn origin(&self, k: usize, l: usize) -> Point<D> {
        self.patches[self.index(k, l)].origin
    }
    /// The frame of patch (k, l).
    pub fn transform(&self, k: usize, l: usize) -> &Affine<D> {
        &self.patches[self.index(k, l)].transform
    }
    /// The support [u_{k−1}, u_{k+1}] × [v_{l−1}, v_{l+1}] of patch (k, l).
    pub fn local_support(&self, k: usize, l: usize) -> ParamRect {
        ParamRect::new(self.knots_u.support(k), self.knots_v.support(l))
    }
    /// Partials of patch (k, l) in world coordinates at the global (u, v), laid out like
    /// [`Surface::eval_partials`].
    pub fn eval_local(&self, (k, l): (usize, usize), (u, v): (f64, f64), du: usize, dv: usize, out: &mut [Point<D>]) {
        self.patches[self.index(k, l)].eval(u, v, du, dv, out)
    }
    /// The control net of a Bézier patch in world coordinates (row-major, u first), with
    /// its degrees; `None` for sub-surface patches.
    pub fn bezier_net(&self, k: usize, l: usize) -> Option<(&[Point<D>], (usize, usize))> {
        match &self.patches[self.index(k, l)].shape {
            PatchShape::Bezier(p) => Some((&p.world, p.degrees)),
            PatchShape::Shared(_) => None,
        }
    }
    /// The control net of a Bézier patch in its rest frame (before its transform; the
    /// model's coordinates, row-major, u first), with its degrees: the Hermite-fitted net
    /// or the one set by [`Self::set_bezier_net`]. `None` for sub-surface patches.
    pub fn bezier_rest_net(&self, k: usize, l: usize) -> Option<(&[Point<D>], (usize, usize))> {
        match &self.patches.get(self.index(k, l))?.shape {
            PatchShape::Bezier(p) => Some((&p.net, p.degrees)),
            PatchShape::Shared(_) => None,
        }
    }
    /// Replaces the net of Bézier patch (k, l) (in its rest frame, row-major, u first, as
    /// [`Self::bezier_rest_net`] gives it), keeping its support, origin and frame, as
    /// GMlib's `PBezierSurf` edits its coefficients; returns the rectangles whose points
    /// changed ([`Self::affected_rects`]). An error when the patch is not a Bézier patch
    /// or `net` is not (d_u + 1)(d_v + 1) finite points.
    pub fn set_bezier_net(&mut self, k: usize, l: usize, net: Vec<Point<D>>) -> Result<Vec<ParamRect>> {
        let (nu, nv) = self.local_count();
        if k >= nu || l >= nv {
            return Err(Error::invalid(
                "local_control_points",
                format!("patch [{k}, {l}] does not exist (there are {nu}×{nv})"),
            ));
        }
        let i = self.index(k, l);
        let patch = &mut self.patches[i];
        let PatchShape::Bezier(p) = &mut patch.shape else {
            return Err(Error::invalid(
                "local_control_points",
                format!("patch [{k}, {l}] is not a Bézier patch (only Bézier patches have control points)"),
            ));
        };
        let (du, dv) = p.degrees;
        if net.len() != (du + 1) * (dv + 1) {
            return Err(Error::invalid(
                "local_control_points",
                format!(
                    "expected {}×{} control points for patch [{k}, {l}] of degrees [{du}, {dv}], got {}",
                    du + 1,
                    dv + 1,
                    net.len()
                ),
            ));
        }
        if let Some(j) = net.iter().position(|q| !q.iter().all(|x| x.is_finite())) {
            return Err(Error::invalid(
                "local_control_points",
                format!("control point [{}, {}] of patch [{k}, {l}] is not finite", j / (dv + 1), j % (dv + 1)),
            ));
        }
        p.world = net.clone();
        p.net = net;
        let transform = patch.transform;
        if transform != Affine::identity() {
            patch.set_transform(transform);
        }
        Ok(self.affected_rects(k, l))
    }
    /// Sets the frame of patch (k, l) about its origin; returns the parameter rectangles
    /// whose points changed.
    pub fn set_transform(&mut self, k: usize, l: usize, transform: Affine<D>) -> Vec<ParamRect> {
        let i = self.index(k, l);
        self.patches[i].set_transform(transform);
        self.affected_rects(k, l)
    }
    /// Poses the animated patches at `time`: patch (k, l)'s frame becomes
    /// track(time) ∘ rest[k·n_v + l]. Returns the rectangles that changed.
    pub fn animate(
        &mut self,
        rest: &[Affine<D>],
        tracks: &[Track<(usize, usize)>],
        time: f64,
    ) -> Result<Vec<ParamRect>> {
        let (nu, nv) = self.local_count();
        if rest.len() != nu * nv {
            return Err(Error::invalid("rest", format!("expected {} rest frames, got {}", nu * nv, rest.len())));
        }
        let mut frames = Vec::with_capacity(tracks.len());
        for (i, track) in tracks.iter().enumerate() {
            let (k, l) = track.local;
            if k >= nu || l >= nv {
                return Err(Error::invalid(
                    format!("animation[{i}].local"),
                    format!("patch [{k}, {l}] does not exist (there are {nu}×{nv})"),
                ));
            }
            let idx = self.index(k, l);
            frames.push(track.at(time, &self.patches[idx].origin)?.after(&rest[idx]));
        }
        let mut rects = Vec::new();
        for (track, frame) in tracks.iter().zip(frames) {
            rects.extend(self.set_transform(track.local.0, track.local.1, frame));
        }
        Ok(rects)
    }
    /// The frames of all patches, row-major (k·n_v + l).
    pub fn transforms(&self) -> Vec<Affine<D>> {
        self.patches.iter().map(|p| p.transform).collect()
    }
    /// Where patch (k, l) takes part: its support clipped to the domain, split at seams.
    pub fn affected_rects(&self, k: usize, l: usize) -> Vec<ParamRect> {
        let mut rects = Vec::new();
        for ru in self.knots_u.affected_ranges(k) {
            for rv in self.knots_v.affected_ranges(l) {
                rects.push(ParamRect::new(ru, rv));
            }
        }
        rects
    }

    /// Both spans, and the four patch indices [(a,b)] = [(0,0), (0,1), (1,0), (1,1)] with
    /// the parameters they are evaluated at.
    fn cell(&self, su: &BlendSpan, sv: &BlendSpan) -> [(usize, f64, f64); 4] {
        let nv = self.knots_v.count();
        let (u0, u1) = (su.t, su.t + su.second_shift);
        let (v0, v1) = (sv.t, sv.t + sv.second_shift);
        [
            (su.first * nv + sv.first, u0, v0),
            (su.first * nv + sv.second, u0, v1),
            (su.second * nv + sv.first, u1, v0),
            (su.second * nv + sv.second, u1, v1),
        ]
    }
}

/// Largest number of patches of a surface.
pub(super) const MAX_PATCHES: usize = 1_000_000;

fn make_patch<const D: usize>(
    model: &Arc<dyn Surface<D>>,
    kind: PatchKind,
    knots_u: &BlendKnots,
    knots_v: &BlendKnots,
    k: usize,
    l: usize,
) -> Result<LocalPatch<D>> {
    let (uc, vc) = (knots_u.centre(k), knots_v.centre(l));
    let origin = model.point(uc, vc);
    let shape = match kind {
        PatchKind::SubSurface => PatchShape::Shared(model.clone()),
        PatchKind::Bezier(du, dv) => {
            let mut g = vec![Point::<D>::zeros(); (du + 1) * (dv + 1)];
            model.eval_partials(uc, vc, du, dv, &mut g);
            let support = ParamRect::new(knots_u.support(k), knots_v.support(l));
            PatchShape::Bezier(hermite_patch(&g, (du, dv), support, (uc, vc), "the model's")?)
        }
    };
    Ok(LocalPatch { shape, origin, transform: Affine::identity() })
}

/// The Bézier patch of degrees (d_u, d_v) on `support` whose mixed partials ∂^{i,j} at
/// `at` (i ≤ d_u, j ≤ d_v) are `g` (row-major, i first): the net C = H_u⁻¹ G H_v⁻ᵀ.
/// `whose` names the partials' source in the error for a non-finite one.
pub(super) fn hermite_patch<const D: usize>(
    g: &[Point<D>],
    (du, dv): (usize, usize),
    support: ParamRect,
    (uc, vc): (f64, f64),
    whose: &str,
) -> Result<HermitePatch<D>> {
    if let Some(i) = g.iter().position(|p| !p.iter().all(|x| x.is_finite())) {
        return Err(Error::numerical(
            "blending-spline surface",
            format!("{whose} partial ({}, {}) at ({uc}, {vc}) is not finite", i / (dv + 1), i % (dv + 1)),
        ));
    }
    let (su, sv) = (support.u, support.v);
    let hu = inverse_hermite_matrix(du, (uc - su.start) / su.length(), su.length())?;
    let hv = inverse_hermite_matrix(dv, (vc - sv.start) / sv.length(), sv.length())?;
    let mut net = vec![Point::<D>::zeros(); (du + 1) * (dv + 1)];
    for a in 0..=du {
        for b in 0..=dv {
            let mut acc = Point::<D>::zeros();
            for i in 0..=du {
                for j in 0..=dv {
                    acc += g[i * (dv + 1) + j] * (hu[(a, i)] * hv[(b, j)]);
                }
            }
            net[a * (dv + 1) + b] = acc;
        }
    }
    Ok(HermitePatch { degrees: (du, dv), world: net.clone(), net, support })
}

impl<const D: usize> Surface<D> for BlendingSplineSurface<D> {
    crate::surface::axes::axes_surface_domains!(knots_u, knots_v);
    /// The knots: where the active patches change (as [`BlendingSplineCurve`]'s
    /// breakpoints).
    ///
    /// [`BlendingSplineCurve`]: crate::blend::BlendingSplineCurve
    fn breakpoints_u(&self) -> Vec<f64> {
        self.knots_u.breakpoints()
    }
    fn breakpoints_v(&self) -> Vec<f64> {
        self.knots_v.breakpoints()
    }

    fn eval_partials(&self, u: f64, v: f64, du: usize, dv: usize, out: &mut [Point<D>]) {
        let su = self.knots_u.locate(u, Side::Right);
        let sv = self.knots_v.locate(v, Side::Right);
        let w = (du + 1) * (dv + 1);
        let mut s: SmallVec<[Point<D>; 36]> = smallvec![Point::<D>::zeros(); 4 * w];
        // Sub-surface patches are all the model: where the four active patches see it at
        // the same point (always but on seam intervals of a model closed by force), the
        // model is evaluated once and each frame applied, so nesting costs one evaluation
        // per level, not four.
        let shared = match (&self.model, self.kind) {
            (Some(model), PatchKind::SubSurface) => {
                (su.second_shift == 0.0 || model.is_closed_u()) && (sv.second_shift == 0.0 || model.is_closed_v())
            }
            _ => false,
        };
        if let (true, Some(model)) = (shared, &self.model) {
            model.eval_partials(su.t, sv.t, du, dv, &mut s[..w]);
            for c in 1..4 {
                s.copy_within(0..w, c * w);
            }
        }
        for (c, (p, pu, pv)) in self.cell(&su, &sv).into_iter().enumerate() {
            if shared {
                self.patches[p].to_world(&mut s[c * w..(c + 1) * w]);
            } else {
                self.patches[p].eval(pu, pv, du, dv, &mut s[c * w..(c + 1) * w]);
            }
        }
        let mut bu: SmallVec<[f64; 8]> = smallvec![0.0; du + 1];
        let mut bv: SmallVec<[f64; 8]> = smallvec![0.0; dv + 1];
        self.bfunction.eval(su.w, &mut bu);
        self.bfunction.eval(sv.w, &mut bv);
        // Blend in u for the two v-rows (each v-order j a strided column of partials), then
        // in v for each u-order i (a contiguous row).
        let mut t: SmallVec<[Point<D>; 18]> = smallvec![Point::<D>::zeros(); 2 * w];
        let (hu, hv) = (1.0 / su.width, 1.0 / sv.width);
        let row = dv + 1;
        for b in 0..2 {
            let (s0, s1) = (&s[b * w..(b + 1) * w], &s[(2 + b) * w..(3 + b) * w]);
            for j in 0..=dv {
                blend_derivatives_strided(&s0[j..], &s1[j..], &bu, hu, &mut t[b * w + j..], row, du + 1);
            }
        }
        for i in 0..=du {
            let (t0, t1) = (&t[i * row..(i + 1) * row], &t[w + i * row..w + (i + 1) * row]);
            blend_derivatives(t0, t1, &bv, hv, &mut out[i * row..(i + 1) * row]);
        }
    }

    /// Bézier patches: the Bernstein bases are computed once per grid row and column, and
    /// each patch's net is contracted with the v-basis once per grid column, so a point
    /// costs four (d_u + 1)-term sums for S, S_u and S_v and the blend.
    fn eval_grid_with_normals(&self, us: &[f64], vs: &[f64], points: &mut [Point<D>], normals: &mut [Point<D>]) {
        let PatchKind::Bezier(du, dv) = self.kind else {
            return default_grid_with_normals(self, us, vs, points, normals);
        };
        let nu = du + 1;
        let columns = self.bezier_grid_columns(us, du);
        let mut bv = vec![0.0; 2 * (dv + 1)];
        let mut rows = vec![Point::<D>::zeros(); self.knots_u.count() * 2 * 2 * nu];
        for (b, &v) in vs.iter().enumerate() {
            let sv = self.knots_v.locate(v, Side::Right);
            let mut gamma = [0.0; 2];
            self.bfunction.eval(sv.w, &mut gamma);
            gamma[1] /= sv.width;
            self.contract_bezier_rows(&sv, (du, dv), &mut bv, &mut rows);
            for (a, span) in columns.spans.iter().enumerate() {
                // S, S_u, S_v of the four active patches (a, b) ∈ {first, second}², then the blend.
                let mut s = [[Point::<D>::zeros(); 3]; 4];
                for (c, (col, row)) in
                    [(span.first, 0), (span.first, 1), (span.second, 0), (span.second, 1)].into_iter().enumerate()
                {
                    let cb = (a * 2 + c / 2) * 2 * nu;
                    let base = ((col * 2 + row) * 2) * nu;
                    s[c] = patch_first_partials(&rows[base..base + 2 * nu], &columns.bases[cb..cb + 2 * nu]);
                }
                let (p, su, sv) = blend_first_partials(&s, columns.beta[a], gamma);
                points[a * vs.len() + b] = p;
                normals[a * vs.len() + b] = unit_normal(&su, &sv).unwrap_or_else(Point::<D>::zeros);
            }
        }
    }
}

/// The u side of the Bézier grid path: per u sample its span, (B(w), B′(w)/Δ) and the
/// degree-d_u Bernstein bases with first derivatives of its two patch columns.
struct BezierGridColumns {
    spans: Vec<BlendSpan>,
    beta: Vec<[f64; 2]>,
    /// `2·(d_u + 1)` values (basis, then derivative) per sample and patch column.
    bases: Vec<f64>,
}

impl<const D: usize> BlendingSplineSurface<D> {
    fn bezier_grid_columns(&self, us: &[f64], du: usize) -> BezierGridColumns {
        let nu = du + 1;
        let mut columns = BezierGridColumns {
            spans: Vec::with_capacity(us.len()),
            beta: Vec::new(),
            bases: vec![0.0; us.len() * 4 * nu],
        };
        for (a, &u) in us.iter().enumerate() {
            let span = self.knots_u.locate(u, Side::Right);
            let mut beta = [0.0; 2];
            self.bfunction.eval(span.w, &mut beta);
            for (c, (col, at)) in
                [(span.first, span.t), (span.second, span.t + span.second_shift)].into_iter().enumerate()
            {
                let base = (a * 2 + c) * 2 * nu;
                scaled_bernstein(du, self.knots_u.support(col), at, 1, &mut columns.bases[base..base + 2 * nu]);
            }
            columns.spans.push(span);
            columns.beta.push([beta[0], beta[1] / span.width]);
        }
        columns
    }

    /// For the v sample of span `sv`: r_a = Σ_b C_ab N_b(v) and r′_a (the net contracted
    /// with the v-basis and its derivative) for every patch column and both active patch
    /// rows, into `rows` (`bv` is scratch for the basis).
    fn contract_bezier_rows(&self, sv: &BlendSpan, (du, dv): (usize, usize), bv: &mut [f64], rows: &mut [Point<D>]) {
        let (nu, nv) = (du + 1, dv + 1);
        for (row, (l, at)) in [(sv.first, sv.t), (sv.second, sv.t + sv.second_shift)].into_iter().enumerate() {
            scaled_bernstein(dv, self.knots_v.support(l), at, 1, bv);
            for k in 0..self.knots_u.count() {
                let PatchShape::Bezier(p) = &self.patches[k * self.knots_v.count() + l].shape else {
                    unreachable!("all patches are Bézier")
                };
                let base = ((k * 2 + row) * 2) * nu;
                for a in 0..nu {
                    let net = &p.world[a * nv..(a + 1) * nv];
                    let (mut val, mut der) = (Point::<D>::zeros(), Point::<D>::zeros());
                    for b in 0..nv {
                        val += net[b] * bv[b];
                        der += net[b] * bv[nv + b];
                    }
                    rows[base + a] = val;
                    rows[base + nu + a] = der;
                }
            }
        }
    }
}

/// S, S_u, S_v of one Bézier patch from its row contractions (r, then r′) and its u-bases
/// (N, then N′): S = Σ r_a N_a, S_u = Σ r_a N′_a, S_v = Σ r′_a N_a.
#[inline(always)]
fn patch_first_partials<const D: usize>(rows: &[Point<D>], bases: &[f64]) -> [Point<D>; 3] {
    let nu = bases.len() / 2;
    let (rv, rd) = rows.split_at(nu);
    let (nb, nd) = bases.split_at(nu);
    let (mut p, mut pu, mut pv) = (Point::<D>::zeros(), Point::<D>::zeros(), Point::<D>::zeros());
    for i in 0..nu {
        p += rv[i] * nb[i];
        pu += rv[i] * nd[i];
        pv += rd[i] * nb[i];
    }
    [p, pu, pv]
}

/// S, S_u, S_v of the blend of four patches `s[2·a + b]` = [S, S_u, S_v] of patch (a, b):
/// the Leibniz blend in u of each patch row (first order for S, S_u; S_v is blended as a
/// value), then in v. `beta` and `gamma` are (B, B′/Δ) in u and in v.
#[inline(always)]
fn blend_first_partials<const D: usize>(
    s: &[[Point<D>; 3]; 4],
    beta: [f64; 2],
    gamma: [f64; 2],
) -> (Point<D>, Point<D>, Point<D>) {
    let row = |r: usize| -> [Point<D>; 3] {
        let (x, y) = (&s[r], &s[2 + r]);
        let mut t = [Point::<D>::zeros(); 3];
        blend_derivatives(&x[..2], &y[..2], &beta, 1.0, &mut t[..2]);
        blend_derivatives(&x[2..], &y[2..], &beta, 1.0, &mut t[2..]);
        t
    };
    let (t0, t1) = (row(0), row(1));
    let (mut p_sv, mut su) = ([Point::<D>::zeros(); 2], [Point::<D>::zeros()]);
    blend_derivatives(&[t0[0], t0[2]], &[t1[0], t1[2]], &gamma, 1.0, &mut p_sv);
    blend_derivatives(&t0[1..2], &t1[1..2], &gamma, 1.0, &mut su);
    (p_sv[0], su[0], p_sv[1])
}

/// The trait's generic grid path, for sub-surface patches.
fn default_grid_with_normals<const D: usize, S: Surface<D> + ?Sized>(
    s: &S,
    us: &[f64],
    vs: &[f64],
    points: &mut [Point<D>],
    normals: &mut [Point<D>],
) {
    let mut values = [Point::<D>::zeros(); 4];
    for (a, &u) in us.iter().enumerate() {
        for (b, &v) in vs.iter().enumerate() {
            s.eval_partials(u, v, 1, 1, &mut values);
            points[a * vs.len() + b] = values[0];
            normals[a * vs.len() + b] = unit_normal(&values[2], &values[1]).unwrap_or_else(Point::<D>::zeros);
        }
    }
}
