//! What the 3-D view keeps between frames, all of it derived from the document and the
//! camera: the composed scene (brought up to date in place during a drag), the
//! blending-spline surfaces kept evaluated, the handles as last drawn and the one under
//! the cursor, the bounds drawn, what changed since the last frame, and the named panel
//! widgets of the last frame (for the handle report). None of it is saved or undone.

use splinekit_render::{RenderScene, compose_with};
use splinekit_scene::scenes::SceneDocument;

use crate::error::StudioError;
use crate::handles::{Handle, handles_with};
use crate::live_surfaces::LiveSurfaces;
use crate::live_view::{self, Changes, KeptPolyline, Lattice};
use crate::view_camera::Projector;

/// How close (pixels) the cursor must be to a handle to grab it.
pub const PICK_RADIUS: f64 = 10.0;

/// An axis-aligned box: its lowest and highest corners.
pub type Bounds = ([f32; 3], [f32; 3]);

/// The box around both (either when the other is `None`).
fn union(a: Option<Bounds>, b: Option<Bounds>) -> Option<Bounds> {
    match (a, b) {
        (Some((lo, hi)), Some((l, h))) => Some((
            [lo[0].min(l[0]), lo[1].min(l[1]), lo[2].min(l[2])],
            [hi[0].max(h[0]), hi[1].max(h[1]), hi[2].max(h[2])],
        )),
        (a, b) => a.or(b),
    }
}

/// The scene as last composed, and what it was composed from.
struct Composed {
    scene: SceneDocument,
    time: Option<f64>,
    composed: RenderScene,
    /// The bounds of `composed`.
    bounds: Option<Bounds>,
    /// Composed afresh (not brought up to date in place during a drag).
    exact: bool,
    /// The live surfaces' meshes, by object ([`live_view::lattices`]).
    lattices: Vec<Option<Lattice>>,
    /// The adaptive curves' polylines kept during a drag ([`live_view::patch`]).
    polylines: Vec<Option<KeptPolyline>>,
}

/// The view's caches.
pub struct ViewCaches {
    /// The handles as last drawn.
    pub handles: Vec<Handle>,
    /// The handle under the cursor.
    pub hovered: Option<Handle>,
    /// Named panel widgets drawn in the last frame and their rectangles (egui points:
    /// left, top, right, bottom), for the handle report (`object 0`, `knots`,
    /// `knots: periodic`, …): what a script clicks.
    pub widgets: Vec<(String, [f32; 4])>,
    /// The bounds of the scene as last drawn.
    pub bounds: Option<Bounds>,
    /// The blending-spline surfaces kept evaluated between compositions.
    pub live: LiveSurfaces,
    /// The last composition.
    composed: Option<Composed>,
    /// What changed in the composition since the last frame ([`Self::finish_frame`]).
    changes: Changes,
}

impl Default for ViewCaches {
    fn default() -> Self {
        ViewCaches {
            handles: Vec::new(),
            hovered: None,
            widgets: Vec::new(),
            bounds: None,
            live: LiveSurfaces::default(),
            composed: None,
            changes: Changes::All,
        }
    }
}

impl ViewCaches {
    /// Brings the composition up to date with `scene` at `time`: reused while only the
    /// camera, hover or selection change; during a drag (`dragging`) brought up to date in
    /// place ([`crate::live_view::patch`]); else composed afresh, blending-spline surfaces
    /// re-evaluated only where their frames changed ([`LiveSurfaces`]). After a drag the
    /// still scene is composed afresh. The handles are made again with it.
    pub fn compose(
        &mut self,
        scene: &SceneDocument,
        time: Option<f64>,
        aspect: f32,
        dragging: bool,
    ) -> Result<(), StudioError> {
        if let Some(c) = &self.composed
            && c.scene == *scene
            && c.time == time
            && (c.exact || dragging)
        {
            return Ok(());
        }
        self.live.update(scene, time);
        if dragging
            && let Some(c) = self.composed.as_mut()
            && c.time == time
            && let Some(changes) = live_view::patch(
                &c.scene,
                scene,
                time,
                aspect,
                &mut c.composed,
                &c.lattices,
                &mut c.polylines,
                &self.live,
            )
        {
            c.scene = scene.clone();
            c.bounds = c.composed.bounds();
            c.exact = false;
            self.changes.merge(changes);
            self.handles = self.visible_handles(scene, time)?;
            return Ok(());
        }
        let live = &self.live;
        let composed = compose_with(scene, time, aspect, &|i| live.surface(i))?;
        let lattices = live_view::lattices(scene, &composed, live);
        self.handles = self.visible_handles(scene, time)?;
        let bounds = composed.bounds();
        self.composed = Some(Composed {
            scene: scene.clone(),
            time,
            composed,
            bounds,
            exact: true,
            lattices,
            polylines: Vec::new(),
        });
        self.changes = Changes::All;
        Ok(())
    }

    /// Ends a frame: the bounds drawn are the composition's and `overlay`'s together
    /// ([`Self::bounds`]). Returns the composition, those bounds and what changed in it
    /// since the last frame (`None` before the first composition).
    pub fn finish_frame(&mut self, overlay: Option<Bounds>) -> Option<(&RenderScene, Option<Bounds>, Changes)> {
        let c = self.composed.as_ref()?;
        self.bounds = union(c.bounds, overlay);
        let changes = std::mem::replace(&mut self.changes, Changes::none());
        Some((&c.composed, self.bounds, changes))
    }

    /// The last composition and its bounds (`None` before the first).
    pub fn composed(&self) -> Option<(&RenderScene, Option<Bounds>)> {
        self.composed.as_ref().map(|c| (&c.composed, c.bounds))
    }

    /// The handles the view may show and pick in `scene` at `time`: local pieces (origins
    /// and Bézier control points) of objects drawn with `local_pieces`, control points of
    /// objects drawn with `control_net`.
    pub fn visible_handles(&self, scene: &SceneDocument, time: Option<f64>) -> Result<Vec<Handle>, StudioError> {
        let live = &self.live;
        let all = handles_with(scene, time, &|i, d| live.built_from(i, d))?;
        let shown = |h: &Handle| {
            let style = &scene.objects[h.object].style;
            if h.kind.piece().is_some() { style.local_pieces } else { style.control_net }
        };
        Ok(all.into_iter().filter(shown).collect())
    }

    /// Moves the hovered handle to where the handles just made put it; one that no longer
    /// exists is let go.
    pub fn follow_hover(&mut self) {
        let hovered = self.hovered.take();
        self.hovered =
            hovered.and_then(|h| self.handles.iter().find(|n| n.object == h.object && n.kind == h.kind).cloned());
    }

    /// The handles the view shows with `selected` picked: [`Self::handles`] without the
    /// control points of local Béziers other than the selected local piece's
    /// ([`Handle::shown_with`]).
    pub fn shown_handles<'a>(&'a self, selected: Option<&'a Handle>) -> impl Iterator<Item = &'a Handle> {
        self.handles.iter().filter(move |h| h.shown_with(selected))
    }

    /// The shown handle within [`PICK_RADIUS`] pixels of `mouse`, the nearest first.
    pub fn pick(&self, selected: Option<&Handle>, projector: &Projector, mouse: [f64; 2]) -> Option<Handle> {
        let mut best: Option<(f64, &Handle)> = None;
        for h in self.shown_handles(selected) {
            if let Some((p, _)) = projector.project(h.position) {
                let d = (p[0] - mouse[0]).hypot(p[1] - mouse[1]);
                if d <= PICK_RADIUS && best.is_none_or(|(b, _)| d < b) {
                    best = Some((d, h));
                }
            }
        }
        best.map(|(_, h)| h.clone())
    }
}
