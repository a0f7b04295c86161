//! Limit masks: the point of the limit surface at a vertex and two tangents spanning its
//! tangent plane, as weights of the vertex's 1-ring (Halstead, Kass and DeRose 1993 for
//! Catmull–Clark, Hoppe et al. 1994 for Loop, Biermann et al. 2000 for the
//! crease/boundary cross tangents, with the weights as OpenSubdiv's `Sdc` writes them).
//!
//! Catmull–Clark, at a vertex of n quads with edge neighbours eᵢ and diagonal corners dᵢ
//! (face i between edges i and i + 1, counter-clockwise), θ = 2π/n:
//! - smooth: x∞ = (n²v + 4Σeᵢ + Σdᵢ)/(n(n + 5));
//!   t₁ = Σ 4cos(iθ) eᵢ + (cos(iθ) + cos((i+1)θ))/(4λ − 1) dᵢ, t₂ the same mask turned by
//!   one edge, λ = 5/16 + (cos θ + cos(θ/2)√(2(9 + cos θ)))/16 the subdominant eigenvalue;
//! - crease (sharp edges i < j): x∞ = (eᵢ + 4v + eⱼ)/6 (the cubic B-spline of the crease
//!   polygon), t₁ = (eᵢ − eⱼ)/2 along the crease, t₂ across the faces i..j−1;
//! - corner: x∞ = v, t₁ = eᵢ − v, t₂ = eⱼ − v.
//!
//! Loop, at a vertex of valence n: smooth x∞ = (ωv + Σeᵢ)/(ω + n) with ω = 3/(8β),
//! t₁ = Σcos(iθ)eᵢ, t₂ = Σsin(iθ)eᵢ; crease and corner as for Catmull–Clark with Loop's
//! cross tangents.
//!
//! The normal is t₁ × t₂ normalised (outward for counter-clockwise faces). A mask applies
//! when every edge at the vertex is smooth or infinitely sharp (and, for Catmull–Clark,
//! every face at it a quad); [`super::SubdivisionSurface::limit_frame`] subdivides the
//! vertex's star until it does.

use std::f64::consts::PI;

use super::cage::Cage;
use super::creases::{VertexRule, is_boundary_corner, rule_for};
use super::loop_scheme::loop_beta;
use super::topology::Topology;
use crate::Point;

/// The limit point of a vertex and its tangent plane.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LimitFrame {
    /// Point of the limit surface.
    pub position: Point<3>,
    /// First tangent (scaled as the mask gives it).
    pub tangent1: Point<3>,
    /// Second tangent.
    pub tangent2: Point<3>,
    /// Unit normal t₁ × t₂ / |t₁ × t₂| (zero where the tangents are parallel).
    pub normal: Point<3>,
}

/// Which masks to use.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum MaskScheme {
    /// Catmull–Clark.
    CatmullClark,
    /// Loop.
    Loop,
}

/// Whether the masks apply at vertex v as it is.
pub fn mask_ready(topo: &Topology, v: u32, scheme: MaskScheme) -> bool {
    let edges_ok = topo.vertex_edges(v).iter().all(|&(e, _)| {
        let s = topo.edge_sharpness(e);
        s == 0.0 || s.is_infinite()
    });
    let faces_ok =
        scheme == MaskScheme::Loop || topo.outgoing(v).iter().all(|&h| topo.face_len(topo.he_face[h as usize]) == 4);
    edges_ok && faces_ok && !topo.outgoing(v).is_empty()
}

/// The limit frame at v (call only where [`mask_ready`] holds). At an interior crease or
/// corner vertex the tangent plane is that of the sector counter-clockwise after its first
/// sharp edge; [`limit_frame_in_sector`] gives the others.
pub fn limit_frame(cage: &Cage, topo: &Topology, v: u32, scheme: MaskScheme) -> LimitFrame {
    limit_frame_in_sector(cage, topo, v, scheme, 0)
}

/// The limit frame at v on the side of the face of v's outgoing half-edge number `corner`
/// (counter-clockwise order): where sharp edges split the surface at v into sectors, each
/// has its own tangent plane (the position is the same).
pub fn limit_frame_in_sector(cage: &Cage, topo: &Topology, v: u32, scheme: MaskScheme, corner: usize) -> LimitFrame {
    let vs = &cage.vertices;
    let p = vs[v as usize];
    let mut edges = topo.vertex_edges(v);
    let mut out = topo.outgoing(v).to_vec();
    if !topo.vertex_boundary[v as usize] && !out.is_empty() {
        // Turn the fan so that it starts at the last sharp edge at or before `corner`.
        let n = out.len();
        let k = corner % n;
        if let Some(s0) = (0..n).map(|d| (k + n - d) % n).find(|&i| topo.edge_sharpness(edges[i].0) > 0.0) {
            edges.rotate_left(s0);
            out.rotate_left(s0);
        }
    }
    let e = |i: usize| vs[edges[i].1 as usize];
    let d = |i: usize| vs[topo.dest(topo.next(out[i])) as usize];
    let sharp: Vec<usize> = (0..edges.len()).filter(|&i| topo.edge_sharpness(edges[i].0) > 0.0).collect();
    let rule = rule_for(sharp.len(), is_boundary_corner(topo, v, cage.boundary));
    let zero = Point::<3>::zeros();
    let (position, t1, t2) = match rule {
        VertexRule::Smooth => {
            let n = edges.len();
            let nf = n as f64;
            let theta = 2.0 * PI / nf;
            match scheme {
                MaskScheme::CatmullClark => {
                    let mut pos = p * (nf * nf);
                    let lambda =
                        5.0 / 16.0 + (theta.cos() + (theta / 2.0).cos() * (2.0 * (9.0 + theta.cos())).sqrt()) / 16.0;
                    let fs = 1.0 / (4.0 * lambda - 1.0);
                    let (mut t1, mut t2) = (zero, zero);
                    for i in 0..n {
                        pos += e(i) * 4.0 + d(i);
                        let ew = |k: usize| 4.0 * (k as f64 * theta).cos();
                        let fw = |k: usize| fs * ((k as f64 * theta).cos() + ((k + 1) as f64 * theta).cos());
                        t1 += e(i) * ew(i) + d(i) * fw(i);
                        let j = (i + n - 1) % n;
                        t2 += e(i) * ew(j) + d(i) * fw(j);
                    }
                    (pos / (nf * (nf + 5.0)), t1, t2)
                }
                MaskScheme::Loop => {
                    let omega = 3.0 / (8.0 * loop_beta(n));
                    let mut pos = p * omega;
                    let (mut t1, mut t2) = (zero, zero);
                    for i in 0..n {
                        pos += e(i);
                        t1 += e(i) * (i as f64 * theta).cos();
                        t2 += e(i) * (i as f64 * theta).sin();
                    }
                    (pos / (omega + nf), t1, t2)
                }
            }
        }
        VertexRule::Crease => {
            let (i, j) = (sharp[0], sharp[1]);
            let pos = (e(i) + p * 4.0 + e(j)) / 6.0;
            let interior = j - i - 1;
            match scheme {
                MaskScheme::CatmullClark => {
                    let t1 = (e(i) - e(j)) * 0.5;
                    let t2 = if interior == 1 {
                        (-p * 4.0 - e(i) + e(i + 1) * 4.0 - e(j) + d(i) + d(i + 1)) / 6.0
                    } else if interior > 1 {
                        let k = (interior + 1) as f64;
                        let th = PI / k;
                        let denom = 1.0 / (k * (3.0 + th.cos()));
                        let r = (th.cos() + 1.0) / th.sin();
                        let mut t = p * (4.0 * r * (th.cos() - 1.0) * denom)
                            + (e(i) + e(j)) * (-r * (1.0 + 2.0 * th.cos()) * denom);
                        t += d(i) * (th.sin() * denom);
                        for m in 1..=interior {
                            let (s0, s1) = ((m as f64 * th).sin(), ((m + 1) as f64 * th).sin());
                            t += e(i + m) * (4.0 * s0 * denom) + d(i + m) * ((s0 + s1) * denom);
                        }
                        t
                    } else {
                        (e(i) + e(j)) * 3.0 - p * 6.0
                    };
                    (pos, t1, t2)
                }
                MaskScheme::Loop => {
                    let t1 = (e(i) - e(j)) * 1.5;
                    let t2 = match interior {
                        0 => (e(i) + e(j)) * 3.0 - p * 6.0,
                        1 => e(i + 1) * 3.0 - p * 3.0,
                        2 => {
                            let r3 = 3f64.sqrt();
                            -p * r3 - (e(i) + e(j)) * (r3 / 2.0) + (e(i + 1) + e(i + 2)) * r3
                        }
                        _ => {
                            let th = PI / (interior + 1) as f64;
                            let mut t = (e(i) + e(j)) * (-3.0 * th.sin());
                            let c = -6.0 * (th.cos() - 1.0);
                            for m in 1..=interior {
                                t += e(i + m) * (c * (m as f64 * th).sin());
                            }
                            t
                        }
                    };
                    (pos, t1, t2)
                }
            }
        }
        VertexRule::Corner => {
            let (i, j) = if sharp.len() >= 2 { (sharp[0], sharp[1]) } else { (0, edges.len() - 1) };
            (p, e(i) - p, e(j) - p)
        }
    };
    let c = t1.cross(&t2);
    let len = c.norm();
    LimitFrame { position, tangent1: t1, tangent2: t2, normal: if len > 0.0 { c / len } else { zero } }
}
