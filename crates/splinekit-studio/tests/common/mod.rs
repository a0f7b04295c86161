//! What the live-path tests share: a studio on a document's text, and the item-by-item
//! comparison of two composed scenes (meshes, lines and points, bit for bit).

use splinekit_render::RenderScene;
use splinekit_studio::studio::Studio;

/// A studio on the scene or shape document `text` (which must be valid).
pub fn studio(text: &str) -> Studio {
    Studio::new(splinekit_studio::document::parse(text).expect("a valid scene"), None)
}

/// Asserts that `a` and `b` hold the same meshes, lines and points, float for float (the
/// camera and the drawing order are the caller's to compare).
pub fn assert_same_items(a: &RenderScene, b: &RenderScene, what: &str) {
    assert_eq!(a.meshes.len(), b.meshes.len(), "{what}: meshes");
    for (m, n) in a.meshes.iter().zip(&b.meshes) {
        assert!(m.positions == n.positions && m.normals == n.normals, "{what}: mesh vertices differ");
        assert!(m.triangles == n.triangles && m.colors == n.colors && m.color == n.color, "{what}: mesh");
    }
    assert_eq!(a.lines.len(), b.lines.len(), "{what}: lines");
    for (i, (l, m)) in a.lines.iter().zip(&b.lines).enumerate() {
        assert!(l.points == m.points && l.color == m.color && l.width == m.width, "{what}: line {i} differs");
    }
    let points = |s: &RenderScene| s.points.iter().map(|p| (p.position, p.color, p.size)).collect::<Vec<_>>();
    assert_eq!(points(a), points(b), "{what}: points");
}
