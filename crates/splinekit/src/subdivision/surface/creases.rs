//! Crease rules shared by the schemes (DeRose, Kass and Truong 1998; OpenSubdiv's
//! `Sdc::Crease`, uniform sharpness decay).
//!
//! - An edge of sharpness s takes the crease rule (midpoint) while s ≥ 1, a blend
//!   s·crease + (1 − s)·smooth when 0 < s < 1, the smooth rule when s = 0; its two child
//!   edges get sharpness max(s − 1, 0) (infinite stays infinite). Boundary edges are
//!   infinitely sharp.
//! - A vertex's rule follows the number of sharp (s > 0) edges at it: 0 smooth, 1 dart
//!   (smooth masks), 2 crease ((e₀ + 6v + e₁)/8 with the two crease neighbours), 3 or
//!   more corner (v stays); a boundary vertex of a single face under the "edge and corner"
//!   rule is a corner.
//! - When the rule of the parent (sharpness s) and of the child (sharpness s − 1) differ,
//!   the vertex point is w·parent + (1 − w)·child with w the mean parent sharpness of the
//!   edges that turn smooth, clamped to 1 (OpenSubdiv's fractional weight).

use super::cage::BoundaryRule;
use super::topology::Topology;
use crate::Point;

/// The rule a vertex takes.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum VertexRule {
    /// No sharp edge (or one: a dart): the scheme's smooth rule.
    Smooth,
    /// Two sharp edges: the crease rule.
    Crease,
    /// Three or more sharp edges, or a boundary corner: the vertex stays.
    Corner,
}

/// Sharpness of the child edges of an edge of sharpness s (uniform decay).
pub fn child_sharpness(s: f64) -> f64 {
    if s.is_infinite() { s } else { (s - 1.0).max(0.0) }
}

/// The rule for `sharp` sharp edges at a vertex (`corner`: forced corner).
pub fn rule_for(sharp: usize, corner: bool) -> VertexRule {
    if corner || sharp >= 3 {
        VertexRule::Corner
    } else if sharp == 2 {
        VertexRule::Crease
    } else {
        VertexRule::Smooth
    }
}

/// Whether vertex v is a corner by the boundary rule.
pub fn is_boundary_corner(topo: &Topology, v: u32, rule: BoundaryRule) -> bool {
    rule == BoundaryRule::EdgeAndCorner && topo.vertex_boundary[v as usize] && topo.outgoing(v).len() == 1
}

/// The new position of vertex v (at `p`, with edges `edges` = (edge, neighbour) around
/// it), given the scheme's smooth rule.
pub fn vertex_point(
    topo: &Topology,
    vertices: &[Point<3>],
    v: u32,
    edges: &[(u32, u32)],
    corner: bool,
    smooth: impl Fn() -> Point<3>,
) -> Point<3> {
    let p = vertices[v as usize];
    let s: Vec<f64> = edges.iter().map(|&(e, _)| topo.edge_sharpness(e)).collect();
    let parent = rule_for(s.iter().filter(|&&x| x > 0.0).count(), corner);
    let child = rule_for(s.iter().filter(|&&x| child_sharpness(x) > 0.0).count(), corner);
    let mask = |rule: VertexRule, level: &dyn Fn(f64) -> f64| -> Point<3> {
        match rule {
            VertexRule::Smooth => smooth(),
            VertexRule::Corner => p,
            VertexRule::Crease => {
                let mut sum = p * 6.0;
                for (k, &(_, w)) in edges.iter().enumerate() {
                    if level(s[k]) > 0.0 {
                        sum += vertices[w as usize];
                    }
                }
                sum / 8.0
            }
        }
    };
    if parent == child {
        return mask(parent, &|x| x);
    }
    let (mut sum, mut count) = (0.0, 0usize);
    for &x in &s {
        if x > 0.0 && child_sharpness(x) <= 0.0 {
            sum += x;
            count += 1;
        }
    }
    let w = if count == 0 { 0.0 } else { (sum / count as f64).min(1.0) };
    mask(parent, &|x| x) * w + mask(child, &child_sharpness) * (1.0 - w)
}

/// The vertex points of every vertex of a cage, in the cage's order, pushed onto `out`: a
/// vertex without edges stays; the others move by [`vertex_point`], with the boundary rule
/// `boundary` and the scheme's smooth rule `smooth(v, edges)` (`edges` = (edge, neighbour)
/// around v).
pub fn vertex_points(
    topo: &Topology,
    vertices: &[Point<3>],
    boundary: BoundaryRule,
    out: &mut Vec<Point<3>>,
    smooth: impl Fn(u32, &[(u32, u32)]) -> Point<3>,
) {
    let mut edges = Vec::new();
    for v in 0..vertices.len() as u32 {
        if topo.outgoing(v).is_empty() {
            out.push(vertices[v as usize]);
            continue;
        }
        edges.clear();
        edges.extend(topo.vertex_edges(v));
        let corner = is_boundary_corner(topo, v, boundary);
        out.push(vertex_point(topo, vertices, v, &edges, corner, || smooth(v, &edges)));
    }
}

/// The new position of an edge's point given its crease (midpoint) and smooth points.
pub fn edge_point(sharpness: f64, crease: Point<3>, smooth: impl Fn() -> Point<3>) -> Point<3> {
    if sharpness >= 1.0 {
        crease
    } else if sharpness <= 0.0 {
        smooth()
    } else {
        crease * sharpness + smooth() * (1.0 - sharpness)
    }
}
