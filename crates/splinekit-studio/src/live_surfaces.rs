//! The window's live refresh of blending-spline surfaces: each visible 3-D
//! `blending_spline_surface` object keeps its kernel surface and the samples of the grid the
//! renderer meshes it on ([`SurfaceGridSamples`], made on the first request of that grid).
//! When the document changes only in patch frames or edited Bézier nets (a drag of a patch
//! or of one of its control points, an undo of one, the animation's pose at a new time),
//! the surface built from the new document is kept, and only the rectangles the kernel
//! reports for the patches whose frame, `transforms` entry or `local_control_points` entry
//! changed ([`BlendingSplineSurface::affected_rects`]) are re-evaluated
//! ([`SurfaceGridSamples::refresh`]), as GMlib does; any other change makes the samples
//! afresh. (The new surface is kept rather than the frames set on the old one: a patch's
//! control points in the world are its frame applied to its net, and an identity frame
//! applied is not bitwise the net it was never applied to.) The renderer meshes the kept surface
//! ([`splinekit_render::compose_with`]), whose grid evaluation returns the kept samples, so
//! the scene is the one a full re-evaluation composes, bit for bit (grid samples do not
//! depend on which part of the grid is evaluated).

use std::sync::Mutex;

use splinekit::blend::BlendingSplineSurface;
use splinekit::surface::{Curvatures, FundamentalForms, Surface, SurfaceGridSamples, TrimLoops};
use splinekit::{ParamRect, Point};
use splinekit_scene::blending::BlendingSplineSurfaceDoc;
use splinekit_scene::blending::local_points::PatchControlPoints;
use splinekit_scene::scenes::SceneDocument;
use splinekit_scene::transforms::PatchTransforms;
use splinekit_scene::{Decoration, DocumentError, DocumentKind, ShapeDocument};

/// The kept surfaces of a scene, by object.
#[derive(Default)]
pub struct LiveSurfaces {
    kept: Vec<Option<KeptSurface>>,
    /// The surface the last edit's check built ([`Self::check_build`]): its object and
    /// document; the next update keeps it instead of building it again.
    checked: Option<(usize, BlendingSplineSurfaceDoc, BlendingSplineSurface<3>)>,
    /// Grid samples re-evaluated by the last [`LiveSurfaces::update`] after frames changed.
    pub last_refreshed: usize,
}

/// One object's surface and its grid samples.
pub struct KeptSurface {
    /// The document it was made from, without its frames ([`frameless`]).
    key: BlendingSplineSurfaceDoc,
    /// The document's `transforms`.
    transforms: PatchTransforms,
    /// The document's `local_control_points`.
    nets: PatchControlPoints,
    /// The document as posed, which `surface` was built from.
    posed: BlendingSplineSurfaceDoc,
    surface: BlendingSplineSurface<3>,
    samples: Mutex<Option<SurfaceGridSamples<3>>>,
    /// What the last [`LiveSurfaces::update`] did: `None` when it made the surface afresh;
    /// else the patches whose frame or net changed and the rectangles it refreshed.
    followed: Option<Followed>,
}

/// The patches a frame change moved and the parameter rectangles refreshed for them.
#[derive(Debug, Clone, Default)]
pub struct Followed {
    /// The patches (k, l) whose frame, transform entry or edited net changed.
    pub patches: Vec<(usize, usize)>,
    /// The rectangles re-evaluated (those the kernel reports for them).
    pub rects: Vec<ParamRect>,
}

impl LiveSurfaces {
    /// Brings the kept surfaces up to date with `scene` posed at `time`: frames that
    /// changed are set and their rectangles refreshed; an object whose document changed
    /// otherwise is made afresh (its samples on the next meshing). Objects that cannot be
    /// built are dropped (composing reports their error).
    pub fn update(&mut self, scene: &SceneDocument, time: Option<f64>) {
        self.kept.resize_with(scene.objects.len(), || None);
        self.kept.truncate(scene.objects.len());
        self.last_refreshed = 0;
        for (index, (slot, obj)) in self.kept.iter_mut().zip(&scene.objects).enumerate() {
            let mut shape = obj.shape.clone();
            if let Some(t) = time {
                shape.set_time(t);
            }
            let ShapeDocument::Surface(s) = &shape else {
                *slot = None;
                continue;
            };
            let Decoration::LocalPatches(doc) = s.decoration() else {
                *slot = None;
                continue;
            };
            if obj.style.hidden || doc.dimension().ok() != Some(3) {
                *slot = None;
                continue;
            }
            let key = frameless(doc);
            let built = match self.checked.take() {
                Some((i, checked, s)) if i == index && checked == *doc => Ok(s),
                other => {
                    self.checked = other;
                    doc.surface::<3>()
                }
            };
            let Ok(posed) = built else {
                *slot = None;
                continue;
            };
            let (transforms, nets) = (doc.transforms.clone(), doc.local_control_points.clone());
            match slot {
                Some(kept) if kept.key == key => {
                    kept.posed = doc.clone();
                    self.last_refreshed += kept.follow(posed, transforms, nets)
                }
                _ => {
                    *slot = Some(KeptSurface {
                        key,
                        transforms,
                        nets,
                        posed: doc.clone(),
                        surface: posed,
                        samples: Mutex::new(None),
                        followed: None,
                    })
                }
            }
        }
    }

    /// Builds an edited object's shape to check the edit ([`crate::edit::Edit::apply_with`]):
    /// a 3-D blending-spline surface as the next [`Self::update`] would build it, kept for
    /// it when the scene is not posed at a time (`time` is `None`), so that a drag step
    /// builds the surface once; any other shape as [`crate::edit::check_builds`] does.
    pub fn check_build(
        &mut self,
        object: usize,
        shape: &ShapeDocument,
        time: Option<f64>,
    ) -> Result<(), DocumentError> {
        match shape {
            ShapeDocument::Surface(s) if time.is_none() => match s.decoration() {
                Decoration::LocalPatches(doc) if doc.dimension().ok() == Some(3) => {
                    self.checked = Some((object, doc.clone(), doc.surface::<3>()?));
                    Ok(())
                }
                _ => crate::edit::check_builds(shape),
            },
            _ => crate::edit::check_builds(shape),
        }
    }

    /// The kept surface of object `object`, for [`splinekit_render::compose_with`].
    pub fn surface(&self, object: usize) -> Option<&(dyn Surface<3> + 'static)> {
        self.kept.get(object)?.as_ref().map(|k| k as &(dyn Surface<3> + 'static))
    }

    /// Object `object`'s kept surface and samples.
    pub fn kept(&self, object: usize) -> Option<&KeptSurface> {
        self.kept.get(object)?.as_ref()
    }

    /// Object `object`'s blending-spline surface as built from the document posed at the
    /// last update's time: the one built surface the studio shares (handles, decorations,
    /// meshing).
    pub fn blending(&self, object: usize) -> Option<&BlendingSplineSurface<3>> {
        self.kept(object).map(KeptSurface::blending)
    }

    /// Object `object`'s blending-spline surface if it was built from `doc` (the document
    /// posed as the caller poses it), else `None`.
    pub fn built_from(&self, object: usize, doc: &BlendingSplineSurfaceDoc) -> Option<&BlendingSplineSurface<3>> {
        self.kept(object).filter(|k| k.posed == *doc).map(KeptSurface::blending)
    }
}

/// The document without its frames and edited nets (`transforms`, `local_control_points`,
/// `animation` and the time they are posed at; the model keeps its own time): what must
/// stay the same for frames and nets alone to change.
fn frameless(doc: &BlendingSplineSurfaceDoc) -> BlendingSplineSurfaceDoc {
    let mut key = doc.clone();
    key.transforms.clear();
    key.local_control_points.clear();
    key.animation.clear();
    key.time = None;
    key
}

impl KeptSurface {
    /// Keeps `posed` (built from the document with `transforms` and `nets`) and refreshes
    /// the samples in the rectangles of the patches whose frame, transform entry or edited
    /// net changed; returns the number of samples re-evaluated.
    fn follow(
        &mut self,
        posed: BlendingSplineSurface<3>,
        transforms: PatchTransforms,
        nets: PatchControlPoints,
    ) -> usize {
        let (nu, nv) = posed.local_count();
        let entry = |ts: &PatchTransforms, k: usize, l: usize| ts.iter().rev().find(|(i, _)| *i == (k, l)).cloned();
        let net = |ns: &PatchControlPoints, k: usize, l: usize| ns.iter().rev().find(|(i, _)| *i == (k, l)).cloned();
        let (mut rects, mut patches) = (Vec::new(), Vec::new());
        for k in 0..nu {
            for l in 0..nv {
                let moved = self.surface.transform(k, l) != posed.transform(k, l);
                if moved
                    || entry(&self.transforms, k, l) != entry(&transforms, k, l)
                    || net(&self.nets, k, l) != net(&nets, k, l)
                {
                    rects.extend(posed.affected_rects(k, l));
                    patches.push((k, l));
                }
            }
        }
        self.surface = posed;
        self.transforms = transforms;
        self.nets = nets;
        let samples = self.samples.get_mut().unwrap_or_else(|e| e.into_inner());
        let done = match samples {
            Some(s) if !rects.is_empty() => s.refresh(&self.surface, &rects),
            _ => 0,
        };
        self.followed = Some(Followed { patches, rects });
        done
    }

    /// The blending-spline surface built from the document.
    pub fn blending(&self) -> &BlendingSplineSurface<3> {
        &self.surface
    }

    /// What the last update did: `None` when it made the surface afresh, else the patches
    /// that moved and the rectangles refreshed (both empty when nothing changed).
    pub fn followed(&self) -> Option<&Followed> {
        self.followed.as_ref()
    }

    /// Runs `f` on the kept grid samples (`None` before the first meshing).
    pub fn with_samples<R>(&self, f: impl FnOnce(&SurfaceGridSamples<3>) -> R) -> Option<R> {
        self.samples.lock().unwrap_or_else(|e| e.into_inner()).as_ref().map(f)
    }

    /// The kept samples into `points` and `normals` when they are of the grid `us` × `vs`
    /// (made on the first request); `false` when that grid is not the kept one.
    fn kept_grid(&self, us: &[f64], vs: &[f64], points: &mut [Point<3>], normals: &mut [Point<3>]) -> bool {
        let mut kept = self.samples.lock().unwrap_or_else(|e| e.into_inner());
        let fits = |s: &SurfaceGridSamples<3>| s.us() == us && s.vs() == vs;
        if !kept.as_ref().is_some_and(fits) {
            match SurfaceGridSamples::uniform(&self.surface, us.len(), vs.len()) {
                Ok(s) if fits(&s) => *kept = Some(s),
                _ => return false,
            }
        }
        let Some(s) = kept.as_ref() else { return false };
        if points.len() != s.points().len() || normals.len() != s.normals().len() {
            return false;
        }
        points.copy_from_slice(s.points());
        normals.copy_from_slice(s.normals());
        true
    }
}

/// The kept surface, evaluating as the kernel surface does, except that the grid it keeps
/// comes from its samples.
impl Surface<3> for KeptSurface {
    splinekit::wrapped_surface_domains!(surface);
    fn eval_partials(&self, u: f64, v: f64, du: usize, dv: usize, out: &mut [Point<3>]) {
        self.surface.eval_partials(u, v, du, dv, out)
    }
    fn eval_grid(&self, us: &[f64], vs: &[f64], du: usize, dv: usize, out: &mut [Point<3>]) {
        self.surface.eval_grid(us, vs, du, dv, out)
    }
    fn eval_grid_with_normals(&self, us: &[f64], vs: &[f64], points: &mut [Point<3>], normals: &mut [Point<3>]) {
        if !self.kept_grid(us, vs, points, normals) {
            self.surface.eval_grid_with_normals(us, vs, points, normals)
        }
    }
    fn breakpoints_u(&self) -> Vec<f64> {
        self.surface.breakpoints_u()
    }
    fn breakpoints_v(&self) -> Vec<f64> {
        self.surface.breakpoints_v()
    }
    fn trim_contains(&self, u: f64, v: f64) -> Option<bool> {
        self.surface.trim_contains(u, v)
    }
    fn trim_loops(&self) -> Option<TrimLoops<'_>> {
        self.surface.trim_loops()
    }
    fn point(&self, u: f64, v: f64) -> Point<3> {
        self.surface.point(u, v)
    }
    fn partial(&self, u: f64, v: f64, i: usize, j: usize) -> Point<3> {
        self.surface.partial(u, v, i, j)
    }
    fn normal(&self, u: f64, v: f64) -> Option<Point<3>> {
        self.surface.normal(u, v)
    }
    fn fundamental_forms(&self, u: f64, v: f64) -> Option<FundamentalForms> {
        self.surface.fundamental_forms(u, v)
    }
    fn curvatures(&self, u: f64, v: f64) -> Option<Curvatures> {
        self.surface.curvatures(u, v)
    }
}
