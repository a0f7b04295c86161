//! The handles of a scene: what the mouse can grab. A handle at each local origin of a
//! blending-spline curve or surface (the frame origin moved by its transform,
//! o + t), and one at each control point of a Bézier, B-spline or NURBS curve or net.

use serde_json::Value;
use splinekit_scene::blending::{BlendingSplineDoc, BlendingSplineSurfaceDoc};
use splinekit_scene::scenes::SceneDocument;
use splinekit_scene::transforms::TransformDoc;
use splinekit_scene::{Decoration, DocumentError, DocumentKind, ShapeDocument};

/// What a handle stands for.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum HandleKind {
    /// Local curve k of a blending-spline curve.
    LocalCurve(usize),
    /// Local patch (k, l) of a blending-spline surface.
    LocalPatch(usize, usize),
    /// Control point i of a curve, in its document field (`control_points`, or `points` of
    /// interpolating curves).
    ControlPoint(usize, &'static str),
    /// Control point (i, j) of a net.
    NetPoint(usize, usize),
}

/// One grabbable point.
#[derive(Debug, Clone, PartialEq)]
pub struct Handle {
    /// Index of the object.
    pub object: usize,
    /// What it stands for.
    pub kind: HandleKind,
    /// World position (z = 0 for plane shapes).
    pub position: [f64; 3],
    /// The local piece's origin o before its transform (where the transform's centred
    /// coordinates start); for control points the point itself.
    pub origin: [f64; 3],
    /// Number of coordinates of the shape (2 or 3).
    pub dimension: usize,
}

impl HandleKind {
    /// The JSON pointer (within the object's document) of the value the handle edits.
    pub fn pointer(&self) -> String {
        match *self {
            HandleKind::LocalCurve(k) => format!("/shape/transforms/{k}"),
            HandleKind::LocalPatch(k, l) => format!("/shape/transforms/{k},{l}"),
            HandleKind::ControlPoint(i, field) => format!("/shape/{field}/{i}"),
            HandleKind::NetPoint(i, j) => format!("/shape/control_points/{i}/{j}"),
        }
    }

    /// The field as the library names it in messages (`transforms[3]`).
    pub fn field(&self) -> String {
        match *self {
            HandleKind::LocalCurve(k) => format!("transforms[{k}]"),
            HandleKind::LocalPatch(k, l) => format!("transforms[{k},{l}]"),
            HandleKind::ControlPoint(i, field) => format!("{field}[{i}]"),
            HandleKind::NetPoint(i, j) => format!("control_points[{i}][{j}]"),
        }
    }

    /// Whether the handle moves a local piece's frame (rather than a control point).
    pub fn is_local(&self) -> bool {
        matches!(self, HandleKind::LocalCurve(_) | HandleKind::LocalPatch(..))
    }
}

/// The handles of every visible object of the scene, posed at `time`.
pub fn handles(scene: &SceneDocument, time: Option<f64>) -> Result<Vec<Handle>, DocumentError> {
    let mut out = Vec::new();
    for (object, obj) in scene.objects.iter().enumerate() {
        let mut shape = obj.shape.clone();
        if let Some(t) = time {
            shape.set_time(t);
        }
        let within = |e: DocumentError| e.within(&format!("objects[{object}].shape"));
        let (decoration, field) = match &shape {
            ShapeDocument::Curve(c) => {
                let interpolating = matches!(c.type_name(), "hermite" | "catmull_rom");
                (c.decoration(), if interpolating { "points" } else { "control_points" })
            }
            ShapeDocument::Surface(s) => (s.decoration(), "control_points"),
        };
        let mut push = |kind, p: &[f64], o: &[f64], dimension| {
            out.push(Handle { object, kind, position: to3(p), origin: to3(o), dimension })
        };
        match decoration {
            Decoration::None => {}
            Decoration::ControlPolygon { points, .. } => {
                for (i, p) in points.iter().enumerate() {
                    push(HandleKind::ControlPoint(i, field), p, p, p.len().min(3));
                }
            }
            Decoration::ControlNet(net) => {
                for (i, row) in net.iter().enumerate() {
                    for (j, p) in row.iter().enumerate() {
                        push(HandleKind::NetPoint(i, j), p, p, p.len().min(3));
                    }
                }
            }
            Decoration::LocalCurves(d) => local_curves(d, &mut push).map_err(within)?,
            Decoration::LocalPatches(d) => local_patches(d, &mut push).map_err(within)?,
        }
    }
    Ok(out)
}

fn to3(p: &[f64]) -> [f64; 3] {
    [p.first().copied().unwrap_or(0.0), p.get(1).copied().unwrap_or(0.0), p.get(2).copied().unwrap_or(0.0)]
}

/// The moved origins o_k + t_k of a blending-spline curve's locals.
fn local_curves(
    d: &BlendingSplineDoc,
    push: &mut impl FnMut(HandleKind, &[f64], &[f64], usize),
) -> Result<(), DocumentError> {
    macro_rules! origins {
        ($dim:literal) => {{
            let c = d.curve::<$dim>()?;
            for k in 0..c.local_count() {
                let o = c.origin(k);
                let moved = c.transform(k).apply_point_about(&o, &o);
                push(HandleKind::LocalCurve(k), moved.as_slice(), o.as_slice(), $dim);
            }
        }};
    }
    match d.dimension()? {
        2 => origins!(2),
        3 => origins!(3),
        other => {
            return Err(DocumentError::new("local_curves", format!("handles for 2-D and 3-D curves, not {other}-D")));
        }
    }
    Ok(())
}

/// The moved origins of a blending-spline surface's patches.
fn local_patches(
    d: &BlendingSplineSurfaceDoc,
    push: &mut impl FnMut(HandleKind, &[f64], &[f64], usize),
) -> Result<(), DocumentError> {
    let s = d.surface::<3>()?;
    let (nu, nv) = s.local_count();
    for k in 0..nu {
        for l in 0..nv {
            let o = s.origin(k, l);
            let moved = s.transform(k, l).apply_point_about(&o, &o);
            push(HandleKind::LocalPatch(k, l), moved.as_slice(), o.as_slice(), 3);
        }
    }
    Ok(())
}

/// The current transform document of a local handle (identity when it has none).
pub fn transform_of(scene: &SceneDocument, handle: &Handle) -> TransformDoc {
    let doc = scene.objects.get(handle.object).map(|o| o.to_value());
    doc.and_then(|d| d.pointer(&handle.kind.pointer()).cloned())
        .and_then(|v| serde_json::from_value(v).ok())
        .unwrap_or_default()
}

/// The current coordinates of a control-point handle, as the document writes them.
pub fn coordinates_of(scene: &SceneDocument, handle: &Handle) -> Option<Vec<f64>> {
    let doc = scene.objects.get(handle.object)?.to_value();
    let value: Value = doc.pointer(&handle.kind.pointer())?.clone();
    serde_json::from_value(value).ok()
}
