//! The studio's state without a window, composed of its parts: the document and its
//! history ([`Document`]), the selection ([`Selection`]), what the view keeps between
//! frames ([`ViewCaches`]) and the messages shown ([`Status`]), with the view camera, the
//! tools' settings, the drag in progress and the clock; and what the 3-D view draws (the
//! document composed by the renderer's [`compose`](splinekit_render::compose()), with the view's
//! camera and the handles highlighted). Everything here is testable headless.

use std::path::PathBuf;

use splinekit::surface::iso_curve::Direction;
use splinekit_render::{LineItem, PointItem, RenderScene};
use splinekit_scene::ShapeDocument;
use splinekit_scene::scenes::SceneDocument;

use crate::actions::Action;
use crate::analysis::Analysis;
use crate::clock::Clock;
use crate::command::{Command, FieldEdit};
use crate::document::{self, Document};
use crate::edit::{Edit, EditError};
use crate::error::StudioError;
use crate::gesture::{Gesture, GestureKind};
use crate::group_move::{GroupMove, GroupStart};
use crate::handles::{Handle, HandleKind};
use crate::knot_edit::{self, KnotTool};
use crate::knot_split;
use crate::live_view::Changes;
use crate::local_insert;
use crate::net_knot_edit;
use crate::selection::{Selection, in_box};
use crate::snapping::Snapping;
use crate::status::Status;
use crate::view_caches::ViewCaches;
use crate::view_camera::{Projector, StandardView, ViewCamera};

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

/// The handles (patch origins and control points, which the renderer does not mark, and
/// the handles of a split knot's copies, each with a line to its joint), the
/// control polygon of the selected local Bézier curve or the net (rows and columns) of the
/// selected Bézier patch, and the selected handles (the last picked largest) and the hovered
/// one drawn larger.
fn overlay_handles(
    handles: &[Handle],
    selected: Option<&Handle>,
    selected_handles: &[Handle],
    hovered: Option<&Handle>,
    rs: &mut RenderScene,
) {
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
        rs.lines.push(LineItem {
            points,
            closed: false,
            color: [0.35, 0.35, 0.35, 1.0],
            width: 1.0,
            colors: Vec::new(),
        });
    }
    // The renderer marks local curves' origins; a copy of a split knot has its handle off
    // the origin (the joint), drawn here with a line to the joint it turns about.
    let drawn = |h: &Handle| !matches!(h.kind, HandleKind::LocalCurve(_)) || h.pivot.is_some();
    for h in handles.iter().filter(|h| drawn(h) && h.shown_with(selected)) {
        if let Some(pivot) = h.pivot {
            let points = [pivot, h.position].map(|p| p.map(|x| x as f32)).to_vec();
            rs.lines.push(LineItem {
                points,
                closed: false,
                color: [0.35, 0.35, 0.35, 1.0],
                width: 1.0,
                colors: Vec::new(),
            });
        }
        let position = h.position.map(|x| x as f32);
        rs.points.push(PointItem { position, color: [0.15, 0.15, 0.15, 1.0], size: 7.0 });
    }
    for h in selected_handles {
        let position = h.position.map(|x| x as f32);
        rs.points.push(PointItem { position, color: [0.95, 0.45, 0.0, 1.0], size: 11.0 });
    }
    for (h, color, size) in [(selected, [1.0, 0.55, 0.0, 1.0], 14.0), (hovered, [1.0, 0.85, 0.1, 1.0], 12.0)] {
        if let Some(h) = h {
            let position = h.position.map(|x| x as f32);
            rs.points.push(PointItem { position, color, size });
        }
    }
}

/// The parameter a knot tool's click hits: `at` is what the shape's samples say (`None`: the
/// click missed the shape, here named `what`); the error is the status line's message.
fn clicked<T>(at: Result<Option<T>, StudioError>, what: &str) -> Result<T, StudioError> {
    at?.ok_or_else(|| StudioError::refused(format!("click on the {what} itself (Escape: cancel)")))
}

/// The studio's state: the document (with its history), what is selected, what the view
/// keeps between frames and the messages shown, composed with the view's camera, the
/// tools' settings, the drag in progress, the clock and the queued commands. Edits reach
/// the document only through [`Studio::edit`] (one undo step, or a drag's merged steps).
pub struct Studio {
    /// The document being edited, the file it came from, undo and redo.
    pub document: Document,
    /// The selected object and handles.
    pub selection: Selection,
    /// What the 3-D view keeps between frames (composition, handles, hover, widgets).
    pub view: ViewCaches,
    /// The status line's message and the errors shown.
    pub status: Status,
    /// The camera of the 3-D view (`None` until the first frame fits one).
    pub camera: Option<ViewCamera>,
    /// What a moved handle snaps to, and the nudge step.
    pub snapping: Snapping,
    /// What the next click on the selected curve does to its knots (`None`: selects).
    pub knot_tool: Option<KnotTool>,
    /// How far a knot removal may move the curve (world units).
    pub knot_tolerance: f64,
    /// The curvature comb and continuity drawn over the view.
    pub analysis: Analysis,
    /// The drag in progress.
    pub gesture: Option<Gesture>,
    /// The animation clock.
    pub clock: Clock,
    /// Commands queued by the panels, run by [`Studio::run_commands`].
    pub(crate) commands: Vec<Command>,
}

impl Studio {
    /// The studio on a document.
    pub fn new(scene: SceneDocument, path: Option<PathBuf>) -> Self {
        Studio {
            document: Document::new(scene, path),
            selection: Selection::default(),
            view: ViewCaches::default(),
            status: Status::default(),
            camera: None,
            snapping: Snapping::default(),
            knot_tool: None,
            knot_tolerance: 1e-3,
            analysis: Analysis::default(),
            gesture: None,
            clock: Clock::new(),
            commands: Vec::new(),
        }
    }

    /// Queues a command (panels ask through this; the window runs the queue after the
    /// panels are drawn).
    pub fn queue(&mut self, command: Command) {
        self.commands.push(command);
    }

    /// Runs the queued commands in order; returns the actions only the window can carry
    /// out (screenshots, closing, overlays), in order.
    pub fn run_commands(&mut self) -> Vec<Action> {
        let mut left = Vec::new();
        for c in std::mem::take(&mut self.commands) {
            left.extend(self.run(c));
        }
        left
    }

    /// Runs one command; returns its action when only the window can carry it out.
    pub fn run(&mut self, command: Command) -> Option<Action> {
        match command {
            Command::Action(a) => return self.run_action(a),
            Command::Open(path) => self.open(PathBuf::from(path)),
            Command::Export(path) => self.export_selected(std::path::Path::new(&path)),
            Command::Edit(FieldEdit { edit, field, select }) => {
                let done = self.edit(edit, false);
                self.status.field_error = match (done, field) {
                    (false, Some(f)) => self.status.message.clone().map(|m| (f, m)),
                    _ => None,
                };
                if let (true, Some(object)) = (done, select) {
                    self.select_object(object);
                }
            }
            Command::SelectObject(object) => self.select_object(object),
        }
        None
    }

    /// Selects object `object` (none: `None`; an index past the end selects none) and no
    /// handle.
    pub fn select_object(&mut self, object: Option<usize>) {
        self.selection.select_object(object, self.document.scene().objects.len());
    }

    /// The selected object when it is a curve the knot edits work on (else a message).
    fn curve_object(&self) -> Result<usize, StudioError> {
        let object = self.selection.object.ok_or("select a B-spline, NURBS or Bézier curve first")?;
        match &self.document.scene().objects[object].shape {
            ShapeDocument::Curve(_) => Ok(object),
            ShapeDocument::Surface(_) => Err("knot removal and degree elevation work on curves; on B-spline, NURBS \
                 and Bézier surfaces the window inserts knots (K + click)"
                .into()),
        }
    }

    /// Applies an edit made elsewhere (one undo step), or shows why there is none.
    fn apply_or_say(&mut self, edit: Result<Edit, StudioError>) {
        match edit {
            Ok(edit) => {
                if self.edit(edit, false) {
                    self.refresh_selection();
                }
            }
            Err(e) => self.status.say(&e),
        }
    }

    /// The selected object when it is a spline net (B-spline, NURBS or Bézier surface):
    /// knot insertion works on it.
    fn net_object(&self) -> Option<usize> {
        let object = self.selection.object?;
        match &self.document.scene().objects[object].shape {
            ShapeDocument::Surface(s) if s.spline().is_some() => Some(object),
            _ => None,
        }
    }

    /// The selected object when it is a blending spline (curve or surface): local
    /// insertion works on it.
    fn blending_object(&self) -> Option<usize> {
        let object = self.selection.object?;
        local_insert::takes_locals(&self.document.scene().objects[object].shape).then_some(object)
    }

    /// Arms a knot tool: the next click on the selected curve (or, inserting, spline
    /// surface; inserting a local, blending spline) uses it, as the message says.
    fn arm(&mut self, tool: KnotTool) {
        let shape = self.selection.object.map(|o| &self.document.scene().objects[o].shape);
        let armed: Result<String, StudioError> = match tool {
            KnotTool::InsertLocal => match (shape, self.blending_object()) {
                (Some(ShapeDocument::Curve(_)), Some(_)) => {
                    Ok("click on the blending spline where the local curve goes (Escape: cancel)".into())
                }
                (Some(ShapeDocument::Surface(_)), Some(_)) => Ok("click on the surface: a row of local patches \
                                                                  along u there (Shift + click: along v; Escape: \
                                                                  cancel)"
                    .into()),
                _ => Err("insert local piece: select a blending spline (curve or surface) first".into()),
            },
            KnotTool::Insert if self.net_object().is_some() => {
                Ok("click on the surface: a u-knot there (Shift + click: a v-knot; Escape: cancel)".into())
            }
            KnotTool::Insert => {
                self.curve_object().map(|_| "click on the curve where the knot goes (Escape: cancel)".into())
            }
            KnotTool::Remove => {
                self.curve_object().map(|_| "click on the curve near the knot to remove (Escape: cancel)".into())
            }
            KnotTool::SplitKnot => match shape {
                Some(shape) if knot_split::splits(shape) => {
                    Ok("click on the blending spline near the knot to split (Escape: cancel)".into())
                }
                _ => Err(knot_split::SELECT_A_BLENDING_CURVE.into()),
            },
        };
        match armed {
            Ok(m) => {
                self.knot_tool = Some(tool);
                self.status.message = Some(m);
            }
            Err(e) => self.status.say(&e),
        }
    }

    /// A click at `mouse` on the selected spline surface with the insert tool armed (or,
    /// with `local`, on the selected blending surface with the insert-local tool): a
    /// u-knot (a row of local patches) at the clicked u, with `shift` at the clicked v;
    /// one undo step. A click off the surface leaves the tool armed.
    fn net_knot_click(&mut self, object: usize, projector: &Projector, mouse: [f64; 2], shift: bool, local: bool) {
        let shape = &self.document.scene().objects[object].shape;
        let at = net_knot_edit::surface_samples(shape, net_knot_edit::GRID)
            .map(|grid| net_knot_edit::parameters_at(&grid, projector, mouse));
        let Some((u, v)) = self.status.said(clicked(at, "surface")) else { return };
        let (direction, t) = if shift { (Direction::V, v) } else { (Direction::U, u) };
        let edit = if local {
            local_insert::insert_line(shape, object, direction, t)
        } else {
            net_knot_edit::insert(shape, object, direction, t)
        };
        self.knot_tool = None;
        self.apply_or_say(edit);
    }

    /// A click at `mouse` with a knot tool armed: the tool's edit at the clicked parameter
    /// of the selected curve, or (inserting) at the clicked u of the selected spline
    /// surface (with `shift`: its v); one undo step. A click off the shape leaves the tool
    /// armed.
    pub fn knot_click(&mut self, tool: KnotTool, projector: &Projector, mouse: [f64; 2], shift: bool) {
        if let (KnotTool::Insert, Some(object)) = (tool, self.net_object()) {
            self.net_knot_click(object, projector, mouse, shift, false);
            return;
        }
        if tool == KnotTool::InsertLocal {
            match self.blending_object() {
                Some(object) if matches!(self.document.scene().objects[object].shape, ShapeDocument::Surface(_)) => {
                    self.net_knot_click(object, projector, mouse, shift, true);
                    return;
                }
                Some(_) => {}
                None => {
                    self.knot_tool = None;
                    self.status.message =
                        Some("insert local piece: select a blending spline (curve or surface) first".into());
                    return;
                }
            }
        }
        let object = match self.curve_object() {
            Ok(o) => o,
            Err(e) => {
                self.knot_tool = None;
                self.status.say(&e);
                return;
            }
        };
        let shape = &self.document.scene().objects[object].shape;
        let at = knot_edit::curve_samples(shape, knot_edit::SAMPLES)
            .map(|samples| knot_edit::parameter_at(&samples, projector, mouse));
        let Some(u) = self.status.said(clicked(at, "curve")) else { return };
        let edit = match tool {
            KnotTool::Insert => knot_edit::insert(shape, object, u),
            KnotTool::Remove => knot_edit::remove(shape, object, u, self.knot_tolerance),
            KnotTool::InsertLocal => local_insert::insert_curve(shape, object, u),
            KnotTool::SplitKnot => {
                let split = knot_split::split_near(shape, object, u);
                self.knot_tool = None;
                match split {
                    Ok((edit, k)) => self.split_done(edit, k),
                    Err(e) => self.status.say(&e),
                }
                return;
            }
        };
        self.knot_tool = None;
        self.apply_or_say(edit);
    }

    /// Split knot: with a local curve (its origin or a control point) of the selected
    /// blending-spline curve selected, splits its knot at once (one undo step); otherwise
    /// arms the tool, and the next click splits the knot nearest it.
    fn split_knot(&mut self) {
        let Some(object) = self.selection.object else {
            self.status.message = Some(knot_split::SELECT_A_BLENDING_CURVE.into());
            return;
        };
        let shape = &self.document.scene().objects[object].shape;
        let local = self.selection.handle.as_ref().filter(|h| h.object == object).and_then(|h| h.kind.piece());
        match local {
            Some((k, None)) if knot_split::splits(shape) => {
                let edit = knot_split::split_local(shape, object, k);
                match edit {
                    Ok(edit) => self.split_done(edit, k),
                    Err(e) => self.status.say(&e),
                }
            }
            _ => self.arm(KnotTool::SplitKnot),
        }
    }

    /// Applies a split of knot `k` (one undo step) and says what the copies do.
    fn split_done(&mut self, edit: Edit, k: usize) {
        if self.edit(edit, false) {
            self.refresh_selection();
            self.status.message = Some(format!(
                "knot {k} split: local curves {k} and {} meet there; drag either to turn and scale it about the joint",
                k + 1
            ));
        }
    }

    /// Selects no handle.
    pub fn clear_selection(&mut self) {
        self.selection.clear_handles();
    }

    /// A click on `picked` (none: empty space): selects it alone, or with `add` (Shift)
    /// adds it to the selection or removes it. A click on empty space without `add`
    /// clears the selection ([`Selection::click`]).
    pub fn click(&mut self, picked: Option<Handle>, add: bool) {
        self.selection.click(picked, add);
    }

    /// Selects the shown handles whose projection lies in the box with corners `a` and `b`
    /// (view pixels); with `add`, in addition to the selection.
    pub fn box_select(&mut self, projector: &Projector, a: [f64; 2], b: [f64; 2], add: bool) {
        let inside = in_box(self.shown_handles(), projector, a, b);
        self.selection.select_box(inside, add);
    }

    /// Selects every shown handle of the selected object.
    pub fn select_all(&mut self) {
        let Some(object) = self.selection.object else {
            self.status.message = Some("select all: select an object first".into());
            return;
        };
        let all: Vec<Handle> = self.shown_handles().filter(|h| h.object == object).cloned().collect();
        self.selection.add_all(all);
    }

    /// Moves the selection by `steps` snapping steps along world axis `axis`: one edit.
    pub fn nudge(&mut self, axis: usize, steps: i32) {
        let handles = self.selection.selected_handles();
        if handles.is_empty() {
            self.status.message = Some("nudge: select handles first".into());
            return;
        }
        if axis == 2 && handles.iter().all(|h| h.dimension == 2) {
            self.status.message = Some("nudge: a plane shape has no z".into());
            return;
        }
        let mut d = [0.0; 3];
        d[axis] = self.snapping.step * f64::from(steps);
        let edit = GroupStart::read(self.document.scene(), self.time(), &handles)
            .ok_or(StudioError::refused("nudge: the selection's values cannot be read"))
            .and_then(|g| Ok(g.edit(&GroupMove::Translate(d))?));
        self.apply_or_say(edit);
    }

    /// Brings the selected handles to their places in the document as it is now.
    fn refresh_selection(&mut self) {
        if let Ok(now) = self.view.visible_handles(self.document.scene(), self.time()) {
            self.selection.follow(&now);
        }
    }

    /// Carries out an action of the registry; returns it when only the window can
    /// (screenshots, closing, overlays).
    pub fn run_action(&mut self, action: Action) -> Option<Action> {
        let look = |studio: &mut Studio, v| studio.camera.iter_mut().for_each(|c| c.look_from(v));
        match action {
            Action::Save => self.save(),
            Action::Undo => self.undo(),
            Action::Redo => self.redo(),
            Action::LookTop => look(self, StandardView::Top),
            Action::LookFront => look(self, StandardView::Front),
            Action::LookSide => look(self, StandardView::Side),
            Action::Home => self.camera.iter_mut().for_each(|c| c.camera = c.home),
            Action::Frame => self.frame_selection(),
            Action::TogglePlay => self.clock.playing = !self.clock.playing,
            Action::ClearSelection => {
                self.knot_tool = None;
                self.clear_selection();
            }
            Action::ToggleComb => self.analysis.comb = !self.analysis.comb,
            Action::ToggleContinuity => self.analysis.continuity = !self.analysis.continuity,
            Action::InsertKnot => self.arm(KnotTool::Insert),
            Action::RemoveKnot => self.arm(KnotTool::Remove),
            Action::InsertLocal => self.arm(KnotTool::InsertLocal),
            Action::SplitKnot => self.split_knot(),
            Action::ElevateDegree => {
                let edit =
                    self.curve_object().and_then(|o| knot_edit::elevate(&self.document.scene().objects[o].shape, o));
                self.apply_or_say(edit);
            }
            Action::SelectAll => self.select_all(),
            Action::Nudge(axis, steps) => self.nudge(axis, steps),
            Action::AddBeat => match self.selection.object {
                Some(object) => {
                    self.add_beat(object);
                }
                None => {
                    self.status.message = Some("a beat moves the local pieces of a blending spline: select one".into())
                }
            },
            Action::Screenshot | Action::Quit | Action::FrameTimes | Action::Help => return Some(action),
        }
        None
    }

    /// Opens another document; a document that does not parse leaves the current one and
    /// shows its error.
    pub fn open(&mut self, path: PathBuf) {
        match document::read(&path) {
            Ok(scene) => {
                *self = Studio::new(scene, Some(path));
            }
            Err(e) => self.status.load_error = Some(e.to_string()),
        }
    }

    /// The time the scene is posed at (`None` when it has no animation).
    pub fn time(&self) -> Option<f64> {
        self.document.scene().is_animated().then_some(self.clock.time)
    }

    /// Applies an edit through the document's history, the edited shape built by the
    /// view's live surfaces; a refused edit leaves its message.
    pub fn edit(&mut self, edit: Edit, merge: bool) -> bool {
        let time = self.time();
        let live = &mut self.view.live;
        let mut check = |object: usize, shape: &ShapeDocument| live.check_build(object, shape, time);
        match self.document.edit(edit, merge, &mut check) {
            Ok(()) => {
                self.status.message = None;
                true
            }
            Err(e) => {
                self.status.message = Some(e.to_string());
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
        let all = crate::handles::handles(self.document.scene(), None).unwrap_or_default();
        let pieces: Vec<&Handle> = all.iter().filter(|h| h.object == object && h.kind.is_local()).collect();
        if pieces.is_empty() {
            self.status.message = Some("a beat moves the local pieces of a blending spline: select one".into());
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
        let done = self.document.undo();
        self.report(done, "nothing to undo");
        self.refresh_selection();
    }

    /// Redoes the last undone edit.
    pub fn redo(&mut self) {
        let done = self.document.redo();
        self.report(done, "nothing to redo");
        self.refresh_selection();
    }

    fn report(&mut self, done: Result<bool, EditError>, nothing: &str) {
        self.status.message = match done {
            Ok(true) => None,
            Ok(false) => Some(nothing.into()),
            Err(e) => Some(e.to_string()),
        };
    }

    /// Saves to the file opened (or `studio.json`), with the view's camera, so that
    /// `splinekit render` of the file shows what the view shows.
    pub fn save(&mut self) {
        let camera = self.camera.as_ref().map(ViewCamera::to_doc);
        self.status.message = Some(self.document.save(camera));
    }

    /// Writes the selected object as a mesh file (format by extension, see [`crate::export`]).
    pub fn export_selected(&mut self, path: &std::path::Path) {
        let Some(object) = self.selection.object.and_then(|i| self.document.scene().objects.get(i)) else {
            self.status.message = Some("export: select an object first".into());
            return;
        };
        let written = crate::export::export(object, self.time(), path).and_then(|bytes| {
            splinekit_scene::write_file(path, &bytes).map_err(|e| StudioError::file(path, format!("cannot write: {e}")))
        });
        self.status.message = Some(written.map_or_else(|e| e.to_string(), |()| format!("exported {}", path.display())));
    }

    /// The scene as the 3-D view draws it at `size` pixels, as one scene ([`ViewScene::merged`]).
    pub fn render_scene(&mut self, size: (u32, u32), overlays: bool) -> Result<RenderScene, StudioError> {
        Ok(self.view_scene(size, overlays)?.merged())
    }

    /// The scene as the 3-D view draws it at `size` pixels: composed as `splinekit render`
    /// composes it (during a drag brought up to date in place, [`crate::live_view`]), with
    /// the view camera (fitted on the first frame), the analysis asked for (comb,
    /// continuity, [`Analysis`]); with `overlays`, the handles and the
    /// selected local Bézier's net, the hovered and selected handles drawn larger. The
    /// changes since the last call come with it.
    pub fn view_scene(&mut self, size: (u32, u32), overlays: bool) -> Result<ViewScene<'_>, StudioError> {
        let aspect = size.0.max(1) as f32 / size.1.max(1) as f32;
        let time = self.time();
        self.view.compose(self.document.scene(), time, aspect, self.gesture.is_some())?;
        self.follow_handles();
        let Some((rs, composed_bounds)) = self.view.composed() else {
            return Err(StudioError::Graphics("nothing composed".into()));
        };
        let camera = self.camera.get_or_insert_with(|| {
            ViewCamera::new(rs.camera.unwrap_or_else(|| {
                splinekit_render::Camera::fit(composed_bounds.unwrap_or(([-1.0; 3], [1.0; 3])), 0.9, 0.5, aspect)
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
        self.analysis.overlay(self.document.scene(), time, &mut overlay);
        if overlays {
            overlay_handles(
                &self.view.handles,
                self.selection.handle.as_ref(),
                &self.selection.handles,
                self.view.hovered.as_ref(),
                &mut overlay,
            );
        }
        let Some((composed, bounds, changes)) = self.view.finish_frame(overlay.bounds()) else {
            return Err("nothing composed".into());
        };
        Ok(ViewScene { composed, overlay, bounds, changes })
    }

    /// Moves the selected and hovered handles to where the handles just made put them (an
    /// undo, a redo or a panel's edit moves them too); one that no longer exists is let go.
    fn follow_handles(&mut self) {
        self.selection.follow(&self.view.handles);
        self.view.follow_hover();
    }

    /// Frames the selected handle (a box a quarter of the scene's size around it), else
    /// the whole scene.
    pub fn frame_selection(&mut self) {
        let Some((lo, hi)) = self.view.bounds else { return };
        let bounds = match &self.selection.handle {
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

    /// The handles the view shows now: [`ViewCaches::handles`] without the control points
    /// of local Béziers other than the selected local piece's ([`Handle::shown_with`]).
    pub fn shown_handles(&self) -> impl Iterator<Item = &Handle> {
        self.view.shown_handles(self.selection.handle.as_ref())
    }

    /// The shown handle within [`PICK_RADIUS`](crate::view_caches::PICK_RADIUS) pixels of `mouse`, the nearest first.
    pub fn pick(&self, projector: &Projector, mouse: [f64; 2]) -> Option<Handle> {
        self.view.pick(self.selection.handle.as_ref(), projector, mouse)
    }

    /// Starts dragging the handle under `mouse`; `false` when there is none. A handle of
    /// a selection of several drags the whole selection; another becomes the selection.
    pub fn begin_drag(&mut self, projector: &Projector, mouse: [f64; 2], kind: GestureKind) -> bool {
        let Some(h) = self.pick(projector, mouse) else { return false };
        let time = self.time();
        if self.selection.handles.len() > 1 && self.selection.contains(&h) && kind != GestureKind::Weight {
            let group = self.selection.handles.clone();
            self.gesture = Gesture::start_group(self.document.scene(), time, projector, &h, &group, kind, mouse);
            self.selection.object = Some(h.object);
            self.selection.handle = Some(h);
        } else {
            self.gesture = Gesture::start_at(self.document.scene(), time, projector, &h, kind, mouse);
            self.selection.select_only(h);
        }
        self.gesture.is_some()
    }

    /// Moves the drag to `mouse`: one edit, merged with the drag's earlier ones; the
    /// dragged handle snaps as [`Self::snapping`] says (to handles outside the selection).
    pub fn drag_to(&mut self, projector: &Projector, mouse: [f64; 2]) {
        let Some(g) = &self.gesture else { return };
        let snapping = self.snapping;
        let targets: Vec<[f64; 3]> = if snapping.handles {
            self.shown_handles()
                .filter(|h| !self.selection.contains(h) && **h != g.handle)
                .map(|h| h.position)
                .collect()
        } else {
            Vec::new()
        };
        let dimension = g.handle.dimension;
        let snap = |p: [f64; 3]| if snapping.any() { snapping.snap(p, dimension, &targets, projector) } else { p };
        match g.edit_snapped(projector, mouse, &snap) {
            Ok(edit) => {
                self.edit(edit, true);
            }
            Err(e) => self.status.message = Some(e.to_string()),
        }
    }

    /// Ends the drag (one undo step).
    pub fn end_drag(&mut self) {
        self.gesture = None;
        self.document.close_step();
        self.refresh_selection();
    }
}
