//! The studio's state without a window: the document and its history, the view camera,
//! selection and hover, the drag in progress, the clock; and what the 3-D view draws
//! (the document composed by the renderer's [`compose`], with the view's camera and the
//! handles highlighted). Everything here is testable headless.

use std::path::PathBuf;

use splinekit_render::{LineItem, PointItem, RenderScene, compose_with};
use splinekit_scene::ShapeDocument;
use splinekit_scene::scenes::SceneDocument;

use crate::clock::Clock;
use crate::document;
use crate::edit::{Edit, EditError};
use crate::gesture::{Gesture, GestureKind};
use crate::handles::{Handle, HandleKind, handles_with};
use crate::history::History;
use crate::live_surfaces::LiveSurfaces;
use crate::live_view::{self, Changes, KeptPolyline, Lattice};
use crate::view_camera::{Projector, ViewCamera};

/// The scene as last composed, and what it was composed from.
struct Composed {
    scene: SceneDocument,
    time: Option<f64>,
    composed: RenderScene,
    /// The bounds of `composed`.
    bounds: Option<([f32; 3], [f32; 3])>,
    /// Composed afresh (not brought up to date in place during a drag).
    exact: bool,
    /// The live surfaces' meshes, by object ([`live_view::lattices`]).
    lattices: Vec<Option<Lattice>>,
    /// The adaptive curves' polylines kept during a drag ([`live_view::patch`]).
    polylines: Vec<Option<KeptPolyline>>,
}

/// What the 3-D view draws: the composed scene (kept between frames), the overlays drawn
/// over it (handles, the selected local Bézier's net; with the view's camera, lights and
/// background), the bounds of both, and what changed in the composed scene since the last
/// [`Studio::view_scene`].
pub struct ViewScene<'a> {
    /// The composed scene.
    pub composed: &'a RenderScene,
    /// The overlays, drawn after it; its camera, lights and background are the view's.
    pub overlay: RenderScene,
    /// The bounds of both.
    pub bounds: Option<([f32; 3], [f32; 3])>,
    /// What changed in `composed` since the last view.
    pub changes: Changes,
}

impl ViewScene<'_> {
    /// The composed scene with the overlays' items after its own and the view's camera:
    /// what drawing the two as layers draws.
    pub fn merged(&self) -> RenderScene {
        let mut rs = self.composed.clone();
        rs.camera = self.overlay.camera;
        rs.lines.extend(self.overlay.lines.iter().cloned());
        rs.points.extend(self.overlay.points.iter().copied());
        rs
    }
}

fn union(a: Option<([f32; 3], [f32; 3])>, b: Option<([f32; 3], [f32; 3])>) -> Option<([f32; 3], [f32; 3])> {
    match (a, b) {
        (Some((lo, hi)), Some((l, h))) => Some((
            [lo[0].min(l[0]), lo[1].min(l[1]), lo[2].min(l[2])],
            [hi[0].max(h[0]), hi[1].max(h[1]), hi[2].max(h[2])],
        )),
        (a, b) => a.or(b),
    }
}

/// The handles (patch origins and control points, which the renderer does not mark), the
/// control polygon of the selected local Bézier curve or the net (rows and columns) of the
/// selected Bézier patch, and the selected and hovered handles drawn larger.
fn overlay_handles(handles: &[Handle], selected: Option<&Handle>, hovered: Option<&Handle>, rs: &mut RenderScene) {
    let mut rows: Vec<Vec<[f32; 3]>> = Vec::new();
    let mut columns: Vec<Vec<[f32; 3]>> = Vec::new();
    for h in handles.iter().filter(|h| h.kind.point_path().is_some() && h.shown_with(selected)) {
        let (a, b) = match h.kind {
            HandleKind::LocalPatchPoint(_, _, a, b) => (a, Some(b)),
            _ => (0, None),
        };
        let p = h.position.map(|x| x as f32);
        for (lines, i) in [(&mut rows, Some(a)), (&mut columns, b)] {
            let Some(i) = i else { continue };
            if lines.len() <= i {
                lines.resize(i + 1, Vec::new());
            }
            lines[i].push(p);
        }
    }
    for points in rows.into_iter().chain(columns).filter(|l| l.len() > 1) {
        rs.lines.push(LineItem { points, closed: false, color: [0.35, 0.35, 0.35, 1.0], width: 1.0 });
    }
    for h in handles.iter().filter(|h| !matches!(h.kind, HandleKind::LocalCurve(_)) && h.shown_with(selected)) {
        let position = h.position.map(|x| x as f32);
        rs.points.push(PointItem { position, color: [0.15, 0.15, 0.15, 1.0], size: 7.0 });
    }
    for (h, color, size) in [(selected, [1.0, 0.55, 0.0, 1.0], 14.0), (hovered, [1.0, 0.85, 0.1, 1.0], 12.0)] {
        if let Some(h) = h {
            let position = h.position.map(|x| x as f32);
            rs.points.push(PointItem { position, color, size });
        }
    }
}

/// How close (pixels) the cursor must be to a handle to grab it.
pub const PICK_RADIUS: f64 = 10.0;

/// The studio's state.
pub struct Studio {
    /// The document being edited.
    pub scene: SceneDocument,
    /// The file it came from.
    pub path: Option<PathBuf>,
    /// Undo and redo.
    pub history: History,
    /// The camera of the 3-D view (`None` until the first frame fits one).
    pub camera: Option<ViewCamera>,
    /// The selected object.
    pub selected_object: Option<usize>,
    /// The selected handle.
    pub selected: Option<Handle>,
    /// The handle under the cursor.
    pub hovered: Option<Handle>,
    /// The drag in progress.
    pub gesture: Option<Gesture>,
    /// The animation clock.
    pub clock: Clock,
    /// The last message for the status line (an edit refused, a file saved, …).
    pub message: Option<String>,
    /// A document that failed to open: its error, shown instead of the view.
    pub load_error: Option<String>,
    /// The handles as last drawn.
    pub handles: Vec<Handle>,
    /// The field (JSON pointer) whose last change was refused, and the message.
    pub field_error: Option<(String, String)>,
    /// Named panel widgets drawn in the last frame and their rectangles (egui points:
    /// left, top, right, bottom), for the handle report (`object 0`, `knots`,
    /// `knots: periodic`, …): what a script clicks.
    pub widgets: Vec<(String, [f32; 4])>,
    /// The bounds of the scene as last drawn.
    pub bounds: Option<([f32; 3], [f32; 3])>,
    /// The last composition.
    cache: Option<Composed>,
    /// The blending-spline surfaces kept evaluated between compositions.
    pub live: LiveSurfaces,
    /// What changed in the composition since the last [`Studio::view_scene`].
    changes: Changes,
}

impl Studio {
    /// The studio on a document.
    pub fn new(scene: SceneDocument, path: Option<PathBuf>) -> Self {
        Studio {
            scene,
            path,
            history: History::default(),
            camera: None,
            selected_object: None,
            selected: None,
            hovered: None,
            gesture: None,
            clock: Clock::new(),
            message: None,
            load_error: None,
            handles: Vec::new(),
            field_error: None,
            widgets: Vec::new(),
            bounds: None,
            cache: None,
            live: LiveSurfaces::default(),
            changes: Changes::All,
        }
    }

    /// Opens another document; a document that does not parse leaves the current one and
    /// shows its error.
    pub fn open(&mut self, path: PathBuf) {
        match document::read(&path) {
            Ok(scene) => {
                *self = Studio::new(scene, Some(path));
            }
            Err(e) => self.load_error = Some(e),
        }
    }

    /// The time the scene is posed at (`None` when it has no animation).
    pub fn time(&self) -> Option<f64> {
        self.scene.is_animated().then_some(self.clock.time)
    }

    /// Applies an edit through the history; a refused edit leaves its message.
    pub fn edit(&mut self, edit: Edit, merge: bool) -> bool {
        let time = self.time();
        let live = &mut self.live;
        let mut check = |object: usize, shape: &ShapeDocument| live.check_build(object, shape, time);
        match self.history.apply_with(&mut self.scene, edit, merge, &mut check) {
            Ok(()) => {
                self.message = None;
                true
            }
            Err(e) => {
                self.message = Some(e.to_string());
                false
            }
        }
    }

    /// Gives object `object`'s local pieces a beat, one undoable edit of its `animation`:
    /// each piece oscillates (amplitude 8 % of the pieces' mean distance from their
    /// centroid c, one beat a second) along the unit direction from c to its origin o_k,
    /// so a blending spline swells and shrinks about its centre like the seed's beating
    /// heart; then plays. `false` (with a message) for objects without local pieces.
    pub fn add_beat(&mut self, object: usize) -> bool {
        let all = crate::handles::handles(&self.scene, None).unwrap_or_default();
        let pieces: Vec<&Handle> = all.iter().filter(|h| h.object == object && h.kind.is_local()).collect();
        if pieces.is_empty() {
            self.message = Some("a beat moves the local pieces of a blending spline: select one".into());
            return false;
        }
        let n = pieces.len() as f64;
        let c = [0, 1, 2].map(|i| pieces.iter().map(|h| h.origin[i]).sum::<f64>() / n);
        let away = |h: &Handle| [0, 1, 2].map(|i| h.origin[i] - c[i]);
        let length = |d: [f64; 3]| d.iter().map(|x| x * x).sum::<f64>().sqrt();
        let amplitude = 0.08 * pieces.iter().map(|h| length(away(h))).sum::<f64>() / n;
        let tracks: Vec<serde_json::Value> = pieces
            .iter()
            .map(|h| {
                let d = away(h);
                let r = length(d);
                let direction: Vec<f64> =
                    if r > 0.0 { d.map(|x| x / r)[..h.dimension].to_vec() } else { vec![0.0; h.dimension] };
                let local = match h.kind.piece() {
                    Some((k, Some(l))) => serde_json::json!([k, l]),
                    Some((k, None)) => serde_json::json!(k),
                    None => serde_json::Value::Null,
                };
                serde_json::json!({"local": local, "motions": [{"oscillate": {"direction": direction, "amplitude": amplitude}}]})
            })
            .collect();
        let edit = Edit::Set { object, pointer: "/shape/animation".into(), value: Some(tracks.into()) };
        let done = self.edit(edit, false);
        self.clock.playing = done;
        done
    }

    /// Undoes the last edit.
    pub fn undo(&mut self) {
        let done = self.history.undo(&mut self.scene);
        self.report(done, "nothing to undo");
    }

    /// Redoes the last undone edit.
    pub fn redo(&mut self) {
        let done = self.history.redo(&mut self.scene);
        self.report(done, "nothing to redo");
    }

    fn report(&mut self, done: Result<bool, EditError>, nothing: &str) {
        self.message = match done {
            Ok(true) => None,
            Ok(false) => Some(nothing.into()),
            Err(e) => Some(e.to_string()),
        };
    }

    /// Saves to the file opened (or `studio.json`), with the view's camera, so that
    /// `splinekit render` of the file shows what the view shows.
    pub fn save(&mut self) {
        let path = document::save_path(self.path.as_deref());
        let mut scene = self.scene.clone();
        if let Some(c) = &self.camera {
            scene.camera = Some(c.to_doc());
        }
        self.message = Some(match document::write(&scene, &path) {
            Ok(()) => format!("saved {}", path.display()),
            Err(e) => e,
        });
        self.path = Some(path);
    }

    /// Writes the selected object as a mesh file (format by extension, see [`crate::export`]).
    pub fn export_selected(&mut self, path: &std::path::Path) {
        let Some(object) = self.selected_object.and_then(|i| self.scene.objects.get(i)) else {
            self.message = Some("export: select an object first".into());
            return;
        };
        let written = crate::export::export(object, self.time(), path).and_then(|bytes| {
            splinekit_scene::write_file(path, &bytes).map_err(|e| format!("{}: cannot write: {e}", path.display()))
        });
        self.message = Some(written.map_or_else(|e| e, |()| format!("exported {}", path.display())));
    }

    /// The scene as the 3-D view draws it at `size` pixels, as one scene ([`ViewScene::merged`]).
    pub fn render_scene(&mut self, size: (u32, u32), overlays: bool) -> Result<RenderScene, String> {
        Ok(self.view_scene(size, overlays)?.merged())
    }

    /// The scene as the 3-D view draws it at `size` pixels: composed as `splinekit render`
    /// composes it (during a drag brought up to date in place, [`crate::live_view`]), with
    /// the view camera (fitted on the first frame); with `overlays`, the handles and the
    /// selected local Bézier's net, the hovered and selected handles drawn larger. The
    /// changes since the last call come with it.
    pub fn view_scene(&mut self, size: (u32, u32), overlays: bool) -> Result<ViewScene<'_>, String> {
        let aspect = size.0.max(1) as f32 / size.1.max(1) as f32;
        self.compose(aspect)?;
        self.follow_handles();
        let Some(cache) = self.cache.as_ref() else { return Err("nothing composed".into()) };
        let rs = &cache.composed;
        let camera = self.camera.get_or_insert_with(|| {
            ViewCamera::new(rs.camera.unwrap_or_else(|| {
                splinekit_render::Camera::fit(cache.bounds.unwrap_or(([-1.0; 3], [1.0; 3])), 0.9, 0.5, aspect)
            }))
        });
        let mut overlay = RenderScene {
            background: rs.background,
            camera: Some(camera.camera),
            lights: rs.lights,
            ambient: rs.ambient,
            painter_order: rs.painter_order,
            ..Default::default()
        };
        if overlays {
            overlay_handles(&self.handles, self.selected.as_ref(), self.hovered.as_ref(), &mut overlay);
        }
        let bounds = union(cache.bounds, overlay.bounds());
        self.bounds = bounds;
        let changes = std::mem::replace(&mut self.changes, Changes::none());
        Ok(ViewScene { composed: rs, overlay, bounds, changes })
    }

    /// Brings the composition up to date with the document at the current time: reused
    /// while only the camera, hover or selection change; during a drag brought up to date
    /// in place ([`crate::live_view::patch`]); else composed afresh, blending-spline surfaces
    /// re-evaluated only where their frames changed ([`LiveSurfaces`]). After a drag the
    /// still scene is composed afresh.
    fn compose(&mut self, aspect: f32) -> Result<(), String> {
        let time = self.time();
        let dragging = self.gesture.is_some();
        if let Some(c) = &self.cache
            && c.scene == self.scene
            && c.time == time
            && (c.exact || dragging)
        {
            return Ok(());
        }
        self.live.update(&self.scene, time);
        if dragging
            && let Some(c) = self.cache.as_mut()
            && c.time == time
            && let Some(changes) = live_view::patch(
                &c.scene,
                &self.scene,
                time,
                aspect,
                &mut c.composed,
                &c.lattices,
                &mut c.polylines,
                &self.live,
            )
        {
            c.scene = self.scene.clone();
            c.bounds = c.composed.bounds();
            c.exact = false;
            self.changes.merge(changes);
            self.handles = self.visible_handles()?;
            return Ok(());
        }
        let live = &self.live;
        let composed = compose_with(&self.scene, time, aspect, &|i| live.surface(i)).map_err(|e| e.to_string())?;
        let lattices = live_view::lattices(&self.scene, &composed, live);
        self.handles = self.visible_handles()?;
        let bounds = composed.bounds();
        self.cache = Some(Composed {
            scene: self.scene.clone(),
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

    /// Moves the selected and hovered handles to where the handles just made put them (an
    /// undo, a redo or a panel's edit moves them too); one that no longer exists is let go.
    fn follow_handles(&mut self) {
        let find = |h: &Option<Handle>| {
            let h = h.as_ref()?;
            self.handles.iter().find(|n| n.object == h.object && n.kind == h.kind).cloned()
        };
        (self.selected, self.hovered) = (find(&self.selected), find(&self.hovered));
    }

    /// The handles the view may show and pick: local pieces (origins and Bézier control
    /// points) of objects drawn with `local_pieces`, control points of objects drawn with
    /// `control_net`.
    fn visible_handles(&self) -> Result<Vec<Handle>, String> {
        let live = &self.live;
        let all = handles_with(&self.scene, self.time(), &|i, d| live.built_from(i, d)).map_err(|e| e.to_string())?;
        let shown = |h: &Handle| {
            let style = &self.scene.objects[h.object].style;
            if h.kind.piece().is_some() { style.local_pieces } else { style.control_net }
        };
        Ok(all.into_iter().filter(shown).collect())
    }

    /// Frames the selected handle (a box a quarter of the scene's size around it), else
    /// the whole scene.
    pub fn frame_selection(&mut self) {
        let Some((lo, hi)) = self.bounds else { return };
        let bounds = match &self.selected {
            Some(h) => {
                let r = (0..3).map(|k| hi[k] - lo[k]).fold(0.0f32, f32::max) / 8.0;
                let p = h.position.map(|x| x as f32);
                (p.map(|x| x - r), p.map(|x| x + r))
            }
            None => (lo, hi),
        };
        if let Some(c) = self.camera.as_mut() {
            c.frame(bounds);
        }
    }

    /// The handles the view shows now: [`Self::handles`] without the control points of
    /// local Béziers other than the selected local piece's ([`Handle::shown_with`]).
    pub fn shown_handles(&self) -> impl Iterator<Item = &Handle> {
        self.handles.iter().filter(|h| h.shown_with(self.selected.as_ref()))
    }

    /// The shown handle within [`PICK_RADIUS`] pixels of `mouse`, the nearest first.
    pub fn pick(&self, projector: &Projector, mouse: [f64; 2]) -> Option<Handle> {
        let mut best: Option<(f64, &Handle)> = None;
        for h in self.shown_handles() {
            if let Some((p, _)) = projector.project(h.position) {
                let d = (p[0] - mouse[0]).hypot(p[1] - mouse[1]);
                if d <= PICK_RADIUS && best.is_none_or(|(b, _)| d < b) {
                    best = Some((d, h));
                }
            }
        }
        best.map(|(_, h)| h.clone())
    }

    /// Starts dragging the handle under `mouse`; `false` when there is none.
    pub fn begin_drag(&mut self, projector: &Projector, mouse: [f64; 2], kind: GestureKind) -> bool {
        let Some(h) = self.pick(projector, mouse) else { return false };
        self.selected_object = Some(h.object);
        self.gesture = Gesture::start_at(&self.scene, self.time(), projector, &h, kind, mouse);
        self.selected = Some(h);
        self.gesture.is_some()
    }

    /// Moves the drag to `mouse`: one edit, merged with the drag's earlier ones.
    pub fn drag_to(&mut self, projector: &Projector, mouse: [f64; 2]) {
        let Some(g) = &self.gesture else { return };
        match g.edit_at(projector, mouse) {
            Ok(edit) => {
                self.edit(edit, true);
            }
            Err(e) => self.message = Some(e.to_string()),
        }
    }

    /// Ends the drag (one undo step).
    pub fn end_drag(&mut self) {
        self.gesture = None;
        self.history.close();
        if let Some(sel) = &self.selected {
            self.selected = self
                .visible_handles()
                .ok()
                .and_then(|hs| hs.into_iter().find(|h| h.object == sel.object && h.kind == sel.kind));
        }
    }
}
