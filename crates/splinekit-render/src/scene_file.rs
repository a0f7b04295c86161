//! Scenes to every mesh format: what the scene draws (its composition, the same meshes
//! and lines as its glTF, at each object's `density`) written as one file. OBJ has a group
//! (`o` and `g`) per object with its triangles and its lines (`l`); STL and PLY hold one
//! mesh of every object's triangles, PLY with the lines as edges and each vertex's colour.
//! STL holds triangles only: a curve in the scene is refused, naming its object, and the
//! drawing aids of surfaces (wireframe, control nets, local patches) are left out. glTF
//! carries the scene's animation as morph targets ([`scene_to_gltf`]).
//!
//! The composition is in 32-bit floats (what the renderer and glTF hold); the text formats
//! write each coordinate as the shortest decimal of its 32-bit value, so `0.3` stays
//! `0.3`.

use std::borrow::Cow;

use splinekit_mesh::TriangleMesh;
use splinekit_mesh::export::obj::{ObjObject, write_obj_objects};
use splinekit_mesh::export::ply::write_ply_with_edges;
use splinekit_mesh::export::{ExportError, Format, mesh_bytes};
use splinekit_scene::scenes::SceneDocument;
use splinekit_scene::{DocumentError, ShapeDocument};

use crate::compose::compose;
use crate::gltf_export::scene_to_gltf;
use crate::scene::RenderScene;

/// The f64 whose shortest decimal is that of the f32 `x` (the f32 read back exactly).
fn widen(x: f32) -> f64 {
    x.to_string().parse().unwrap_or(x as f64)
}

fn widen3(p: &[f32; 3]) -> [f64; 3] {
    p.map(widen)
}

/// An export error as a document error (the same line: field, then message).
fn export_error(e: ExportError) -> DocumentError {
    match e {
        ExportError::Unrepresentable { field, message } => DocumentError::new(field, message),
        ExportError::Io(e) => DocumentError::new("", format!("cannot write: {e}")),
    }
}

/// One object's drawn triangles and lines.
struct Drawn {
    /// Its index in the scene.
    index: usize,
    /// Its document type.
    kind: &'static str,
    /// Its name in files: type and index (`torus_0`).
    name: String,
    /// Whether its shape is a curve.
    curve: bool,
    mesh: TriangleMesh,
    lines: Vec<(Vec<[f64; 3]>, bool)>,
    /// Colours (sRGB) of the mesh's vertices and of each line.
    vertex_colors: Vec<[f32; 4]>,
    line_colors: Vec<[f32; 4]>,
}

/// The objects of a composition that draw anything, each its meshes merged into one.
fn drawn(scene: &SceneDocument, composed: &RenderScene) -> Vec<Drawn> {
    let mut out = Vec::new();
    for (i, items) in composed.objects.iter().enumerate() {
        if items.meshes.is_empty() && items.lines.is_empty() {
            continue;
        }
        let kind = match &scene.objects[i].shape {
            ShapeDocument::Curve(c) => c.type_name(),
            ShapeDocument::Surface(s) => s.type_name(),
        };
        let mut d = Drawn {
            index: i,
            kind,
            name: format!("{kind}_{i}"),
            curve: matches!(scene.objects[i].shape, ShapeDocument::Curve(_)),
            mesh: TriangleMesh::default(),
            lines: Vec::new(),
            vertex_colors: Vec::new(),
            line_colors: Vec::new(),
        };
        for m in &composed.meshes[items.meshes.clone()] {
            let base = d.mesh.positions.len() as u32;
            d.mesh.positions.extend(m.positions.iter().map(widen3));
            d.mesh.normals.extend(m.normals.iter().map(widen3));
            d.mesh.triangles.extend(m.triangles.iter().map(|t| t.map(|k| k + base)));
            if m.colors.is_empty() {
                d.vertex_colors.extend(std::iter::repeat_n(m.color, m.positions.len()));
            } else {
                d.vertex_colors.extend(&m.colors);
            }
        }
        for l in &composed.lines[items.lines.clone()] {
            d.lines.push((l.points.iter().map(widen3).collect(), l.closed));
            d.line_colors.push(l.color);
        }
        out.push(d);
    }
    out
}

/// Every object's triangles in one mesh (normals kept; colours per vertex when `colors`).
fn one_mesh(objects: &[Drawn], colors: bool) -> TriangleMesh {
    let mut mesh = TriangleMesh::default();
    for d in objects {
        let base = mesh.positions.len() as u32;
        mesh.positions.extend(&d.mesh.positions);
        mesh.normals.extend(&d.mesh.normals);
        mesh.triangles.extend(d.mesh.triangles.iter().map(|t| t.map(|k| k + base)));
        if colors {
            mesh.colors.extend(&d.vertex_colors);
        }
    }
    mesh
}

/// The scene (posed at `time`, else at the start of its animation) as a file of `format`
/// (one of [`Format::MESHES`]); `name` names the STL solid. glTF carries an animated
/// scene's frames ([`scene_to_gltf`], `time` unused). Errors name the object
/// (`objects[1]: …`).
pub fn scene_file(
    scene: &SceneDocument,
    format: Format,
    name: &str,
    time: Option<f64>,
) -> Result<Vec<u8>, DocumentError> {
    if format.is_gltf() {
        let (frames, fps) = if scene.is_animated() { (scene.clock().frames(), scene.clock().fps) } else { (1, 1.0) };
        return scene_to_gltf(scene, frames, fps)?.to_format_bytes(format).map_err(export_error);
    }
    if !format.holds_triangles() {
        let formats = splinekit_mesh::export::format::phrase(Format::MESHES);
        return Err(DocumentError::new("format", format!("scenes are written as {formats}, not {format}")));
    }
    let composed = compose(scene, time.or(scene.is_animated().then_some(0.0)), 1.0)?;
    let objects = drawn(scene, &composed);
    let mut bytes = Vec::new();
    match format {
        Format::Obj => {
            let parts: Vec<ObjObject<'_>> =
                objects.iter().map(|d| ObjObject { name: &d.name, mesh: &d.mesh, lines: &d.lines }).collect();
            write_obj_objects(&parts, &mut bytes).map_err(export_error)?;
        }
        Format::Ply => {
            let mut mesh = one_mesh(&objects, true);
            let mut edges = Vec::new();
            for d in &objects {
                for ((points, closed), color) in d.lines.iter().zip(&d.line_colors) {
                    let first = mesh.positions.len() as u32;
                    let n = points.len() as u32;
                    mesh.positions.extend(points);
                    mesh.normals.extend(std::iter::repeat_n([0.0; 3], points.len()));
                    mesh.colors.extend(std::iter::repeat_n(*color, points.len()));
                    edges.extend((1..n).map(|k| [first + k - 1, first + k]));
                    if *closed && n > 2 {
                        edges.push([first + n - 1, first]);
                    }
                }
            }
            write_ply_with_edges(&mesh, &edges, &mut bytes).map_err(export_error)?;
        }
        _ => {
            if let Some(d) = objects.iter().find(|d| d.curve) {
                return Err(DocumentError::new(
                    format!("objects[{}]", d.index),
                    format!(
                        "a curve ({}), which STL cannot hold (triangles only): write .obj or .ply, or leave the \
                         curve out",
                        d.kind
                    ),
                ));
            }
            let mesh = one_mesh(&objects, false);
            if mesh.triangles.is_empty() {
                return Err(DocumentError::new("objects", "no visible surface: STL holds triangles only"));
            }
            bytes = mesh_bytes(Cow::Owned(mesh), name, format).map_err(export_error)?;
        }
    }
    Ok(bytes)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn scene(json: &str) -> SceneDocument {
        splinekit_scene::SceneOrShape::from_json(json).unwrap().into_scene()
    }

    #[test]
    fn obj_has_a_group_per_object_with_triangles_and_lines() {
        let s = scene(
            r#"{"type":"scene","objects":[{"shape":{"type":"torus"},"density":8},
                {"shape":{"type":"circle"},"density":16},{"shape":{"type":"sphere"},"hidden":true}]}"#,
        );
        let text = String::from_utf8(scene_file(&s, Format::Obj, "s", None).unwrap()).unwrap();
        let heads: Vec<&str> = text.lines().filter(|l| l.starts_with("o ")).collect();
        assert_eq!(heads, ["o torus_0", "o circle_1"], "the hidden sphere draws nothing");
        assert_eq!(text.lines().filter(|l| l.starts_with("l ")).count(), 1);
        let mesh = splinekit_mesh::export::obj::read_obj(&text).unwrap();
        assert_eq!(mesh.triangles.len(), 2 * 8 * 8);
        assert_eq!(mesh.positions.len(), 9 * 9 + 16, "the circle's points follow the torus's");
        assert!(text.lines().any(|l| l == "l 82 83 84 85 86 87 88 89 90 91 92 93 94 95 96 97 82"), "{text}");
    }

    #[test]
    fn stl_refuses_a_curve_naming_it_and_ply_keeps_it_as_edges() {
        let s = scene(
            r#"{"type":"scene","objects":[{"shape":{"type":"torus"},"density":8,"wireframe":true},
                {"shape":{"type":"heart"},"density":10}]}"#,
        );
        let e = scene_file(&s, Format::Stl, "s", None).unwrap_err().to_string();
        assert!(e.starts_with("objects[1]: a curve (heart), which STL cannot hold"), "{e}");
        let ply = String::from_utf8(scene_file(&s, Format::Ply, "s", None).unwrap()).unwrap();
        assert!(ply.contains("element face 128\n"), "{ply}");
        // The wireframe's 2 × 9 lines of 129 points and the heart's 10 (closed: 10 edges).
        assert!(ply.contains(&format!("element vertex {}\n", 81 + 18 * 129 + 10)), "{ply}");
        assert!(ply.contains(&format!("element edge {}\n", 18 * 128 + 10)), "{ply}");
        let only_torus =
            scene(r#"{"type":"scene","objects":[{"shape":{"type":"torus"},"density":8,"wireframe":true}]}"#);
        let stl = scene_file(&only_torus, Format::Stl, "s", None).unwrap();
        assert_eq!(stl.len(), 84 + 50 * 128, "the wireframe is left out");
        let hidden = scene(r#"{"type":"scene","objects":[{"shape":{"type":"torus"},"hidden":true}]}"#);
        let e = scene_file(&hidden, Format::Stl, "s", None).unwrap_err();
        assert_eq!(e.to_string(), "objects: no visible surface: STL holds triangles only");
    }
}
