//! Shape and scene documents from arbitrary text: parsing never panics, and a document
//! whose estimated cost fits a small budget builds (or is refused with an error) without
//! panicking.
#![no_main]

use libfuzzer_sys::fuzz_target;
use splinekit_scene::budget::Budget;
use splinekit_scene::{SceneOrShape, ShapeDocument};

fuzz_target!(|data: &[u8]| {
    let Ok(text) = std::str::from_utf8(data) else { return };
    let budget = Budget { max_bytes: 64e6, max_work: 1e7 };
    match SceneOrShape::from_json(text) {
        Ok(SceneOrShape::Shape(doc)) => build(&doc, &budget),
        Ok(SceneOrShape::Scene(scene)) => scene.objects.iter().for_each(|o| build(&o.shape, &budget)),
        Err(e) => assert!(!e.to_string().is_empty()),
    }
});

fn build(doc: &ShapeDocument, budget: &Budget) {
    if budget.check_shape(&doc.cost()).is_err() {
        return;
    }
    let _ = match doc {
        ShapeDocument::Curve(c) => c.build().map(|_| ()),
        ShapeDocument::Surface(s) => s.build().map(|_| ()),
    };
}
