//! The handles of a scene: what the mouse can grab. A handle at each local origin of a
//! blending-spline curve or surface (the frame origin moved by its transform,
//! o + t), one at each control point of a Bézier local curve or patch of a blending spline
//! (in the world: its frame applied, o + T(P − o); the view shows those of the selected
//! local piece only, [`Handle::shown_with`]), one at each control point of a Bézier,
//! B-spline or NURBS curve or net or of a Bézier triangle, one at each cage vertex of a
//! subdivision surface (`vertices[i]`), and one at each local's moved origin of a GERBS
//! triangle or a blending triangulation (its `transforms[k]`).

use serde_json::Value;
use splinekit::blend::BlendingSplineSurface;
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
    /// Control point i of the Bézier local curve k of a blending spline.
    LocalCurvePoint(usize, usize),
    /// Control point (a, b) of the Bézier patch (k, l) of a blending-spline surface.
    LocalPatchPoint(usize, usize, usize, usize),
    /// Local k of the triangle family's blending kinds: corner k's local triangle of a
    /// `gerbs_triangle` (0, 1, 2: corners u, v, w), vertex k's local of a
    /// `blending_triangulation`; its frame is `transforms[k]`.
    LocalTriangle(usize),
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
    /// A copy of a split knot (a local curve whose support ends at its own knot): the
    /// joint, its moved origin o + t, about which a drag turns and scales it
    /// ([`crate::gesture`]); the handle itself then sits on the copy's local curve a third
    /// (the first copy) or half (the second) of the way from the joint to the neighbouring
    /// knot. `None` for every other handle.
    pub pivot: Option<[f64; 3]>,
}

impl HandleKind {
    /// The JSON pointer (within the object's document) of the value the handle edits.
    pub fn pointer(&self) -> String {
        let (field, pointer, _) = self.place();
        format!("/shape/{field}{pointer}")
    }

    /// The field as the library names it in messages (`transforms[3]`).
    pub fn field(&self) -> String {
        let (field, _, message) = self.place();
        format!("{field}{message}")
    }

    /// Where in the shape's document the handle's value lives: the document field, and
    /// what follows it in [`Self::pointer`] (down to the value the handle edits: a local's
    /// whole point list) and in [`Self::field`] (down to the point itself).
    fn place(&self) -> (&'static str, String, String) {
        match *self {
            HandleKind::LocalCurve(k) | HandleKind::LocalTriangle(k) => {
                ("transforms", format!("/{k}"), format!("[{k}]"))
            }
            HandleKind::LocalPatch(k, l) => ("transforms", format!("/{k},{l}"), format!("[{k},{l}]")),
            HandleKind::ControlPoint(i, field) => (field, format!("/{i}"), format!("[{i}]")),
            HandleKind::NetPoint(i, j) => ("control_points", format!("/{i}/{j}"), format!("[{i}][{j}]")),
            HandleKind::LocalCurvePoint(k, i) => ("local_control_points", format!("/{k}"), format!(".{k}[{i}]")),
            HandleKind::LocalPatchPoint(k, l, a, b) => {
                ("local_control_points", format!("/{k},{l}"), format!(".{k},{l}[{a}][{b}]"))
            }
        }
    }

    /// Where the point sits in the value at [`Self::pointer`] of a local Bézier's
    /// control-point handle (`[i]`, `[a, b]`); `None` for other handles.
    pub fn point_path(&self) -> Option<Vec<usize>> {
        match *self {
            HandleKind::LocalCurvePoint(_, i) => Some(vec![i]),
            HandleKind::LocalPatchPoint(_, _, a, b) => Some(vec![a, b]),
            _ => None,
        }
    }

    /// The local piece the handle belongs to (its origin or one of its control points):
    /// `(k, None)` for local curve k, `(k, Some(l))` for patch (k, l).
    pub fn piece(&self) -> Option<(usize, Option<usize>)> {
        match *self {
            HandleKind::LocalCurve(k) | HandleKind::LocalCurvePoint(k, _) | HandleKind::LocalTriangle(k) => {
                Some((k, None))
            }
            HandleKind::LocalPatch(k, l) | HandleKind::LocalPatchPoint(k, l, _, _) => Some((k, Some(l))),
            _ => None,
        }
    }

    /// Whether the handle moves a local piece's frame (rather than a control point).
    pub fn is_local(&self) -> bool {
        matches!(self, HandleKind::LocalCurve(_) | HandleKind::LocalPatch(..) | HandleKind::LocalTriangle(_))
    }
}

impl Handle {
    /// Whether the view shows (and picks) this handle while `selected` is selected: a
    /// local Bézier's control points only when their local piece (its origin or one of
    /// its control points) is selected; every other handle always.
    pub fn shown_with(&self, selected: Option<&Handle>) -> bool {
        if self.kind.point_path().is_none() {
            return true;
        }
        selected.is_some_and(|s| s.object == self.object && s.kind.piece() == self.kind.piece())
    }
}

/// A blending-spline surface already built from object i's document (posed), if any.
pub type BuiltSurface<'a> = dyn Fn(usize, &BlendingSplineSurfaceDoc) -> Option<&'a BlendingSplineSurface<3>> + 'a;

/// The handles of every visible object of the scene, posed at `time`.
pub fn handles(scene: &SceneDocument, time: Option<f64>) -> Result<Vec<Handle>, DocumentError> {
    handles_with(scene, time, &|_, _| None)
}

/// [`handles`], with the blending-spline surfaces `built` gives used instead of building
/// them again (the studio's one built surface per object, [`crate::live_surfaces`]).
pub fn handles_with<'a>(
    scene: &SceneDocument,
    time: Option<f64>,
    built: &BuiltSurface<'a>,
) -> Result<Vec<Handle>, DocumentError> {
    let mut out = Vec::new();
    for (object, obj) in scene.objects.iter().enumerate() {
        let mut shape = obj.shape.clone();
        if let Some(t) = time {
            shape.set_time(t);
        }
        let within = |e: DocumentError| e.within(&format!("objects[{object}].shape"));
        let decoration = match &shape {
            ShapeDocument::Curve(c) => c.decoration(),
            ShapeDocument::Surface(s) => s.decoration(),
        };
        let mut push = |kind, p: &[f64], o: &[f64], dimension, pivot: Option<&[f64]>| {
            let pivot = pivot.map(to3);
            out.push(Handle { object, kind, position: to3(p), origin: to3(o), dimension, pivot })
        };
        match decoration {
            Decoration::None => {}
            Decoration::ControlPolygon { points, field, .. } => {
                for (i, p) in points.iter().enumerate() {
                    push(HandleKind::ControlPoint(i, field), p, p, p.len().min(3), None);
                }
            }
            Decoration::ControlNet(net) => {
                for (i, row) in net.iter().enumerate() {
                    for (j, p) in row.iter().enumerate() {
                        push(HandleKind::NetPoint(i, j), p, p, p.len().min(3), None);
                    }
                }
            }
            Decoration::TriangularNet { points, field } => {
                for (i, p) in points.iter().enumerate() {
                    push(HandleKind::ControlPoint(i, field), p, p, p.len().min(3), None);
                }
            }
            // A handle at each local's moved origin, editing its `transforms` entry as
            // those of blending-spline curves do.
            Decoration::LocalPieces(d) => {
                let (dimension, origins) = d.local_origins().map_err(within)?;
                for (k, o) in origins.iter().enumerate() {
                    push(HandleKind::LocalTriangle(k), &o.moved, &o.origin, dimension.min(3), None);
                }
            }
            Decoration::Cage { vertices, .. } => {
                for (i, p) in vertices.iter().enumerate() {
                    push(HandleKind::ControlPoint(i, "vertices"), p, p, 3, None);
                }
            }
            Decoration::LocalCurves(d) => local_curves(d, &mut push).map_err(within)?,
            Decoration::LocalPatches(d) => local_patches(d, built(object, d), &mut push).map_err(within)?,
        }
    }
    Ok(out)
}

fn to3(p: &[f64]) -> [f64; 3] {
    [p.first().copied().unwrap_or(0.0), p.get(1).copied().unwrap_or(0.0), p.get(2).copied().unwrap_or(0.0)]
}

/// The moved origins o_k + t_k of a blending-spline curve's locals; for the two copies
/// of a split knot (a local whose support [c_{k−1}, c_{k+1}] ends at its own knot c_k),
/// the local's world point a third (the first copy) or half (the second) of the way from
/// c_k to the other end of its support, with the moved origin (the joint) as the pivot.
fn local_curves(
    d: &BlendingSplineDoc,
    push: &mut impl FnMut(HandleKind, &[f64], &[f64], usize, Option<&[f64]>),
) -> Result<(), DocumentError> {
    macro_rules! origins {
        ($dim:literal) => {{
            let c = d.curve::<$dim>()?;
            for k in 0..c.local_count() {
                let o = c.origin(k);
                let moved = c.transform(k).apply_point_about(&o, &o);
                let (centre, support) = (c.centre(k), c.local_support(k));
                // The first copy a third of the way, the second halfway: apart even where
                // the local is symmetric about its knot (at a cusp of the model).
                let (other, part) = if support.end == centre { (support.start, 3.0) } else { (support.end, 2.0) };
                if support.start == centre || support.end == centre {
                    let mut at = [splinekit::Point::<$dim>::zeros(); 1];
                    c.eval_local(k, centre + (other - centre) / part, &mut at);
                    push(HandleKind::LocalCurve(k), at[0].as_slice(), o.as_slice(), $dim, Some(moved.as_slice()));
                } else {
                    push(HandleKind::LocalCurve(k), moved.as_slice(), o.as_slice(), $dim, None);
                }
                for (i, p) in c.local_bezier_world_points(k).unwrap_or_default().iter().enumerate() {
                    push(HandleKind::LocalCurvePoint(k, i), p.as_slice(), p.as_slice(), $dim, None);
                }
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
    built: Option<&BlendingSplineSurface<3>>,
    push: &mut impl FnMut(HandleKind, &[f64], &[f64], usize, Option<&[f64]>),
) -> Result<(), DocumentError> {
    let owned;
    let s = match built {
        Some(s) => s,
        None => {
            owned = d.surface::<3>()?;
            &owned
        }
    };
    let (nu, nv) = s.local_count();
    for k in 0..nu {
        for l in 0..nv {
            let o = s.origin(k, l);
            let moved = s.transform(k, l).apply_point_about(&o, &o);
            push(HandleKind::LocalPatch(k, l), moved.as_slice(), o.as_slice(), 3, None);
            if let Some((world, (_, dv))) = s.bezier_net(k, l) {
                for (j, p) in world.iter().enumerate() {
                    push(
                        HandleKind::LocalPatchPoint(k, l, j / (dv + 1), j % (dv + 1)),
                        p.as_slice(),
                        p.as_slice(),
                        3,
                        None,
                    );
                }
            }
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

/// For the handle of a control point of a local Bézier: the local's control points in its
/// rest frame as the document writes them (its `local_control_points` entry, else the
/// Hermite-fitted ones), and the inverse of the linear part of the local's frame posed at
/// `time` (3 × 3, rows; the z row and column of a plane shape's are those of the identity),
/// which maps a world displacement of the handle to the change of the point in the rest
/// frame. `None` for other handles or a singular frame.
pub fn local_points_of(scene: &SceneDocument, handle: &Handle, time: Option<f64>) -> Option<(Value, [[f64; 3]; 3])> {
    let mut shape = scene.objects.get(handle.object)?.shape.clone();
    if let Some(t) = time {
        shape.set_time(t);
    }
    macro_rules! curve_points {
        ($d:expr, $k:expr, $dim:literal) => {{
            let c = $d.curve::<$dim>().ok()?;
            let rest: Vec<Vec<f64>> = c.local_bezier_points($k)?.iter().map(|p| p.as_slice().to_vec()).collect();
            let inv = c.transform($k).linear.try_inverse()?;
            let mut m = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
            for (i, row) in m.iter_mut().enumerate().take($dim) {
                for (j, x) in row.iter_mut().enumerate().take($dim) {
                    *x = inv[(i, j)];
                }
            }
            Some((serde_json::to_value(rest).ok()?, m))
        }};
    }
    let decoration = match &shape {
        ShapeDocument::Curve(c) => c.decoration(),
        ShapeDocument::Surface(s) => s.decoration(),
    };
    match (decoration, handle.kind) {
        (Decoration::LocalCurves(d), HandleKind::LocalCurvePoint(k, _)) => match d.dimension().ok()? {
            2 => curve_points!(d, k, 2),
            3 => curve_points!(d, k, 3),
            _ => None,
        },
        (Decoration::LocalPatches(d), HandleKind::LocalPatchPoint(k, l, _, _)) => {
            let s = d.surface::<3>().ok()?;
            let (net, (_, dv)) = s.bezier_rest_net(k, l)?;
            let rows: Vec<Vec<Vec<f64>>> =
                net.chunks(dv + 1).map(|row| row.iter().map(|p| p.as_slice().to_vec()).collect()).collect();
            let inv = s.transform(k, l).linear.try_inverse()?;
            let m = [0, 1, 2].map(|i| [0, 1, 2].map(|j| inv[(i, j)]));
            Some((serde_json::to_value(rows).ok()?, m))
        }
        _ => None,
    }
}

#[cfg(test)]
mod tests {
    use super::HandleKind;

    /// Each kind's value as a JSON pointer and as the library's messages name it.
    #[test]
    fn pointers_and_fields_of_every_kind() {
        let cases = [
            (HandleKind::LocalCurve(3), "/shape/transforms/3", "transforms[3]"),
            (HandleKind::LocalPatch(1, 2), "/shape/transforms/1,2", "transforms[1,2]"),
            (HandleKind::ControlPoint(4, "points"), "/shape/points/4", "points[4]"),
            (HandleKind::NetPoint(1, 5), "/shape/control_points/1/5", "control_points[1][5]"),
            (HandleKind::LocalCurvePoint(2, 1), "/shape/local_control_points/2", "local_control_points.2[1]"),
            (
                HandleKind::LocalPatchPoint(0, 3, 1, 2),
                "/shape/local_control_points/0,3",
                "local_control_points.0,3[1][2]",
            ),
        ];
        for (kind, pointer, field) in cases {
            assert_eq!((kind.pointer().as_str(), kind.field().as_str()), (pointer, field), "{kind:?}");
        }
    }
}
