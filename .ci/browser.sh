#!/usr/bin/env bash
# The gallery in a real browser (tools/browser/README.md): checks that the vendored three.js
# bundle is what tools/browser/package-lock.json builds, then opens GALLERY/index.html from
# file:// in headless Chromium and tests every 3-D view, the beating heart's morph weights
# against its glb, screenshots of the playing heart, orbit, zoom and the time bar.
# Usage: .ci/browser.sh [GALLERY]; without GALLERY, the debug build writes one into
# target/gallery-browser (about 3 minutes). Screenshots and measurements go to
# target/browser-test/.
set -euo pipefail
cd "$(dirname "$0")/.."
bash .ci/install-browser.sh
node tools/browser/build_vendor.mjs --check

gallery="${1:-}"
if [ -z "$gallery" ]; then
    cargo build -p splinekit-cli --locked -q
    gallery=target/gallery-browser
    target/debug/splinekit gallery -o "$gallery"
fi
node tools/browser/gallery_test.mjs "$gallery" --out target/browser-test
