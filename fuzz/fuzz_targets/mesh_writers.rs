//! Every mesh writer (OBJ, STL binary and ASCII, PLY, glTF, glb, SVG) on triangle meshes
//! made from arbitrary OBJ text, values of any magnitude included: never a panic.
#![no_main]

use libfuzzer_sys::fuzz_target;
use splinekit::Point;
use splinekit_mesh::export::{Format, GltfGeometry, GltfScene, obj, ply, stl};
use splinekit_mesh::subdivision_surface::read_obj_polygons;
use splinekit_mesh::{Projection, SvgFigure};

fuzz_target!(|data: &[u8]| {
    let Ok(text) = std::str::from_utf8(data) else { return };
    let Ok(polygons) = read_obj_polygons(text) else { return };
    if polygons.faces.iter().map(Vec::len).sum::<usize>() > 4096 || polygons.faces.iter().any(|f| f.len() < 3) {
        return;
    }
    let mesh = polygons.triangulate();
    let _ = obj::write_obj(&mesh, "fuzz", Vec::new());
    let _ = stl::write_stl_binary(&mesh, Vec::new());
    let _ = stl::write_stl_ascii(&mesh, "fuzz", Vec::new());
    let _ = ply::write_ply(&mesh, Vec::new());
    let color = [0.5, 0.5, 0.5, 1.0];
    let _ = GltfScene::single("fuzz", GltfGeometry::Mesh(mesh.clone()), color).to_format_bytes(Format::Glb);
    let _ =
        GltfScene::single("fuzz", GltfGeometry::LineStrip(mesh.positions.clone()), color).to_format_bytes(Format::Gltf);
    let _ = obj::write_obj_polyline(&mesh.positions, true, "fuzz", Vec::new());
    let points: Vec<Point<3>> = mesh.positions.iter().map(|p| Point::<3>::from(*p)).collect();
    let mut figure = SvgFigure::new(200.0, 100.0, Projection::view(0.6, 0.45));
    figure.path(&points, false, "#000", 1.0);
    let _ = figure.render();
});
