//! Export of one object to a mesh file, in the formats `splinekit tessellate` writes,
//! chosen by the extension ([`Subject::formats`]): surfaces as .obj, .stl (binary), .stla
//! (ASCII STL), .ply, .gltf, .glb; curves as .svg drawings, .obj polylines, .gltf/.glb line
//! strips. Sampled regularly at
//! the object's `density` (default: 64 cells per direction, 1000 curve segments), posed at
//! `time`.

use std::path::Path;

use splinekit::curve::Curve;
use splinekit::surface::Surface;
use splinekit_mesh::export::by_extension::{mesh_bytes, object_name, polyline_bytes, polyline_svg};
use splinekit_mesh::export::{Format, Subject};
use splinekit_mesh::surface_mesh::{regular, to3};
use splinekit_mesh::{MeshOptions, Polyline, TriangleMesh};
use splinekit_scene::scenes::SceneObject;
use splinekit_scene::{Curves, DimensionVisitor, ShapeDocument, Surfaces};

use crate::error::StudioError;

struct CurvePoints(usize);

impl DimensionVisitor<Curves> for CurvePoints {
    type Output = Result<(Vec<[f64; 3]>, bool, usize), StudioError>;
    fn visit<const D: usize>(self, c: &dyn Curve<D>) -> Self::Output {
        let poly = Polyline::regular(c, self.0).map_err(|e| StudioError::Export(e.to_string()))?;
        Ok((poly.points.iter().map(to3).collect(), poly.closed, D))
    }
}

struct SurfaceMesh(usize);

impl DimensionVisitor<Surfaces> for SurfaceMesh {
    type Output = Result<TriangleMesh, StudioError>;
    fn visit<const D: usize>(self, s: &dyn Surface<D>) -> Self::Output {
        regular(s, self.0, self.0, MeshOptions { uv: true }).map_err(|e| StudioError::Export(e.to_string()))
    }
}

/// The bytes of `object` (posed at `time`) in the format of `path`'s extension.
pub fn export(object: &SceneObject, time: Option<f64>, path: &Path) -> Result<Vec<u8>, StudioError> {
    let (format, name) = (Format::of_path(path), object_name(path));
    let shown = path.display().to_string();
    let refused = |e: String| StudioError::refused(e).of_action("export");
    let exported = |e: splinekit_mesh::export::ExportError| StudioError::Export(e.to_string());
    let mut shape = object.shape.clone();
    if let Some(t) = time {
        shape.set_time(t);
    }
    match &shape {
        ShapeDocument::Curve(c) => {
            let (points, closed, dim) = c.build()?.visit(CurvePoints(object.style.density.unwrap_or(1000)))?;
            let format = Subject::Curve.check(format, &shown).map_err(refused)?;
            match format {
                Format::Svg => polyline_svg(&points, closed, dim).map(String::into_bytes),
                _ => polyline_bytes(&points, closed, &name, format),
            }
            .map_err(exported)
        }
        ShapeDocument::Surface(s) => {
            let mesh = s.build()?.visit(SurfaceMesh(object.style.density.unwrap_or(64)))?;
            let format = Subject::Surface.check(format, &shown).map_err(refused)?;
            mesh_bytes(std::borrow::Cow::Owned(mesh), &name, format).map_err(exported)
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
        let e = export(&heart, None, Path::new("h.stl")).expect_err("a curve has no triangles").to_string();
        assert_eq!(e, "export: curves are written as .svg, .obj, .gltf or .glb, not 'h.stl'");
        assert!(export(&heart, None, Path::new("h.svg")).expect("svg").starts_with(b"<svg"));
    }
}
