//! Indexed triangle meshes: positions, unit normals, optional (u, v) and colours, and
//! counter-clockwise triangles (seen from the side the normals point to).

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
        let [a, b, c] = self.triangles[t].map(|i| self.positions[i as usize]);
        normalize(cross(sub(b, a), sub(c, a)))
    }
    /// Twice the area of triangle t.
    pub fn double_area(&self, t: usize) -> f64 {
        let [a, b, c] = self.triangles[t].map(|i| self.positions[i as usize]);
        norm(cross(sub(b, a), sub(c, a)))
    }
    /// Total surface area.
    pub fn area(&self) -> f64 {
        (0..self.triangles.len()).map(|t| 0.5 * self.double_area(t)).sum()
    }
    /// The axis-aligned bounding box (min, max); `None` for an empty mesh.
    pub fn bounds(&self) -> Option<([f64; 3], [f64; 3])> {
        let first = *self.positions.first()?;
        Some(self.positions.iter().fold((first, first), |(lo, hi), p| {
            ([lo[0].min(p[0]), lo[1].min(p[1]), lo[2].min(p[2])], [hi[0].max(p[0]), hi[1].max(p[1]), hi[2].max(p[2])])
        }))
    }
    /// Replaces zero normals (poles, cusps) by the area-weighted mean of the adjacent faces'
    /// normals; fills all normals that way when there are none.
    pub fn repair_normals(&mut self) {
        if self.normals.len() != self.positions.len() {
            self.normals = vec![[0.0; 3]; self.positions.len()];
        }
        let missing: Vec<bool> = self.normals.iter().map(|n| norm(*n) < 0.5).collect();
        if !missing.iter().any(|&m| m) {
            return;
        }
        let mut acc = vec![[0.0; 3]; self.positions.len()];
        for t in &self.triangles {
            let [a, b, c] = t.map(|i| self.positions[i as usize]);
            let n = cross(sub(b, a), sub(c, a));
            for &i in t {
                let s = &mut acc[i as usize];
                for k in 0..3 {
                    s[k] += n[k];
                }
            }
        }
        for (i, m) in missing.iter().enumerate() {
            if *m {
                self.normals[i] = normalize(acc[i]);
            }
        }
    }
    /// Removes triangles with two equal vertex indices or zero area.
    pub fn drop_degenerate(&mut self) {
        let keep: Vec<bool> = (0..self.triangles.len())
            .map(|t| {
                let [a, b, c] = self.triangles[t];
                a != b && b != c && a != c && self.double_area(t) > 0.0
            })
            .collect();
        let mut i = 0;
        self.triangles.retain(|_| {
            i += 1;
            keep[i - 1]
        });
    }
    /// Edges used by exactly one triangle (the boundary; empty for a closed surface).
    pub fn boundary_edges(&self) -> Vec<[u32; 2]> {
        let mut count = std::collections::HashMap::new();
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

pub(crate) fn sub(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}
pub(crate) fn cross(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]
}
pub(crate) fn norm(a: [f64; 3]) -> f64 {
    (a[0] * a[0] + a[1] * a[1] + a[2] * a[2]).sqrt()
}
pub(crate) fn normalize(a: [f64; 3]) -> [f64; 3] {
    let n = norm(a);
    if n > 0.0 && n.is_finite() { [a[0] / n, a[1] / n, a[2] / n] } else { [0.0; 3] }
}
