#!/usr/bin/env bash
# cargo-fuzz (libFuzzer) for the fuzz targets under fuzz/ (see fuzz/README.md). Idempotent:
# does nothing when the pinned version is installed. The targets build on the stable
# toolchain with RUSTC_BOOTSTRAP=1 (cargo-fuzz needs -Zsanitizer=address).
set -euo pipefail
version=0.13.2
if cargo fuzz --version 2>/dev/null | grep -q "$version"; then
    echo "fuzz: cargo-fuzz $version present"
    exit 0
fi
cargo install cargo-fuzz --version "$version" --locked --quiet
