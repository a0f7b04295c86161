//! Properties of the selected object, applied at once: style toggles, sample density and
//! line width; the degree and knot style (clamped, uniform, periodic) of B-splines and
//! NURBS, curves and nets; for blending splines the number of local
//! pieces, their kind (Bézier of a degree, sub-curve/surface, arc), knot spacing,
//! open/closed and the B-function with its parameters
//! (and a plot of B and B′); the numbers of the selected handle for exact entry.

use serde_json::{Value, json};
use splinekit::curve::Curve;
use splinekit_scene::bfunctions::{BFunctionDoc, ErbsDoc};
use splinekit_scene::scenes::{ArrowFieldDoc, ArrowPlacementDoc, ColorMapDoc};
use splinekit_scene::{Curves, Decoration, DimensionVisitor, ShapeDocument};

use super::context::PanelContext;
use super::fields::{count, error_label, number, read, toggle, write};
use super::knots::{CURVE, NET_U, NET_V, knot_style};
use super::plot::{bfunction_plot, blending_basis_plot};
use crate::actions::{ACTIONS, Action};
use crate::command::Command;
use crate::knot_edit::KnotTool;
use crate::studio::Studio;

/// The editors the Properties panel has for a shape, chosen by what its kind declares
/// (its spline view and what it decorates) rather than by its type name.
enum Editors {
    /// Degree, knot style and knot edits: a B-spline or NURBS curve.
    SplineCurve,
    /// Knot edits: a (rational) Bézier curve.
    BezierCurve,
    /// Degrees and knot styles: a B-spline or NURBS net.
    SplineNet,
    /// Locals and B-function of a blending-spline curve.
    BlendingCurve,
    /// Locals and B-function of a blending-spline surface.
    BlendingSurface,
    /// None besides the style.
    None,
}

impl Editors {
    fn of(shape: &ShapeDocument) -> Editors {
        match shape {
            ShapeDocument::Curve(c) => match (c.spline(), c.decoration()) {
                (Some(view), _) if view.knots.is_some() => Editors::SplineCurve,
                (Some(_), _) => Editors::BezierCurve,
                (None, Decoration::LocalCurves(_)) => Editors::BlendingCurve,
                (None, _) => Editors::None,
            },
            ShapeDocument::Surface(s) => match (s.spline(), s.decoration()) {
                (Some(view), _) if view.knots.is_some() => Editors::SplineNet,
                (None, Decoration::LocalPatches(_)) => Editors::BlendingSurface,
                _ => Editors::None,
            },
        }
    }
}

/// The Properties panel.
pub fn properties_panel(ui: &mut egui::Ui, studio: &mut Studio) {
    properties(ui, &mut PanelContext::of(studio));
}

/// The Properties panel.
fn properties(ui: &mut egui::Ui, cx: &mut PanelContext<'_>) {
    ui.set_max_width(super::SIDE_WIDTH - 16.0);
    ui.heading("Properties");
    let Some(object) = cx.selection.object.filter(|&i| i < cx.scene.objects.len()) else {
        ui.label("Select an object or a handle.");
        return;
    };
    let ty = read(cx, object, "/shape/type").and_then(|v| v.as_str().map(String::from)).unwrap_or_default();
    ui.label(format!("objects[{object}]: {ty}"));
    ui.separator();
    style(ui, cx, object);
    let surface = matches!(cx.scene.objects[object].shape, ShapeDocument::Surface(_));
    color_map(ui, cx, object, surface);
    arrows(ui, cx, object, surface);
    ui.separator();
    match Editors::of(&cx.scene.objects[object].shape) {
        Editors::SplineCurve => {
            count(ui, cx, object, "/shape/degree", "degree", 3);
            knot_style(ui, cx, object, CURVE, "knots");
            knot_edits(ui, cx, false);
        }
        Editors::BezierCurve => knot_edits(ui, cx, false),
        Editors::SplineNet => {
            count(ui, cx, object, "/shape/degree_u", "degree u", 3);
            count(ui, cx, object, "/shape/degree_v", "degree v", 3);
            knot_style(ui, cx, object, NET_U, "knots u");
            knot_style(ui, cx, object, NET_V, "knots v");
            knot_edits(ui, cx, true);
        }
        Editors::BlendingCurve => blending_curve(ui, cx, object),
        Editors::BlendingSurface => blending_surface(ui, cx, object),
        Editors::None => {}
    }
    selected_handle(ui, cx);
}

/// The registry's panel actions among `offered` as buttons (an armed tool's shown
/// selected); a click queues the action.
fn action_buttons(ui: &mut egui::Ui, cx: &mut PanelContext<'_>, offered: &[Action]) {
    ui.horizontal_wrapped(|ui| {
        for s in ACTIONS.iter().filter(|s| s.panel && offered.contains(&s.action)) {
            let armed = match s.action {
                Action::InsertKnot => cx.knot_tool == Some(KnotTool::Insert),
                Action::RemoveKnot => cx.knot_tool == Some(KnotTool::Remove),
                Action::InsertLocal => cx.knot_tool == Some(KnotTool::InsertLocal),
                Action::SplitKnot => cx.knot_tool == Some(KnotTool::SplitKnot),
                _ => false,
            };
            let button = ui.add(egui::Button::new(s.label).selected(armed)).on_hover_text(s.help);
            cx.widgets.push((s.label.to_lowercase(), super::rect(&button)));
            if button.clicked() {
                cx.queue(Command::Action(s.action));
            }
        }
    });
}

/// The knot edits (insert and remove a knot, elevate the degree) as buttons, and the
/// tolerance of a removal; on a spline `surface` only knot insertion (a click inserts a
/// u-knot, Shift + click a v-knot).
fn knot_edits(ui: &mut egui::Ui, cx: &mut PanelContext<'_>, surface: bool) {
    let offered: &[Action] =
        if surface { &[Action::InsertKnot] } else { &[Action::InsertKnot, Action::RemoveKnot, Action::ElevateDegree] };
    action_buttons(ui, cx, offered);
    if surface {
        ui.label("Insert knot, then click: a u-knot (Shift + click: a v-knot)");
        return;
    }
    ui.horizontal(|ui| {
        let name = ui.label("removal tolerance");
        ui.add(egui::DragValue::new(cx.knot_tolerance).range(0.0..=1e6).speed(1e-4).max_decimals(6))
            .labelled_by(name.id);
    });
}

/// The colour map: none, or one of those the shape takes (a surface's curvatures,
/// coordinates, parameters, speeds, zebra stripes or isophotes; a curve's coordinates,
/// parameter, speed, curvature or torsion).
fn color_map(ui: &mut egui::Ui, cx: &mut PanelContext<'_>, object: usize, surface: bool) {
    let current = cx.scene.objects[object].style.color_map;
    let mut chosen = current;
    let combo = egui::ComboBox::from_label("colour map")
        .selected_text(current.map_or("none", ColorMapDoc::name))
        .show_ui(ui, |ui| {
            ui.selectable_value(&mut chosen, None, "none");
            for m in ColorMapDoc::ALL.into_iter().filter(|m| if surface { m.for_surfaces() } else { m.for_curves() }) {
                ui.selectable_value(&mut chosen, Some(m), m.name());
            }
        });
    cx.widgets.push(("colour map".into(), super::rect(&combo.response)));
    if chosen != current {
        write(cx, object, "/color_map", chosen.map(|m| m.name().into()));
    }
    error_label(ui, cx, "/color_map");
}

/// Arrows of a vector field: none, or a field the shape has, over all of it or on its
/// boundary only.
fn arrows(ui: &mut egui::Ui, cx: &mut PanelContext<'_>, object: usize, surface: bool) {
    let current = cx.scene.objects[object].style.arrows.clone();
    let field = current.as_ref().map(|a| a.field);
    let mut chosen = field;
    let combo = egui::ComboBox::from_label("arrows").selected_text(field.map_or("none", ArrowFieldDoc::name)).show_ui(
        ui,
        |ui| {
            ui.selectable_value(&mut chosen, None, "none");
            for f in ArrowFieldDoc::ALL.into_iter().filter(|f| if surface { f.for_surfaces() } else { f.for_curves() })
            {
                ui.selectable_value(&mut chosen, Some(f), f.name());
            }
        },
    );
    cx.widgets.push(("arrows".into(), super::rect(&combo.response)));
    if chosen != field {
        write(cx, object, "/arrows", chosen.map(|f| serde_json::json!({"field": f.name()})));
    }
    if let Some(a) = current {
        let mut boundary = a.on == ArrowPlacementDoc::Boundary;
        if ui.checkbox(&mut boundary, "arrows on the boundary only").changed() {
            write(cx, object, "/arrows/on", Some(if boundary { "boundary" } else { "all" }.into()));
        }
    }
    error_label(ui, cx, "/arrows");
}

fn style(ui: &mut egui::Ui, cx: &mut PanelContext<'_>, object: usize) {
    toggle(ui, cx, object, "/hidden", "hide the shape", false);
    toggle(ui, cx, object, "/control_net", "control polygon / net", false);
    toggle(ui, cx, object, "/local_pieces", "local curves / patches", false);
    toggle(ui, cx, object, "/wireframe", "parameter lines", false);
    toggle(ui, cx, object, "/color_cycle", "colour cycling (animation)", false);
    let density = read(cx, object, "/density").and_then(|v| v.as_u64());
    let mut adaptive = density.is_none();
    if ui.checkbox(&mut adaptive, "adaptive sampling").changed() {
        write(cx, object, "/density", if adaptive { None } else { Some(64.into()) });
    }
    if !adaptive {
        count(ui, cx, object, "/density", "density", 64);
    }
    number(ui, cx, object, "/line_width", "line width", 2.5);
}

fn blending_curve(ui: &mut egui::Ui, cx: &mut PanelContext<'_>, object: usize) {
    if read(cx, object, "/shape/model").is_some() {
        local_count(ui, cx, object, ["/shape/local_curves", "/shape/knots"], "local curves", 10);
        local_kind(ui, cx, object, false);
        action_buttons(ui, cx, &[Action::InsertLocal, Action::SplitKnot]);
        ui.label("Insert local piece, then click on the curve: a local curve there");
        ui.label("Split knot: the selected local's knot, else click near one");
    }
    let closed = is_closed(cx, object);
    toggle(ui, cx, object, "/shape/closed", "closed", closed);
    bfunction(ui, cx, object);
}

fn blending_surface(ui: &mut egui::Ui, cx: &mut PanelContext<'_>, object: usize) {
    local_count(ui, cx, object, ["/shape/local_surfaces/0", "/shape/knots_u"], "patches in u", 4);
    local_count(ui, cx, object, ["/shape/local_surfaces/1", "/shape/knots_v"], "patches in v", 4);
    action_buttons(ui, cx, &[Action::InsertLocal]);
    ui.label("Insert local piece, then click: a row of patches along u (Shift + click: along v)");
    local_kind(ui, cx, object, true);
    toggle(ui, cx, object, "/shape/closed_u", "closed in u", true);
    toggle(ui, cx, object, "/shape/closed_v", "closed in v", true);
    bfunction(ui, cx, object);
}

/// The number of local pieces in one direction: an editable count over even knots; once
/// a local was inserted the knots are explicit (`knots`), the count follows them, and a
/// button takes them back to even spacing (one edit; the count stays).
/// `pointers` are the count's and the knots'.
fn local_count(
    ui: &mut egui::Ui,
    cx: &mut PanelContext<'_>,
    object: usize,
    pointers: [&str; 2],
    label: &str,
    default: u64,
) {
    let [pointer, knots] = pointers;
    if read(cx, object, knots).is_none() {
        count(ui, cx, object, pointer, label, default);
        return;
    }
    let n = read(cx, object, pointer).and_then(|v| v.as_u64()).unwrap_or(0);
    ui.horizontal(|ui| {
        ui.label(format!("{label}: {n} (knots as inserted)"));
        let button = ui.button("even knots").on_hover_text("space the knots evenly again (the count can then change)");
        cx.widgets.push((format!("even knots {label}"), super::rect(&button)));
        if button.clicked() {
            write(cx, object, knots, None);
        }
    });
    error_label(ui, cx, knots);
}

/// The kind of locals made from the model (Bézier of a degree, the model itself, arcs for
/// curves) and, for curves with knots not given explicitly, the knot spacing.
fn local_kind(ui: &mut egui::Ui, cx: &mut PanelContext<'_>, object: usize, surface: bool) {
    let local = read(cx, object, "/shape/local").unwrap_or_else(|| json!({"type": "bezier"}));
    let kind = local.get("type").and_then(Value::as_str).unwrap_or("bezier").to_string();
    let kinds: &[&str] = if surface { &["bezier", "sub_surface"] } else { &["bezier", "sub_curve", "arc"] };
    let mut chosen = kind.clone();
    egui::ComboBox::from_label("locals").selected_text(&chosen).show_ui(ui, |ui| {
        for k in kinds {
            ui.selectable_value(&mut chosen, k.to_string(), *k);
        }
    });
    if chosen != kind {
        write(cx, object, "/shape/local", Some(json!({"type": chosen})));
    }
    error_label(ui, cx, "/shape/local");
    if kind == "bezier" {
        bezier_degree(ui, cx, object, &local, surface);
    }
    // Explicit knots (after an insertion) say where the locals are: no spacing to choose.
    if !surface && read(cx, object, "/shape/knots").is_none() {
        let spacing = read(cx, object, "/shape/knot_spacing").and_then(|v| v.as_str().map(String::from));
        let current = spacing.unwrap_or_else(|| "uniform".into());
        let mut chosen = current.clone();
        egui::ComboBox::from_label("knots").selected_text(&chosen).show_ui(ui, |ui| {
            for k in ["uniform", "chord_length", "arc_length"] {
                ui.selectable_value(&mut chosen, k.to_string(), k);
            }
        });
        if chosen != current {
            write(cx, object, "/shape/knot_spacing", Some(chosen.into()));
        }
        error_label(ui, cx, "/shape/knot_spacing");
    }
}

/// Whether the object's curve is closed as built (the default of `closed`: the model's).
fn is_closed(cx: &PanelContext<'_>, object: usize) -> bool {
    struct Closed;
    impl DimensionVisitor<Curves> for Closed {
        type Output = bool;
        fn visit<const D: usize>(self, c: &dyn Curve<D>) -> bool {
            c.is_closed()
        }
    }
    match &cx.scene.objects[object].shape {
        ShapeDocument::Curve(c) => c.build().is_ok_and(|c| c.visit(Closed)),
        ShapeDocument::Surface(_) => false,
    }
}

/// The degree of Bézier locals (d, or [d_u, d_v] for patches), written as the whole
/// `local` object so that a document without one gets `"type": "bezier"` too.
fn bezier_degree(ui: &mut egui::Ui, cx: &mut PanelContext<'_>, object: usize, local: &Value, surface: bool) {
    let degree = local.get("degree");
    let mut d: Vec<u64> = if surface {
        degree.and_then(|d| serde_json::from_value(d.clone()).ok()).unwrap_or_else(|| vec![3, 3])
    } else {
        vec![degree.and_then(Value::as_u64).unwrap_or(3)]
    };
    let mut changed = false;
    ui.horizontal(|ui| {
        let name = ui.label("Bézier degree");
        for x in d.iter_mut() {
            changed |= ui.add(egui::DragValue::new(x).range(1..=12).speed(0.1)).labelled_by(name.id).changed();
        }
    });
    if changed {
        let degree = if surface { json!(d) } else { json!(d[0]) };
        write(cx, object, "/shape/local", Some(json!({"type": "bezier", "degree": degree})));
    }
}

/// The B-function kind, its parameters and the plot.
fn bfunction(ui: &mut egui::Ui, cx: &mut PanelContext<'_>, object: usize) {
    let value = read(cx, object, "/shape/bfunction").unwrap_or_else(|| json!({"type": "erbs"}));
    let kind = value.get("type").and_then(Value::as_str).unwrap_or("erbs").to_string();
    let mut chosen = kind.clone();
    egui::ComboBox::from_label("B-function").selected_text(&chosen).show_ui(ui, |ui| {
        for b in BFunctionDoc::TYPES {
            ui.selectable_value(&mut chosen, b.to_string(), b);
        }
    });
    if chosen != kind {
        write(cx, object, "/shape/bfunction", Some(json!({"type": chosen})));
    }
    error_label(ui, cx, "/shape/bfunction");
    // ERBS's parameters with the document's defaults (α, β, γ, λ).
    let params = match kind.as_str() {
        "erbs" => json!(ErbsDoc::default()).as_object().cloned().unwrap_or_default(),
        _ => serde_json::Map::new(),
    };
    for (name, default) in &params {
        number(ui, cx, object, &format!("/shape/bfunction/{name}"), name, default.as_f64().unwrap_or(0.0));
    }
    if kind == "polynomial" {
        count(ui, cx, object, "/shape/bfunction/smoothness", "smoothness", 1);
    }
    if let Some(b) = read(cx, object, "/shape/bfunction")
        .or_else(|| Some(json!({"type": "erbs"})))
        .and_then(|v| BFunctionDoc::from_value(v).ok())
        .and_then(|d| d.build().ok())
    {
        ui.label("B (text colour), B' (orange) and B'' (blue):");
        bfunction_plot(ui, &b, egui::vec2(200.0, 90.0));
        if let Some(knots) = curve_knots(cx, object) {
            ui.label("the blending basis of the knots:");
            blending_basis_plot(ui, &b, &knots, egui::vec2(200.0, 70.0));
        }
    }
}

/// The knots of a blending curve: its `knots`, else 0, 1, …, n (n local curves, one knot
/// more when closed) standing in for its even knots over the model's domain.
fn curve_knots(cx: &PanelContext<'_>, object: usize) -> Option<Vec<f64>> {
    if let Some(k) = read(cx, object, "/shape/knots").and_then(|v| serde_json::from_value::<Vec<f64>>(v).ok()) {
        return Some(k);
    }
    let n = read(cx, object, "/shape/local_curves")?.as_u64()? as usize;
    let closed = read(cx, object, "/shape/closed").and_then(|v| v.as_bool()).unwrap_or(false);
    (2..=4096).contains(&n).then(|| (0..n + usize::from(closed)).map(|i| i as f64).collect())
}

/// The selected handle's value for exact entry (translation of a local piece, or the
/// coordinates of a control point and, of NURBS and rational Béziers, its weight).
fn selected_handle(ui: &mut egui::Ui, cx: &mut PanelContext<'_>) {
    let Some(h) = cx.selection.handle.clone() else { return };
    ui.separator();
    ui.label(format!("selected: {}", h.kind.field()));
    let pointer = h.kind.pointer();
    if let Some(path) = h.kind.point_path() {
        local_point(ui, cx, &h, &path, &pointer);
        return;
    }
    let coords = if h.kind.is_local() { format!("{pointer}/translate") } else { pointer.clone() };
    let n = h.dimension;
    let mut values: Vec<f64> =
        read(cx, h.object, &coords).and_then(|v| serde_json::from_value(v).ok()).unwrap_or_else(|| vec![0.0; n]);
    let mut changed = false;
    let name = ui.label(if h.kind.is_local() { "translate" } else { "point" });
    ui.horizontal_wrapped(|ui| {
        for x in values.iter_mut() {
            changed |= ui.add(egui::DragValue::new(x).speed(0.01).max_decimals(3)).labelled_by(name.id).changed();
        }
    });
    if changed {
        write(cx, h.object, &coords, Some(values.into()));
    }
    error_label(ui, cx, &coords);
    if let Some((pointer, w)) = crate::gesture::weight_of(cx.scene, &h) {
        number(ui, cx, h.object, &pointer, "weight", w);
    }
}

/// The rest-frame coordinates of a local Bézier's control point for exact entry: a change
/// writes the local's whole `local_control_points` entry (the other points as they are).
fn local_point(
    ui: &mut egui::Ui,
    cx: &mut PanelContext<'_>,
    h: &crate::handles::Handle,
    path: &[usize],
    pointer: &str,
) {
    let Some((mut rest, _)) = crate::handles::local_points_of(cx.scene, h, cx.time) else {
        return;
    };
    let Some(point) = path.iter().try_fold(&mut rest, |v, &i| v.get_mut(i)) else { return };
    let mut values: Vec<f64> = serde_json::from_value(point.clone()).unwrap_or_default();
    let name = ui.label("point (in the local's rest frame)");
    let mut changed = false;
    ui.horizontal_wrapped(|ui| {
        for x in values.iter_mut() {
            changed |= ui.add(egui::DragValue::new(x).speed(0.01).max_decimals(3)).labelled_by(name.id).changed();
        }
    });
    if changed {
        *point = values.into();
        write(cx, h.object, pointer, Some(rest));
    }
    error_label(ui, cx, pointer);
}
