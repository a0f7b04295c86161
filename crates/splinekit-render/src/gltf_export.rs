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
        // glTF multiplies COLOR_0 by the base colour; the renderer draws the vertex colours
        // (a colour map) alone, so the base colour is then white.
        let color = if m.colors.is_empty() { srgba_to_linear(m.color) } else { [1.0; 4] };
        out.objects.push(GltfObject {
            name: object_name(scene, &first, i, |o| &o.meshes).unwrap_or_else(|| format!("surface {i}")),
            geometry: GltfGeometry::Mesh(mesh),
            color,
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
        // A colour-mapped curve: its colours per point (COLOR_0) on a white base colour.
        let (geometry, color) = if l.colors.len() == l.points.len() && !l.colors.is_empty() {
            let mut colors: Vec<[f32; 4]> = l.colors.iter().copied().map(srgba_to_linear).collect();
            if l.closed {
                colors.push(colors[0]);
            }
            (GltfGeometry::ColoredLineStrip(pts, colors), [1.0; 4])
        } else {
            (GltfGeometry::LineStrip(pts), srgba_to_linear(l.color))
        };
        let name = object_name(scene, &first, i, |o| &o.lines).unwrap_or_else(|| format!("line {i}"));
        out.objects.push(GltfObject { name, geometry, color, frames: frames_out });
    }
    Ok(out)
}

/// The `name` of the scene object whose items (`range` of them) hold item `i`, if it has
/// one: a part's occurrence in an assembly names its node.
fn object_name(
    scene: &SceneDocument,
    composed: &crate::scene::RenderScene,
    i: usize,
    range: impl Fn(&crate::scene::ObjectItems) -> &std::ops::Range<usize>,
) -> Option<String> {
    let k = composed.objects.iter().position(|o| range(o).contains(&i))?;
    scene.objects.get(k)?.name.clone()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn scene(json: &str) -> SceneDocument {
        splinekit_scene::SceneOrShape::from_json(json).unwrap().into_scene()
    }

    #[test]
    fn a_colour_mapped_mesh_has_a_white_base_colour_and_a_plain_one_its_own() {
        let mapped = scene_to_gltf(
            &scene(r#"{"type":"scene","objects":[{"shape":{"type":"torus"},"color_map":"gaussian"}]}"#),
            1,
            1.0,
        )
        .unwrap();
        let GltfGeometry::Mesh(mesh) = &mapped.objects[0].geometry else { panic!("a torus is a mesh") };
        assert!(!mesh.colors.is_empty());
        assert_eq!(mapped.objects[0].color, [1.0; 4], "COLOR_0 is multiplied by the base colour");
        let plain = scene_to_gltf(
            &scene(r#"{"type":"scene","objects":[{"shape":{"type":"torus"},"color":[0.5,0.25,1.0]}]}"#),
            1,
            1.0,
        )
        .unwrap();
        let GltfGeometry::Mesh(mesh) = &plain.objects[0].geometry else { panic!("a torus is a mesh") };
        assert!(mesh.colors.is_empty());
        assert_eq!(plain.objects[0].color, srgba_to_linear([0.5, 0.25, 1.0, 1.0]));
    }

    #[test]
    fn a_colour_mapped_curve_is_a_strip_with_a_colour_per_point() {
        let mapped = scene_to_gltf(
            &scene(r#"{"type":"scene","objects":[{"shape":{"type":"helix"},"color_map":"z","density":40}]}"#),
            1,
            1.0,
        )
        .unwrap();
        let GltfGeometry::ColoredLineStrip(points, colors) = &mapped.objects[0].geometry else {
            panic!("a colour-mapped curve carries its colours")
        };
        assert_eq!(points.len(), 41);
        assert_eq!(colors.len(), 41);
        assert_ne!(colors[0], colors[40], "z rises along the helix");
        assert_eq!(mapped.objects[0].color, [1.0; 4]);
        let bytes = mapped.to_format_bytes(splinekit_mesh::export::Format::Gltf).unwrap();
        assert!(String::from_utf8(bytes).unwrap().contains("COLOR_0"));
    }
}
