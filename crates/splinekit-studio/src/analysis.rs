//! Shape analysis drawn over the 3-D view, live while dragging: the curvature comb of
//! every shown curve (a tooth −s·κ·N at each of [`COMB_TEETH`] samples and the line
//! through the tips, s the comb scale times a length fitted to the curve's size) and the
//! continuity at the knots of B-splines and NURBS and the junctions (knots) of
//! blending-spline curves: the gap |c(t⁻) − c(t⁺)|, the angle between the one-sided
//! tangents and the relative jump of the curvature vector
//! |κ⁻N⁻ − κ⁺N⁺| / max(κ⁻, κ⁺), classified G2, G1, G0 or a gap, marked on the shape in
//! the class's colour and listed in the Analysis panel.

use splinekit::basis::Side;
use splinekit::curve::{Curve, curvature_from};
use splinekit::query::Aabb;
use splinekit::{Point, blend::BlendingSplineCurve};
use splinekit_render::{LineItem, PointItem, RenderScene};
use splinekit_scene::scenes::SceneDocument;
use splinekit_scene::{CurveDocument, Curves, Decoration, DimensionVisitor, DocumentKind, ShapeDocument};

/// Teeth of a curvature comb.
pub const COMB_TEETH: usize = 240;

/// Gap, angle (radians) and relative curvature jump below which a junction counts as
/// closed, tangent-continuous and curvature-continuous.
pub const TOLERANCES: (f64, f64, f64) = (1e-9, 1e-7, 1e-6);

/// The geometric continuity at one knot or junction.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Junction {
    /// The parameter.
    pub t: f64,
    /// The point (left limit; z = 0 for plane curves).
    pub point: [f64; 3],
    /// |c(t⁻) − c(t⁺)|, relative to the curve's size.
    pub gap: f64,
    /// The angle between the one-sided unit tangents (radians).
    pub angle: f64,
    /// |κ⁻N⁻ − κ⁺N⁺| / max(κ⁻, κ⁺) (0 where both curvatures vanish).
    pub curvature_jump: f64,
}

impl Junction {
    /// The highest order of geometric continuity that holds within [`TOLERANCES`]:
    /// `Some(0..=2)`, `None` for a gap.
    pub fn order(&self) -> Option<u8> {
        let (gap, angle, jump) = TOLERANCES;
        match (self.gap <= gap, self.angle <= angle, self.curvature_jump <= jump) {
            (false, _, _) => None,
            (true, false, _) => Some(0),
            (true, true, false) => Some(1),
            (true, true, true) => Some(2),
        }
    }

    /// `G2`, `G1`, `G0` or `gap`.
    pub fn label(&self) -> &'static str {
        match self.order() {
            Some(2) => "G2",
            Some(1) => "G1",
            Some(_) => "G0",
            None => "gap",
        }
    }

    /// The colour its marker is drawn in (green G2, yellow G1, orange G0, red gap).
    pub fn color(&self) -> [f32; 4] {
        match self.order() {
            Some(2) => [0.1, 0.7, 0.2, 1.0],
            Some(1) => [0.9, 0.8, 0.0, 1.0],
            Some(_) => [1.0, 0.45, 0.0, 1.0],
            None => [0.9, 0.1, 0.1, 1.0],
        }
    }
}

/// Comb teeth: (foot on the curve, tip).
type Teeth = Vec<([f64; 3], [f64; 3])>;

fn to3<const D: usize>(p: &Point<D>) -> [f64; 3] {
    [0, 1, 2].map(|k| if k < D { p[k] } else { 0.0 })
}

/// The curvature vector κN = (c'' − (c''·T)T)/|c'|² from the first two derivatives.
fn curvature_vector<const D: usize>(d1: &Point<D>, d2: &Point<D>) -> Point<D> {
    let s2 = d1.norm_squared();
    if s2 == 0.0 {
        return Point::<D>::zeros();
    }
    (d2 - d1 * (d1.dot(d2) / s2)) / s2
}

/// The continuity of `c` at `t` (one-sided limits), the gap relative to `size`.
fn junction<const D: usize>(c: &dyn Curve<D>, t: f64, size: f64) -> Junction {
    let mut left = [Point::<D>::zeros(); 3];
    let mut right = [Point::<D>::zeros(); 3];
    c.eval_side(t, Side::Left, &mut left);
    c.eval_side(t, Side::Right, &mut right);
    let gap = (left[0] - right[0]).norm() / size.max(f64::MIN_POSITIVE);
    let (a, b) = (left[1].norm(), right[1].norm());
    let angle = if a > 0.0 && b > 0.0 { (left[1] / a).dot(&(right[1] / b)).clamp(-1.0, 1.0).acos() } else { 0.0 };
    let (ka, kb) = (curvature_from(&left[1], &left[2]), curvature_from(&right[1], &right[2]));
    let jump = (curvature_vector(&left[1], &left[2]) - curvature_vector(&right[1], &right[2])).norm();
    let curvature_jump = if ka.max(kb) > 0.0 { jump / ka.max(kb) } else { 0.0 };
    Junction { t, point: to3(&left[0]), gap, angle, curvature_jump }
}

/// Comb teeth (foot, tip) of `c` with tips at −κN·length, and the curve's size (the
/// diagonal of its samples' box).
fn comb_of<const D: usize>(c: &dyn Curve<D>, scale: f64) -> (Teeth, f64) {
    let domain = c.domain();
    let mut out = [Point::<D>::zeros(); 3];
    let samples: Vec<([f64; 3], Point<D>)> = (0..=COMB_TEETH)
        .map(|i| {
            c.eval(domain.lerp(i as f64 / COMB_TEETH as f64), &mut out);
            (to3(&out[0]), curvature_vector(&out[1], &out[2]))
        })
        .collect();
    let size = diagonal(samples.iter().map(|s| s.0));
    let largest = samples.iter().map(|s| s.1.norm()).fold(0.0, f64::max);
    // The longest tooth is a fifth of the curve's size at scale 1.
    let length = if largest > 0.0 { 0.2 * size * scale / largest } else { 0.0 };
    let teeth = samples.into_iter().map(|(p, k)| (p, [0, 1, 2].map(|i| p[i] - length * to3(&k)[i]))).collect();
    (teeth, size)
}

/// The diagonal of the points' box ([`Aabb::spanning`]), a coordinate no point has a
/// number for counting 0.
fn diagonal(points: impl Iterator<Item = [f64; 3]>) -> f64 {
    let Some(b) = Aabb::spanning(points.map(Point::<3>::from)) else { return 0.0 };
    (0..3).map(|k| (b.max[k] - b.min[k]).max(0.0).powi(2)).sum::<f64>().sqrt()
}

/// The parameters where a curve's pieces meet: the distinct interior knots of a B-spline
/// or NURBS document, the distinct knots (local centres; a split knot once) of a
/// blending-spline curve inside its domain.
fn junction_parameters(doc: &CurveDocument) -> Vec<f64> {
    let interior = |knots: &[f64]| -> Vec<f64> {
        let (Some(&a), Some(&b)) = (knots.first(), knots.last()) else { return Vec::new() };
        let mut inner: Vec<f64> = knots.iter().copied().filter(|&k| k > a && k < b).collect();
        inner.dedup();
        inner
    };
    fn centres<const D: usize>(c: &BlendingSplineCurve<D>) -> Vec<f64> {
        let domain = c.domain();
        let mut inner: Vec<f64> =
            (0..c.local_count()).map(|k| c.centre(k)).filter(|&t| t > domain.start && t < domain.end).collect();
        inner.dedup();
        inner
    }
    match doc {
        CurveDocument::Bspline(d) => interior(&d.knots),
        CurveDocument::Nurbs(d) => interior(&d.knots),
        other => match other.decoration() {
            Decoration::LocalCurves(d) => match d.dimension() {
                Ok(2) => d.curve::<2>().map(|c| centres(&c)).unwrap_or_default(),
                Ok(3) => d.curve::<3>().map(|c| centres(&c)).unwrap_or_default(),
                _ => Vec::new(),
            },
            _ => Vec::new(),
        },
    }
}

/// The comb (teeth) and the junctions of one curve document posed as built.
fn analyse(doc: &CurveDocument, comb_scale: Option<f64>) -> (Teeth, Vec<Junction>) {
    struct Analyse<'a>(Option<f64>, &'a [f64]);
    impl DimensionVisitor<Curves> for Analyse<'_> {
        type Output = (Teeth, Vec<Junction>);
        fn visit<const D: usize>(self, c: &dyn Curve<D>) -> Self::Output {
            let (teeth, size) = comb_of(c, self.0.unwrap_or(0.0));
            let junctions = self.1.iter().map(|&t| junction(c, t, size)).collect();
            (if self.0.is_some() { teeth } else { Vec::new() }, junctions)
        }
    }
    let ts = junction_parameters(doc);
    doc.build().map(|c| c.visit(Analyse(comb_scale, &ts))).unwrap_or_default()
}

/// What the view analyses, and the last analysis (kept while the document is the same).
#[derive(Debug, Clone)]
pub struct Analysis {
    /// Draw the curvature comb of every shown curve.
    pub comb: bool,
    /// The comb's scale (1: the longest tooth a fifth of the curve's size).
    pub comb_scale: f64,
    /// Mark the continuity at knots and junctions.
    pub continuity: bool,
    kept: Option<Kept>,
}

#[derive(Debug, Clone)]
struct Kept {
    scene: SceneDocument,
    time: Option<f64>,
    comb: Option<f64>,
    continuity: bool,
    lines: Vec<LineItem>,
    points: Vec<PointItem>,
    junctions: Vec<(usize, Vec<Junction>)>,
}

impl Default for Analysis {
    fn default() -> Self {
        Analysis { comb: false, comb_scale: 1.0, continuity: false, kept: None }
    }
}

fn f32x3(p: [f64; 3]) -> [f32; 3] {
    p.map(|x| x as f32)
}

impl Analysis {
    /// Whether anything is drawn.
    pub fn any(&self) -> bool {
        self.comb || self.continuity
    }

    /// Brings the analysis up to date with `scene` posed at `time` (reused while nothing
    /// changed) and appends its lines and markers to `rs`.
    pub fn overlay(&mut self, scene: &SceneDocument, time: Option<f64>, rs: &mut RenderScene) {
        if !self.any() {
            return;
        }
        let comb = self.comb.then_some(self.comb_scale);
        let fresh = self
            .kept
            .as_ref()
            .is_some_and(|k| k.scene == *scene && k.time == time && k.comb == comb && k.continuity == self.continuity);
        if !fresh {
            self.kept = Some(self.analyse(scene, time, comb));
        }
        if let Some(k) = &self.kept {
            rs.lines.extend(k.lines.iter().cloned());
            rs.points.extend(k.points.iter().copied());
        }
    }

    fn analyse(&self, scene: &SceneDocument, time: Option<f64>, comb: Option<f64>) -> Kept {
        let (mut lines, mut points, mut junctions) = (Vec::new(), Vec::new(), Vec::new());
        for (i, o) in scene.objects.iter().enumerate() {
            let ShapeDocument::Curve(doc) = &o.shape else { continue };
            if o.style.hidden {
                continue;
            }
            let mut doc = doc.clone();
            if let Some(t) = time {
                doc.set_time(t);
            }
            let (teeth, js) = analyse(&doc, comb);
            let color = [0.55, 0.2, 0.75, 1.0];
            for (foot, tip) in &teeth {
                lines.push(LineItem {
                    points: vec![f32x3(*foot), f32x3(*tip)],
                    closed: false,
                    color,
                    width: 1.0,
                    colors: Vec::new(),
                });
            }
            if !teeth.is_empty() {
                let tips = teeth.iter().map(|(_, tip)| f32x3(*tip)).collect();
                lines.push(LineItem { points: tips, closed: false, color, width: 1.5, colors: Vec::new() });
            }
            if self.continuity {
                points.extend(js.iter().map(|j| PointItem { position: f32x3(j.point), color: j.color(), size: 10.0 }));
                junctions.push((i, js));
            }
        }
        Kept { scene: scene.clone(), time, comb, continuity: self.continuity, lines, points, junctions }
    }

    /// The junctions of object `object` as last analysed.
    pub fn junctions(&self, object: usize) -> &[Junction] {
        self.kept
            .as_ref()
            .and_then(|k| k.junctions.iter().find(|(i, _)| *i == object))
            .map_or(&[], |(_, js)| js.as_slice())
    }
}

/// The Analysis panel: the comb and its scale, the continuity markers and, for the
/// selected object, each junction's class and numbers.
pub fn analysis_panel(ui: &mut egui::Ui, analysis: &mut Analysis, selected: Option<usize>) {
    ui.heading("Analysis");
    ui.checkbox(&mut analysis.comb, crate::actions::menu_label(crate::actions::Action::ToggleComb));
    ui.horizontal(|ui| {
        let name = ui.label("comb scale");
        ui.add(egui::DragValue::new(&mut analysis.comb_scale).range(0.01..=100.0).speed(0.02)).labelled_by(name.id);
    });
    ui.checkbox(&mut analysis.continuity, crate::actions::menu_label(crate::actions::Action::ToggleContinuity));
    if !analysis.continuity {
        return;
    }
    let Some(object) = selected else {
        ui.label("select a curve for its junctions");
        return;
    };
    let js = analysis.junctions(object);
    if js.is_empty() {
        ui.label("no knots or junctions inside the selected curve");
        return;
    }
    egui::Grid::new("junctions").striped(true).show(ui, |ui| {
        for h in ["t", "", "gap", "angle°", "Δκ"] {
            ui.label(h);
        }
        ui.end_row();
        for j in js {
            ui.label(format!("{:.4}", j.t));
            ui.label(j.label());
            ui.label(format!("{:.1e}", j.gap));
            ui.label(format!("{:.2}", j.angle.to_degrees()));
            ui.label(format!("{:.1e}", j.curvature_jump));
            ui.end_row();
        }
    });
}

#[cfg(test)]
mod tests {
    use super::*;

    fn curve(v: serde_json::Value) -> CurveDocument {
        let ShapeDocument::Curve(c) = ShapeDocument::from_value(v).expect("valid") else { panic!("a curve") };
        c
    }

    #[test]
    fn knots_of_a_cubic_are_g2_a_double_knot_g1_at_best_and_a_kink_g0() {
        let pts = serde_json::json!([[0, 0], [1, 2], [2, -1], [3, 2], [4, 0], [5, 1]]);
        let cubic = curve(serde_json::json!({"type": "bspline", "degree": 3,
            "knots": [0, 0, 0, 0, 1, 2, 3, 3, 3, 3], "control_points": pts}));
        let (teeth, js) = analyse(&cubic, Some(1.0));
        assert_eq!(teeth.len(), COMB_TEETH + 1);
        assert_eq!(js.iter().map(Junction::label).collect::<Vec<_>>(), ["G2", "G2"]);
        // A quadratic with a double knot at 1 and collinear control points around it: G1,
        // with a curvature jump.
        let g1 = curve(serde_json::json!({"type": "bspline", "degree": 2,
            "knots": [0, 0, 0, 1, 1, 2, 2, 2], "control_points": [[0, 0], [1, 1], [2, 1], [3, 1], [4, 3]]}));
        let (_, js) = analyse(&g1, None);
        assert_eq!(js.len(), 1);
        assert_eq!(js[0].label(), "G1", "{:?}", js[0]);
        assert!(js[0].curvature_jump > 0.1);
        // Linear pieces meet at an angle: G0, 45°.
        let kink = curve(serde_json::json!({"type": "bspline", "degree": 1,
            "knots": [0, 0, 1, 2, 2], "control_points": [[0, 0], [1, 0], [2, 1]]}));
        let (_, js) = analyse(&kink, None);
        assert_eq!(js[0].label(), "G0");
        assert!((js[0].angle.to_degrees() - 45.0).abs() < 1e-9);
    }

    #[test]
    fn a_circle_combs_evenly_outwards() {
        // The exact NURBS circle: every tooth as long as every other, pointing outwards.
        let circle = curve(serde_json::json!({"type": "circle", "radius": 2}));
        let (teeth, _) = analyse(&circle, Some(1.0));
        let lengths: Vec<f64> =
            teeth.iter().map(|(f, t)| (0..3).map(|k| (t[k] - f[k]).powi(2)).sum::<f64>().sqrt()).collect();
        let (lo, hi) = lengths.iter().fold((f64::INFINITY, 0.0f64), |(a, b), &l| (a.min(l), b.max(l)));
        assert!(hi - lo < 1e-9 * hi, "{lo} {hi}");
        for (f, t) in &teeth {
            assert!(t[0].hypot(t[1]) > f[0].hypot(f[1]), "outwards");
        }
    }
}
