//! From scene documents to what the renderer draws: curves become polylines, surfaces
//! triangle meshes (with colour maps and parameter lines), control nets and blending-spline
//! local pieces become lines and points, all posed at a time of the scene's animation.

use splinekit::Point;
use splinekit::blend::{BlendingSplineCurve, BlendingSplineSurface};
use splinekit::curve::Curve;
use splinekit::surface::Surface;
use splinekit_mesh::surface_mesh::{regular, to3};
use splinekit_mesh::{MeshOptions, Polyline};
use splinekit_scene::blending::BlendingSplineSurfaceDoc;
use splinekit_scene::placement::RigidTransform;
use splinekit_scene::scenes::{ArrowFieldDoc, CameraDoc, ColorMapDoc, SceneDocument, SceneObject, StyleDoc};
use splinekit_scene::{Curves, Decoration, DimensionVisitor, DocumentError, DocumentKind, ShapeDocument, Surfaces};

use crate::camera::Camera;
use crate::fields;
use crate::scene::{LineItem, MeshItem, ObjectItems, PointItem, RenderScene};

/// Colours given to objects without one (sRGB).
pub const PALETTE: [[f32; 4]; 6] = [
    [0.18, 0.40, 0.78, 1.0],
    [0.86, 0.33, 0.12, 1.0],
    [0.20, 0.62, 0.30, 1.0],
    [0.58, 0.30, 0.70, 1.0],
    [0.85, 0.65, 0.10, 1.0],
    [0.10, 0.60, 0.65, 1.0],
];
const NET: [f32; 4] = [0.35, 0.35, 0.35, 1.0];

/// Colour of local piece k of n: a ramp from blue to orange (as GMlib shows them).
pub fn local_color(k: usize, n: usize) -> [f32; 4] {
    let s = if n > 1 { k as f32 / (n - 1) as f32 } else { 0.0 };
    [0.15 + 0.8 * s, 0.35 + 0.3 * (1.0 - (2.0 * s - 1.0).abs()), 0.85 - 0.75 * s, 1.0]
}

fn f32x3(p: [f64; 3]) -> [f32; 3] {
    p.map(|x| x as f32)
}

/// The scene posed at `time` (seconds; `None`: the rest pose) for an image of this aspect.
pub fn compose(scene: &SceneDocument, time: Option<f64>, aspect: f32) -> Result<RenderScene, DocumentError> {
    compose_with(scene, time, aspect, &|_| None)
}

/// A 3-D surface standing in for an object's shape (see [`compose_with`]).
pub type SurfaceFor<'a> = dyn Fn(usize) -> Option<&'a (dyn Surface<3> + 'static)> + 'a;

/// [`compose`], with the surface of object i meshed from `surfaces(i)` when that gives one
/// instead of built from its document (decorations still come from the document). A caller
/// keeping a surface evaluated as the document would build it (the studio's live refresh,
/// which re-evaluates only what an edit changed) gets the same scene.
pub fn compose_with<'a>(
    scene: &SceneDocument,
    time: Option<f64>,
    aspect: f32,
    surfaces: &SurfaceFor<'a>,
) -> Result<RenderScene, DocumentError> {
    let mut out = RenderScene {
        background: [scene.background[0] as f32, scene.background[1] as f32, scene.background[2] as f32, 1.0],
        ..Default::default()
    };
    for i in 0..scene.objects.len() {
        let items = match instance_source(scene, i) {
            Some(k) if surfaces(i).is_none() && surfaces(k).is_none() => copy_instance(scene, k, i, &mut out)?,
            _ => compose_object(scene, i, time, surfaces(i), &mut out)?,
        };
        out.objects.push(items);
    }
    finish(scene, aspect, &mut out);
    Ok(out)
}

/// The earlier object whose items object `i` can reuse: the one it is an instance of,
/// drawn in the same style and without points of its own (an assembly's repeated part is
/// meshed once).
fn instance_source(scene: &SceneDocument, i: usize) -> Option<usize> {
    let (obj, k) = (&scene.objects[i], scene.objects[i].instance_of?);
    let first = scene.objects.get(k).filter(|_| k < i)?;
    (first.style == obj.style && obj.points.is_empty() && first.points.is_empty()).then_some(k)
}

/// Object `i`'s items as copies of object `k`'s, moved from k's placement to i's.
fn copy_instance(
    scene: &SceneDocument,
    k: usize,
    i: usize,
    out: &mut RenderScene,
) -> Result<ObjectItems, DocumentError> {
    let transform = |o: usize| -> Result<RigidTransform, DocumentError> {
        scene.objects[o].placement.as_ref().map_or(Ok(RigidTransform::IDENTITY), |p| {
            p.transform().map_err(|e| e.within(&format!("objects[{o}].placement")))
        })
    };
    let motion = transform(i)?.compose(&transform(k)?.inverse());
    let from = out.objects[k].clone();
    let start = (out.meshes.len(), out.lines.len(), out.points.len());
    out.meshes.extend_from_within(from.meshes.clone());
    out.lines.extend_from_within(from.lines.clone());
    out.points.extend_from_within(from.points.clone());
    place(&motion, start, out);
    Ok(ObjectItems {
        meshes: start.0..out.meshes.len(),
        lines: start.1..out.lines.len(),
        points: start.2..out.points.len(),
        flat: from.flat && motion == RigidTransform::IDENTITY,
    })
}

/// Composes object `index` of the scene again (with `given` standing in for its surface as
/// in [`compose_with`]) and puts its items where its old ones were in `out`, a
/// composition of the same scene before the object changed; the scene-wide parts (axes,
/// painter's order, camera) are made again; the objects after it keep their items, moved
/// when the object made a different number of them. Scenes with `axes` (which follow the
/// bounds of everything) are refused with an error naming the field.
pub fn recompose_object(
    scene: &SceneDocument,
    index: usize,
    time: Option<f64>,
    aspect: f32,
    given: Option<&(dyn Surface<3> + 'static)>,
    out: &mut RenderScene,
) -> Result<(), DocumentError> {
    if scene.axes {
        return Err(DocumentError::new("axes", "a scene with axes is composed whole"));
    }
    let Some(old) = out.objects.get(index).cloned() else {
        return Err(DocumentError::new("objects", format!("object {index} of {} was not composed", out.objects.len())));
    };
    let mut one = RenderScene::default();
    let items = compose_object(scene, index, time, given, &mut one)?;
    let shift = |r: &std::ops::Range<usize>, at: usize, n: usize, by: usize| {
        if r.start >= at { r.start - n + by..r.end - n + by } else { r.clone() }
    };
    let (nm, nl, np) = (one.meshes.len(), one.lines.len(), one.points.len());
    out.meshes.splice(old.meshes.clone(), one.meshes);
    out.lines.splice(old.lines.clone(), one.lines);
    out.points.splice(old.points.clone(), one.points);
    for (i, o) in out.objects.iter_mut().enumerate() {
        if i == index {
            *o = ObjectItems {
                meshes: old.meshes.start..old.meshes.start + nm,
                lines: old.lines.start..old.lines.start + nl,
                points: old.points.start..old.points.start + np,
                flat: items.flat,
            };
        } else if i > index {
            o.meshes = shift(&o.meshes, old.meshes.end, old.meshes.len(), nm);
            o.lines = shift(&o.lines, old.lines.end, old.lines.len(), nl);
            o.points = shift(&o.points, old.points.end, old.points.len(), np);
        }
    }
    finish(scene, aspect, out);
    Ok(())
}

/// Appends object `index`'s items (shape, decoration, points) to `out`.
fn compose_object(
    scene: &SceneDocument,
    index: usize,
    time: Option<f64>,
    given: Option<&(dyn Surface<3> + 'static)>,
    out: &mut RenderScene,
) -> Result<ObjectItems, DocumentError> {
    let obj = &scene.objects[index];
    let color =
        obj.style.color.as_ref().map_or(PALETTE[index % PALETTE.len()], |c| {
            [c[0], c[1], c[2], *c.get(3).unwrap_or(&1.0)].map(|x| x as f32)
        });
    let color = match time {
        Some(t) if obj.style.color_cycle => hue_turned(color, (t / scene.clock().duration) as f32),
        _ => color,
    };
    let start = (out.meshes.len(), out.lines.len(), out.points.len());
    let mut flat = object(obj, &format!("objects[{index}].shape"), time, color, given, out)?;
    for p in &obj.points {
        out.points.push(PointItem { position: f32x3(*p), color, size: 8.0 });
    }
    if let Some(placement) = &obj.placement {
        let t = placement.transform().map_err(|e| e.within(&format!("objects[{index}].placement")))?;
        place(&t, start, out);
        flat = false;
    }
    Ok(ObjectItems {
        meshes: start.0..out.meshes.len(),
        lines: start.1..out.lines.len(),
        points: start.2..out.points.len(),
        flat,
    })
}

/// Moves the items from `start` (meshes, lines, points) by the rigid motion `t`: points
/// and normals in f64, back to f32.
fn place(t: &RigidTransform, start: (usize, usize, usize), out: &mut RenderScene) {
    let point = |p: &mut [f32; 3]| *p = t.apply(p.map(f64::from)).map(|x| x as f32);
    let vector = |v: &mut [f32; 3]| *v = t.apply_vector(v.map(f64::from)).map(|x| x as f32);
    for m in &mut out.meshes[start.0..] {
        m.positions.iter_mut().for_each(point);
        m.normals.iter_mut().for_each(vector);
    }
    for l in &mut out.lines[start.1..] {
        l.points.iter_mut().for_each(point);
    }
    for p in &mut out.points[start.2..] {
        point(&mut p.position);
    }
}

/// The scene-wide parts of a composition, from its objects' items: axes, painter's order,
/// camera, lights.
fn finish(scene: &SceneDocument, aspect: f32, out: &mut RenderScene) {
    let mut flat = out.objects.iter().all(|o| o.flat);
    let bounds = out.bounds().unwrap_or(([-1.0; 3], [1.0; 3]));
    if scene.axes {
        axes(bounds, out);
    }
    let bounds = out.bounds().unwrap_or(bounds);
    // Everything in one plane z = const: a plane figure, seen from the top.
    let extent = (0..3).map(|k| bounds.1[k] - bounds.0[k]).fold(0.0f32, f32::max);
    flat |= out.meshes.is_empty() && bounds.1[2] - bounds.0[2] <= 1e-6 * extent;
    // A top view of a scene with meshes keeps depth testing.
    let top_view = matches!(scene.camera, Some(CameraDoc::Orbit { top: true, .. }));
    out.painter_order = if top_view { out.meshes.is_empty() } else { flat };
    out.camera = Some(camera(scene, bounds, flat, aspect));
    for (k, l) in scene.lights.iter().enumerate() {
        out.lights[k] = (l.direction.map(|x| x as f32), l.intensity as f32);
    }
}

/// Adds one object's shape, posed at `time`, with its decoration (local pieces and
/// control polygons under a curve, control nets and local patches over a surface);
/// returns whether it is a plane figure (a curve of at most two dimensions). Errors in
/// the document are reported within the object's `field`. A surface given in `given` is
/// meshed instead of the one the document builds.
fn object(
    obj: &SceneObject,
    field: &str,
    time: Option<f64>,
    color: [f32; 4],
    given: Option<&(dyn Surface<3> + 'static)>,
    out: &mut RenderScene,
) -> Result<bool, DocumentError> {
    let mut shape = obj.shape.clone();
    if let Some(t) = time {
        shape.set_time(t);
    }
    let within = |e: DocumentError| e.within(field);
    check_style(&obj.style, matches!(shape, ShapeDocument::Surface(_)))
        .map_err(|e| e.within(field.strip_suffix(".shape").unwrap_or(field)))?;
    match &shape {
        ShapeDocument::Curve(c) => {
            if let Decoration::LocalCurves(d) = c.decoration() {
                // A blending spline, built once for its local curves and its line.
                macro_rules! blending {
                    ($dim:literal) => {{
                        let curve = d.curve::<$dim>().map_err(within)?;
                        if obj.style.local_pieces {
                            local_curves(&curve, &obj.style, out);
                        }
                        if !obj.style.hidden {
                            out.lines.extend(CurveLine { obj, color }.visit::<$dim>(&curve)?);
                        }
                        return Ok($dim <= 2);
                    }};
                }
                match d.dimension().map_err(within)? {
                    2 => blending!(2),
                    3 => blending!(3),
                    other => {
                        let e = format!("drawn for 2-D and 3-D curves, not {other}-D");
                        return Err(within(DocumentError::new("local_pieces", e)));
                    }
                }
            }
            let curve = c.build().map_err(within)?;
            decorate(c.decoration(), &obj.style, out).map_err(within)?;
            if !obj.style.hidden {
                out.lines.extend(curve.visit(CurveLine { obj, color })?);
            }
            Ok(curve.dimension() <= 2)
        }
        ShapeDocument::Surface(s) => {
            if let Some(given) = given {
                if !obj.style.hidden {
                    SurfaceMesh { obj, color, out: &mut *out }.visit::<3>(given)?;
                }
            } else {
                let surface = s.build().map_err(within)?;
                if !obj.style.hidden {
                    surface.visit(SurfaceMesh { obj, color, out: &mut *out })?;
                }
            }
            decorate(s.decoration(), &obj.style, out).map_err(within)?;
            Ok(false)
        }
    }
}

/// Refuses a colour map or arrows the shape has not (a surface's curvatures on a curve, a
/// curve's torsion on a surface), naming them and what the shape takes.
fn check_style(style: &StyleDoc, surface: bool) -> Result<(), DocumentError> {
    let what = if surface { "surfaces" } else { "curves" };
    if let Some(m) = style.color_map
        && !(if surface { m.for_surfaces() } else { m.for_curves() })
    {
        return Err(DocumentError::new(
            "color_map",
            format!("\"{}\" does not colour {what}, which take {}", m.name(), ColorMapDoc::names_for(surface)),
        ));
    }
    if let Some(a) = &style.arrows
        && !(if surface { a.field.for_surfaces() } else { a.field.for_curves() })
    {
        let names: Vec<&str> = ArrowFieldDoc::ALL
            .iter()
            .filter(|f| if surface { f.for_surfaces() } else { f.for_curves() })
            .map(|f| f.name())
            .collect();
        return Err(DocumentError::new(
            "arrows.field",
            format!("{what} have no \"{}\" field; they take {}", a.field.name(), names.join(", ")),
        ));
    }
    Ok(())
}

/// Arrows in a darker shade of the shape's colour.
fn arrow_color(c: [f32; 4]) -> [f32; 4] {
    [c[0] * 0.45, c[1] * 0.45, c[2] * 0.45, 1.0]
}

/// Draws what the style asks for of a shape's decoration.
fn decorate(decoration: Decoration<'_>, style: &StyleDoc, out: &mut RenderScene) -> Result<(), DocumentError> {
    match decoration {
        Decoration::None => {}
        Decoration::ControlPolygon { points, closed, .. } => {
            if style.control_net {
                polygon(points, closed, out);
            }
        }
        Decoration::ControlNet(net) => {
            if style.control_net {
                control_net(net, out);
            }
        }
        // Drawn with the curve, which is built once for both (see `object`).
        Decoration::LocalCurves(_) => {}
        Decoration::LocalPatches(d) => {
            if style.local_pieces {
                local_patches(d, out)?;
            }
        }
        Decoration::Cage { vertices, faces } => {
            if style.control_net {
                cage(vertices, faces, out);
            }
        }
        Decoration::TriangularNet { points, .. } => {
            if style.control_net {
                triangular_net(points, out);
            }
        }
        Decoration::LocalPieces(d) => {
            if style.local_pieces {
                let pieces = d.local_pieces()?;
                let n = pieces.len();
                for (k, (lines, origin)) in pieces.into_iter().enumerate() {
                    let color = local_color(k, n);
                    for line in lines {
                        out.lines.push(LineItem {
                            points: line.iter().map(|p| f32x3(*p)).collect(),
                            closed: false,
                            color,
                            width: 1.0,
                            colors: Vec::new(),
                        });
                    }
                    out.points.push(PointItem { position: f32x3(origin), color, size: 6.0 });
                }
            }
        }
    }
    Ok(())
}

/// A Bézier triangle's net (points b_ijk in storage order, row r = j + k holding r + 1
/// points): the lines of constant i, of constant j and of constant k, with the points.
fn triangular_net(points: &[Vec<f64>], out: &mut RenderScene) {
    let at = |p: &Vec<f64>| [p[0] as f32, *p.get(1).unwrap_or(&0.0) as f32, *p.get(2).unwrap_or(&0.0) as f32];
    let Ok(n) = splinekit::triangle::net::degree_of_len(points.len(), "control_points") else { return };
    let index = |j: usize, k: usize| splinekit::triangle::net_index(j, k);
    let mut push = |idx: Vec<usize>| {
        if idx.len() > 1 {
            let pts = idx.iter().map(|&i| at(&points[i])).collect();
            out.lines.push(LineItem { points: pts, closed: false, color: NET, width: 1.5, colors: Vec::new() });
        }
    };
    for c in 0..n {
        // i = c: j + k = n − c; j = c: i + k = n − c; k = c.
        push((0..=n - c).map(|k| index(n - c - k, k)).collect());
        push((0..=n - c).map(|k| index(c, k)).collect());
        push((0..=n - c).map(|j| index(j, c)).collect());
    }
    out.points.extend(points.iter().map(|p| PointItem { position: at(p), color: [0.1, 0.1, 0.1, 1.0], size: 7.0 }));
}

/// The x (red), y (green) and z (blue) axes, 35 % of the scene's largest extent long.
fn axes(bounds: ([f32; 3], [f32; 3]), out: &mut RenderScene) {
    let size = (0..3).map(|k| bounds.1[k] - bounds.0[k]).fold(0.0f32, f32::max).max(1e-3) * 0.35;
    for (k, c) in [[0.85, 0.1, 0.1, 1.0], [0.1, 0.65, 0.1, 1.0], [0.1, 0.2, 0.85, 1.0]].into_iter().enumerate() {
        let mut end = [0.0; 3];
        end[k] = size;
        out.lines.push(LineItem {
            points: vec![[0.0; 3], end],
            closed: false,
            color: c,
            width: 2.0,
            colors: Vec::new(),
        });
    }
}

/// The scene's camera, or one fitted to the bounds (from the top for plane figures).
fn camera(scene: &SceneDocument, bounds: ([f32; 3], [f32; 3]), flat: bool, aspect: f32) -> Camera {
    match &scene.camera {
        Some(CameraDoc::LookAt { eye, target, up, half_height: Some(h), .. }) => Camera::Orthographic {
            eye: eye.map(|x| x as f32),
            target: target.map(|x| x as f32),
            up: up.map(|x| x as f32),
            half_height: *h as f32,
        },
        Some(CameraDoc::LookAt { eye, target, up, fov, half_height: None }) => Camera::Perspective {
            eye: eye.map(|x| x as f32),
            target: target.map(|x| x as f32),
            up: up.map(|x| x as f32),
            fov_y: *fov as f32,
        },
        Some(CameraDoc::Orbit { top: true, .. }) => Camera::top(bounds, aspect),
        Some(CameraDoc::Orbit { azimuth, elevation, .. }) => {
            Camera::fit(bounds, azimuth.to_radians() as f32, elevation.to_radians() as f32, aspect)
        }
        None if flat => Camera::top(bounds, aspect),
        None => Camera::fit(bounds, 50f32.to_radians(), 28f32.to_radians(), aspect),
    }
}

/// Most points of a curve's adaptive polyline.
pub const CURVE_POINTS: usize = 200_000;

/// The chord-height tolerance a curve without a `density` is flattened to: 4·10⁻⁴ of its
/// size ([`Polyline::rough_size`]: the largest distance of 64 regular samples from the
/// first).
pub fn curve_tolerance<const D: usize>(c: &dyn Curve<D>) -> Result<f64, DocumentError> {
    let size = Polyline::rough_size(c)?.max(1e-9);
    Ok(size * 4e-4)
}

/// The line drawn for a curve's polyline: its points in single precision (a 1-D curve, a
/// B-function, as its graph (t, c(t))).
pub fn polyline_points<const D: usize>(params: &[f64], points: &[Point<D>]) -> Vec<[f32; 3]> {
    if D == 1 {
        params.iter().zip(points).map(|(t, p)| [*t as f32, p[0] as f32, 0.0]).collect()
    } else {
        points.iter().map(|p| f32x3(to3(p))).collect()
    }
}

struct CurveLine<'a> {
    obj: &'a SceneObject,
    color: [f32; 4],
}

impl DimensionVisitor<Curves> for CurveLine<'_> {
    /// The curve's line, then its arrows.
    type Output = Result<Vec<LineItem>, DocumentError>;
    fn visit<const D: usize>(self, c: &dyn Curve<D>) -> Self::Output {
        let poly = match self.obj.style.density {
            Some(n) => Polyline::regular(c, n)?,
            None => Polyline::adaptive_with_limit(c, curve_tolerance(c)?, CURVE_POINTS)?,
        };
        let points = polyline_points(&poly.params, &poly.points);
        let colors = match self.obj.style.color_map {
            Some(map) => fields::curve_colors(c, map, &poly.params),
            None => Vec::new(),
        };
        let mut lines = Vec::new();
        if let Some(a) = &self.obj.style.arrows {
            let size = fields::box_diagonal(poly.points.iter().map(to3));
            lines = fields::curve_arrows(c, a, size, arrow_color(self.color));
        }
        lines.insert(
            0,
            LineItem {
                points,
                closed: poly.closed,
                color: self.color,
                width: self.obj.style.line_width as f32,
                colors,
            },
        );
        Ok(lines)
    }
}

fn polygon(points: &[Vec<f64>], closed: bool, out: &mut RenderScene) {
    let pts: Vec<[f32; 3]> = points
        .iter()
        .map(|p| [p[0] as f32, *p.get(1).unwrap_or(&0.0) as f32, *p.get(2).unwrap_or(&0.0) as f32])
        .collect();
    out.lines.push(LineItem { points: pts.clone(), closed, color: NET, width: 1.5, colors: Vec::new() });
    out.points.extend(pts.iter().map(|&p| PointItem { position: p, color: [0.1, 0.1, 0.1, 1.0], size: 7.0 }));
}

/// A subdivision cage: each face as a closed polygon, with the vertices.
fn cage(vertices: &[Vec<f64>], faces: &[Vec<u32>], out: &mut RenderScene) {
    let at = |p: &Vec<f64>| [p[0] as f32, *p.get(1).unwrap_or(&0.0) as f32, *p.get(2).unwrap_or(&0.0) as f32];
    for face in faces {
        let points: Vec<[f32; 3]> = face.iter().filter_map(|&i| vertices.get(i as usize)).map(at).collect();
        out.lines.push(LineItem { points, closed: true, color: NET, width: 1.5, colors: Vec::new() });
    }
    out.points.extend(vertices.iter().map(|p| PointItem { position: at(p), color: [0.1, 0.1, 0.1, 1.0], size: 7.0 }));
}

/// A control net: its rows and its columns as polygons, with the points.
fn control_net(net: &[Vec<Vec<f64>>], out: &mut RenderScene) {
    for row in net {
        polygon(row, false, out);
    }
    let cols = net.first().map_or(0, Vec::len);
    for j in 0..cols {
        let col: Vec<Vec<f64>> = net.iter().filter_map(|r| r.get(j).cloned()).collect();
        let pts: Vec<[f32; 3]> = col
            .iter()
            .map(|p| [p[0] as f32, *p.get(1).unwrap_or(&0.0) as f32, *p.get(2).unwrap_or(&0.0) as f32])
            .collect();
        out.lines.push(LineItem { points: pts, closed: false, color: NET, width: 1.5, colors: Vec::new() });
    }
}

/// The local curves of a blending spline in their own colours (97 points over each one's
/// support), with their origins where their transforms moved them.
fn local_curves<const D: usize>(c: &BlendingSplineCurve<D>, style: &StyleDoc, out: &mut RenderScene) {
    for k in 0..c.local_count() {
        let (line, point) = local_curve_items(c, k, style);
        out.lines.push(line);
        out.points.push(point);
    }
}

/// What [`compose`] draws for local curve k of a blending spline with `local_pieces`: the
/// local over its support (97 points) and its frame origin where its transform moved it,
/// in its own colour ([`local_color`]).
pub fn local_curve_items<const D: usize>(
    c: &BlendingSplineCurve<D>,
    k: usize,
    style: &StyleDoc,
) -> (LineItem, PointItem) {
    let n = c.local_count();
    let support = c.local_support(k);
    let (a, b) = (support.start, support.end);
    let mut v = [Point::<D>::zeros(); 1];
    let pts: Vec<[f32; 3]> = (0..=96)
        .map(|i| {
            c.eval_local(k, a + (b - a) * i as f64 / 96.0, &mut v);
            f32x3(to3(&v[0]))
        })
        .collect();
    let line = LineItem {
        points: pts,
        closed: false,
        color: local_color(k, n),
        width: style.line_width as f32 * 0.6,
        colors: Vec::new(),
    };
    let origin = c.transform(k).apply_point_about(&c.origin(k), &c.origin(k));
    (line, PointItem { position: f32x3(to3(&origin)), color: local_color(k, n), size: 7.0 })
}

/// The local patches of a blending-spline surface: outline and middle lines of each over
/// its support, in its own colour.
fn local_patches(d: &BlendingSplineSurfaceDoc, out: &mut RenderScene) -> Result<(), DocumentError> {
    let s = d.surface::<3>()?;
    let (nu, nv) = s.local_count();
    for k in 0..nu {
        for l in 0..nv {
            out.lines.extend(local_patch_lines(&s, (k, l)));
        }
    }
    Ok(())
}

/// Lines drawn for each local patch with `local_pieces`.
pub const LOCAL_PATCH_LINES: usize = 6;

/// The lines drawn for local patch (k, l) of a blending-spline surface: its outline and
/// middle lines over its support (fixed u at the support's start, middle and end, then
/// fixed v), 33 points each, in its own colour ([`local_color`]).
pub fn local_patch_lines(s: &BlendingSplineSurface<3>, (k, l): (usize, usize)) -> [LineItem; LOCAL_PATCH_LINES] {
    let (nu, nv) = s.local_count();
    let rect = s.local_support(k, l);
    let ((u0, u1), (v0, v1)) = ((rect.u.start, rect.u.end), (rect.v.start, rect.v.end));
    let color = local_color(k * nv + l, nu * nv);
    let mut v = [Point::<3>::zeros(); 1];
    [(true, 0.0), (true, 0.5), (true, 1.0), (false, 0.0), (false, 0.5), (false, 1.0)].map(|(fixed_u, t)| {
        let pts: Vec<[f32; 3]> = (0..=32)
            .map(|i| {
                let s_ = i as f64 / 32.0;
                let (u, vv) = if fixed_u {
                    (u0 + (u1 - u0) * t, v0 + (v1 - v0) * s_)
                } else {
                    (u0 + (u1 - u0) * s_, v0 + (v1 - v0) * t)
                };
                s.eval_local((k, l), (u, vv), 0, 0, &mut v);
                f32x3(to3(&v[0]))
            })
            .collect();
        LineItem { points: pts, closed: false, color, width: 1.0, colors: Vec::new() }
    })
}

struct SurfaceMesh<'a> {
    obj: &'a SceneObject,
    color: [f32; 4],
    out: &'a mut RenderScene,
}

impl DimensionVisitor<Surfaces> for SurfaceMesh<'_> {
    type Output = Result<(), DocumentError>;
    fn visit<const D: usize>(self, s: &dyn Surface<D>) -> Self::Output {
        let n = self.obj.style.density.unwrap_or(64);
        let mesh = regular(s, n, n, MeshOptions { uv: true })?;
        let (du, dv) = (s.domain_u(), s.domain_v());
        let colors = match self.obj.style.color_map {
            // A solid whose every face has its colour from the CAD file (sRGB, as the
            // file's styles give them), unless the scene colours the object itself.
            None if self.obj.style.color.is_none() && mesh.colors.len() == mesh.positions.len() => mesh.colors.clone(),
            None => Vec::new(),
            Some(map) => fields::surface_colors(s, map, &mesh.uvs, &mesh.positions, &mesh.normals, self.color),
        };
        if let Some(a) = &self.obj.style.arrows {
            let size = fields::box_diagonal(mesh.positions.iter().copied());
            self.out.lines.extend(fields::surface_arrows(s, a, size, arrow_color(self.color)));
        }
        self.out.meshes.push(MeshItem {
            positions: mesh.positions.iter().map(|p| f32x3(*p)).collect(),
            normals: mesh.normals.iter().map(|p| f32x3(*p)).collect(),
            colors,
            color: self.color,
            triangles: mesh.triangles.clone(),
        });
        if self.obj.style.wireframe {
            let lines = 16.min(n);
            let mut v = [Point::<D>::zeros(); 1];
            for (fixed_u, count) in [(true, lines), (false, lines)] {
                for i in 0..=count {
                    let f = i as f64 / count as f64;
                    let pts: Vec<[f32; 3]> = (0..=128)
                        .map(|j| {
                            let g = j as f64 / 128.0;
                            let (u, w) = if fixed_u { (du.lerp(f), dv.lerp(g)) } else { (du.lerp(g), dv.lerp(f)) };
                            s.eval_partials(u, w, 0, 0, &mut v);
                            f32x3(to3(&v[0]))
                        })
                        .collect();
                    self.out.lines.push(LineItem {
                        points: pts,
                        closed: false,
                        color: [0.12, 0.12, 0.15, 1.0],
                        width: 1.0,
                        colors: Vec::new(),
                    });
                }
            }
        }
        Ok(())
    }
}

/// The colour with its HSV hue turned by `turns` full turns (saturation, value and alpha
/// kept).
fn hue_turned(c: [f32; 4], turns: f32) -> [f32; 4] {
    let (max, min) = (c[0].max(c[1]).max(c[2]), c[0].min(c[1]).min(c[2]));
    let chroma = max - min;
    if chroma <= 0.0 {
        return c;
    }
    let sector = if max == c[0] {
        ((c[1] - c[2]) / chroma).rem_euclid(6.0)
    } else if max == c[1] {
        (c[2] - c[0]) / chroma + 2.0
    } else {
        (c[0] - c[1]) / chroma + 4.0
    };
    let h = (sector + 6.0 * turns).rem_euclid(6.0);
    let x = chroma * (1.0 - (h % 2.0 - 1.0).abs());
    let (r, g, b) = match h as u32 {
        0 => (chroma, x, 0.0),
        1 => (x, chroma, 0.0),
        2 => (0.0, chroma, x),
        3 => (0.0, x, chroma),
        4 => (x, 0.0, chroma),
        _ => (chroma, 0.0, x),
    };
    [r + min, g + min, b + min, c[3]]
}

#[cfg(test)]
mod tests {
    use super::{MeshItem, compose, hue_turned};
    use crate::fields::{isophote, zebra};

    #[test]
    fn zebra_stripes_and_isophotes_follow_the_normal() {
        let (white, black) = (zebra(7.5f64.to_radians()), zebra(-7.5f64.to_radians()));
        assert_eq!((white[0], black[0]), (0.95, 0.05), "stripes change at 0°");
        assert_eq!(zebra(22.5f64.to_radians()), black, "15° to 30°: the next stripe");
        let c = [0.2, 0.4, 0.8, 1.0];
        assert_eq!(isophote(0.3001, c), [0.05, 0.05, 0.05, 1.0]);
        assert_eq!(isophote(0.35, c), c);
        // A sphere in zebra: both stripes, a vertex colour each.
        let doc = r#"{"type": "scene", "objects": [{"shape": {"type": "sphere"}, "color_map": "zebra"}]}"#;
        let scene = splinekit_scene::SceneOrShape::from_json(doc).expect("valid").into_scene();
        let rs = super::compose(&scene, None, 1.0).expect("composes");
        let colors = &rs.meshes[0].colors;
        assert_eq!(colors.len(), rs.meshes[0].positions.len());
        assert!(colors.iter().any(|c| c[0] > 0.9) && colors.iter().any(|c| c[0] < 0.1), "both stripes");
    }

    /// A solid from a CAD file is drawn in its faces' colours (every face coloured), and
    /// in the scene's colour where the object has one.
    #[test]
    fn a_solid_is_drawn_in_its_faces_colours() {
        use splinekit_scene::scenes::SceneDocument;
        use splinekit_scene::surfaces::{BrepDoc, SurfaceDocument};
        let mut cube = BrepDoc::cube();
        let colours: Vec<[f32; 4]> = (0..6).map(|k| [k as f32 / 6.0, 0.5, 0.25, 1.0]).collect();
        for (face, c) in cube.faces.iter_mut().zip(&colours) {
            face.color = Some(*c);
        }
        let mut scene = SceneDocument::of_shape(splinekit_scene::ShapeDocument::Surface(SurfaceDocument::Brep(cube)));
        let drawn = compose(&scene, None, 1.0).unwrap();
        let m = &drawn.meshes[0];
        assert_eq!(m.colors.len(), m.positions.len());
        assert!(m.colors.iter().all(|c| colours.contains(c)));
        assert!(colours.iter().all(|c| m.colors.contains(c)), "every face's colour is drawn");
        scene.objects[0].style.color = Some(vec![1.0, 0.0, 0.0]);
        assert!(compose(&scene, None, 1.0).unwrap().meshes[0].colors.is_empty());
    }

    /// A placed object is drawn moved; an instance is its part's mesh moved to its own
    /// placement, the same (to f32 rounding) as meshing the part there anew.
    #[test]
    fn placements_move_objects_and_instances_reuse_their_parts_mesh() {
        let doc = |second: &str| {
            let text = format!(
                r#"{{"type": "scene", "objects": [
                    {{"shape": {{"type": "torus"}}, "placement": {{"origin": [5, 0, 0]}}}},
                    {{{second}, "placement": {{"origin": [0, 3, 0], "axis": [1, 0, 0], "ref_direction": [0, 1, 0]}}}}]}}"#
            );
            splinekit_scene::SceneOrShape::from_json(&text).unwrap().into_scene()
        };
        let instanced = compose(&doc(r#""instance_of": 0"#), None, 1.0).unwrap();
        let meshed = compose(&doc(r#""shape": {"type": "torus"}"#), None, 1.0).unwrap();
        let (a, b) =
            (&instanced.meshes[instanced.objects[1].meshes.start], &meshed.meshes[meshed.objects[1].meshes.start]);
        assert_eq!(a.positions.len(), b.positions.len());
        let worst = a
            .positions
            .iter()
            .zip(&b.positions)
            .flat_map(|(p, q)| (0..3).map(move |k| (p[k] - q[k]).abs()))
            .fold(0.0f32, f32::max);
        assert!(worst < 1e-5, "{worst}");
        // The torus (radius 3 about z, tube 1) about (5, 0, 0); the second turned to lie
        // about x through (0, 3, 0): x within ±1, y within 3 ± 4.
        let bounds = |m: &MeshItem| {
            m.positions.iter().fold(([f32::MAX; 3], [f32::MIN; 3]), |(lo, hi), p| {
                (std::array::from_fn(|k| lo[k].min(p[k])), std::array::from_fn(|k| hi[k].max(p[k])))
            })
        };
        let (lo, hi) = bounds(&instanced.meshes[0]);
        assert!(
            (lo[0] - 1.0).abs() < 1e-3 && (hi[0] - 9.0).abs() < 1e-3 && (hi[2] - 1.0).abs() < 1e-3,
            "{lo:?} {hi:?}"
        );
        let (lo, hi) = bounds(a);
        assert!(
            (lo[0] + 1.0).abs() < 1e-3 && (hi[0] - 1.0).abs() < 1e-3 && (lo[1] + 1.0).abs() < 1e-3,
            "{lo:?} {hi:?}"
        );
        assert!((hi[1] - 7.0).abs() < 1e-3, "{lo:?} {hi:?}");
    }

    #[test]
    fn a_third_of_a_turn_takes_red_to_green_and_a_whole_turn_back() {
        let red = [0.9, 0.1, 0.1, 1.0];
        let g = hue_turned(red, 1.0 / 3.0);
        assert!((g[0] - 0.1).abs() < 1e-5 && (g[1] - 0.9).abs() < 1e-5 && (g[2] - 0.1).abs() < 1e-5, "{g:?}");
        let back = hue_turned(red, 1.0);
        assert!(back.iter().zip(red).all(|(a, b)| (a - b).abs() < 1e-5), "{back:?}");
        assert_eq!(hue_turned([0.5, 0.5, 0.5, 1.0], 0.3), [0.5, 0.5, 0.5, 1.0], "greys have no hue");
    }
}
