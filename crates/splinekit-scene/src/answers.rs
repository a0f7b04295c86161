//! The answers of the geometric queries as JSON — intersections (`splinekit intersect`),
//! plane sections (`section`) and offsets (`offset`) — computed and written in one place
//! for the command line and Python, which differ only in how they name their arguments
//! (`A`, `--tolerance` on the command line; `a`, `tolerance` in Python): each caller
//! passes the names its errors use.

use serde_json::{Value, json};
use splinekit::Point;
use splinekit::curve::Curve;
use splinekit::query::{
    CurveIntersections, CurveSurfaceIntersection, EarlyStop, IntersectionBranch, IntersectionKind,
    intersect_curve_surface, intersect_curves, intersect_surfaces, offset_curve, offset_surface, self_intersections,
};
use splinekit::surface::Surface;
use splinekit::surface::model::Plane;

use crate::refine::{bspline_doc, bspline_surface_doc};
use crate::{CurveDocument, Curves, DimensionVisitor, DocumentError, ShapeDocument, SurfaceDocument};

/// `"crossing"` or `"tangent"`.
pub fn kind_name(kind: IntersectionKind) -> &'static str {
    match kind {
        IntersectionKind::Crossing => "crossing",
        IntersectionKind::Tangent => "tangent",
    }
}

/// Two curves' (or one curve's self-) intersections: `{points: [{params: [t_a, t_b],
/// point, kind}], overlaps: [{params_a, params_b}], curves: []}`.
pub fn curve_intersections_json<const D: usize>(r: &CurveIntersections<D>) -> Value {
    let points: Vec<Value> = r
        .points
        .iter()
        .map(|p| {
            json!({"params": [p.t_a, p.t_b], "point": p.point.iter().collect::<Vec<_>>(), "kind": kind_name(p.kind)})
        })
        .collect();
    let overlaps: Vec<Value> =
        r.overlaps.iter().map(|o| json!({"params_a": [o.a.start, o.a.end], "params_b": [o.b.0, o.b.1]})).collect();
    json!({"points": points, "overlaps": overlaps, "curves": []})
}

/// A curve–surface answer: `params` are [t, u, v].
pub fn curve_surface_json(r: &[CurveSurfaceIntersection]) -> Value {
    let points: Vec<Value> = r
        .iter()
        .map(|p| json!({"params": [p.t, p.u, p.v], "point": [p.point.x, p.point.y, p.point.z], "kind": kind_name(p.kind)}))
        .collect();
    json!({"points": points, "overlaps": [], "curves": []})
}

/// The JSON of intersection branches: `{points, params_a, params_b, closed, tangent,
/// early_stop, bspline, fit_error}`, the B-spline fitted within `fit` of the points where
/// it can be.
pub fn branches_json(branches: &[IntersectionBranch], fit: f64) -> splinekit::Result<Vec<Value>> {
    branches
        .iter()
        .map(|b| {
            let stop = b.early_stop.map(|s| match s {
                EarlyStop::Tangential => "tangential",
                EarlyStop::StepLimit => "step_limit",
                EarlyStop::PointLimit => "point_limit",
            });
            let points: Vec<[f64; 3]> = b.points.iter().map(|p| [p.x, p.y, p.z]).collect();
            let (bspline, error) = match b.points.len() {
                0 | 1 => (Value::Null, Value::Null),
                _ => {
                    let f = b.fit_bspline(fit)?;
                    (bspline_doc(&f.curve).to_value(), json!(f.max_error))
                }
            };
            Ok(json!({"points": points, "params_a": b.params_a, "params_b": b.params_b, "closed": b.closed,
                "tangent": b.tangent, "early_stop": stop, "bspline": bspline, "fit_error": error}))
        })
        .collect()
}

/// An error about the shape `name` (`A: knots: …`).
fn about(name: &str) -> impl Fn(DocumentError) -> DocumentError + '_ {
    move |e| e.about(name)
}

struct IntersectCurves<'a> {
    b: Option<(&'a CurveDocument, &'a str)>,
    a_name: &'a str,
    tolerance: f64,
}

impl DimensionVisitor<Curves> for IntersectCurves<'_> {
    type Output = crate::Result<Value>;
    fn visit<const D: usize>(self, a: &dyn Curve<D>) -> Self::Output {
        let Some((doc, b_name)) = self.b else {
            return Ok(curve_intersections_json(&self_intersections(a, self.tolerance)?));
        };
        let dim = doc.dimension().map_err(about(b_name))?;
        if dim != D {
            return Err(DocumentError::new(
                b_name,
                format!("the curves must have the same dimension, {} is {D}-D and {b_name} is {dim}-D", self.a_name),
            ));
        }
        let b = doc.build_in::<D>().map_err(about(b_name))?;
        Ok(curve_intersections_json(&intersect_curves(a, b.as_ref(), self.tolerance)?))
    }
}

/// Builds a 3-D curve and surface, `name_c` and `name_s` naming them in errors, and
/// intersects them.
fn curve_and_surface(
    c: &CurveDocument,
    s: &SurfaceDocument,
    (name_c, name_s): (&str, &str),
    tolerance: f64,
) -> crate::Result<Value> {
    for (name, dim) in [(name_c, c.dimension()), (name_s, s.dimension())] {
        let dim = dim.map_err(about(name))?;
        if dim != 3 {
            return Err(DocumentError::new(
                name,
                format!("a curve and a surface intersect in 3-D only, this shape is {dim}-D"),
            ));
        }
    }
    let curve = c.build_in::<3>().map_err(about(name_c))?;
    let surface = s.build_in::<3>().map_err(about(name_s))?;
    Ok(curve_surface_json(&intersect_curve_surface(curve.as_ref(), surface.as_ref(), tolerance)?))
}

/// Builds two 3-D surfaces and intersects them (curves fitted within `chord`).
fn two_surfaces(
    a: &SurfaceDocument,
    b: &SurfaceDocument,
    (name_a, name_b): (&str, &str),
    tolerance: f64,
    chord: f64,
) -> crate::Result<Value> {
    for (name, dim) in [(name_a, a.dimension()), (name_b, b.dimension())] {
        let dim = dim.map_err(about(name))?;
        if dim != 3 {
            return Err(DocumentError::new(name, format!("surfaces intersect in 3-D only, this surface is {dim}-D")));
        }
    }
    let sa = a.build_in::<3>().map_err(about(name_a))?;
    let sb = b.build_in::<3>().map_err(about(name_b))?;
    let branches = intersect_surfaces(sa.as_ref(), sb.as_ref(), tolerance, chord)?;
    Ok(json!({"points": [], "overlaps": [], "curves": branches_json(&branches, chord)?}))
}

/// `splinekit intersect A [B]`: where two shapes meet, or where a curve crosses itself,
/// as `{points, overlaps, curves}`; `names` are what errors call the two shapes.
pub fn intersect(
    a: &ShapeDocument,
    b: Option<&ShapeDocument>,
    (name_a, name_b): (&str, &str),
    tolerance: f64,
    chord: f64,
) -> crate::Result<Value> {
    match (a, b) {
        (ShapeDocument::Curve(a), b) => {
            let b = match b {
                None => None,
                Some(ShapeDocument::Curve(b)) => Some((b, name_b)),
                Some(ShapeDocument::Surface(s)) => return curve_and_surface(a, s, (name_a, name_b), tolerance),
            };
            a.build().map_err(about(name_a))?.visit(IntersectCurves { b, a_name: name_a, tolerance })
        }
        (ShapeDocument::Surface(s), Some(ShapeDocument::Curve(c))) => {
            curve_and_surface(c, s, (name_b, name_a), tolerance)
        }
        (ShapeDocument::Surface(_), None) => Err(DocumentError::new(
            name_b,
            "a surface needs a second shape (self-intersections of surfaces are not computed)",
        )),
        (ShapeDocument::Surface(a), Some(ShapeDocument::Surface(b))) => {
            two_surfaces(a, b, (name_a, name_b), tolerance, chord)
        }
    }
}

/// Most planes one section may cut with.
pub const MAX_SECTION_LEVELS: usize = 100;

/// Heights (along n, from o) of the cuts, and the surface's centre and size.
fn levels(s: &dyn Surface<3>, o: &Point<3>, n: &Point<3>, count: usize) -> (Vec<f64>, Point<3>, f64) {
    let (du, dv) = (s.domain_u(), s.domain_v());
    let pts: Vec<Point<3>> =
        (0..33 * 33).map(|k| s.point(du.lerp((k / 33) as f64 / 32.0), dv.lerp((k % 33) as f64 / 32.0))).collect();
    let heights: Vec<f64> = pts.iter().map(|p| (p - o).dot(n)).collect();
    let (lo, hi) = heights.iter().fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &h| (a.min(h), b.max(h)));
    let centre = pts.iter().fold(Point::<3>::zeros(), |c, p| c + p) / pts.len() as f64;
    let size = splinekit::query::Aabb::around(&pts, 0.0).diagonal().max(1.0);
    let cuts = if count == 1 {
        vec![0.0]
    } else {
        (0..count).map(|k| lo + (hi - lo) * (k as f64 + 0.5) / count as f64).collect()
    };
    (cuts, centre, size)
}

/// A square plane at height h, centred on the surface and far larger than it.
fn big_plane(o: &Point<3>, n: &Point<3>, h: f64, centre: &Point<3>, size: f64) -> splinekit::Result<Plane> {
    let helper = if n.x.abs() < 0.9 { Point::<3>::x() } else { Point::<3>::y() };
    let (a, b) = (n.cross(&helper).normalize(), n.cross(&helper).normalize().cross(n));
    let foot = centre - n * ((centre - o).dot(n) - h);
    let (a, b) = (a * (4.0 * size), b * (4.0 * size));
    Plane::new(foot - (a + b) * 0.5, a, b)
}

/// `splinekit section`: the sections of the surface document `doc` (named `name` in
/// errors) by planes through `o` with unit normal `n` — the plane itself for one level,
/// else the middles of `count` equal slabs of the surface's extent along `n` — as
/// `{"sections": [{origin, normal, curves}, …]}`, each curve as [`branches_json`] with
/// its surface parameters as `params`.
pub fn sections(
    doc: ShapeDocument,
    name: &str,
    (o, n): (&Point<3>, &Point<3>),
    count: usize,
    tolerance: f64,
    chord: f64,
) -> crate::Result<Value> {
    let ShapeDocument::Surface(doc) = doc else {
        return Err(DocumentError::new(name, "section cuts surfaces, this document is a curve"));
    };
    let dim = doc.dimension()?;
    if dim != 3 {
        return Err(DocumentError::new(name, format!("sections are of 3-D surfaces, this one is {dim}-D")));
    }
    let surface = doc.build_in::<3>().map_err(about(name))?;
    let (cuts, centre, size) = levels(surface.as_ref(), o, n, count);
    let mut sections = Vec::with_capacity(cuts.len());
    for h in cuts {
        let plane = big_plane(o, n, h, &centre, size)?;
        let branches = intersect_surfaces(surface.as_ref(), &plane, tolerance, chord)?;
        let curves: Vec<Value> = branches_json(&branches, chord)?
            .into_iter()
            .map(|mut c| {
                if let Some(m) = c.as_object_mut() {
                    m.remove("params_b");
                    if let Some(p) = m.remove("params_a") {
                        m.insert("params".into(), p);
                    }
                }
                c
            })
            .collect();
        let origin = o + n * h;
        sections.push(json!({"origin": [origin.x, origin.y, origin.z], "normal": [n.x, n.y, n.z], "curves": curves}));
    }
    Ok(json!({ "sections": sections }))
}

/// The argument of an offset that a kernel error is about (`distance`, `tolerance` or
/// `normal`, which its message starts with), or `None` when it is about the shape.
pub fn offset_argument(e: &splinekit::Error) -> Option<&'static str> {
    let message = e.to_string();
    ["distance", "tolerance", "normal"]
        .into_iter()
        .find(|field| message.strip_prefix(field).is_some_and(|r| r.starts_with(':')))
}

/// A curve's offset: the documents of its pieces (cubic B-splines) and the line that
/// reports it.
pub struct OffsetCurve {
    /// Signed distance (to the right of the direction, T × N).
    pub distance: f64,
    /// Largest distance from the exact offset.
    pub tolerance: f64,
    /// The normal of a 3-D curve's plane (default z).
    pub normal: Option<Point<3>>,
}

impl DimensionVisitor<Curves> for OffsetCurve {
    type Output = splinekit::Result<(Vec<CurveDocument>, String)>;
    fn visit<const D: usize>(self, curve: &dyn Curve<D>) -> Self::Output {
        let normal = if D == 3 { self.normal.or(Some(Point::<3>::z())) } else { self.normal };
        let off = offset_curve(curve, self.distance, normal, self.tolerance)?;
        let report = format!(
            "offset: {} piece{}, max error {:.3e} (tolerance {:e}), {} cusps and {} self-intersections of the raw offset trimmed",
            off.pieces.len(),
            if off.pieces.len() == 1 { "" } else { "s" },
            off.max_error,
            self.tolerance,
            off.cusps.len(),
            off.crossings.len()
        );
        Ok((off.pieces.iter().map(|p| bspline_doc(&p.curve)).collect(), report))
    }
}

/// A 3-D surface's offset: the bicubic B-spline surface's document and the line that
/// reports it.
pub fn offset_surface_document(
    surface: &dyn Surface<3>,
    distance: f64,
    tolerance: f64,
) -> splinekit::Result<(SurfaceDocument, String)> {
    let off = offset_surface(surface, distance, tolerance)?;
    let report = format!(
        "offset: max error {:.3e} (tolerance {:e}), {} × {} grid",
        off.max_error, tolerance, off.grid.0, off.grid.1
    );
    Ok((bspline_surface_doc(&off.surface), report))
}
