//! Export of one object to a mesh file, in the formats `splinekit tessellate` writes,
//! chosen by the extension: surfaces as .obj, .stl (binary), .stla (ASCII STL), .ply,
//! .gltf, .glb; curves as .obj polylines, .gltf/.glb line strips. Sampled regularly at
//! the object's `density` (default: 64 cells per direction, 1000 curve segments), posed at
//! `time`.

use std::path::Path;

use splinekit::curve::Curve;
use splinekit::surface::Surface;
use splinekit_mesh::export::{ExportError, GltfGeometry, GltfScene, obj, ply, stl};
use splinekit_mesh::surface_mesh::{regular, to3};
use splinekit_mesh::{MeshOptions, Polyline, TriangleMesh};
use splinekit_scene::scenes::SceneObject;
use splinekit_scene::{Curves, DimensionVisitor, ShapeDocument, Surfaces};

/// The colour of exported glTF objects (linear RGBA), as `tessellate` gives them.
const EXPORT_COLOR: [f32; 4] = [0.12, 0.37, 0.75, 1.0];

struct CurvePoints(usize);

impl DimensionVisitor<Curves> for CurvePoints {
    type Output = Result<(Vec<[f64; 3]>, bool), String>;
    fn visit<const D: usize>(self, c: &dyn Curve<D>) -> Self::Output {
        let poly = Polyline::regular(c, self.0).map_err(|e| e.to_string())?;
        Ok((poly.points.iter().map(to3).collect(), poly.closed))
    }
}

struct SurfaceMesh(usize);

impl DimensionVisitor<Surfaces> for SurfaceMesh {
    type Output = Result<TriangleMesh, String>;
    fn visit<const D: usize>(self, s: &dyn Surface<D>) -> Self::Output {
        regular(s, self.0, self.0, MeshOptions { uv: true }).map_err(|e| e.to_string())
    }
}

fn written(write: impl FnOnce(&mut Vec<u8>) -> Result<(), ExportError>) -> Result<Vec<u8>, String> {
    let mut bytes = Vec::new();
    write(&mut bytes).map_err(|e| e.to_string())?;
    Ok(bytes)
}

/// The bytes of `object` (posed at `time`) in the format of `path`'s extension.
pub fn export(object: &SceneObject, time: Option<f64>, path: &Path) -> Result<Vec<u8>, String> {
    let ext = path.extension().and_then(|e| e.to_str()).unwrap_or("").to_ascii_lowercase();
    let name = path.file_stem().and_then(|s| s.to_str()).unwrap_or("shape").to_string();
    let mut shape = object.shape.clone();
    if let Some(t) = time {
        shape.set_time(t);
    }
    match &shape {
        ShapeDocument::Curve(c) => {
            let (points, closed) =
                c.build().map_err(|e| e.to_string())?.visit(CurvePoints(object.style.density.unwrap_or(1000)))?;
            match ext.as_str() {
                "obj" => written(|out| obj::write_obj_polyline(&points, closed, &name, out)),
                "gltf" | "glb" => {
                    let mut strip = points.clone();
                    if closed && !points.is_empty() {
                        strip.push(points[0]);
                    }
                    GltfScene::single(&name, GltfGeometry::LineStrip(strip), EXPORT_COLOR)
                        .to_file_bytes(&ext)
                        .map_err(|e| e.to_string())
                }
                _ => Err(format!("export: curves are written as .obj, .gltf or .glb, not '{}'", path.display())),
            }
        }
        ShapeDocument::Surface(s) => {
            let mesh = s.build().map_err(|e| e.to_string())?.visit(SurfaceMesh(object.style.density.unwrap_or(64)))?;
            match ext.as_str() {
                "obj" => written(|out| obj::write_obj(&mesh, &name, out)),
                "stl" => written(|out| stl::write_stl_binary(&mesh, out)),
                "stla" => written(|out| stl::write_stl_ascii(&mesh, &name, out)),
                "ply" => written(|out| ply::write_ply(&mesh, out)),
                "gltf" | "glb" => GltfScene::single(&name, GltfGeometry::Mesh(mesh), EXPORT_COLOR)
                    .to_file_bytes(&ext)
                    .map_err(|e| e.to_string()),
                _ => Err(format!(
                    "export: surfaces are written as .obj, .stl, .stla, .ply, .gltf or .glb, not '{}'",
                    path.display()
                )),
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn surfaces_and_curves_export_in_tessellates_formats_and_others_are_refused() {
        let plane =
            SceneObject::from_value(serde_json::json!({"shape": {"type": "plane"}, "density": 8})).expect("valid");
        let obj = export(&plane, None, Path::new("p.obj")).expect("obj");
        let text = String::from_utf8(obj).expect("text");
        assert_eq!(text.lines().filter(|l| l.starts_with("v ")).count(), 9 * 9, "a regular 8×8 grid");
        assert!(export(&plane, None, Path::new("p.glb")).expect("glb").starts_with(b"glTF"));
        let heart = SceneObject::from_value(serde_json::json!({"shape": {"type": "heart"}})).expect("valid");
        assert!(export(&heart, None, Path::new("h.obj")).is_ok());
        let e = export(&heart, None, Path::new("h.stl")).expect_err("a curve has no triangles");
        assert!(e.contains(".obj, .gltf or .glb"), "{e}");
    }
}
