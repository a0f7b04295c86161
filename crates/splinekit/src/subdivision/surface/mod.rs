//! Subdivision surfaces: Catmull–Clark, Loop and bilinear refinement of a polygon cage
//! with sharp and semi-sharp creases and boundary rules, limit masks at vertices, and
//! exact evaluation of the limit surface at any (face, u, v).
//!
//! One concept per file: [`cage`] (the data), [`atlas`] (the limit as one parametric surface), [`topology`] (half-edge adjacency),
//! [`creases`] (sharpness rules), [`catmull_clark`], [`loop_scheme`], [`bilinear`] (one
//! step each), [`bezier_patches`] (the limit as Bézier patches, for STEP; [`loop_bezier`] the regular Loop patch as one), [`limit_masks`], [`regular_patch`], [`box_spline`] and `regular_face` (polynomial patches
//! on regular faces), [`local`] (neighbourhoods), [`limit_eval`] (exact evaluation) and [`obj_cage`] (reading
//! a cage from OBJ).
//! Doo–Sabin steps live with the polygon meshes of `splinekit-mesh`.

pub mod atlas;
pub mod bezier_patches;
pub mod bilinear;
pub mod box_spline;
pub mod cage;
pub mod catmull_clark;
pub mod creases;
pub mod limit_eval;
pub mod limit_masks;
pub mod local;
pub mod loop_bezier;
pub mod loop_scheme;
pub mod obj_cage;
mod regular_face;
pub mod regular_patch;
pub mod topology;

pub use atlas::{Chart, LimitAtlas};
pub use cage::{BoundaryRule, Cage, Crease, INFINITE_SHARPNESS};
pub use limit_eval::{LimitSample, Partials};
pub use limit_masks::LimitFrame;
pub use obj_cage::{ObjCage, read_obj_cage};
pub use topology::Topology;

use crate::{Error, Result};
use limit_eval::{EvalScheme, evaluate_local};
use limit_masks::MaskScheme;

/// A subdivision scheme.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Scheme {
    /// Catmull–Clark (any polygons; bicubic B-spline limit on regular quads).
    CatmullClark,
    /// Loop (triangles; quartic box-spline limit on regular triangles).
    Loop,
    /// Bilinear (the Catmull–Clark split with linear rules; limit: bilinear patches).
    Bilinear,
}

impl Scheme {
    /// The scheme's name in documents and on the command line.
    pub fn name(self) -> &'static str {
        match self {
            Scheme::CatmullClark => "catmull-clark",
            Scheme::Loop => "loop",
            Scheme::Bilinear => "bilinear",
        }
    }
}

/// A cage, its adjacency and a scheme.
#[derive(Debug, Clone)]
pub struct SubdivisionSurface {
    cage: Cage,
    topology: Topology,
    scheme: Scheme,
}

/// Refuses more than this many faces from [`SubdivisionSurface::subdivide`].
pub const MAX_FACES: usize = 20_000_000;

impl SubdivisionSurface {
    /// A surface; checks the cage (see [`Topology::new`]) and, for Loop, that every face is
    /// a triangle (set `triangulate` to split polygons into fans first).
    pub fn new(cage: Cage, scheme: Scheme, triangulate: bool) -> Result<Self> {
        let cage =
            if scheme == Scheme::Loop && triangulate && !cage.is_triangle_mesh() { cage.triangulated() } else { cage };
        let topology = Topology::new(&cage)?;
        if scheme == Scheme::Loop
            && let Some(f) = (0..cage.face_count()).find(|&f| cage.face(f).len() != 3)
        {
            return Err(Error::invalid(
                format!("faces[{f}]"),
                format!(
                    "Loop subdivision takes triangles, this face has {} vertices (ask for triangulation)",
                    cage.face(f).len()
                ),
            ));
        }
        Ok(SubdivisionSurface { cage, topology, scheme })
    }

    /// The cage.
    pub fn cage(&self) -> &Cage {
        &self.cage
    }
    /// The adjacency.
    pub fn topology(&self) -> &Topology {
        &self.topology
    }
    /// The scheme.
    pub fn scheme(&self) -> Scheme {
        self.scheme
    }

    /// One subdivision step (vertex i of the cage stays vertex i).
    pub fn step(&self) -> Result<SubdivisionSurface> {
        let cage = match self.scheme {
            Scheme::CatmullClark => catmull_clark::catmull_clark_step(&self.cage, &self.topology),
            Scheme::Bilinear => bilinear::bilinear_step(&self.cage, &self.topology),
            Scheme::Loop => loop_scheme::loop_step(&self.cage, &self.topology)?,
        };
        let topology = Topology::new(&cage)?;
        Ok(SubdivisionSurface { cage, topology, scheme: self.scheme })
    }

    /// `steps` steps, refusing results of more than [`MAX_FACES`] faces.
    pub fn subdivide(&self, steps: usize) -> Result<SubdivisionSurface> {
        let mut s = self.clone();
        for k in 0..steps {
            let next_faces = match self.scheme {
                Scheme::Loop => s.cage.face_count() * 4,
                _ => s.cage.face_vertices.len(),
            };
            if next_faces > MAX_FACES {
                return Err(Error::invalid(
                    "steps",
                    format!("step {} of {steps} would make {next_faces} faces, more than {MAX_FACES}", k + 1),
                ));
            }
            s = s.step()?;
        }
        Ok(s)
    }

    fn mask_scheme(&self) -> Option<MaskScheme> {
        match self.scheme {
            Scheme::CatmullClark => Some(MaskScheme::CatmullClark),
            Scheme::Loop => Some(MaskScheme::Loop),
            Scheme::Bilinear => None,
        }
    }

    /// The limit point and tangent plane of vertex v: the limit mask where it applies,
    /// else the mask at v's child after subdividing v's star until it applies (semi-sharp
    /// edges decayed, every face a quad). Bilinear: the vertex itself, with the normal of
    /// the summed corner cross products.
    pub fn limit_frame(&self, v: u32) -> Result<LimitFrame> {
        let topo = &self.topology;
        if v as usize >= self.cage.vertices.len() {
            return Err(Error::invalid(
                "vertex",
                format!("{v} does not exist (there are {})", self.cage.vertices.len()),
            ));
        }
        let Some(ms) = self.mask_scheme() else {
            let p = self.cage.vertices[v as usize];
            let mut n = crate::Point::<3>::zeros();
            for &h in topo.outgoing(v) {
                let a = self.cage.vertices[topo.dest(h) as usize] - p;
                let b = self.cage.vertices[topo.origin(topo.prev(h)) as usize] - p;
                n += a.cross(&b);
            }
            let len = n.norm();
            return Ok(LimitFrame {
                position: p,
                tangent1: crate::Point::<3>::zeros(),
                tangent2: crate::Point::<3>::zeros(),
                normal: if len > 0.0 { n / len } else { n },
            });
        };
        if topo.outgoing(v).is_empty() {
            return Err(Error::invalid(format!("vertices[{v}]"), "the vertex is in no face, it has no limit"));
        }
        if limit_masks::mask_ready(topo, v, ms) {
            return Ok(limit_masks::limit_frame(&self.cage, topo, v, ms));
        }
        let (mut cage, map) = local::sub_cage(&self.cage, topo, &local::star_faces(topo, v));
        let mut c = map[&v];
        for _ in 0..64 {
            let t = Topology::new(&cage)?;
            if limit_masks::mask_ready(&t, c, ms) {
                return Ok(limit_masks::limit_frame(&cage, &t, c, ms));
            }
            let (star, map) = local::sub_cage(&cage, &t, &local::star_faces(&t, c));
            let st = Topology::new(&star)?;
            c = map[&c];
            cage = match ms {
                MaskScheme::CatmullClark => catmull_clark::catmull_clark_step(&star, &st),
                MaskScheme::Loop => loop_scheme::loop_step(&star, &st)?,
            };
        }
        Err(Error::invalid(format!("vertices[{v}]"), "the limit masks did not apply after 64 local steps"))
    }

    /// The limit normal at every face corner (`face_offsets` order): the vertex's normal,
    /// except at a vertex where sharp edges split the surface, where each corner takes the
    /// normal of its own side of the crease.
    pub fn limit_corner_normals(&self, frames: &[LimitFrame]) -> Vec<crate::Point<3>> {
        let topo = &self.topology;
        let ms = self.mask_scheme();
        (0..self.cage.face_vertices.len() as u32)
            .map(|h| {
                let v = topo.origin(h);
                let frame = frames[v as usize];
                let split = !topo.vertex_boundary[v as usize]
                    && topo.vertex_edges(v).iter().filter(|&&(e, _)| topo.sharpness[e as usize] > 0.0).count() >= 2;
                match ms {
                    Some(ms) if split && limit_masks::mask_ready(topo, v, ms) => {
                        let k = topo.outgoing(v).iter().position(|&x| x == h).unwrap_or(0);
                        limit_masks::limit_frame_in_sector(&self.cage, topo, v, ms, k).normal
                    }
                    _ => frame.normal,
                }
            })
            .collect()
    }

    /// Limit frames of all vertices, in order.
    pub fn limit_frames(&self) -> Result<Vec<LimitFrame>> {
        (0..self.cage.vertices.len() as u32).map(|v| self.limit_frame(v)).collect()
    }

    /// The limit surface at (u, v) of face `face` (a quad for Catmull–Clark and bilinear,
    /// a triangle for Loop): exact, see [`limit_eval`].
    pub fn evaluate(&self, face: usize, u: f64, v: f64) -> Result<LimitSample> {
        self.check_face(face, u, v)?;
        let n = self.cage.face(face).len();
        let expected = if self.scheme == Scheme::Loop { 3 } else { 4 };
        if n != expected {
            return Err(Error::invalid(
                "face",
                format!(
                    "faces[{face}] has {n} vertices; (face, u, v) evaluation takes {} (use evaluate_subface for the quads of other polygons)",
                    if expected == 3 { "triangles" } else { "quads" }
                ),
            ));
        }
        self.evaluate_checked(&self.cage, &self.topology, face as u32, u, v)
    }

    /// The limit surface on the quad that corner `corner` of polygon `face` becomes after
    /// one Catmull–Clark or bilinear step (u from the corner towards the next edge's
    /// midpoint, v towards the previous edge's midpoint).
    pub fn evaluate_subface(&self, face: usize, corner: usize, u: f64, v: f64) -> Result<LimitSample> {
        self.check_face(face, u, v)?;
        if self.scheme == Scheme::Loop {
            return Err(Error::invalid("corner", "Loop faces are triangles: use evaluate"));
        }
        let n = self.cage.face(face).len();
        if corner >= n {
            return Err(Error::invalid("corner", format!("faces[{face}] has {n} corners, got {corner}")));
        }
        let ring = local::one_ring_faces(&self.topology, face as u32);
        let (sub, _) = local::sub_cage(&self.cage, &self.topology, &ring);
        let t = Topology::new(&sub)?;
        let child = match self.scheme {
            Scheme::Bilinear => bilinear::bilinear_step(&sub, &t),
            _ => catmull_clark::catmull_clark_step(&sub, &t),
        };
        let ct = Topology::new(&child)?;
        self.evaluate_checked(&child, &ct, corner as u32, u, v)
    }

    fn check_face(&self, face: usize, u: f64, v: f64) -> Result<()> {
        if face >= self.cage.face_count() {
            return Err(Error::invalid(
                "face",
                format!("{face} does not exist (there are {})", self.cage.face_count()),
            ));
        }
        let inside = if self.scheme == Scheme::Loop {
            u >= 0.0 && v >= 0.0 && u + v <= 1.0
        } else {
            (0.0..=1.0).contains(&u) && (0.0..=1.0).contains(&v)
        };
        if !inside {
            return Err(Error::invalid(
                "(u, v)",
                format!(
                    "({u}, {v}) is outside the face's domain ({})",
                    if self.scheme == Scheme::Loop { "u, v ≥ 0, u + v ≤ 1" } else { "[0, 1]²" }
                ),
            ));
        }
        Ok(())
    }

    fn evaluate_checked(&self, cage: &Cage, topo: &Topology, face: u32, u: f64, v: f64) -> Result<LimitSample> {
        let scheme = match self.scheme {
            Scheme::Bilinear => return Ok(bilinear_patch(cage, face, u, v)),
            Scheme::CatmullClark => EvalScheme::CatmullClark,
            Scheme::Loop => EvalScheme::Loop,
        };
        let ring = local::one_ring_faces(topo, face);
        let (sub, _) = local::sub_cage(cage, topo, &ring);
        evaluate_local(sub, 0, u, v, scheme, Some(regular_face::regular))
    }
}

/// The bilinear patch (1−u)(1−v)c₀ + u(1−v)c₁ + uv c₂ + (1−u)v c₃ of a quad.
fn bilinear_patch(cage: &Cage, face: u32, u: f64, v: f64) -> LimitSample {
    let c: Vec<crate::Point<3>> = cage.face(face as usize).iter().map(|&i| cage.vertices[i as usize]).collect();
    let position = c[0] * ((1.0 - u) * (1.0 - v)) + c[1] * (u * (1.0 - v)) + c[2] * (u * v) + c[3] * ((1.0 - u) * v);
    let du = (c[1] - c[0]) * (1.0 - v) + (c[2] - c[3]) * v;
    let dv = (c[3] - c[0]) * (1.0 - u) + (c[2] - c[1]) * u;
    let duv = c[0] - c[1] + c[2] - c[3];
    let n = du.cross(&dv);
    let len = n.norm();
    LimitSample {
        position,
        normal: if len > 0.0 { n / len } else { n },
        partials: Some(Partials { du, dv, duu: crate::Point::<3>::zeros(), duv, dvv: crate::Point::<3>::zeros() }),
    }
}
