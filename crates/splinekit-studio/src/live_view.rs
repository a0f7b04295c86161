//! The live path of a drag: the scene composed before the drag step is brought up to date
//! in place, and what changed is listed for the window to write into its vertex buffers
//! ([`Changes`]); the rest of the scene, on the CPU and on the GPU, stays.
//!
//! - A blending-spline surface whose mesh is the plain lattice of its kept grid samples
//!   ([`Lattice`], checked at each full composition) has the mesh rows its moved patches
//!   refreshed ([`crate::live_surfaces`]) copied from the samples, and the outline and
//!   middle lines of those patches drawn again
//!   ([`splinekit_render::compose::local_patch_lines`]). Styles whose drawing depends on
//!   the whole surface go the full path instead: a curvature or (u, v) colour map (its
//!   scale is a percentile over all vertices), parameter lines.
//! - A blending-spline curve drawn adaptively (no `density`) whose frames or local Bézier
//!   points alone changed keeps its polyline with the parameters of its vertices
//!   ([`KeptPolyline`]): only the spans between breakpoints that the kernel reports for the
//!   changed locals (`BlendingSplineCurve::affected_ranges`) are flattened again
//!   ([`splinekit_mesh::Polyline::adaptive_span`]) and spliced in, and only the changed
//!   locals' lines and origins are drawn again
//!   ([`splinekit_render::compose::local_curve_items`]). Adaptive flattening is local
//!   (breakpoints are always vertices, each span is flattened from its own samples), so the
//!   spliced polyline is, vertex for vertex, what flattening the whole edited curve to the
//!   same tolerance gives. The tolerance is the one of the drag's first step (4·10⁻⁴ of the
//!   curve's size then, [`splinekit_render::compose::curve_tolerance`]): when the drag
//!   changes the curve's size, a fresh composition flattens to a slightly different
//!   tolerance and its polyline differs (both within their tolerance of the curve) until the
//!   drag ends and the still scene is composed afresh.
//! - Any other changed object is composed again on its own
//!   ([`splinekit_render::recompose_object`]) and its items are listed whole.
//!
//! The mesher's clean-up ([`splinekit_mesh::surface_mesh::regular`]) could make a
//! different mesh of the moved surface: edges that collapse in single precision, normals
//! it repairs (not of unit length, or facing against their triangles), poles or seams
//! found anew. Those are checked on the refreshed rows and the rows next to them (and the
//! poles and seams whenever a refreshed rectangle touches the domain's boundary); any of
//! them sends the step down the full path. One decision is kept from the last full
//! composition: which way a closed mesh faces (the mesher turns a closed mesh whose signed
//! volume is negative inside out). The studio composes afresh when the drag ends, so the
//! still image is always the full composition's, which is what `splinekit render` draws.

use std::ops::Range;

use splinekit::Point;
use splinekit::blend::BlendingSplineCurve;
use splinekit::curve::Curve;
use splinekit::surface::{Surface, SurfaceGridSamples};
use splinekit_mesh::Polyline;
use splinekit_mesh::boundary_gluing::Gluing;
use splinekit_render::compose::{
    CURVE_POINTS, LOCAL_PATCH_LINES, curve_tolerance, local_curve_items, local_patch_lines, polyline_points,
};
use splinekit_render::geometry::segment_count;
use splinekit_render::{ObjectItems, RenderScene, recompose_object};
use splinekit_scene::blending::BlendingSplineDoc;
use splinekit_scene::scenes::{SceneDocument, SceneObject, StyleDoc};
use splinekit_scene::{Decoration, DocumentKind, ShapeDocument};

use crate::live_surfaces::{KeptSurface, LiveSurfaces};

/// What changed in the composed scene since the window last drew it.
#[derive(Debug, Clone, PartialEq)]
pub enum Changes {
    /// Everything: upload the scene afresh.
    All,
    /// These items only.
    Items {
        /// Meshes and their vertex ranges, as indices of [`RenderScene::meshes`].
        meshes: Vec<(usize, Range<usize>)>,
        /// Lines, as indices of [`RenderScene::lines`].
        lines: Vec<usize>,
        /// Lines of which only some segments changed (as [`splinekit_render::geometry::pack_line`]
        /// numbers them), with those segments; when a line's number of segments changed,
        /// all of its segments from the run's start on.
        runs: Vec<(usize, Range<usize>)>,
    },
}

impl Changes {
    /// Nothing changed.
    pub fn none() -> Self {
        Changes::Items { meshes: Vec::new(), lines: Vec::new(), runs: Vec::new() }
    }

    /// Adds the changes of `other`.
    pub fn merge(&mut self, other: Changes) {
        match (&mut *self, other) {
            (Changes::All, _) => {}
            (_, Changes::All) => *self = Changes::All,
            (Changes::Items { meshes, lines, runs }, Changes::Items { meshes: m, lines: l, runs: r }) => {
                meshes.extend(m);
                lines.extend(l);
                // Runs of two splices in a row: the earlier's indices no longer hold after
                // the later, so the line is written from the first changed segment on.
                for (line, run) in r {
                    match runs.iter_mut().find(|(l, _)| *l == line) {
                        Some((_, old)) => *old = old.start.min(run.start)..usize::MAX,
                        None => runs.push((line, run)),
                    }
                }
            }
        }
    }
}

/// How a live surface's mesh lies in the composed scene: vertex i·n_v + j at grid sample
/// (i, j) (positions and normals those of the samples in single precision; the normals
/// negated when the mesher turned the mesh inside out), two triangles a cell, and the
/// poles and seams the mesher found.
#[derive(Debug, Clone)]
pub struct Lattice {
    flipped: bool,
    gluing: Gluing,
}

fn f32x3(p: &Point<3>) -> [f32; 3] {
    [p.x as f32, p.y as f32, p.z as f32]
}

/// The lattices of the scene's live surfaces, by object, checked against the composed
/// scene (`None` for objects that are not live surfaces, or whose mesh is not the plain
/// lattice or whose style is drawn from the whole surface).
pub fn lattices(scene: &SceneDocument, composed: &RenderScene, live: &LiveSurfaces) -> Vec<Option<Lattice>> {
    let objects = scene.objects.iter().zip(&composed.objects).enumerate();
    objects.map(|(i, (obj, items))| live.kept(i).and_then(|k| lattice(obj, items, composed, k))).collect()
}

fn lattice(obj: &SceneObject, items: &ObjectItems, composed: &RenderScene, kept: &KeptSurface) -> Option<Lattice> {
    let style = &obj.style;
    let (nu, nv) = kept.blending().local_count();
    let lines = if style.local_pieces { LOCAL_PATCH_LINES * nu * nv } else { 0 };
    if style.color_map.is_some() || style.wireframe || items.meshes.len() != 1 || items.lines.len() != lines {
        return None;
    }
    let m = &composed.meshes[items.meshes.start];
    kept.with_samples(|s| {
        let (su, sv) = (s.us().len(), s.vs().len());
        if m.positions.len() != su * sv || m.triangles.len() != 2 * (su - 1) * (sv - 1) || !m.colors.is_empty() {
            return None;
        }
        let positions = s.points().iter().zip(&m.positions).all(|(p, q)| f32x3(p) == *q);
        let normals = |sign: f32| s.normals().iter().zip(&m.normals).all(|(n, q)| f32x3(n).map(|x| sign * x) == *q);
        let flipped = if normals(1.0) {
            false
        } else if normals(-1.0) {
            true
        } else {
            return None;
        };
        positions.then(|| Lattice { flipped, gluing: Gluing::detect(kept.blending()) })
    })?
}

/// A blending-spline curve's adaptive polyline as the live path keeps it: the parameters of
/// its vertices (those of the line in the composed scene) and the tolerance it was
/// flattened to.
#[derive(Debug, Clone)]
pub struct KeptPolyline {
    params: Vec<f64>,
    tolerance: f64,
}

/// Brings `composed` (the scene composed from `before`, with `lattices`) up to `scene`,
/// both posed at `time`, after [`LiveSurfaces::update`] followed the edit; returns what
/// changed, or `None` when the step must be composed afresh (something other than the
/// objects changed, the scene has axes, or a check of the module documentation failed;
/// `composed` is then left half done). `polylines` (by object, grown as needed) keeps the
/// adaptive curves' polylines between steps; start it empty after a full composition.
#[allow(clippy::too_many_arguments)]
pub fn patch(
    before: &SceneDocument,
    scene: &SceneDocument,
    time: Option<f64>,
    aspect: f32,
    composed: &mut RenderScene,
    lattices: &[Option<Lattice>],
    polylines: &mut Vec<Option<KeptPolyline>>,
    live: &LiveSurfaces,
) -> Option<Changes> {
    let rest = |s: &SceneDocument| SceneDocument { objects: Vec::new(), ..s.clone() };
    let same_rest = before.objects.len() == scene.objects.len() && rest(before) == rest(scene);
    if !same_rest || scene.axes {
        return None;
    }
    polylines.resize_with(scene.objects.len(), || None);
    let mut changes = Changes::none();
    for (i, (old, new)) in before.objects.iter().zip(&scene.objects).enumerate() {
        if old == new {
            continue;
        }
        let items = composed.objects.get(i)?.clone();
        let surface = match (lattices.get(i).and_then(Option::as_ref), live.kept(i)) {
            (Some(lattice), Some(kept)) if old.style == new.style => Some((lattice, kept)),
            _ => None,
        };
        match surface {
            Some((lattice, kept)) => changes.merge(patch_surface(new, &items, lattice, kept, composed)?),
            None if let Some(c) = patch_curve(old, new, time, &items, composed, &mut polylines[i]) => changes.merge(c),
            None => {
                recompose_object(scene, i, time, aspect, live.surface(i), composed).ok()?;
                let meshes = items.meshes.clone().map(|m| (m, 0..composed.meshes[m].positions.len()));
                changes.merge(Changes::Items {
                    meshes: meshes.collect(),
                    lines: items.lines.collect(),
                    runs: Vec::new(),
                });
            }
        }
    }
    Some(changes)
}

/// Copies the rows the last update refreshed into the live surface's mesh and draws its
/// moved patches' lines again.
fn patch_surface(
    obj: &SceneObject,
    items: &ObjectItems,
    lattice: &Lattice,
    kept: &KeptSurface,
    composed: &mut RenderScene,
) -> Option<Changes> {
    let followed = kept.followed()?;
    let surface = kept.blending();
    let (du, dv) = (surface.domain_u(), surface.domain_v());
    let on_boundary = |r: &splinekit::ParamRect| {
        r.u.start <= du.start || r.u.end >= du.end || r.v.start <= dv.start || r.v.end >= dv.end
    };
    if followed.rects.iter().any(on_boundary) && Gluing::detect(surface) != lattice.gluing {
        return None;
    }
    if items.meshes.len() != 1 {
        return None;
    }
    let index = items.meshes.start;
    let mesh = &mut composed.meshes[index];
    let rows = kept.with_samples(|s| {
        let rows = merged(followed.rects.iter().map(|r| rows_in(s.us(), r.u)).collect());
        let nv = s.vs().len();
        let sign = if lattice.flipped { -1.0 } else { 1.0 };
        for r in &rows {
            if !meshes_alike(s, r.start.saturating_sub(1)..(r.end + 1).min(s.us().len())) {
                return None;
            }
            for k in r.start * nv..r.end * nv {
                mesh.positions[k] = f32x3(&s.points()[k]);
                mesh.normals[k] = f32x3(&s.normals()[k]).map(|x| sign * x);
            }
        }
        Some(rows.into_iter().map(|r| (index, r.start * nv..r.end * nv)).collect::<Vec<_>>())
    })??;
    let mut lines = Vec::new();
    if obj.style.local_pieces {
        let nv = surface.local_count().1;
        for &(k, l) in &followed.patches {
            let first = items.lines.start + LOCAL_PATCH_LINES * (k * nv + l);
            for (m, line) in local_patch_lines(surface, (k, l)).into_iter().enumerate() {
                composed.lines[first + m] = line;
                lines.push(first + m);
            }
        }
    }
    Some(Changes::Items { meshes: rows, lines, runs: Vec::new() })
}

/// The shape's blending-spline document, posed at `time`, and the document without its
/// frames and local Bézier points (what must stay for those alone to have changed).
fn blending_curve(obj: &SceneObject, time: Option<f64>) -> Option<(BlendingSplineDoc, BlendingSplineDoc)> {
    let mut shape = obj.shape.clone();
    if let Some(t) = time {
        shape.set_time(t);
    }
    let ShapeDocument::Curve(c) = &shape else { return None };
    let Decoration::LocalCurves(d) = c.decoration() else { return None };
    let mut key = d.clone();
    key.transforms.clear();
    key.local_control_points.clear();
    Some((d.clone(), key))
}

/// Brings a blending-spline curve drawn adaptively up to date after its frames or local
/// Bézier points changed (see the module documentation); `None` for anything else.
fn patch_curve(
    old: &SceneObject,
    new: &SceneObject,
    time: Option<f64>,
    items: &ObjectItems,
    composed: &mut RenderScene,
    kept: &mut Option<KeptPolyline>,
) -> Option<Changes> {
    let style = &new.style;
    if old.style != *style || style.density.is_some() || style.hidden || old.points != new.points {
        return None;
    }
    let ((before, key), (doc, new_key)) = (blending_curve(old, time)?, blending_curve(new, time)?);
    if key != new_key {
        return None;
    }
    let splice = Splice { before: &before, style, items };
    match doc.dimension().ok()? {
        2 => splice.curve::<2>(&doc.curve::<2>().ok()?, &doc, composed, kept),
        3 => splice.curve::<3>(&doc.curve::<3>().ok()?, &doc, composed, kept),
        _ => None,
    }
}

/// A curve object's document before the step, its style and its items.
struct Splice<'a> {
    before: &'a BlendingSplineDoc,
    style: &'a StyleDoc,
    items: &'a ObjectItems,
}

/// Draws the `changed` locals of the edited `curve` again and splices their spans into its
/// kept polyline (flattened whole on the drag's first step).
impl Splice<'_> {
    fn curve<const D: usize>(
        &self,
        curve: &BlendingSplineCurve<D>,
        doc: &BlendingSplineDoc,
        composed: &mut RenderScene,
        kept: &mut Option<KeptPolyline>,
    ) -> Option<Changes> {
        let (style, items) = (self.style, self.items);
        let n = curve.local_count();
        let entry = |d: &BlendingSplineDoc, k: usize| {
            let t = d.transforms.iter().rev().find(|(i, _)| *i == k).map(|(_, t)| t);
            let p = d.local_control_points.iter().rev().find(|(i, _)| *i == k).map(|(_, p)| p);
            (t.cloned(), p.cloned())
        };
        let changed: Vec<usize> = (0..n).filter(|&k| entry(self.before, k) != entry(doc, k)).collect();
        let locals = if style.local_pieces { n } else { 0 };
        // A colour-mapped line is coloured from the whole curve: composed again whole.
        if style.color_map.is_some() || items.lines.len() != locals + 1 || items.points.len() < locals {
            return None;
        }
        let line = items.lines.end - 1;
        let mut lines = Vec::new();
        if style.local_pieces {
            for &k in &changed {
                let (l, p) = local_curve_items(curve, k, style);
                composed.lines[items.lines.start + k] = l;
                composed.points[items.points.start + k] = p;
                lines.push(items.lines.start + k);
            }
        }
        let Some(kept) = kept.as_mut().filter(|k| k.params.len() == composed.lines[line].points.len()) else {
            let tolerance = curve_tolerance::<D>(curve).ok()?;
            let poly = Polyline::adaptive_with_limit(curve, tolerance, CURVE_POINTS).ok()?;
            composed.lines[line].points = polyline_points(&poly.params, &poly.points);
            *kept = Some(KeptPolyline { params: poly.params, tolerance });
            return Some(Changes::Items { meshes: Vec::new(), lines, runs: vec![(line, 0..usize::MAX)] });
        };
        let bps = curve.breakpoints();
        let last = bps.len().checked_sub(1).filter(|&l| l > 0)?;
        let spans: Vec<Range<usize>> = changed
            .iter()
            .flat_map(|&k| curve.affected_ranges(k))
            .map(|r| {
                let from = bps.partition_point(|&b| b <= r.start).saturating_sub(1);
                let to = bps.partition_point(|&b| b < r.end).clamp(from + 1, last);
                from..to
            })
            .collect();
        let closed = composed.lines[line].closed;
        let (mut runs, mut closing) = (Vec::new(), false);
        for span in merged(spans) {
            let (mut params, mut points) =
                Polyline::adaptive_span(curve, kept.tolerance, span.clone(), CURVE_POINTS).ok()?;
            let start = kept.params.binary_search_by(|t| t.total_cmp(&bps[span.start])).ok()?;
            let end = if closed && span.end == last {
                params.pop();
                points.pop();
                kept.params.len()
            } else {
                kept.params.binary_search_by(|t| t.total_cmp(&bps[span.end])).ok()? + 1
            };
            let count = params.len();
            if start >= end || kept.params.len() - (end - start) + count > CURVE_POINTS {
                return None;
            }
            let drawn = polyline_points(&params, &points);
            kept.params.splice(start..end, params);
            composed.lines[line].points.splice(start..end, drawn);
            runs.push((line, start.saturating_sub(1)..start + count));
            closing |= closed && start == 0;
        }
        if closing {
            // The closing segment ends at the first point.
            let segments = segment_count(&composed.lines[line]);
            runs.push((line, segments.saturating_sub(1)..segments));
        }
        Some(Changes::Items { meshes: Vec::new(), lines, runs })
    }
}

/// The indices of the sorted parameters `xs` inside the closed interval.
fn rows_in(xs: &[f64], i: splinekit::Interval) -> Range<usize> {
    xs.partition_point(|&x| x < i.start)..xs.partition_point(|&x| x <= i.end)
}

/// Sorted, overlapping ranges joined.
fn merged(mut ranges: Vec<Range<usize>>) -> Vec<Range<usize>> {
    ranges.retain(|r| !r.is_empty());
    ranges.sort_by_key(|r| r.start);
    let mut out: Vec<Range<usize>> = Vec::new();
    for r in ranges {
        match out.last_mut() {
            Some(last) if r.start <= last.end => last.end = last.end.max(r.end),
            _ => out.push(r),
        }
    }
    out
}

/// Whether the mesher leaves grid rows `rows` as they are: every position finite, no
/// edge of the lattice (right, down, diagonal) whose ends are the same single-precision
/// point, every normal of unit length (within 10⁻⁶) and facing along the sum of its
/// triangles' normals ((b − a) × (c − a) of the triangles (i, j), (i+1, j), (i+1, j+1) and
/// (i, j), (i+1, j+1), (i, j+1) of each cell), as [`splinekit_mesh::TriangleMesh`]'s
/// normal repair asks.
fn meshes_alike(s: &SurfaceGridSamples<3>, rows: Range<usize>) -> bool {
    let (su, sv) = (s.us().len(), s.vs().len());
    let at = |i: usize, j: usize| &s.points()[i * sv + j];
    let cross = |a: &Point<3>, b: &Point<3>, c: &Point<3>| (b - a).cross(&(c - a));
    for i in rows {
        for j in 0..sv {
            let p = at(i, j);
            if !p.iter().all(|x| x.is_finite()) {
                return false;
            }
            let neighbours = [(i + 1, j), (i, j + 1), (i + 1, j + 1)];
            if neighbours.iter().any(|&(a, b)| a < su && b < sv && f32x3(at(a, b)) == f32x3(p)) {
                return false;
            }
            let mut own = Point::<3>::zeros();
            let cells =
                [(i.checked_sub(1), j.checked_sub(1)), (i.checked_sub(1), Some(j)), (Some(i), j.checked_sub(1))];
            for (ci, cj) in cells.into_iter().chain([(Some(i), Some(j))]) {
                let (Some(ci), Some(cj)) = (ci, cj) else { continue };
                if ci + 1 >= su || cj + 1 >= sv {
                    continue;
                }
                let (a, b, c, d) = ((ci, cj), (ci + 1, cj), (ci + 1, cj + 1), (ci, cj + 1));
                for t in [[a, b, c], [a, c, d]] {
                    if t.contains(&(i, j)) {
                        own += cross(at(t[0].0, t[0].1), at(t[1].0, t[1].1), at(t[2].0, t[2].1));
                    }
                }
            }
            let n = &s.normals()[i * sv + j];
            if (n.norm() - 1.0).abs() >= 1e-6 || own.dot(n) <= 0.0 {
                return false;
            }
        }
    }
    true
}
