//! OBJ text read as a polygon mesh, then subdivided by Catmull–Clark and Doo–Sabin: errors
//! for bad meshes, never a panic.
#![no_main]

use libfuzzer_sys::fuzz_target;
use splinekit_mesh::subdivision_surface::{SurfaceScheme, read_obj_polygons};

fuzz_target!(|data: &[u8]| {
    let Ok(text) = std::str::from_utf8(data) else { return };
    let Ok(mesh) = read_obj_polygons(text) else { return };
    let corners: usize = mesh.faces.iter().map(Vec::len).sum();
    if corners > 4096 {
        return;
    }
    for scheme in [SurfaceScheme::CatmullClark, SurfaceScheme::DooSabin] {
        if let Ok(out) = mesh.subdivide(scheme, 2) {
            let _ = out.triangulate();
        }
    }
});
