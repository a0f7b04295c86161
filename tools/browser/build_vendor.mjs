// Bundles the pinned three.js (package-lock.json) into the gallery's vendored viewer
// library, crates/splinekit-render/vendor/three-gltf-orbit.min.js, with three's
// licence beside it. `node build_vendor.mjs --check` rebuilds in memory and fails when the
// committed file differs: the vendored bytes are what the lock file gives.
import { build } from 'esbuild';
import { readFileSync, writeFileSync } from 'node:fs';
import { dirname, join } from 'node:path';
import { fileURLToPath } from 'node:url';

const here = dirname(fileURLToPath(import.meta.url));
const vendor = join(here, '../../crates/splinekit-render/vendor');
const bundlePath = join(vendor, 'three-gltf-orbit.min.js');
const licencePath = join(vendor, 'three-LICENSE');
const three = JSON.parse(readFileSync(join(here, 'node_modules/three/package.json'), 'utf8'));
const esbuildVersion = JSON.parse(readFileSync(join(here, 'node_modules/esbuild/package.json'), 'utf8')).version;

const result = await build({
    entryPoints: [join(here, 'vendor_entry.js')],
    bundle: true,
    minify: true,
    format: 'iife',
    globalName: 'SplinekitThree',
    target: 'es2020',
    legalComments: 'none',
    write: false,
    banner: {
        js:
            `/* three.js ${three.version} (MIT licence, three-LICENSE): WebGLRenderer, GLTFLoader, OrbitControls, wide lines and ` +
            `what they need, bundled by esbuild ${esbuildVersion} from tools/browser/vendor_entry.js ` +
            `(tools/browser/build_vendor.mjs) */`,
    },
});
const bundle = result.outputFiles[0].text;
const licence = readFileSync(join(here, 'node_modules/three/LICENSE'), 'utf8');

if (process.argv.includes('--check')) {
    const stale = [
        [bundlePath, bundle],
        [licencePath, licence],
    ].filter(([path, text]) => {
        try {
            return readFileSync(path, 'utf8') !== text;
        } catch {
            return true;
        }
    });
    if (stale.length > 0) {
        console.error(`vendor: ${stale.map(([p]) => p).join(', ')} differ from what the lock file builds; run npm run vendor in tools/browser`);
        process.exit(1);
    }
    console.log(`vendor: three.js ${three.version} bundle (${bundle.length} bytes) matches the lock file`);
} else {
    writeFileSync(bundlePath, bundle);
    writeFileSync(licencePath, licence);
    console.log(`vendor: wrote ${bundlePath} (${bundle.length} bytes), three.js ${three.version}`);
}
