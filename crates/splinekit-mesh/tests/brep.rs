//! Watertight meshes of B-reps, and the exact area and volume integrals, on shapes whose
//! area and volume are known.

use splinekit::brep::integrals;
use splinekit_mesh::brep_mesh::{brep_mesh, open_edges};
use splinekit_scene::surfaces::BrepDoc;

#[test]
fn the_unit_cube_meshes_closed_with_its_volume_and_area() {
    let brep = BrepDoc::cube().build().unwrap();
    let mesh = brep_mesh(&brep, 1e-3).unwrap();
    assert_eq!(open_edges(&mesh), 0);
    assert!((mesh.signed_volume() - 1.0).abs() < 1e-12, "{}", mesh.signed_volume());
    assert!((mesh.area() - 6.0).abs() < 1e-12, "{}", mesh.area());
    assert!((integrals::area(&brep) - 6.0).abs() < 1e-12);
    assert!((integrals::volume(&brep, &[0]).unwrap() - 1.0).abs() < 1e-12);
}

#[test]
fn a_face_turned_the_wrong_way_shows_in_the_mesh() {
    let mut doc = BrepDoc::cube();
    doc.faces[1].reversed = !doc.faces[1].reversed;
    let mesh = brep_mesh(&doc.build().unwrap(), 1e-3).unwrap();
    // Its triangles turn the other way: each of its four edges is used twice one way and
    // never the other.
    assert_eq!(open_edges(&mesh), 4);
}
