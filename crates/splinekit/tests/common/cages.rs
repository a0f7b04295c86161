//! Cages shared by the subdivision tests.
#![allow(dead_code)]

use splinekit::Point;
use splinekit::subdivision::surface::Cage;

/// The regular icosahedron on the unit sphere: twelve vertices of valence 5 (each at
/// 1/√5 in dot product with its five neighbours), twenty triangles, outward.
pub fn icosahedron() -> Cage {
    let t = (1.0 + 5f64.sqrt()) / 2.0;
    let p = |x: f64, y: f64, z: f64| Point::<3>::new(x, y, z);
    let raw = [
        p(-1.0, t, 0.0),
        p(1.0, t, 0.0),
        p(-1.0, -t, 0.0),
        p(1.0, -t, 0.0),
        p(0.0, -1.0, t),
        p(0.0, 1.0, t),
        p(0.0, -1.0, -t),
        p(0.0, 1.0, -t),
        p(t, 0.0, -1.0),
        p(t, 0.0, 1.0),
        p(-t, 0.0, -1.0),
        p(-t, 0.0, 1.0),
    ];
    let faces: Vec<Vec<u32>> = [
        [0, 11, 5],
        [0, 5, 1],
        [0, 1, 7],
        [0, 7, 10],
        [0, 10, 11],
        [1, 5, 9],
        [5, 11, 4],
        [11, 10, 2],
        [10, 7, 6],
        [7, 1, 8],
        [3, 9, 4],
        [3, 4, 2],
        [3, 2, 6],
        [3, 6, 8],
        [3, 8, 9],
        [4, 9, 5],
        [2, 4, 11],
        [6, 2, 10],
        [8, 6, 7],
        [9, 8, 1],
    ]
    .iter()
    .map(|f| f.to_vec())
    .collect();
    Cage::new(raw.iter().map(|x| x / x.norm()).collect(), &faces)
}
