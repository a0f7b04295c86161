//! Watertight meshes of B-reps, and the exact area and volume integrals, on shapes whose
//! area and volume are known.

use std::collections::HashMap;

use splinekit::brep::integrals;
use splinekit_mesh::TriangleMesh;
use splinekit_mesh::brep_mesh::brep_mesh;
use splinekit_scene::surfaces::BrepDoc;

/// Welded by exact position: every directed edge used once and its reverse once (a closed,
/// consistently oriented 2-manifold); the number of edges that are not.
fn open_edges(mesh: &TriangleMesh) -> usize {
    let mut ids: HashMap<[u64; 3], u32> = HashMap::new();
    let key = |p: [f64; 3]| p.map(f64::to_bits);
    let welded: Vec<u32> = mesh
        .positions
        .iter()
        .map(|&p| {
            let n = ids.len() as u32;
            *ids.entry(key(p)).or_insert(n)
        })
        .collect();
    let mut uses: HashMap<(u32, u32), usize> = HashMap::new();
    for t in &mesh.triangles {
        let [a, b, c] = t.map(|i| welded[i as usize]);
        for e in [(a, b), (b, c), (c, a)] {
            *uses.entry(e).or_default() += 1;
        }
    }
    uses.iter().filter(|(e, n)| **n != 1 || uses.get(&(e.1, e.0)) != Some(&1)).count()
}

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
