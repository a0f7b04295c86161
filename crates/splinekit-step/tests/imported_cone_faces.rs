//! A cone's face as OpenCASCADE writes it (tests/fixtures/occ_cone_face.step: the lateral
//! face of `BRepPrimAPI_MakeCone(ax, 2, 0.5, 3, 5 rad)`), whose generatrix edges are LINEs
//! parametrised by length with LINE pcurves of constant u parametrised by the height v.
//! ISO 10303-42 lets a pcurve have any speed and start; the second fixture is the same face
//! with both generatrix pcurves reparametrised (origin moved along v, the VECTOR's magnitude
//! 2 and 0.5 instead of 1). Both must come back as the same face, whose boundary passes
//! through the face's four vertices.

use splinekit_scene::{ShapeDocument, SurfaceDocument};
use splinekit_step::documents::import_items;
use splinekit_step::part21::StepFile;

fn import(name: &str) -> ShapeDocument {
    let path = format!("{}/tests/fixtures/{name}", env!("CARGO_MANIFEST_DIR"));
    let file = StepFile::from_bytes(std::fs::read(path).unwrap()).unwrap();
    let imported = import_items(&file).unwrap();
    assert_eq!(imported.items.len(), 1, "{name}");
    // Everything is read: the representation's own placement is structure, not geometry
    // left behind.
    assert!(imported.not_understood.is_empty(), "{name}: {:?}", imported.not_understood);
    imported.items[0].document.clone()
}

#[test]
fn generatrix_pcurves_of_any_speed_and_start_give_the_same_face() {
    let original = import("occ_cone_face.step");
    let rescaled = import("occ_cone_face_rescaled_pcurves.step");
    assert_eq!(rescaled, original);

    // The outer loop's corners, mapped through the surface, are the face's vertices: the
    // ends of the two generatrices (x, y) = r (cos u, sin u) at z = 0 (r = 2) and z = 3
    // (r = 0.5), at the angles 0 and 5 about z.
    let ShapeDocument::Surface(SurfaceDocument::Trimmed(face)) = &original else { panic!("not a face: {original:?}") };
    let surface = face.surface.build_in::<3>().unwrap();
    let outer = face.outer.as_ref().expect("an outer loop").build_in::<2>().unwrap();
    let d = outer.domain();
    let mut corners: Vec<[f64; 3]> = (0..4)
        .map(|k| {
            let uv = outer.point(d.lerp(k as f64 / 4.0));
            let p = surface.point(uv[0], uv[1]);
            [p[0], p[1], p[2]]
        })
        .collect();
    let mut expected: Vec<[f64; 3]> = [(2.0, 0.0, 0.0), (0.5, 0.0, 3.0), (2.0, 5.0, 0.0), (0.5, 5.0, 3.0)]
        .iter()
        .map(|&(r, u, z): &(f64, f64, f64)| [r * u.cos(), r * u.sin(), z])
        .collect();
    let key = |p: &[f64; 3]| (p[2] * 10.0).round() as i64 * 100 + (p[1] * 10.0).round() as i64;
    corners.sort_by_key(key);
    expected.sort_by_key(key);
    for (c, e) in corners.iter().zip(&expected) {
        let gap = (0..3).map(|k| (c[k] - e[k]).abs()).fold(0.0, f64::max);
        assert!(gap < 1e-9, "corner {c:?} is {gap:e} from the vertex {e:?}");
    }
}
