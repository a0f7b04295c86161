//! Boundary representations: solids made of shells made of faces, where each edge and
//! vertex is shared by the faces that meet there (ISO 10303-42's topology, as CAD systems
//! exchange their parts).
//!
//! * A **vertex** is a point.
//! * An **edge** is a 3-D curve over its domain, from one vertex to another (the same one
//!   for a closed edge).
//! * A **face** is a region of a surface bounded by loops in the surface's (u, v): the
//!   outer loop first, then the holes. Each loop is a cycle of *uses*: a 2-D curve (the
//!   pcurve) in (u, v), and, where the use runs along an edge, that edge and whether it
//!   runs from the edge's first vertex to its second (`forward`). The pcurve runs in the
//!   loop's direction. A use without an edge is a curve of the parameter plane that is no
//!   edge in space: the line of a pole or apex (its image is one point), or one side of a
//!   cut across a periodic surface, whose other side is its `twin` (the same points one
//!   period over, run the other way). A face whose normal points against S_u × S_v is
//!   `reversed`.
//! * A **shell** is a set of faces, `closed` when it bounds a volume; a **solid** is an
//!   outer shell and the shells of its voids.
//!
//! The faces of a closed shell meet along their edges, so a mesh made by sampling each edge
//! once and giving those points to both of its faces is closed, and its volume is the
//! solid's ([`crate::brep`] holds the topology; `splinekit_mesh::brep_mesh` meshes it).
//!
//! As a [`Surface`], a B-rep is an atlas of its faces' surfaces: face k is the chart
//! u ∈ [k, k + 1], v ∈ [0, 1], mapped affinely onto the box of the face's loops in its own
//! (u, v). Points of a chart outside the face's loops are its untrimmed surface.

pub mod integrals;

use crate::curve::{Curve, Interval};
use crate::surface::Surface;
use crate::{Error, Point, Result};

/// An edge: a 3-D curve over its domain, from `vertices[0]` to `vertices[1]`.
pub struct BrepEdge {
    /// The curve; its domain is the edge.
    pub curve: Box<dyn Curve<3>>,
    /// Indices of its first and last vertex.
    pub vertices: [usize; 2],
}

/// One piece of a face's loop.
pub struct EdgeUse {
    /// The piece in the face surface's (u, v), in the loop's direction.
    pub pcurve: Box<dyn Curve<2>>,
    /// The edge it runs along, if it is one.
    pub edge: Option<usize>,
    /// Whether it runs from the edge's first vertex to its second.
    pub forward: bool,
    /// For a side of a cut across a periodic surface: the index in the same loop of the
    /// other side.
    pub twin: Option<usize>,
}

/// A face: a region of a surface bounded by loops.
pub struct BrepFace {
    /// The surface.
    pub surface: Box<dyn Surface<3>>,
    /// Whether the face's normal is −(S_u × S_v).
    pub reversed: bool,
    /// The loops, outer first.
    pub loops: Vec<Vec<EdgeUse>>,
    /// The face's colour (linear RGBA), if it has its own.
    pub color: Option<[f32; 4]>,
}

/// A set of faces, closed when it bounds a volume.
#[derive(Debug, Clone, PartialEq)]
pub struct Shell {
    /// Indices of its faces.
    pub faces: Vec<usize>,
    /// Whether it bounds a volume.
    pub closed: bool,
}

/// A solid: its outer shell and the shells of its voids.
#[derive(Debug, Clone, PartialEq)]
pub struct Solid {
    /// Indices of its shells, the outer one first.
    pub shells: Vec<usize>,
}

/// A boundary representation (see the module).
pub struct Brep {
    vertices: Vec<Point<3>>,
    edges: Vec<BrepEdge>,
    faces: Vec<BrepFace>,
    shells: Vec<Shell>,
    solids: Vec<Solid>,
    /// Per face, the box of its loops in (u, v): the chart's map.
    charts: Vec<(Interval, Interval)>,
}

/// Samples of each pcurve whose box is a face's chart.
const CHART_SAMPLES: usize = 16;

impl Brep {
    /// The B-rep of these parts, checked: every index names an existing vertex, edge, face
    /// or shell, every loop has a use, twins are pairs within their loop, and each face's
    /// loops span a box of positive size.
    pub fn new(
        vertices: Vec<Point<3>>,
        edges: Vec<BrepEdge>,
        faces: Vec<BrepFace>,
        shells: Vec<Shell>,
        solids: Vec<Solid>,
    ) -> Result<Self> {
        let index = |field: String, i: usize, n: usize, what: &str| -> Result<()> {
            if i < n { Ok(()) } else { Err(Error::invalid(field, format!("names {what} {i}, but there are {n}"))) }
        };
        for (k, p) in vertices.iter().enumerate() {
            if !p.iter().all(|x| x.is_finite()) {
                return Err(Error::invalid(format!("vertices[{k}]"), "coordinates must be finite"));
            }
        }
        for (k, e) in edges.iter().enumerate() {
            for v in e.vertices {
                index(format!("edges[{k}].vertices"), v, vertices.len(), "vertex")?;
            }
        }
        let mut charts = Vec::with_capacity(faces.len());
        for (f, face) in faces.iter().enumerate() {
            let mut lo = Point::<2>::from([f64::INFINITY; 2]);
            let mut hi = -lo;
            for (l, lp) in face.loops.iter().enumerate() {
                if lp.is_empty() {
                    return Err(Error::invalid(format!("faces[{f}].loops[{l}]"), "a loop needs at least one use"));
                }
                for (u, us) in lp.iter().enumerate() {
                    let field = format!("faces[{f}].loops[{l}][{u}]");
                    if let Some(e) = us.edge {
                        index(format!("{field}.edge"), e, edges.len(), "edge")?;
                    }
                    if let Some(t) = us.twin {
                        index(format!("{field}.twin"), t, lp.len(), "use")?;
                        if lp[t].twin != Some(u) || t == u {
                            return Err(Error::invalid(format!("{field}.twin"), format!("use {t} is not its twin")));
                        }
                    }
                    let d = us.pcurve.domain();
                    for s in 0..=CHART_SAMPLES {
                        let p = us.pcurve.point(d.start + d.length() * s as f64 / CHART_SAMPLES as f64);
                        lo = lo.inf(&p);
                        hi = hi.sup(&p);
                    }
                }
            }
            let whole = (face.surface.domain_u(), face.surface.domain_v());
            let chart = if face.loops.is_empty() {
                whole
            } else {
                if !(hi[0] > lo[0] && hi[1] > lo[1] && (hi - lo).iter().all(|x| x.is_finite())) {
                    return Err(Error::invalid(
                        format!("faces[{f}].loops"),
                        format!("the loops span no region of (u, v): from {lo:?} to {hi:?}"),
                    ));
                }
                (Interval::new(lo[0], hi[0]), Interval::new(lo[1], hi[1]))
            };
            charts.push(chart);
        }
        for (s, shell) in shells.iter().enumerate() {
            for &f in &shell.faces {
                index(format!("shells[{s}].faces"), f, faces.len(), "face")?;
            }
        }
        for (k, solid) in solids.iter().enumerate() {
            if solid.shells.is_empty() {
                return Err(Error::invalid(format!("solids[{k}].shells"), "a solid needs its outer shell"));
            }
            for &s in &solid.shells {
                index(format!("solids[{k}].shells"), s, shells.len(), "shell")?;
            }
        }
        Ok(Brep { vertices, edges, faces, shells, solids, charts })
    }

    /// The vertices.
    pub fn vertices(&self) -> &[Point<3>] {
        &self.vertices
    }
    /// The edges.
    pub fn edges(&self) -> &[BrepEdge] {
        &self.edges
    }
    /// The faces.
    pub fn faces(&self) -> &[BrepFace] {
        &self.faces
    }
    /// The shells.
    pub fn shells(&self) -> &[Shell] {
        &self.shells
    }
    /// The solids.
    pub fn solids(&self) -> &[Solid] {
        &self.solids
    }

    /// Face k's chart: the box of its loops in its surface's (u, v) (its surface's domain
    /// when it has no loops).
    pub fn chart(&self, k: usize) -> (Interval, Interval) {
        self.charts[k]
    }

    /// The face and its own (u, v) of the atlas point (u, v) (see the module): face
    /// ⌊u⌋ clamped to the faces, the fractions mapped onto its chart.
    fn locate(&self, u: f64, v: f64) -> (usize, f64, f64) {
        let n = self.faces.len();
        let k = if u.is_finite() { (u.floor().max(0.0) as usize).min(n.saturating_sub(1)) } else { 0 };
        let (cu, cv) = self.charts[k];
        let (fu, fv) = (u - k as f64, v);
        (k, cu.start + fu * cu.length(), cv.start + fv * cv.length())
    }
}

impl Surface<3> for Brep {
    fn domain_u(&self) -> Interval {
        Interval::new(0.0, self.faces.len().max(1) as f64)
    }
    fn domain_v(&self) -> Interval {
        Interval::new(0.0, 1.0)
    }

    /// The partials of face ⌊u⌋'s surface at the mapped point, scaled by the chart's sides
    /// (chain rule of the affine map); NaN without faces.
    fn eval_partials(&self, u: f64, v: f64, du: usize, dv: usize, out: &mut [Point<3>]) {
        if self.faces.is_empty() {
            out.iter_mut().take((du + 1) * (dv + 1)).for_each(|o| *o = Point::<3>::from([f64::NAN; 3]));
            return;
        }
        let (k, a, b) = self.locate(u, v);
        self.faces[k].surface.eval_partials(a, b, du, dv, out);
        let (cu, cv) = self.charts[k];
        for i in 0..=du {
            for j in 0..=dv {
                out[i * (dv + 1) + j] *= cu.length().powi(i as i32) * cv.length().powi(j as i32);
            }
        }
    }

    fn breakpoints_u(&self) -> Vec<f64> {
        (0..=self.faces.len()).map(|k| k as f64).collect()
    }

    fn brep(&self) -> Option<&Brep> {
        Some(self)
    }
}
