//! Scenes as glTF: every mesh and line of the composed scene becomes one node; an animated
//! scene carries its frames as morph targets of the objects whose vertex counts stay the
//! same from frame to frame (regular meshes and curves drawn at a fixed density).

use splinekit_mesh::TriangleMesh;
use splinekit_mesh::export::{GltfGeometry, GltfObject, GltfScene};
use splinekit_scene::DocumentError;
use splinekit_scene::scenes::SceneDocument;

use crate::compose::compose;
use crate::scene::srgba_to_linear;

fn f64x3(p: &[f32; 3]) -> [f64; 3] {
    p.map(|x| x as f64)
}

/// The scene as glTF, with `frames` frames at `fps` as morph-target animation when
/// `frames` > 1.
pub fn scene_to_gltf(scene: &SceneDocument, frames: usize, fps: f64) -> Result<GltfScene, DocumentError> {
    let animated = frames > 1;
    let first = compose(scene, animated.then_some(0.0), 1.0)?;
    let later: Vec<_> =
        (1..frames.max(1)).map(|k| compose(scene, Some(k as f64 / fps), 1.0)).collect::<Result<_, _>>()?;
    let mut out = GltfScene::default();
    for (i, m) in first.meshes.iter().enumerate() {
        let mesh = TriangleMesh {
            positions: m.positions.iter().map(f64x3).collect(),
            normals: m.normals.iter().map(f64x3).collect(),
            colors: m.colors.iter().copied().map(srgba_to_linear).collect(),
            triangles: m.triangles.clone(),
            ..Default::default()
        };
        let mut frames_out = Vec::new();
        if animated && later.iter().all(|s| s.meshes.get(i).is_some_and(|n| n.positions.len() == m.positions.len())) {
            frames_out.push((0.0, mesh.positions.clone(), mesh.normals.clone()));
            for (k, s) in later.iter().enumerate() {
                let n = &s.meshes[i];
                frames_out.push((
                    ((k + 1) as f64 / fps) as f32,
                    n.positions.iter().map(f64x3).collect(),
                    n.normals.iter().map(f64x3).collect(),
                ));
            }
        }
        out.objects.push(GltfObject {
            name: format!("surface {i}"),
            geometry: GltfGeometry::Mesh(mesh),
            color: srgba_to_linear(m.color),
            frames: frames_out,
        });
    }
    for (i, l) in first.lines.iter().enumerate() {
        let strip = |l: &crate::scene::LineItem| -> Vec<[f64; 3]> {
            let mut pts: Vec<[f64; 3]> = l.points.iter().map(f64x3).collect();
            if l.closed && !pts.is_empty() {
                pts.push(pts[0]);
            }
            pts
        };
        let pts = strip(l);
        let mut frames_out = Vec::new();
        if animated && later.iter().all(|s| s.lines.get(i).is_some_and(|n| n.points.len() == l.points.len())) {
            frames_out.push((0.0, pts.clone(), Vec::new()));
            for (k, s) in later.iter().enumerate() {
                frames_out.push((((k + 1) as f64 / fps) as f32, strip(&s.lines[i]), Vec::new()));
            }
        }
        out.objects.push(GltfObject {
            name: format!("line {i}"),
            geometry: GltfGeometry::LineStrip(pts),
            color: srgba_to_linear(l.color),
            frames: frames_out,
        });
    }
    Ok(out)
}
