//! The mesh of a subdivision surface's cage placed on its limit surface: every vertex at
//! its limit position with its limit normal (limit masks,
//! [`SubdivisionSurface::limit_frames`]), in the cage's vertex order, and along sharp
//! creases one more normal for each face corner on the far side
//! ([`SubdivisionSurface::limit_corner_normals`]). The command line writes it as OBJ
//! (`v`/`vn` corners) and, as triangles, to the other formats; Python returns the triangles.

use std::collections::HashMap;

use splinekit::Point;
use splinekit::subdivision::surface::SubdivisionSurface;

use crate::TriangleMesh;

#[derive(Debug, Clone)]
/// Limit positions (one per vertex, in order), normals (one per vertex, in order, then one
/// more per face corner on the far side of a sharp crease), and faces as (vertex, normal)
/// corners.
pub struct LimitMesh {
    /// The limit position of each cage vertex.
    pub positions: Vec<[f64; 3]>,
    /// The limit normal of each cage vertex, then the corners' own normals.
    pub normals: Vec<[f64; 3]>,
    /// Each face's corners as (position index, normal index).
    pub faces: Vec<Vec<(u32, u32)>>,
}

/// The limit mesh of `s`'s cage.
pub fn limit_mesh(s: &SubdivisionSurface) -> splinekit::Result<LimitMesh> {
    let frames = s.limit_frames()?;
    let corners = s.limit_corner_normals(&frames);
    let arr = |p: &Point<3>| [p.x, p.y, p.z];
    let mut m = LimitMesh {
        positions: frames.iter().map(|f| arr(&f.position)).collect(),
        normals: frames.iter().map(|f| arr(&f.normal)).collect(),
        faces: Vec::with_capacity(s.cage().face_count()),
    };
    let c = s.cage();
    for f in 0..c.face_count() {
        let start = c.face_offsets[f] as usize;
        let face = c
            .face(f)
            .iter()
            .enumerate()
            .map(|(k, &v)| {
                let n = corners[start + k];
                if (n - frames[v as usize].normal).norm() == 0.0 {
                    (v, v)
                } else {
                    m.normals.push(arr(&n));
                    (v, m.normals.len() as u32 - 1)
                }
            })
            .collect();
        m.faces.push(face);
    }
    Ok(m)
}

impl LimitMesh {
    /// Triangle fans of the faces, one mesh vertex per (position, normal) pair: the cage's
    /// vertices first, in order, then a copy of a vertex for each other normal it has at a
    /// sharp crease (corners of one side sharing it), in the order the faces meet them.
    pub fn triangles(&self) -> TriangleMesh {
        let mut t = TriangleMesh {
            positions: self.positions.clone(),
            normals: self.normals[..self.positions.len()].to_vec(),
            ..Default::default()
        };
        let mut split = HashMap::new();
        for face in &self.faces {
            let ids: Vec<u32> = face
                .iter()
                .map(|&(v, n)| {
                    if v == n {
                        return v;
                    }
                    let normal = self.normals[n as usize];
                    *split.entry((v, normal.map(f64::to_bits))).or_insert_with(|| {
                        t.positions.push(self.positions[v as usize]);
                        t.normals.push(normal);
                        t.positions.len() as u32 - 1
                    })
                })
                .collect();
            for k in 1..ids.len() - 1 {
                t.triangles.push([ids[0], ids[k], ids[k + 1]]);
            }
        }
        t
    }
}
