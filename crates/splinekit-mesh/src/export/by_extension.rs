//! The one place that turns a mesh or a polyline into the bytes of the file [`Format`]
//! its extension names, with the default colour of exported objects: the command line
//! (`tessellate`, `subdivide-surface`), Python's `save` and `Mesh.save` and the studio's
//! export all write through it, so a format or the colour is added or changed once.
//!
//! Meshes: .obj (with normals and uv where the mesh has them), .stl (binary), .stla
//! (ASCII STL), .ply (ASCII), .gltf and .glb. Polylines: .obj (a line element), .gltf and
//! .glb (a line strip; a closed polyline repeats its first point at the end), .svg (a
//! drawing).

use std::borrow::Cow;
use std::path::Path;

use super::format::{Format, phrase};
use super::{ExportError, GltfGeometry, GltfScene, obj, ply, stl};
use crate::{Projection, SvgFigure, TriangleMesh};

/// The colour of exported glTF objects (linear RGBA), where the document gives none.
pub const EXPORT_COLOR: [f32; 4] = [0.12, 0.37, 0.75, 1.0];

/// The object name a file gives its contents: `path`'s stem ("shape" without one).
pub fn object_name(path: &Path) -> String {
    path.file_stem().and_then(|s| s.to_str()).unwrap_or("shape").to_string()
}

/// The refusal of a format no writer here takes, naming the formats there are.
fn unknown(format: Format, formats: &[Format]) -> ExportError {
    ExportError::Unrepresentable {
        field: "format".into(),
        message: format!("'{}' is not one of {}", format.extension(), phrase(formats)),
    }
}

/// `mesh` as a file of `format` (one of [`Format::MESHES`]); `name` is the object's name
/// where the format has one. A borrowed mesh is copied only for glTF, whose scene owns it.
pub fn mesh_bytes(mesh: Cow<'_, TriangleMesh>, name: &str, format: Format) -> Result<Vec<u8>, ExportError> {
    let mut bytes = Vec::new();
    match format {
        Format::Obj => obj::write_obj(&mesh, name, &mut bytes)?,
        Format::Stl => stl::write_stl_binary(&mesh, &mut bytes)?,
        Format::StlAscii => stl::write_stl_ascii(&mesh, name, &mut bytes)?,
        Format::Ply => ply::write_ply(&mesh, &mut bytes)?,
        Format::Gltf | Format::Glb => {
            bytes =
                GltfScene::single(name, GltfGeometry::Mesh(mesh.into_owned()), EXPORT_COLOR).to_format_bytes(format)?
        }
        other => return Err(unknown(other, Format::MESHES)),
    }
    Ok(bytes)
}

/// The polyline `points` (joined back to the first when `closed`) as a file of `format`
/// (one of [`Format::POLYLINES`], or [`Format::Svg`] for [`polyline_svg`]).
pub fn polyline_bytes(points: &[[f64; 3]], closed: bool, name: &str, format: Format) -> Result<Vec<u8>, ExportError> {
    match format {
        Format::Obj => {
            let mut bytes = Vec::new();
            obj::write_obj_polyline(points, closed, name, &mut bytes)?;
            Ok(bytes)
        }
        Format::Gltf | Format::Glb => {
            let mut strip = points.to_vec();
            if closed && !points.is_empty() {
                strip.push(points[0]);
            }
            GltfScene::single(name, GltfGeometry::LineStrip(strip), EXPORT_COLOR).to_format_bytes(format)
        }
        other => Err(unknown(other, Format::POLYLINES)),
    }
}

/// The SVG drawing of the polyline of a `dimension`-D curve (800 × 600, from the top for
/// plane curves, in a view for 3-D ones): what `splinekit tessellate CURVE -o FILE.svg`
/// writes and Python's notebook views show.
pub fn polyline_svg(points: &[[f64; 3]], closed: bool, dimension: usize) -> Result<String, ExportError> {
    let proj = if dimension >= 3 { Projection::view(0.6, 0.45) } else { Projection::TOP };
    let mut fig = SvgFigure::new(800.0, 600.0, proj);
    let pts: Vec<splinekit::Point<3>> = points.iter().map(|p| splinekit::Point::<3>::from(*p)).collect();
    fig.path(&pts, closed, "#1f5fbf", 2.0);
    fig.render()
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
        for &format in Format::MESHES {
            let bytes = mesh_bytes(Cow::Owned(triangle()), "t", format).unwrap();
            let start: &[u8] = match format {
                Format::Obj => b"# splinekit",
                Format::StlAscii => b"solid t",
                Format::Ply => b"ply",
                Format::Glb => b"glTF",
                Format::Gltf => b"{",
                _ => b"",
            };
            assert!(bytes.starts_with(start), "{format}");
        }
        // Binary STL: 80-byte header, count, 50 bytes a triangle.
        assert_eq!(mesh_bytes(Cow::Owned(triangle()), "t", Format::Stl).unwrap().len(), 84 + 50);
        assert_eq!(
            mesh_bytes(Cow::Owned(triangle()), "t", Format::Svg).unwrap_err().to_string(),
            "format: 'svg' is not one of .obj, .stl, .stla, .ply, .gltf or .glb"
        );
        let square = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [1.0, 1.0, 0.0]];
        for &format in Format::POLYLINES {
            assert!(!polyline_bytes(&square, true, "p", format).unwrap().is_empty(), "{format}");
        }
        let obj = String::from_utf8(polyline_bytes(&square, true, "p", Format::Obj).unwrap()).unwrap();
        assert!(obj.contains("l 1 2 3 1"), "{obj}");
        assert!(polyline_bytes(&square, false, "p", Format::Stl).is_err());
        assert!(polyline_svg(&square, true, 2).unwrap().starts_with("<svg"));
    }
}
