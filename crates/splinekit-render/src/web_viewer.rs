//! The web viewer's pinned three.js: one classic script defining the global
//! `SplinekitThree` (WebGLRenderer, GLTFLoader, OrbitControls, wide lines), bundled by
//! `tools/browser/build_vendor.mjs` from the versions its lock file pins, and three's
//! licence. The gallery writes it beside its pages; the Python package embeds it in the
//! notebook views of shapes and scenes.

/// three.js with GLTFLoader and OrbitControls, one classic script defining `SplinekitThree`.
pub const THREE_BUNDLE: &str = include_str!("../vendor/three-gltf-orbit.min.js");
/// three.js's licence (MIT), shipped beside the bundle.
pub const THREE_LICENSE: &str = include_str!("../vendor/three-LICENSE");

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_bundle_defines_the_global_and_names_its_version() {
        assert!(THREE_BUNDLE.starts_with("/* three.js "), "the bundle names its three.js version first");
        assert!(THREE_BUNDLE.contains("var SplinekitThree="));
        assert!(THREE_LICENSE.contains("MIT License"));
    }
}
