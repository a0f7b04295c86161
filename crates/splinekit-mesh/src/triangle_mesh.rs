//! Indexed triangle meshes: positions, unit normals, optional (u, v) and colours, and
//! counter-clockwise triangles (seen from the side the normals point to).

use splinekit::Point;
use splinekit::query::Aabb;

/// An indexed triangle mesh.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct TriangleMesh {
    /// Vertex positions.
    pub positions: Vec<[f64; 3]>,
    /// Unit vertex normals (one per position, or empty).
    pub normals: Vec<[f64; 3]>,
    /// Surface parameters (u, v) per vertex, normalised to [0, 1] over the domain, or empty.
    pub uvs: Vec<[f64; 2]>,
    /// Linear RGBA colours per vertex, or empty.
    pub colors: Vec<[f32; 4]>,
    /// Triangles as vertex indices, counter-clockwise around their normal.
    pub triangles: Vec<[u32; 3]>,
}

impl TriangleMesh {
    /// Number of vertices.
    pub fn vertex_count(&self) -> usize {
        self.positions.len()
    }
    /// The unit normal of triangle t (zero for a degenerate triangle).
    pub fn face_normal(&self, t: usize) -> [f64; 3] {
        let [a, b, c] = self.triangles[t].map(|i| v3(self.positions[i as usize]));
        unit_or_zero(face_cross(a, b, c))
    }
    /// Twice the area of triangle t.
    pub fn double_area(&self, t: usize) -> f64 {
        let [a, b, c] = self.triangles[t].map(|i| v3(self.positions[i as usize]));
        (b - a).cross(&(c - a)).norm()
    }
    /// Total surface area.
    pub fn area(&self) -> f64 {
        (0..self.triangles.len()).map(|t| 0.5 * self.double_area(t)).sum()
    }
    /// The axis-aligned bounding box of the positions ([`Aabb::spanning`]: NaN coordinates
    /// passed over); `None` for an empty mesh.
    pub fn bounds(&self) -> Option<Aabb<3>> {
        Aabb::spanning(self.positions.iter().map(|p| Point::<3>::from(*p)))
    }
    /// The volume enclosed by a closed mesh, by the divergence theorem: Σ (a−o)·((b−o) × (c−o)) / 6
    /// over the triangles, o the first vertex (positive when the triangles face outward).
    pub fn signed_volume(&self) -> f64 {
        let Some(&o) = self.positions.first() else { return 0.0 };
        self.triangles
            .iter()
            .map(|t| {
                let [a, b, c] = t.map(|i| v3(self.positions[i as usize]) - v3(o));
                a.dot(&b.cross(&c)) / 6.0
            })
            .sum()
    }
    /// Gives every vertex whose normal is missing, not of unit length, or not on the side
    /// its triangles face (at a crease, the normal evaluated on one side can be
    /// perpendicular to the faces of the other) the area-weighted mean of the normals of
    /// the triangles around its position (or, where those cancel, the mean of its
    /// neighbours' normals); fills all normals that way when there are none. Vertices at
    /// the same position (the two sides of a seam) share the triangles around them.
    pub fn repair_normals(&mut self) {
        if self.normals.len() != self.positions.len() {
            self.normals = vec![[0.0; 3]; self.positions.len()];
        }
        let mut same_place: foldhash::HashMap<[u64; 3], usize> = foldhash::HashMap::default();
        let place: Vec<usize> = (0..self.positions.len())
            .map(|i| *same_place.entry(self.positions[i].map(f64::to_bits)).or_insert(i))
            .collect();
        // Each vertex's own triangles decide whether its normal is wrong; the triangles
        // around its position (both sides of a seam) give the replacement.
        let mut own = vec![[0.0; 3]; self.positions.len()];
        for t in &self.triangles {
            let [a, b, c] = t.map(|i| v3(self.positions[i as usize]));
            let n = face_cross(a, b, c).into();
            for &i in t {
                add(&mut own[i as usize], n);
            }
        }
        let mut fans = vec![[0.0; 3]; self.positions.len()];
        for (i, n) in own.iter().enumerate() {
            add(&mut fans[place[i]], *n);
        }
        let unit = |n: [f64; 3]| (v3(n).norm() - 1.0).abs() < 1e-6;
        let faces_along = |i: usize, n: [f64; 3]| v3(own[i]).dot(&v3(n)) > 0.0;
        let missing: Vec<bool> =
            self.normals.iter().enumerate().map(|(i, n)| !(unit(*n) && faces_along(i, *n))).collect();
        if !missing.iter().any(|&m| m) {
            return;
        }
        let mut neighbours = vec![[0.0; 3]; self.positions.len()];
        for t in &self.triangles {
            for (k, &i) in t.iter().enumerate() {
                for other in [t[(k + 1) % 3], t[(k + 2) % 3]] {
                    if !missing[other as usize] {
                        add(&mut neighbours[i as usize], self.normals[other as usize]);
                    }
                }
            }
        }
        for (i, m) in missing.iter().enumerate() {
            if *m {
                let around = unit_or_zero(v3(fans[place[i]]));
                let candidates = [around, unit_or_zero(v3(own[i])), unit_or_zero(v3(neighbours[i]))];
                self.normals[i] = candidates.into_iter().find(|n| unit(*n) && faces_along(i, *n)).unwrap_or(around);
            }
        }
    }
    /// Edges used by exactly one triangle (the boundary; empty for a closed surface).
    pub fn boundary_edges(&self) -> Vec<[u32; 2]> {
        let mut count = foldhash::HashMap::default();
        for t in &self.triangles {
            for k in 0..3 {
                let (a, b) = (t[k], t[(k + 1) % 3]);
                *count.entry((a.min(b), a.max(b))).or_insert(0usize) += 1;
            }
        }
        let mut edges: Vec<[u32; 2]> = count.into_iter().filter(|(_, c)| *c == 1).map(|((a, b), _)| [a, b]).collect();
        edges.sort_unstable();
        edges
    }
}

/// (b − a) × (c − a), twice the triangle's area along its normal; for triangles so large or
/// small that this over- or underflows, the same direction from edges scaled to unit size
/// (so sums of them stay finite).
fn face_cross(a: Point<3>, b: Point<3>, c: Point<3>) -> Point<3> {
    let n = (b - a).cross(&(c - a));
    let len = n.norm();
    if len.is_finite() && len > f64::MIN_POSITIVE {
        return n;
    }
    let unit = |v: Point<3>| {
        let m = v.iter().fold(0.0f64, |m, x| m.max(x.abs()));
        if m > 0.0 && m.is_finite() { v.map(|x| x / m) } else { Point::<3>::zeros() }
    };
    // Halve first so that the difference of two huge coordinates cannot overflow.
    let half = |p: Point<3>, q: Point<3>| Point::<3>::from_fn(|k, _| 0.5 * p[k] - 0.5 * q[k]);
    unit(half(b, a)).cross(&unit(half(c, a)))
}

fn add(acc: &mut [f64; 3], v: [f64; 3]) {
    for k in 0..3 {
        acc[k] += v[k];
    }
}
/// A position or normal of the mesh as a vector (nalgebra's arithmetic).
pub(crate) fn v3(p: [f64; 3]) -> Point<3> {
    Point::<3>::from(p)
}
/// n/|n|, or zero where |n| is zero or not finite (no direction a mesh can use).
pub(crate) fn unit_or_zero(n: Point<3>) -> [f64; 3] {
    let len = n.norm();
    if len > 0.0 && len.is_finite() { n.map(|x| x / len).into() } else { [0.0; 3] }
}
