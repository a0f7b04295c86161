//! Exact evaluation of the limit surface at (face, u, v).
//!
//! The method is local subdivision (the alternative to Stam's eigenstructure evaluation
//! named in Stam 1998): while the face is not regular, cut out its 1-ring, subdivide it
//! once (see [`super::local`]), move to the child face containing (u, v) and map (u, v)
//! into it. Each child halves the parameter distances, so after about log₂(1/d) steps a
//! point at distance d from an irregular corner lies in a regular child, where the limit
//! is a polynomial patch evaluated exactly ([`super::regular_patch`]). A point that is
//! itself an irregular vertex (still a corner of an irregular child two steps after it
//! became a corner) takes the vertex's limit mask (position and normal; the parametric
//! partials do not exist there). Partials are carried back through the affine
//! maps: with child = A·parent + b, ∂ₐP = Σ_c A_ca ∂_cP′ and ∂ₐ∂_bP = Σ A_ca A_db ∂_c∂_dP′.
//!
//! Parameters: Catmull–Clark and bilinear quads (c₀, c₁, c₂, c₃) put c₀ at (0, 0), c₁ at
//! (1, 0), c₂ at (1, 1), c₃ at (0, 1); Loop triangles put c₀ at (0, 0), c₁ at (1, 0),
//! c₂ at (0, 1) with u, v ≥ 0, u + v ≤ 1.

use super::cage::Cage;
use super::catmull_clark::catmull_clark_step;
use super::limit_masks::{MaskScheme, limit_frame_in_sector, mask_ready};
use super::local::{one_ring_faces, sub_cage};
use super::loop_scheme::loop_step;
use super::topology::Topology;
use crate::{Error, Point, Result};

/// Parametric partials of the limit surface.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Partials {
    /// ∂P/∂u.
    pub du: Point<3>,
    /// ∂P/∂v.
    pub dv: Point<3>,
    /// ∂²P/∂u².
    pub duu: Point<3>,
    /// ∂²P/∂u∂v.
    pub duv: Point<3>,
    /// ∂²P/∂v².
    pub dvv: Point<3>,
}

/// A point of the limit surface.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LimitSample {
    /// The point.
    pub position: Point<3>,
    /// Unit normal (∂u × ∂v normalised, or the limit mask's normal at an irregular vertex).
    pub normal: Point<3>,
    /// The partials, except at an irregular vertex, where they do not exist.
    pub partials: Option<Partials>,
}

/// The scheme for evaluation.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum EvalScheme {
    /// Catmull–Clark.
    CatmullClark,
    /// Loop.
    Loop,
}

/// Local subdivision stops here and takes the nearest corner's limit mask: the distance
/// in parameter is then below 2⁻¹²⁰, and the point within λ¹²⁰ ≤ 0.66¹²⁰ ≈ 10⁻²² of it
/// in units of the cage. A safety net: every point reaches a regular patch (borders and
/// infinitely sharp creases included, through phantom points) or an irregular corner
/// long before, after about log₂(1/d) steps at parameter distance d from the corner.
const MAX_LEVELS: usize = 120;

fn unit(c: Point<3>) -> Point<3> {
    let n = c.norm();
    if n > 0.0 { c / n } else { Point::<3>::zeros() }
}

/// Position and partials [P, Pu, Pv, Puu, Puv, Pvv] on a regular face, or None: the
/// polynomial patches of `regular_face.rs`, passed in so that this file does not
/// depend on the box-spline basis, which is itself derived by evaluating here without them.
pub(crate) type RegularFace = fn(&Cage, &Topology, u32, EvalScheme, f64, f64) -> Option<[Point<3>; 6]>;

/// Evaluates the limit of `cage` on face `face` at (u, v) by local subdivision
/// (`patches` None: never the polynomial patches, only masks at corners — used to
/// derive the box-spline basis).
pub(crate) fn evaluate_local(
    mut cage: Cage,
    mut face: u32,
    mut u: f64,
    mut v: f64,
    scheme: EvalScheme,
    patches: Option<RegularFace>,
) -> Result<LimitSample> {
    // jac[c][a] = ∂(child coordinate c)/∂(root coordinate a).
    let mut jac = [[1.0, 0.0], [0.0, 1.0]];
    let mut offset = Point::<3>::zeros();
    let mut corner_levels = 0;
    let mask_scheme = match scheme {
        EvalScheme::CatmullClark => MaskScheme::CatmullClark,
        EvalScheme::Loop => MaskScheme::Loop,
    };
    let corners: &[(f64, f64)] = match scheme {
        EvalScheme::CatmullClark => &[(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)],
        EvalScheme::Loop => &[(0.0, 0.0), (1.0, 0.0), (0.0, 1.0)],
    };
    for level in 0..=MAX_LEVELS {
        let topo = Topology::new(&cage)?;
        if let Some(regular) = patches
            && let Some(local) = regular(&cage, &topo, face, scheme, u, v)
        {
            let mut r = to_root(local, jac);
            r.position += offset;
            return Ok(r);
        }
        let nearest = (0..corners.len())
            .min_by(|&a, &b| {
                let d = |k: usize| (corners[k].0 - u).abs() + (corners[k].1 - v).abs();
                d(a).total_cmp(&d(b))
            })
            .unwrap_or(0);
        let at_corner = corners[nearest] == (u, v);
        let vertex = topo.origin(topo.face_start(face) + nearest as u32);
        if at_corner {
            corner_levels += 1;
        }
        // At a corner, two more steps put a regular vertex inside a regular patch (with
        // partials); a vertex still irregular then never will be, and takes its mask.
        if ((at_corner && (corner_levels > 2 || patches.is_none())) || level == MAX_LEVELS)
            && mask_ready(&topo, vertex, mask_scheme)
        {
            // The tangent plane on this face's side of any crease through the vertex.
            let h = topo.face_start(face) + nearest as u32;
            let sector = topo.outgoing(vertex).iter().position(|&x| x == h).unwrap_or(0);
            let f = limit_frame_in_sector(&cage, &topo, vertex, mask_scheme, sector);
            return Ok(LimitSample { position: f.position + offset, normal: f.normal, partials: None });
        }
        let ring = one_ring_faces(&topo, face);
        let (mut local, _) = sub_cage(&cage, &topo, &ring);
        // Subdivision commutes with translation: keep the neighbourhood near the origin so
        // its shrinking differences keep their relative precision (tangents at deep levels).
        let o = local.vertices[0];
        for p in &mut local.vertices {
            *p -= o;
        }
        offset += o;
        let local_topo = Topology::new(&local)?;
        // Face 0 of `local` is `face`; its children come first in the refined cage.
        let (child, a, b) = match scheme {
            EvalScheme::CatmullClark => {
                cage = catmull_clark_step(&local, &local_topo);
                quad_child(u, v)
            }
            EvalScheme::Loop => {
                cage = loop_step(&local, &local_topo)?;
                triangle_child(u, v)
            }
        };
        let (nu, nv) = (a[0][0] * u + a[0][1] * v + b.0, a[1][0] * u + a[1][1] * v + b.1);
        u = nu.clamp(0.0, 1.0);
        v = nv.clamp(0.0, 1.0);
        jac = [
            [a[0][0] * jac[0][0] + a[0][1] * jac[1][0], a[0][0] * jac[0][1] + a[0][1] * jac[1][1]],
            [a[1][0] * jac[0][0] + a[1][1] * jac[1][0], a[1][0] * jac[0][1] + a[1][1] * jac[1][1]],
        ];
        face = child;
    }
    Err(Error::invalid(
        "(u, v)",
        format!("the limit at ({u}, {v}) was not reached in {MAX_LEVELS} local subdivision steps"),
    ))
}

pub(crate) type Affine = (u32, [[f64; 2]; 2], (f64, f64));

/// The child quad of a Catmull–Clark quad containing (u, v) and the map into it.
pub(crate) fn quad_child(u: f64, v: f64) -> Affine {
    match (u > 0.5, v > 0.5) {
        (false, false) => (0, [[2.0, 0.0], [0.0, 2.0]], (0.0, 0.0)),
        (true, false) => (1, [[0.0, 2.0], [-2.0, 0.0]], (0.0, 2.0)),
        (true, true) => (2, [[-2.0, 0.0], [0.0, -2.0]], (2.0, 2.0)),
        (false, true) => (3, [[0.0, -2.0], [2.0, 0.0]], (2.0, 0.0)),
    }
}

/// The child triangle of a Loop triangle containing (u, v) and the map into it.
pub(crate) fn triangle_child(u: f64, v: f64) -> Affine {
    if u + v <= 0.5 {
        (0, [[2.0, 0.0], [0.0, 2.0]], (0.0, 0.0))
    } else if u >= 0.5 {
        (1, [[2.0, 0.0], [0.0, 2.0]], (-1.0, 0.0))
    } else if v >= 0.5 {
        (2, [[2.0, 0.0], [0.0, 2.0]], (0.0, -1.0))
    } else {
        (3, [[-2.0, 0.0], [0.0, -2.0]], (1.0, 1.0))
    }
}

/// Carries local partials back to the root parameters.
fn to_root(l: [Point<3>; 6], j: [[f64; 2]; 2]) -> LimitSample {
    let first = |a: usize| l[1] * j[0][a] + l[2] * j[1][a];
    let second = |c: usize, d: usize| match (c, d) {
        (0, 0) => l[3],
        (1, 1) => l[5],
        _ => l[4],
    };
    let hess = |a: usize, b: usize| {
        let mut s = Point::<3>::zeros();
        for c in 0..2 {
            for d in 0..2 {
                s += second(c, d) * (j[c][a] * j[d][b]);
            }
        }
        s
    };
    let p = Partials { du: first(0), dv: first(1), duu: hess(0, 0), duv: hess(0, 1), dvv: hess(1, 1) };
    LimitSample { position: l[0], normal: unit(p.du.cross(&p.dv)), partials: Some(p) }
}
