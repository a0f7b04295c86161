// The parts of three.js the gallery's viewer (crates/splinekit-cli/src/gallery/viewer.js)
// uses, bundled by build_vendor.mjs into one classic script that defines the global
// `SplinekitThree` — a page opened from file:// cannot import ES modules in Chromium.
export {
    AnimationMixer,
    Box3,
    Color,
    DirectionalLight,
    HemisphereLight,
    LoopRepeat,
    OrthographicCamera,
    PerspectiveCamera,
    REVISION,
    SRGBColorSpace,
    Scene,
    Vector3,
    WebGLRenderer,
} from 'three';
export { GLTFLoader } from 'three/addons/loaders/GLTFLoader.js';
export { OrbitControls } from 'three/addons/controls/OrbitControls.js';
export { LineMaterial } from 'three/addons/lines/LineMaterial.js';
export { LineSegments2 } from 'three/addons/lines/LineSegments2.js';
export { LineSegmentsGeometry } from 'three/addons/lines/LineSegmentsGeometry.js';
