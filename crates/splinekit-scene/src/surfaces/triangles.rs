//! Documents of the triangle family: `bezier_triangle`, `sub_triangle`, `gerbs_triangle`,
//! `triangulation` (a height field over a constrained Delaunay triangulation) and
//! `blending_triangulation` (a blending surface over a triangulated surface).
//!
//! None is a tensor-product surface; each is built as a kernel
//! [`TriangleAtlas`](splinekit::triangle::TriangleAtlas): a [`Surface`] over unit charts,
//! chart c over u ∈ [c, c + 1], v ∈ [0, 1], triangle c at the barycentric point
//! (s(1 − t), s t, 1 − s) of (c + s, t) (a Bézier triangle's chart is exactly its degenerate
//! tensor patch). Evaluation, meshing (on each triangle's barycentric lattice), rendering,
//! glTF and STEP read it through the `Surface` trait and its `triangle_atlas` hook.

use std::sync::Arc;

use serde::{Deserialize, Serialize};
use splinekit::Point;
use splinekit::frame::Affine;
use splinekit::surface::Surface;
use splinekit::triangle::{
    BezierTriangle, GerbsTriangle, RationalBezierTriangle, SubTriangle, Triangle, TriangleAtlas, TriangularBFunction,
    TriangularForm, TriangulatedSurface, TriangulationBlend, net_len,
};
use splinekit::triangulation::{Delaunay, HeightInterpolant, gradient_of_normal, height_pieces};

use super::{SphereDoc, SurfaceDecoration, SurfaceDocument, SurfaceForm, Surfaces};
use crate::bfunctions::{BFunctionDoc, DEFAULT_BFUNCTION};
use crate::blending::{TrackDoc, tracks};
use crate::budget::{BFUNCTION_EVALUATION, F64, LOCAL_PIECE, ShapeCost};
use crate::dimension::same_type;
use crate::error::{DocumentError, Result};
use crate::points::{check_finite_list, dimension_of, to_point, to_points};
use crate::registry::{DocumentKind, approximated_kind_items};
use crate::transforms::LocalTransforms;
use crate::views::NetView;

/// The kernel object of a one-triangle document as a [`Triangle`] (for GERBS locals and
/// models): any surface document whose kernel is an atlas of one triangle.
pub fn triangle_of<const D: usize>(doc: &SurfaceDocument, field: &str) -> Result<Arc<dyn Triangle<D>>> {
    let s = doc.build_in::<D>().map_err(|e| e.within(field))?;
    match s.triangle_atlas() {
        Some(a) if a.charts().len() == 1 => Ok(a.charts()[0].clone()),
        _ => Err(DocumentError::new(
            field,
            format!(
                "expected a triangle (bezier_triangle, sub_triangle or gerbs_triangle), got a \"{}\"",
                doc.type_name()
            ),
        )),
    }
}

/// `{"type":"bezier_triangle","control_points":[…],"weights":[…]}`: the Bézier triangle
/// Σ B^n_ijk P_ijk (rational with weights), control points b_n00, then rows of falling i,
/// each by falling j (b_ijk at (j+k)(j+k+1)/2 + k).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct BezierTriangleDoc {
    /// The degree n (optional; must match (n+1)(n+2)/2 control points).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub degree: Option<usize>,
    /// The (n+1)(n+2)/2 control points in storage order.
    pub control_points: Vec<Vec<f64>>,
    /// One positive weight per point: a rational Bézier triangle.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub weights: Option<Vec<f64>>,
}

impl BezierTriangleDoc {
    fn check_degree(&self) -> Result<()> {
        if let Some(n) = self.degree {
            if n > splinekit::triangle::MAX_DEGREE {
                return Err(DocumentError::new(
                    "degree",
                    format!("must be at most {}, got {n}", splinekit::triangle::MAX_DEGREE),
                ));
            }
            let expected = net_len(n);
            if expected != self.control_points.len() {
                return Err(DocumentError::new(
                    "control_points",
                    format!(
                        "expected {} points for degree {n} ((n+1)(n+2)/2, degree at most {}), got {}",
                        expected,
                        splinekit::triangle::MAX_DEGREE,
                        self.control_points.len()
                    ),
                ));
            }
        }
        Ok(())
    }

    /// The kernel triangle (polynomial, or rational with weights) in dimension D.
    pub fn triangle<const D: usize>(&self) -> Result<Arc<dyn Triangle<D>>> {
        Ok(match self.tensor::<D>()? {
            Err(t) => Arc::new(t),
            Ok(t) => Arc::new(t),
        })
    }

    /// The polynomial (`Err`) or rational (`Ok`) kernel triangle.
    fn tensor<const D: usize>(&self) -> Result<std::result::Result<RationalBezierTriangle<D>, BezierTriangle<D>>> {
        self.check_degree()?;
        let points = to_points::<D>(&self.control_points);
        Ok(match &self.weights {
            None => Err(BezierTriangle::new(points)?),
            Some(w) => {
                check_finite_list("weights", w)?;
                Ok(RationalBezierTriangle::new(points, w.clone())?)
            }
        })
    }

    /// The exact degenerate tensor patch of degree (n, n) (3-D and below).
    pub fn tensor_net(&self) -> Result<NetView<'static>> {
        let dimension = self.dimension()?;
        crate::with_dimension!(dimension, "control_points", D => {
            Ok(match self.tensor::<D>()? {
                Err(t) => {
                    let patch = t.to_tensor_patch();
                    let rows: Vec<Vec<Vec<f64>>> =
                        patch.control_points().iter().map(|row| crate::points::from_points(row)).collect();
                    let (p, q) = patch.degrees();
                    NetView {
                        degrees: (p, q),
                        control_points: std::borrow::Cow::Owned(rows),
                        knots: None,
                        weights: None,
                        periodic: (false, false),
                    }
                }
                Ok(t) => NetView::of_nurbs(&t.to_tensor_patch()),
            })
        })
    }
}

impl DocumentKind for BezierTriangleDoc {
    type Family = Surfaces;
    fn dimension(&self) -> Result<usize> {
        dimension_of("control_points", &self.control_points)
    }
    /// De Casteljau: n³/6 interpolations of D coordinates per point.
    fn cost(&self) -> ShapeCost {
        let n = self.control_points.len() as f64;
        let d = self.control_points.first().map_or(1, Vec::len) as f64;
        let degree = (2.0 * n).sqrt();
        ShapeCost::new("control_points", n * (d + 1.0) * F64 * 2.0, n * d, degree.powi(3) * d + 20.0)
    }
    fn build_in<const D: usize>(&self) -> Result<Box<dyn Surface<D>>> {
        Ok(Box::new(TriangleAtlas::single(self.triangle::<D>()?)))
    }
    /// A cubic triangle over the corners (2, 0, 0), (0, 2, 0), (0, 0, 0), its centre point
    /// lifted to z = 1.5 and its edges bowed.
    fn example() -> Self {
        let mut control_points = Vec::new();
        for (i, j, k) in splinekit::triangle::multi_indices(3) {
            let (x, y) = (2.0 * i as f64 / 3.0, 2.0 * j as f64 / 3.0);
            let z = match (i, j, k) {
                (1, 1, 1) => 1.5,
                (3, 0, 0) | (0, 3, 0) | (0, 0, 3) => 0.0,
                _ => 0.4,
            };
            control_points.push(vec![x, y, z]);
        }
        BezierTriangleDoc { degree: Some(3), control_points, weights: None }
    }
    fn decoration(&self) -> SurfaceDecoration<'_> {
        SurfaceDecoration::TriangularNet { points: &self.control_points, field: "control_points" }
    }
    fn set_time(&mut self, _time: f64) {}
    /// A Bézier triangle holds a triangular net, not a tensor-product one.
    fn spline(&self) -> Option<NetView<'_>> {
        None
    }
    /// Exactly its degenerate tensor patch (Bézier, or rational as a NURBS patch).
    fn exact_form(&self) -> Result<SurfaceForm<'_>> {
        Ok(SurfaceForm::Spline(self.tensor_net()?))
    }
    const BLENDING_MODEL: bool = false;
}

/// `{"type":"sub_triangle","surface":{…},"corners":[[u,v],[u,v],[u,v]]}`: T(u, v, w) =
/// S(u a + v b + w c) for the corners a, b, c in the surface's (u, v) domain.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SubTriangleDoc {
    /// The surface.
    pub surface: Box<SurfaceDocument>,
    /// The images a, b, c of the corners u, v, w in the surface's (u, v) domain.
    pub corners: [[f64; 2]; 3],
}

impl SubTriangleDoc {
    /// The kernel sub-triangle in dimension D.
    pub fn triangle<const D: usize>(&self) -> Result<SubTriangle<Box<dyn Surface<D>>>> {
        let s = self.surface.build_in::<D>().map_err(|e| e.within("surface"))?;
        let corners = self.corners.map(|c| Point::<2>::new(c[0], c[1]));
        Ok(SubTriangle::new(s, corners)?)
    }
}

impl DocumentKind for SubTriangleDoc {
    type Family = Surfaces;
    approximated_kind_items!(NetView, SurfaceForm);
    fn dimension(&self) -> Result<usize> {
        self.surface.dimension().map_err(|e| e.within("surface"))
    }
    /// The surface's, with partials of the total order asked for.
    fn cost(&self) -> ShapeCost {
        let s = self.surface.cost().within("surface");
        let mut cost = ShapeCost::new("corners", 64.0, 0.0, 0.0).and(s);
        cost.eval *= 2.0;
        cost
    }
    fn build_in<const D: usize>(&self) -> Result<Box<dyn Surface<D>>> {
        let t: Arc<dyn Triangle<D>> = Arc::new(self.triangle::<D>()?);
        Ok(Box::new(TriangleAtlas::single(t)))
    }
    /// A triangle on the unit sphere.
    fn example() -> Self {
        SubTriangleDoc {
            surface: Box::new(SurfaceDocument::Sphere(SphereDoc::default())),
            corners: [[0.3, 0.2], [1.4, 0.3], [0.8, 1.1]],
        }
    }
    fn decoration(&self) -> SurfaceDecoration<'_> {
        SurfaceDecoration::None
    }
    fn set_time(&mut self, time: f64) {
        self.surface.set_time(time);
    }
}

/// The form of a triangular B-function.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum TriangularFormDoc {
    /// β_i = b_i / Σ b_j (any B-function).
    #[default]
    Rational,
    /// β_i = b_i + (1 − Σ b_j)/3 (symmetric B-functions).
    NonRational,
}

fn is_default<T: Default + PartialEq>(x: &T) -> bool {
    *x == T::default()
}

/// `{"type":"gerbs_triangle","locals":[T,T,T]}` or `{"model":T,"degree":d}`, with
/// `bfunction`, `form`, `transforms`, `animation`: three framed local triangles blended by a
/// triangular B-function.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct GerbsTriangleDoc {
    /// The three local triangles at corners u, v, w (triangle documents).
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub locals: Vec<SurfaceDocument>,
    /// A model triangle whose Hermite Bézier triangles at the corners are the locals.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub model: Option<Box<SurfaceDocument>>,
    /// The Hermite locals' degree (default 3).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub degree: Option<usize>,
    /// The 1-D B-function (default ERBS).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub bfunction: Option<BFunctionDoc>,
    /// Rational (default) or non-rational weights.
    #[serde(default, skip_serializing_if = "is_default")]
    pub form: TriangularFormDoc,
    /// Per-local rest transforms (0, 1, 2: corners u, v, w).
    #[serde(default, with = "crate::transforms::by_index", skip_serializing_if = "Vec::is_empty")]
    pub transforms: LocalTransforms,
    /// Animation tracks (`local` is 0, 1 or 2).
    #[serde(default, deserialize_with = "crate::json::list", skip_serializing_if = "Vec::is_empty")]
    pub animation: Vec<TrackDoc<usize>>,
    /// The time at which the animation is posed (`None`: the rest pose).
    #[serde(skip)]
    pub time: Option<f64>,
}

/// Applies `transforms` and, at `time`, `animation` to `n` locals whose origins `origin`
/// gives, setting each frame with `set`.
fn pose_locals<const D: usize>(
    n: usize,
    what: &str,
    transforms: &LocalTransforms,
    animation: &[TrackDoc<usize>],
    time: Option<f64>,
    origin: impl Fn(usize) -> Point<D>,
    mut set: impl FnMut(usize, Affine<D>) -> splinekit::Result<()>,
) -> Result<()> {
    let mut rest = vec![Affine::<D>::identity(); n];
    for (i, t) in transforms {
        if *i >= n {
            return Err(DocumentError::new("transforms", format!("{what} {i} does not exist (there are {n})")));
        }
        rest[*i] = t.build::<D>(&format!("transforms[{i}]"), &origin(*i))?;
        set(*i, rest[*i])?;
    }
    let tracks = tracks::<usize, D>(animation)?;
    if let Some((k, t)) = tracks.iter().enumerate().find(|(_, t)| t.local >= n) {
        return Err(DocumentError::new(
            format!("animation[{k}].local"),
            format!("{what} {} does not exist (there are {n})", t.local),
        ));
    }
    if let Some(time) = time {
        for t in &tracks {
            let frame = t.at(time, &origin(t.local))?.after(&rest[t.local]);
            set(t.local, frame)?;
        }
    }
    Ok(())
}

impl GerbsTriangleDoc {
    /// The triangular B-function.
    pub fn basis(&self) -> Result<TriangularBFunction> {
        let b = self.bfunction.as_ref().unwrap_or(&DEFAULT_BFUNCTION).build().map_err(|e| e.within("bfunction"))?;
        let form = match self.form {
            TriangularFormDoc::Rational => TriangularForm::Rational,
            TriangularFormDoc::NonRational => TriangularForm::NonRational,
        };
        Ok(TriangularBFunction::new(b, form)?)
    }

    /// The kernel GERBS triangle in dimension D, posed at [`Self::time`].
    pub fn gerbs<const D: usize>(&self) -> Result<GerbsTriangle<D>> {
        let basis = self.basis()?;
        let mut g = match (&self.model, self.locals.len()) {
            (Some(model), 0) => {
                let m = triangle_of::<D>(model, "model")?;
                GerbsTriangle::hermite(m.as_ref(), self.degree.unwrap_or(3), basis)?
            }
            (None, 3) => {
                if self.degree.is_some() {
                    return Err(DocumentError::new("degree", "is for Hermite locals of a \"model\", not given locals"));
                }
                let l: Vec<Arc<dyn Triangle<D>>> = self
                    .locals
                    .iter()
                    .enumerate()
                    .map(|(i, d)| triangle_of::<D>(d, &format!("locals[{i}]")))
                    .collect::<Result<_>>()?;
                GerbsTriangle::new([l[0].clone(), l[1].clone(), l[2].clone()], basis)?
            }
            (None, n) => {
                return Err(DocumentError::new(
                    "locals",
                    format!("expected 3 local triangles (corners u, v, w) or a \"model\", got {n}"),
                ));
            }
            (Some(_), _) => {
                return Err(DocumentError::new("locals", "give either \"locals\" or a \"model\", not both"));
            }
        };
        let origins: Vec<Point<D>> = (0..3).map(|i| g.origin(i).expect("three locals")).collect();
        pose_locals::<D>(
            3,
            "local",
            &self.transforms,
            &self.animation,
            self.time,
            |i| origins[i],
            |i, f| g.set_frame(i, f),
        )?;
        Ok(g)
    }
}

impl DocumentKind for GerbsTriangleDoc {
    type Family = Surfaces;
    approximated_kind_items!(NetView, SurfaceForm);
    fn dimension(&self) -> Result<usize> {
        match (&self.model, self.locals.first()) {
            (Some(m), _) => m.dimension().map_err(|e| e.within("model")),
            (None, Some(first)) => {
                let d = first.dimension().map_err(|e| e.within("locals[0]"))?;
                for (i, l) in self.locals.iter().enumerate().skip(1) {
                    let e = l.dimension().map_err(|e| e.within(&format!("locals[{i}]")))?;
                    if e != d {
                        return Err(DocumentError::new(
                            format!("locals[{i}]"),
                            format!("is {e}-D, the first local {d}-D"),
                        ));
                    }
                }
                Ok(d)
            }
            (None, None) => Err(DocumentError::new("locals", "expected 3 local triangles or a \"model\"")),
        }
    }
    /// Three locals and three B-function evaluations per point.
    fn cost(&self) -> ShapeCost {
        let mut cost = ShapeCost::new("locals", 3.0 * LOCAL_PIECE, 0.0, 0.0);
        if let Some(m) = &self.model {
            let d = self.degree.unwrap_or(3) as f64;
            let m = m.cost().within("model");
            let build = m.eval * (d + 1.0) * (d + 1.0) * 3.0;
            cost = cost.and(m);
            cost.build.work += build;
            cost.eval = 3.0 * d * d * d + 3.0 * BFUNCTION_EVALUATION;
        } else {
            for (i, l) in self.locals.iter().enumerate() {
                cost = cost.and(l.cost().within(&format!("locals[{i}]")));
            }
            cost.eval += 3.0 * BFUNCTION_EVALUATION;
        }
        cost
    }
    fn build_in<const D: usize>(&self) -> Result<Box<dyn Surface<D>>> {
        let t: Arc<dyn Triangle<D>> = Arc::new(self.gerbs::<D>()?);
        Ok(Box::new(TriangleAtlas::single(t)))
    }
    /// Cubic Hermite locals of a triangle on the unit sphere, blended by ERBS.
    fn example() -> Self {
        GerbsTriangleDoc {
            locals: Vec::new(),
            model: Some(Box::new(SurfaceDocument::SubTriangle(SubTriangleDoc::example()))),
            degree: Some(3),
            bfunction: None,
            form: TriangularFormDoc::Rational,
            transforms: Vec::new(),
            animation: Vec::new(),
            time: None,
        }
    }
    fn decoration(&self) -> SurfaceDecoration<'_> {
        SurfaceDecoration::LocalPieces(self)
    }
    fn set_time(&mut self, time: f64) {
        self.time = Some(time);
        if let Some(m) = &mut self.model {
            m.set_time(time);
        }
        self.locals.iter_mut().for_each(|l| l.set_time(time));
    }
}

/// How a `triangulation` interpolates its heights.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum InterpolantDoc {
    /// Piecewise linear.
    #[default]
    Linear,
    /// Clough–Tocher's C¹ cubic split.
    CloughTocher,
}

/// `{"type":"triangulation","points":[[x,y,z],…]}` (or 2-D points with `heights`), with
/// optional constraint `edges`, `interpolant` and `normals`: the height field over the
/// constrained Delaunay triangulation of the points' (x, y).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct TriangulationDoc {
    /// The points: (x, y, z), or (x, y) with `heights`.
    pub points: Vec<Vec<f64>>,
    /// The heights z of 2-D points.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub heights: Option<Vec<f64>>,
    /// Constraint edges (pairs of point numbers) the triangulation keeps.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub edges: Vec<[usize; 2]>,
    /// `linear` (default) or `clough_tocher`.
    #[serde(default, skip_serializing_if = "is_default")]
    pub interpolant: InterpolantDoc,
    /// Unit normals at the points (Clough–Tocher's gradients −n_x/n_z, −n_y/n_z; estimated
    /// from the neighbours when absent).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub normals: Option<Vec<Vec<f64>>>,
}

impl TriangulationDoc {
    /// The (x, y) sites and their heights.
    fn sites(&self) -> Result<(Vec<Point<2>>, Vec<f64>)> {
        let d = dimension_of("points", &self.points)?;
        match (d, &self.heights) {
            (3, None) => Ok((
                self.points.iter().map(|p| Point::<2>::new(p[0], p[1])).collect(),
                self.points.iter().map(|p| p[2]).collect(),
            )),
            (2, Some(h)) => {
                check_finite_list("heights", h)?;
                if h.len() != self.points.len() {
                    return Err(DocumentError::new(
                        "heights",
                        format!("expected {} values, one per point, got {}", self.points.len(), h.len()),
                    ));
                }
                Ok((to_points::<2>(&self.points), h.clone()))
            }
            (3, Some(_)) => {
                Err(DocumentError::new("heights", "3-D points carry their heights; give 2-D points with heights"))
            }
            (2, None) => {
                Err(DocumentError::new("heights", "missing: 2-D points need one height each (or give 3-D points)"))
            }
            (d, _) => Err(DocumentError::new(
                "points[0]",
                format!("expected (x, y, z) or (x, y) with heights, got {d} coordinates"),
            )),
        }
    }

    /// The constrained Delaunay triangulation of the sites.
    pub fn delaunay(&self) -> Result<Delaunay> {
        let (sites, _) = self.sites()?;
        let n = sites.len();
        if let Some((k, e)) = self.edges.iter().enumerate().find(|(_, e)| e[0] >= n || e[1] >= n) {
            return Err(DocumentError::new(
                format!("edges[{k}]"),
                format!("point {} does not exist (there are {n})", e[0].max(e[1])),
            ));
        }
        Ok(Delaunay::with_constraints(&sites, &self.edges)?)
    }

    /// The height field's atlas of Bézier triangles (corners shared).
    pub fn atlas(&self) -> Result<TriangleAtlas<3>> {
        let (_, heights) = self.sites()?;
        let d = self.delaunay()?;
        let kind = match self.interpolant {
            InterpolantDoc::Linear => HeightInterpolant::Linear,
            InterpolantDoc::CloughTocher => HeightInterpolant::CloughTocher,
        };
        let gradients = match &self.normals {
            None => None,
            Some(n) => {
                if n.len() != self.points.len() {
                    return Err(DocumentError::new(
                        "normals",
                        format!("expected {} vectors, one per point, got {}", self.points.len(), n.len()),
                    ));
                }
                let mut g = Vec::with_capacity(n.len());
                for (i, v) in n.iter().enumerate() {
                    let field = format!("normals[{i}]");
                    g.push(gradient_of_normal(&field, &to_point::<3>(&field, v)?)?);
                }
                Some(g)
            }
        };
        let pieces = height_pieces(&d, &heights, gradients.as_deref(), kind)?;
        let charts = pieces.triangles.into_iter().map(|t| Arc::new(t) as Arc<dyn Triangle<3>>).collect();
        Ok(TriangleAtlas::with_corner_ids(charts, pieces.corners)?)
    }
}

/// A kind made of several triangles: no spline view, written triangle by triangle.
macro_rules! triangles_kind_items {
    () => {
        fn spline(&self) -> Option<NetView<'_>> {
            None
        }
        fn exact_form(&self) -> Result<SurfaceForm<'_>> {
            Ok(SurfaceForm::Triangles)
        }
        const BLENDING_MODEL: bool = false;
    };
}

impl DocumentKind for TriangulationDoc {
    type Family = Surfaces;
    triangles_kind_items!();
    fn dimension(&self) -> Result<usize> {
        self.sites()?;
        Ok(3)
    }
    /// Delaunay in O(n log n); a point locates nothing (it names its triangle) and costs a
    /// cubic de Casteljau.
    fn cost(&self) -> ShapeCost {
        let n = self.points.len() as f64;
        ShapeCost::new("points", n * 3.0 * 10.0 * 4.0 * F64, n * (n.max(2.0)).log2() * 50.0 + n * 500.0, 100.0)
    }
    fn build_in<const D: usize>(&self) -> Result<Box<dyn Surface<D>>> {
        let atlas: Box<dyn Surface<3>> = Box::new(self.atlas()?);
        same_type(atlas).ok_or_else(|| DocumentError::new("points", "a triangulation's height field is 3-D"))
    }
    /// A Clough–Tocher height field of twelve points on a ring and its centre.
    fn example() -> Self {
        let mut points = vec![vec![0.0, 0.0, 1.0]];
        for k in 0..12 {
            let a = k as f64 * std::f64::consts::TAU / 12.0;
            let r = if k % 2 == 0 { 2.0 } else { 1.2 };
            points.push(vec![r * a.cos(), r * a.sin(), 0.3 * (3.0 * a).sin()]);
        }
        TriangulationDoc {
            points,
            heights: None,
            edges: Vec::new(),
            interpolant: InterpolantDoc::CloughTocher,
            normals: None,
        }
    }
    /// The Voronoi diagram of the sites (see [`LocalPieces`] for `TriangulationDoc`).
    fn decoration(&self) -> SurfaceDecoration<'_> {
        SurfaceDecoration::LocalPieces(self)
    }
    fn set_time(&mut self, _time: f64) {}
}

/// The triangulated surface a `blending_triangulation` blends over.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(tag = "type", rename_all = "snake_case", deny_unknown_fields)]
pub enum MeshDoc {
    /// The sphere over the icosahedron, split `subdivisions` times.
    Icosphere {
        /// Radius (default 1).
        #[serde(default = "crate::defaults::one")]
        radius: f64,
        /// Times each triangle is split into four (default 1).
        #[serde(default = "one_usize")]
        subdivisions: usize,
    },
    /// The torus ((R + r cos v) cos u, (R + r cos v) sin u, r sin v) on a grid.
    Torus {
        /// R (default 3).
        #[serde(default = "three")]
        major_radius: f64,
        /// r (default 1).
        #[serde(default = "crate::defaults::one")]
        minor_radius: f64,
        /// Grid cells [n_u, n_v] (default [16, 8]).
        #[serde(default = "torus_segments")]
        segments: [usize; 2],
    },
    /// Points in space, with triangles (counter-clockwise seen from outside) or without
    /// (then the Delaunay triangulation of their (x, y)), and optionally unit normals.
    Points {
        /// The vertices (3-D).
        vertices: Vec<Vec<f64>>,
        /// The triangles as vertex numbers.
        #[serde(default, skip_serializing_if = "Option::is_none")]
        triangles: Option<Vec<[u32; 3]>>,
        /// The unit normals, one per vertex.
        #[serde(default, skip_serializing_if = "Option::is_none")]
        normals: Option<Vec<Vec<f64>>>,
    },
}

fn one_usize() -> usize {
    1
}
fn three() -> f64 {
    3.0
}
fn torus_segments() -> [usize; 2] {
    [16, 8]
}

impl MeshDoc {
    /// The kernel's triangulated surface.
    pub fn surface(&self) -> Result<TriangulatedSurface> {
        Ok(match self {
            MeshDoc::Icosphere { radius, subdivisions } => TriangulatedSurface::icosphere(*radius, *subdivisions)?,
            MeshDoc::Torus { major_radius, minor_radius, segments } => {
                TriangulatedSurface::torus(*major_radius, *minor_radius, segments[0], segments[1])?
            }
            MeshDoc::Points { vertices, triangles, normals } => {
                let d = dimension_of("vertices", vertices)?;
                if d != 3 {
                    return Err(DocumentError::new("vertices[0]", format!("expected 3 coordinates, got {d}")));
                }
                let positions = to_points::<3>(vertices);
                let triangles = match triangles {
                    Some(t) => t.clone(),
                    None => {
                        let sites: Vec<Point<2>> = positions.iter().map(|p| Point::<2>::new(p.x, p.y)).collect();
                        let d = Delaunay::new(&sites).map_err(|e| DocumentError::from(e).within("vertices"))?;
                        d.triangles().iter().map(|t| t.map(|i| i as u32)).collect()
                    }
                };
                let normals = match normals {
                    None => Vec::new(),
                    Some(n) => {
                        let d = dimension_of("normals", n)?;
                        if d != 3 {
                            return Err(DocumentError::new("normals[0]", format!("expected 3 coordinates, got {d}")));
                        }
                        to_points::<3>(n)
                    }
                };
                TriangulatedSurface { positions, normals, triangles }
            }
        })
    }

    /// About how many vertices it has.
    fn vertex_count(&self) -> f64 {
        match self {
            MeshDoc::Icosphere { subdivisions, .. } => 10.0 * 4f64.powi((*subdivisions).min(30) as i32) + 2.0,
            MeshDoc::Torus { segments, .. } => segments[0] as f64 * segments[1] as f64,
            MeshDoc::Points { vertices, .. } => vertices.len() as f64,
        }
    }
}

/// `{"type":"blending_triangulation","mesh":{…},"degree":2,"bfunction":{…},"transforms":…,
/// "animation":[…]}`: one framed local per vertex of a triangulated surface, blended over each
/// triangle by radial B-functions (see [`TriangulationBlend`]).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct BlendingTriangulationDoc {
    /// The triangulated surface.
    pub mesh: MeshDoc,
    /// The locals' degree: 1 (tangent planes) or 2 (default: quadratic fits).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub degree: Option<usize>,
    /// The 1-D B-function (default ERBS).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub bfunction: Option<BFunctionDoc>,
    /// Per-local rest transforms, by vertex.
    #[serde(default, with = "crate::transforms::by_index", skip_serializing_if = "Vec::is_empty")]
    pub transforms: LocalTransforms,
    /// Animation tracks (`local` is a vertex number).
    #[serde(default, deserialize_with = "crate::json::list", skip_serializing_if = "Vec::is_empty")]
    pub animation: Vec<TrackDoc<usize>>,
    /// The time at which the animation is posed (`None`: the rest pose).
    #[serde(skip)]
    pub time: Option<f64>,
}

impl BlendingTriangulationDoc {
    /// The kernel blend, posed at [`Self::time`].
    pub fn blend(&self) -> Result<TriangulationBlend> {
        let m = self.mesh.surface().map_err(|e| e.within("mesh"))?;
        let b = self.bfunction.as_ref().unwrap_or(&DEFAULT_BFUNCTION).build().map_err(|e| e.within("bfunction"))?;
        let mut s = TriangulationBlend::new(&m, self.degree.unwrap_or(2), b)
            .map_err(|e| DocumentError::from(e).within("mesh"))?;
        let origins: Vec<Point<3>> = (0..s.vertex_count()).map(|i| s.origin(i).expect("a vertex")).collect();
        pose_locals::<3>(
            s.vertex_count(),
            "vertex",
            &self.transforms,
            &self.animation,
            self.time,
            |i| origins[i],
            |i, f| s.set_frame(i, f),
        )?;
        Ok(s)
    }
}

impl DocumentKind for BlendingTriangulationDoc {
    type Family = Surfaces;
    triangles_kind_items!();
    fn dimension(&self) -> Result<usize> {
        Ok(3)
    }
    /// Per vertex a least-squares fit to about 45 samples per triangle of its star; per point
    /// three locals, three B-functions and the jets of the chart maps.
    fn cost(&self) -> ShapeCost {
        let n = self.mesh.vertex_count();
        ShapeCost::new(
            "mesh",
            n * (LOCAL_PIECE + 200.0 * F64),
            n * 6.0 * 45.0 * 400.0,
            3.0 * BFUNCTION_EVALUATION + 3000.0,
        )
    }
    fn build_in<const D: usize>(&self) -> Result<Box<dyn Surface<D>>> {
        let atlas: Box<dyn Surface<3>> = Box::new(self.blend()?.atlas());
        same_type(atlas).ok_or_else(|| DocumentError::new("mesh", "a blending triangulation is 3-D"))
    }
    /// The unit sphere over the icosahedron split once (42 locals, 80 triangles).
    fn example() -> Self {
        BlendingTriangulationDoc {
            mesh: MeshDoc::Icosphere { radius: 1.0, subdivisions: 1 },
            degree: None,
            bfunction: None,
            transforms: Vec::new(),
            animation: Vec::new(),
            time: None,
        }
    }
    fn decoration(&self) -> SurfaceDecoration<'_> {
        SurfaceDecoration::LocalPieces(self)
    }
    fn set_time(&mut self, time: f64) {
        self.time = Some(time);
    }
}

/// The local pieces of a blending kind of the triangle family, as lines for scenes to draw
/// (each local's outline over the part of its chart it is used on, in its frame) and the
/// moved origins for editors' handles; for a `triangulation`, the Voronoi cells of its
/// points (no handles).
pub trait LocalPieces: std::fmt::Debug + Sync {
    /// Per local: its polylines (3-D points) and its moved origin.
    fn local_pieces(&self) -> Result<Vec<LocalPiece>>;
    /// The dimension of the points (2 or 3) and, per local, its frame's origin o (where
    /// its `transforms` entry acts) and the moved origin F(o), without drawing the pieces:
    /// what an editor's handle of the local's frame needs.
    fn local_origins(&self) -> Result<(usize, Vec<LocalOrigin>)>;
}

/// A local's frame as an editor grabs it: the origin o its transform acts about and the
/// moved origin F(o) (3-D; z = 0 for plane shapes).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LocalOrigin {
    /// o, before the local's transform.
    pub origin: [f64; 3],
    /// F(o), where the local's frame puts it.
    pub moved: [f64; 3],
}

/// One local piece as drawn: its polylines (3-D points) and its moved origin.
pub type LocalPiece = (Vec<Vec<[f64; 3]>>, [f64; 3]);

fn p3<const D: usize>(p: &Point<D>) -> [f64; 3] {
    std::array::from_fn(|k| if k < D { p[k] } else { 0.0 })
}

impl LocalPieces for GerbsTriangleDoc {
    /// Each local triangle's three edges and its three medians (33 points each).
    fn local_pieces(&self) -> Result<Vec<LocalPiece>> {
        let dimension = self.dimension()?;
        crate::with_dimension!(dimension, "locals", D => {
            let g = self.gerbs::<D>()?;
            let mut out = Vec::new();
            for i in 0..3 {
                let mut lines = Vec::new();
                let corners = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
                let mut at = [Point::<D>::zeros(); 1];
                let mut point = |l: [f64; 3]| {
                    g.local_partials(i, l[0], l[1], 0, 0, &mut at).expect("local 0..3");
                    p3(&at[0])
                };
                for (a, b) in [(0, 1), (1, 2), (2, 0)] {
                    lines.push((0..=32).map(|k| {
                        let s = k as f64 / 32.0;
                        point(std::array::from_fn(|x| corners[a][x] * (1.0 - s) + corners[b][x] * s))
                    }).collect());
                }
                let o = g.origin(i).expect("local 0..3");
                let moved = g.frame(i).expect("local 0..3").apply_point_about(&o, &o);
                out.push((lines, p3(&moved)));
            }
            Ok(out)
        })
    }

    fn local_origins(&self) -> Result<(usize, Vec<LocalOrigin>)> {
        let dimension = self.dimension()?;
        crate::with_dimension!(dimension, "locals", D => {
            let g = self.gerbs::<D>()?;
            let origins = (0..3)
                .map(|i| {
                    let o = g.origin(i).expect("local 0..3");
                    let moved = g.frame(i).expect("local 0..3").apply_point_about(&o, &o);
                    LocalOrigin { origin: p3(&o), moved: p3(&moved) }
                })
                .collect();
            Ok((dimension, origins))
        })
    }
}

impl LocalPieces for BlendingTriangulationDoc {
    /// Each local's circle |ζ| = ρ^α (the edge of its weight's support) and two diameters.
    fn local_pieces(&self) -> Result<Vec<LocalPiece>> {
        let s = self.blend()?;
        let mut out = Vec::with_capacity(s.vertex_count());
        let mut v = [Point::<3>::zeros(); 1];
        for i in 0..s.vertex_count() {
            let (n, boundary) = s.valence(i);
            let alpha = if boundary { (3.0 / n as f64).min(1.0) } else { 6.0 / n as f64 };
            let r = splinekit::triangle::triangulation_blend::SUPPORT_RADIUS.powf(alpha);
            let mut line = |f: &dyn Fn(f64) -> Point<2>| -> Vec<[f64; 3]> {
                (0..=48)
                    .map(|k| {
                        s.local_partials(i, f(k as f64 / 48.0), 0, 0, &mut v).expect("a vertex");
                        p3(&v[0])
                    })
                    .collect()
            };
            let circle = line(&|t: f64| {
                let a = t * std::f64::consts::TAU;
                Point::<2>::new(r * a.cos(), r * a.sin())
            });
            let d1 = line(&|t: f64| Point::<2>::new(r * (2.0 * t - 1.0), 0.0));
            let d2 = line(&|t: f64| Point::<2>::new(0.0, r * (2.0 * t - 1.0)));
            let o = s.origin(i).expect("a vertex");
            let moved = s.frame(i).expect("a vertex").apply_point_about(&o, &o);
            out.push((vec![circle, d1, d2], p3(&moved)));
        }
        Ok(out)
    }

    fn local_origins(&self) -> Result<(usize, Vec<LocalOrigin>)> {
        let s = self.blend()?;
        let origins = (0..s.vertex_count())
            .map(|i| {
                let o = s.origin(i).expect("a vertex");
                let moved = s.frame(i).expect("a vertex").apply_point_about(&o, &o);
                LocalOrigin { origin: p3(&o), moved: p3(&moved) }
            })
            .collect();
        Ok((3, origins))
    }
}

impl LocalPieces for TriangulationDoc {
    /// The Voronoi diagram of the sites in the plane z = the lowest height (below the
    /// surface): per point, its cell (closed where bounded; for a site on the convex hull
    /// the finite chain between its two rays) and the point itself (x, y, z). Cells are
    /// clipped to the points' bounding box grown by a tenth of its size each way (the
    /// circumcentres of thin triangles at the hull lie far out).
    fn local_pieces(&self) -> Result<Vec<LocalPiece>> {
        let (sites, heights) = self.sites()?;
        let floor = heights.iter().copied().fold(f64::INFINITY, f64::min);
        let (mut lo, mut hi) = ([f64::INFINITY; 2], [f64::NEG_INFINITY; 2]);
        for p in &sites {
            for a in 0..2 {
                lo[a] = lo[a].min(p[a]);
                hi[a] = hi[a].max(p[a]);
            }
        }
        let margin = 0.1 * (hi[0] - lo[0]).max(hi[1] - lo[1]);
        let (lo, hi) = (lo.map(|x| x - margin), hi.map(|x| x + margin));
        let d = self.delaunay()?;
        Ok(d.voronoi_cells()
            .into_iter()
            .zip(&heights)
            .map(|(cell, &z)| {
                let mut chain: Vec<[f64; 2]> = cell.vertices.iter().map(|v| [v.x, v.y]).collect();
                if cell.bounded && !chain.is_empty() {
                    chain.push(chain[0]);
                }
                let lines = clip_polyline(&chain, lo, hi)
                    .into_iter()
                    .map(|l| l.into_iter().map(|p| [p[0], p[1], floor]).collect())
                    .collect();
                (lines, [cell.site.x, cell.site.y, z])
            })
            .collect())
    }

    /// No handles: a triangulation's points are its data, not frames.
    fn local_origins(&self) -> Result<(usize, Vec<LocalOrigin>)> {
        Ok((3, Vec::new()))
    }
}

/// The parts of the polyline `chain` inside the box [lo, hi] (each segment clipped by
/// Liang and Barsky's method), as polylines of at least two points; a chain wholly inside
/// comes back as it is.
fn clip_polyline(chain: &[[f64; 2]], lo: [f64; 2], hi: [f64; 2]) -> Vec<Vec<[f64; 2]>> {
    let mut out: Vec<Vec<[f64; 2]>> = Vec::new();
    let mut current: Vec<[f64; 2]> = Vec::new();
    for w in chain.windows(2) {
        let (a, b) = (w[0], w[1]);
        let d = [b[0] - a[0], b[1] - a[1]];
        let (mut t0, mut t1) = (0.0f64, 1.0f64);
        let mut inside = true;
        for (p, q) in [(-d[0], a[0] - lo[0]), (d[0], hi[0] - a[0]), (-d[1], a[1] - lo[1]), (d[1], hi[1] - a[1])] {
            if p == 0.0 {
                inside &= q >= 0.0;
            } else if p < 0.0 {
                t0 = t0.max(q / p);
            } else {
                t1 = t1.min(q / p);
            }
        }
        if !inside || t0 > t1 {
            if current.len() > 1 {
                out.push(std::mem::take(&mut current));
            }
            current.clear();
            continue;
        }
        let at = |t: f64| {
            if t == 0.0 {
                a
            } else if t == 1.0 {
                b
            } else {
                [a[0] + t * d[0], a[1] + t * d[1]]
            }
        };
        let (p0, p1) = (at(t0), at(t1));
        if current.last() != Some(&p0) {
            if current.len() > 1 {
                out.push(std::mem::take(&mut current));
            }
            current = vec![p0];
        }
        current.push(p1);
        if t1 < 1.0 {
            out.push(std::mem::take(&mut current));
        }
    }
    if current.len() > 1 {
        out.push(current);
    }
    out
}
