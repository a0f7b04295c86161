//! Regular patches: where a face and its 1-ring are regular, the limit surface on the
//! face is a polynomial patch of fixed control points.
//!
//! - Catmull–Clark: a quad whose four corners are smooth of valence 4 is the uniform
//!   bicubic B-spline patch of its 4×4 neighbourhood (Catmull and Clark 1978). Along an
//!   infinitely sharp edge or boundary the same holds with the row beyond the edge
//!   replaced by phantom points 2pᵢ − qᵢ (the reflection through the edge row), which
//!   reproduces the crease rules (1, 6, 1)/8 and (1, 1)/2; a corner vertex between two
//!   sharp edges of the face takes both reflections. This is the construction of
//!   OpenSubdiv's regular boundary patches.
//! - Loop: a triangle whose three corners are smooth of valence 6 is the quartic
//!   three-direction box-spline patch of its 12 neighbours (Stam 1998), see
//!   [`super::box_spline`]. Along a boundary or infinitely sharp crease the same holds
//!   for a corner that is a regular crease vertex on the face's side (two sharp edges,
//!   three faces between them on that side, every other edge there smooth), with the two
//!   lattice points beyond the crease replaced by phantom points: across the crease edge
//!   (c, a) of the triangle (c, b, a), the point c + a − b, the reflection of b through the
//!   edge's midpoint. The smooth rules applied to these points reproduce the crease rules
//!   exactly: the edge point 3/8(c + a) + 1/8(b + c + a − b) = (c + a)/2, and the vertex
//!   point of c, 5/8 c + 1/16 Σ of its six neighbours, whose phantoms (c + a₀ − b₀) and
//!   (c + a₁ − b₁) cancel its two inner neighbours, = 3/4 c + 1/8 (a₀ + a₁); and the new
//!   phantoms are again reflections of the new points, so the box spline of the extended
//!   lattice is the limit on the crease side. The tests check this against the cubic
//!   B-spline limit of the crease and against global subdivision with limit masks.

use super::cage::Cage;
use super::creases::{VertexRule, is_boundary_corner, rule_for};
use super::topology::{NONE, Topology};
use crate::Point;

/// Sharpness class of an edge: Some(false) smooth, Some(true) infinitely sharp or
/// boundary, None semi-sharp.
fn class(topo: &Topology, e: u32) -> Option<bool> {
    let s = topo.edge_sharpness(e);
    if s == 0.0 {
        Some(false)
    } else if s.is_infinite() {
        Some(true)
    } else {
        None
    }
}

/// The 4×4 B-spline control grid (first index along u) of quad face f if it is regular,
/// with c₀ at grid (1, 1), c₁ at (2, 1), c₂ at (2, 2), c₃ at (1, 2).
pub fn catmull_clark_grid(cage: &Cage, topo: &Topology, f: u32) -> Option<[[Point<3>; 4]; 4]> {
    if topo.face_len(f) != 4 {
        return None;
    }
    let h0 = topo.face_start(f);
    let hs = [h0, h0 + 1, h0 + 2, h0 + 3];
    let mut sharp = [false; 4];
    for k in 0..4 {
        sharp[k] = class(topo, topo.he_edge[hs[k] as usize])?;
    }
    let quad = |h: u32| h != NONE && topo.face_len(topo.he_face[h as usize]) == 4;
    for k in 0..4 {
        let c = topo.origin(hs[k]);
        let mut n_sharp = 0;
        for (e, _) in topo.vertex_edges(c) {
            if class(topo, e)? {
                n_sharp += 1;
            }
        }
        let (a, b) = (sharp[k], sharp[(k + 3) % 4]);
        match rule_for(n_sharp, is_boundary_corner(topo, c, cage.boundary)) {
            VertexRule::Smooth => {
                if n_sharp != 0 || topo.outgoing(c).len() != 4 || !topo.outgoing(c).iter().all(|&h| quad(h)) {
                    return None;
                }
            }
            VertexRule::Crease => {
                if a == b {
                    return None;
                }
                if a {
                    // C and the face across h_{k−1}, then the crease goes on.
                    let t = topo.twin[hs[(k + 3) % 4] as usize];
                    if !quad(t) || !class(topo, topo.he_edge[topo.prev(t) as usize])? {
                        return None;
                    }
                } else {
                    let t = topo.twin[hs[k] as usize];
                    if !quad(t) || !class(topo, topo.he_edge[topo.next(t) as usize])? {
                        return None;
                    }
                }
            }
            VertexRule::Corner => {
                if !(a && b) {
                    return None;
                }
            }
        }
    }
    const P: [(i32, i32); 4] = [(1, 1), (2, 1), (2, 2), (1, 2)];
    const N: [(i32, i32); 4] = [(0, -1), (1, 0), (0, 1), (-1, 0)];
    let add = |a: (i32, i32), b: (i32, i32)| (a.0 + b.0, a.1 + b.1);
    let sub = |a: (i32, i32), b: (i32, i32)| (a.0 - b.0, a.1 - b.1);
    let mut g = [[Point::<3>::zeros(); 4]; 4];
    let vs = &cage.vertices;
    let set = |g: &mut [[Point<3>; 4]; 4], at: (i32, i32), p: Point<3>| g[at.0 as usize][at.1 as usize] = p;
    let get = |g: &[[Point<3>; 4]; 4], at: (i32, i32)| g[at.0 as usize][at.1 as usize];
    for k in 0..4 {
        set(&mut g, P[k], vs[topo.origin(hs[k]) as usize]);
    }
    for k in 0..4 {
        if !sharp[k] {
            let t = topo.twin[hs[k] as usize];
            set(&mut g, add(P[k], N[k]), vs[topo.dest(topo.next(t)) as usize]);
            set(&mut g, add(P[(k + 1) % 4], N[k]), vs[topo.dest(topo.next(topo.next(t))) as usize]);
        }
    }
    for k in 0..4 {
        if !sharp[k] && !sharp[(k + 3) % 4] {
            let t = topo.twin[hs[k] as usize];
            let s = topo.twin[topo.next(t) as usize];
            set(&mut g, add(add(P[k], N[k]), N[(k + 3) % 4]), vs[topo.dest(topo.next(topo.next(s))) as usize]);
        }
    }
    for k in 0..4 {
        if sharp[k] {
            for c in [P[k], P[(k + 1) % 4]] {
                let p = get(&g, c) * 2.0 - get(&g, sub(c, N[k]));
                set(&mut g, add(c, N[k]), p);
            }
        }
    }
    for k in 0..4 {
        let (nk, nl) = (N[k], N[(k + 3) % 4]);
        let q = add(add(P[k], nk), nl);
        if sharp[k] {
            let p = get(&g, sub(q, nk)) * 2.0 - get(&g, sub(sub(q, nk), nk));
            set(&mut g, q, p);
        } else if sharp[(k + 3) % 4] {
            let p = get(&g, sub(q, nl)) * 2.0 - get(&g, sub(sub(q, nl), nl));
            set(&mut g, q, p);
        }
    }
    Some(g)
}

/// The uniform cubic B-spline basis on [0, 1] and its first two derivatives:
/// B₀ = (1 − t)³/6, B₁ = (3t³ − 6t² + 4)/6, B₂ = (−3t³ + 3t² + 3t + 1)/6, B₃ = t³/6.
pub fn cubic_bspline_basis(t: f64) -> [[f64; 4]; 3] {
    let s = 1.0 - t;
    [
        [
            s * s * s / 6.0,
            (3.0 * t * t * t - 6.0 * t * t + 4.0) / 6.0,
            (-3.0 * t * t * t + 3.0 * t * t + 3.0 * t + 1.0) / 6.0,
            t * t * t / 6.0,
        ],
        [-s * s / 2.0, 1.5 * t * t - 2.0 * t, -1.5 * t * t + t + 0.5, t * t / 2.0],
        [s, 3.0 * t - 2.0, 1.0 - 3.0 * t, t],
    ]
}

/// The 12 control points of triangle f (Loop) if its limit is a box-spline patch: every
/// corner a smooth interior vertex of valence 6 or a regular crease vertex on the face's
/// side, whose two lattice points beyond the crease are phantom points (see the module
/// doc). In the order of the basis of [`super::box_spline`]: the corners c₀, c₁, c₂, then
/// for each corner k the three lattice neighbours of cₖ outside the face that follow,
/// counter-clockwise, the edge to cₖ₋₁.
pub fn loop_control_points(cage: &Cage, topo: &Topology, f: u32) -> Option<[Point<3>; 12]> {
    if topo.face_len(f) != 3 {
        return None;
    }
    let h0 = topo.face_start(f);
    let mut r = [Point::<3>::zeros(); 12];
    for k in 0..3u32 {
        let c = topo.origin(h0 + k);
        let ring = lattice_ring(cage, topo, c, h0 + k)?;
        r[k as usize] = cage.vertices[c as usize];
        for m in 0..3 {
            r[3 + 3 * k as usize + m] = ring[2 + m];
        }
    }
    Some(r)
}

/// The six lattice neighbours of corner c counter-clockwise, starting at the end of its
/// outgoing half-edge h (so the face of h lies between the first two), or None if c is
/// not regular on that face's side.
fn lattice_ring(cage: &Cage, topo: &Topology, c: u32, h: u32) -> Option<[Point<3>; 6]> {
    let vs = &cage.vertices;
    let edges = topo.vertex_edges(c);
    let n = edges.len();
    let mut classes = Vec::with_capacity(n);
    for &(e, _) in &edges {
        classes.push(class(topo, e)?);
    }
    let i = topo.outgoing(c).iter().position(|&x| x == h)?;
    let n_sharp = classes.iter().filter(|&&s| s).count();
    if n_sharp == 0 {
        if topo.vertex_boundary[c as usize] || n != 6 {
            return None;
        }
        return Some(std::array::from_fn(|m| vs[edges[(i + m) % 6].1 as usize]));
    }
    if rule_for(n_sharp, is_boundary_corner(topo, c, cage.boundary)) != VertexRule::Crease {
        return None;
    }
    // The sector of h's face: from the last sharp edge at or before edge i to the first
    // sharp edge after it; a boundary vertex's edges do not wrap around.
    let wraps = !topo.vertex_boundary[c as usize];
    let step = |j: usize, forward: bool| -> Option<usize> {
        match (forward, wraps) {
            (true, true) => Some((j + 1) % n),
            (false, true) => Some((j + n - 1) % n),
            (true, false) => (j + 1 < n).then_some(j + 1),
            (false, false) => j.checked_sub(1),
        }
    };
    let mut start = i;
    while !classes[start] {
        start = step(start, false)?;
    }
    let mut sector = vec![start];
    let mut j = start;
    loop {
        j = step(j, true)?;
        sector.push(j);
        if classes[j] || sector.len() > 4 {
            break;
        }
    }
    if sector.len() != 4 || !classes[sector[3]] {
        return None;
    }
    let p = |m: usize| vs[edges[sector[m]].1 as usize];
    let centre = vs[c as usize];
    let lattice = [p(0), p(1), p(2), p(3), centre + p(3) - p(2), centre + p(0) - p(1)];
    let offset = sector.iter().position(|&x| x == i)?;
    Some(std::array::from_fn(|m| lattice[(offset + m) % 6]))
}
