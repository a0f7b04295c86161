//! Export of one object to a mesh file, in the formats `splinekit tessellate` writes,
//! chosen by the extension: surfaces as .obj, .stl (binary), .stla (ASCII STL), .ply,
//! .gltf, .glb; curves as .obj polylines, .gltf/.glb line strips. Sampled regularly at
//! the object's `density` (default: 64 cells per direction, 1000 curve segments), posed at
//! `time`.

use std::path::Path;

use splinekit::curve::Curve;
use splinekit::surface::Surface;
use splinekit_mesh::export::by_extension::{
    MESH_FORMATS, POLYLINE_FORMATS, extension, formats_phrase, mesh_bytes, object_name, polyline_bytes,
};
use splinekit_mesh::surface_mesh::{regular, to3};
use splinekit_mesh::{MeshOptions, Polyline, TriangleMesh};
use splinekit_scene::scenes::SceneObject;
use splinekit_scene::{Curves, DimensionVisitor, ShapeDocument, Surfaces};

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

/// The bytes of `object` (posed at `time`) in the format of `path`'s extension.
pub fn export(object: &SceneObject, time: Option<f64>, path: &Path) -> Result<Vec<u8>, String> {
    let (ext, name) = (extension(path), object_name(path));
    let mut shape = object.shape.clone();
    if let Some(t) = time {
        shape.set_time(t);
    }
    match &shape {
        ShapeDocument::Curve(c) => {
            let (points, closed) =
                c.build().map_err(|e| e.to_string())?.visit(CurvePoints(object.style.density.unwrap_or(1000)))?;
            if !POLYLINE_FORMATS.contains(&ext.as_str()) {
                let formats = formats_phrase(POLYLINE_FORMATS);
                return Err(format!("export: curves are written as {formats}, not '{}'", path.display()));
            }
            polyline_bytes(&points, closed, &name, &ext).map_err(|e| e.to_string())
        }
        ShapeDocument::Surface(s) => {
            let mesh = s.build().map_err(|e| e.to_string())?.visit(SurfaceMesh(object.style.density.unwrap_or(64)))?;
            if !MESH_FORMATS.contains(&ext.as_str()) {
                let formats = formats_phrase(MESH_FORMATS);
                return Err(format!("export: surfaces are written as {formats}, not '{}'", path.display()));
            }
            mesh_bytes(std::borrow::Cow::Owned(mesh), &name, &ext).map_err(|e| e.to_string())
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
