//! The one place that turns a mesh or a polyline into the bytes of the file format its
//! extension names, with the default colour of exported objects: the command line
//! (`tessellate`, `subdivide-surface`), Python's `Mesh.save` and the studio's export all
//! write through it, so a format or the colour is added or changed once.
//!
//! Meshes: .obj (with normals and uv where the mesh has them), .stl (binary), .stla
//! (ASCII STL), .ply (ASCII), .gltf and .glb. Polylines: .obj (a line element), .gltf and
//! .glb (a line strip; a closed polyline repeats its first point at the end).

use std::borrow::Cow;
use std::path::Path;

use super::{ExportError, GltfGeometry, GltfScene, obj, ply, stl};
use crate::TriangleMesh;

/// The colour of exported glTF objects (linear RGBA), where the document gives none.
pub const EXPORT_COLOR: [f32; 4] = [0.12, 0.37, 0.75, 1.0];

/// The extensions [`mesh_bytes`] writes.
pub const MESH_FORMATS: &[&str] = &["obj", "stl", "stla", "ply", "gltf", "glb"];

/// The extensions [`polyline_bytes`] writes.
pub const POLYLINE_FORMATS: &[&str] = &["obj", "gltf", "glb"];

/// The extension of `path`, lower case ("" without one).
pub fn extension(path: &Path) -> String {
    path.extension().and_then(|e| e.to_str()).unwrap_or("").to_ascii_lowercase()
}

/// The object name a file gives its contents: `path`'s stem ("shape" without one).
pub fn object_name(path: &Path) -> String {
    path.file_stem().and_then(|s| s.to_str()).unwrap_or("shape").to_string()
}

/// Extensions for a message: `.a, .b or .c`.
pub fn formats_phrase(formats: &[&str]) -> String {
    let dotted: Vec<String> = formats.iter().map(|f| format!(".{f}")).collect();
    match dotted.split_last() {
        Some((last, [])) => last.clone(),
        Some((last, rest)) => format!("{} or {last}", rest.join(", ")),
        None => String::new(),
    }
}

/// The refusal of an extension no writer takes, naming the formats there are.
fn unknown(ext: &str, formats: &[&str]) -> ExportError {
    ExportError::Unrepresentable {
        field: "format".into(),
        message: format!("'{ext}' is not one of {}", formats_phrase(formats)),
    }
}

/// `mesh` as a file of format `ext` (one of [`MESH_FORMATS`]); `name` is the object's name
/// where the format has one. A borrowed mesh is copied only for glTF, whose scene owns it.
pub fn mesh_bytes(mesh: Cow<'_, TriangleMesh>, name: &str, ext: &str) -> Result<Vec<u8>, ExportError> {
    let mut bytes = Vec::new();
    match ext {
        "obj" => obj::write_obj(&mesh, name, &mut bytes)?,
        "stl" => stl::write_stl_binary(&mesh, &mut bytes)?,
        "stla" => stl::write_stl_ascii(&mesh, name, &mut bytes)?,
        "ply" => ply::write_ply(&mesh, &mut bytes)?,
        "gltf" | "glb" => {
            bytes = GltfScene::single(name, GltfGeometry::Mesh(mesh.into_owned()), EXPORT_COLOR).to_file_bytes(ext)?
        }
        _ => return Err(unknown(ext, MESH_FORMATS)),
    }
    Ok(bytes)
}

/// The polyline `points` (joined back to the first when `closed`) as a file of format
/// `ext` (one of [`POLYLINE_FORMATS`]).
pub fn polyline_bytes(points: &[[f64; 3]], closed: bool, name: &str, ext: &str) -> Result<Vec<u8>, ExportError> {
    match ext {
        "obj" => {
            let mut bytes = Vec::new();
            obj::write_obj_polyline(points, closed, name, &mut bytes)?;
            Ok(bytes)
        }
        "gltf" | "glb" => {
            let mut strip = points.to_vec();
            if closed && !points.is_empty() {
                strip.push(points[0]);
            }
            GltfScene::single(name, GltfGeometry::LineStrip(strip), EXPORT_COLOR).to_file_bytes(ext)
        }
        _ => Err(unknown(ext, POLYLINE_FORMATS)),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn triangle() -> TriangleMesh {
        TriangleMesh {
            positions: vec![[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]],
            triangles: vec![[0, 1, 2]],
            ..TriangleMesh::default()
        }
    }

    #[test]
    fn every_format_is_written_by_its_writer_and_others_are_refused() {
        for ext in MESH_FORMATS {
            let bytes = mesh_bytes(Cow::Owned(triangle()), "t", ext).unwrap();
            let start: &[u8] = match *ext {
                "obj" => b"# splinekit",
                "stla" => b"solid t",
                "ply" => b"ply",
                "glb" => b"glTF",
                "gltf" => b"{",
                _ => b"",
            };
            assert!(bytes.starts_with(start), "{ext}");
        }
        // Binary STL: 80-byte header, count, 50 bytes a triangle.
        assert_eq!(mesh_bytes(Cow::Owned(triangle()), "t", "stl").unwrap().len(), 84 + 50);
        assert_eq!(
            mesh_bytes(Cow::Owned(triangle()), "t", "svg").unwrap_err().to_string(),
            "format: 'svg' is not one of .obj, .stl, .stla, .ply, .gltf or .glb"
        );
        let square = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [1.0, 1.0, 0.0]];
        for ext in POLYLINE_FORMATS {
            assert!(!polyline_bytes(&square, true, "p", ext).unwrap().is_empty(), "{ext}");
        }
        let obj = String::from_utf8(polyline_bytes(&square, true, "p", "obj").unwrap()).unwrap();
        assert!(obj.contains("l 1 2 3 1"), "{obj}");
        assert!(polyline_bytes(&square, false, "p", "stl").is_err());
        assert_eq!(formats_phrase(&["a"]), ".a");
        assert_eq!(formats_phrase(&["a", "b"]), ".a or .b");
    }
}
