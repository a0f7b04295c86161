#!/usr/bin/env bash
# The Python package as a user gets it: builds the abi3 wheel once (`maturin build
# --profile python`: release optimisation without debug info; `--release` would add
# debug line tables, a slower link and a wheel of 18 MB instead of 4.6) and the sdist, checks them (twine check
# --strict, abi3audit), installs the wheel into a fresh venv whose PATH has no cargo and
# no rustc, and there runs the whole pytest suite (scipy and geomdl oracles, pickling
# across processes, Dask on a two-worker LocalCluster, the README's example), the stub
# check (mypy.stubtest) and a quick pass of the benchmark. Then the sdist builds and
# installs (a debug build in a fresh target folder: what is checked is that the sdist
# holds everything a build needs), and the render test runs on a debug
# build with the `render` feature (which reuses the workspace's debug build of wgpu), as
# does the tour notebook (docs/tour.ipynb: executed, exported, opened in Chromium).
# The error tests compare messages with the command-line binary given as $1 (default
# target/debug/splinekit). Each part prints the seconds it took.
set -euo pipefail
cd "$(dirname "$0")/.."
root="$(pwd)"
cli="$root/${1:-target/debug/splinekit}"
test -x "$cli" || { echo "python.sh: $cli is missing (cargo build -p splinekit-cli)" >&2; exit 1; }
python="$(bash .ci/install-python.sh --build-tools | tail -n 1)"
venv="$(dirname "$(dirname "$python")")"
# The maturin build backend is called by name: the venv's bin goes first on PATH.
export PATH="$venv/bin:$PATH"
part_started=$SECONDS
part() { echo "-- $1 (previous part: $((SECONDS - part_started)) s)"; part_started=$SECONDS; }

part "wheel and sdist (maturin build --profile python: release optimisation, no debug info; maturin sdist)"
dist="$root/target/dist"
rm -rf "$dist"
maturin build --profile python --quiet -m crates/splinekit-py/Cargo.toml -o "$dist"
maturin sdist -m crates/splinekit-py/Cargo.toml -o "$dist"
wheel="$(ls "$dist"/splinekit-*-cp39-abi3-*.whl)"
sdist="$(ls "$dist"/splinekit-*.tar.gz)"
ls -l "$wheel" "$sdist"

part "twine check --strict, abi3audit"
twine check --strict "$wheel" "$sdist"
abi3audit --strict --report "$wheel"

part "the wheel in a fresh venv without cargo or rustc"
fresh="$root/target/wheel-venv"
rm -rf "$fresh"
python3 -m venv "$fresh"
# PATH without the folders that hold cargo or rustc.
bare_path="$(IFS=:; for d in $PATH; do [ -x "$d/cargo" ] || [ -x "$d/rustc" ] || printf '%s:' "$d"; done)"
bare_path="$fresh/bin:${bare_path%:}"
install_started=$SECONDS
# shellcheck disable=SC2046 # the pinned packages, one word each
env PATH="$bare_path" "$fresh/bin/pip" install --quiet --disable-pip-version-check "$wheel" \
    $(bash .ci/install-python.sh --test-packages)
echo "installed the wheel and the test packages in $((SECONDS - install_started)) s"
in_fresh() { (cd crates/splinekit-py && env PATH="$bare_path" SPLINEKIT_CLI="$cli" "$@"); }
in_fresh sh -c '! command -v cargo && ! command -v rustc' || { echo "python.sh: cargo on the test PATH" >&2; exit 1; }
in_fresh python -c 'import splinekit, sys; p = splinekit.__file__; print("testing", p); sys.exit("site-packages" not in p)'

part "pytest against the wheel"
in_fresh python -m pytest -q tests

part "mypy.stubtest splinekit"
in_fresh python -m mypy.stubtest splinekit

part "quick benchmark"
(cd "$root" && env -u OPENBLAS_CORETYPE -u OPENBLAS_L2_SIZE PATH="$bare_path" python bench/python/bench.py --quick --repeat 1)

part "the sdist holds the sources, builds and installs"
tar -tzf "$sdist" > "$root/target/sdist-files.txt"
for f in pyproject.toml Cargo.lock crates/splinekit-py/Cargo.toml crates/splinekit-py/src/lib.rs \
    crates/splinekit/src/lib.rs crates/splinekit-scene/src/lib.rs crates/splinekit-mesh/src/lib.rs \
    python/splinekit/__init__.py python/splinekit/_splinekit.pyi; do
    grep -q "^splinekit-[0-9.]*/$f$" "$root/target/sdist-files.txt" || { echo "python.sh: the sdist lacks $f" >&2; exit 1; }
done
# Built by pip from the sdist alone (maturin from the build venv), in debug, in a target
# folder of its own made afresh: the sdist's files carry old times, so a target folder
# that already holds a build of the same crates would take that build as up to date even
# where the sources have changed since (cargo hashes a path crate by its place in the
# workspace, which is the same in the sdist).
rm -rf "$root/target/sdist-wheel" "$root/target/sdist-build"
CARGO_TARGET_DIR="$root/target/sdist-build" MATURIN_PEP517_ARGS="--profile dev" "$python" -m pip wheel --quiet \
    --disable-pip-version-check --no-build-isolation --no-deps "$sdist" -w "$root/target/sdist-wheel"
env PATH="$bare_path" "$fresh/bin/pip" install --quiet --disable-pip-version-check --force-reinstall --no-deps \
    "$root"/target/sdist-wheel/splinekit-*.whl
(cd /tmp && env PATH="$bare_path" python -c 'import numpy as np, splinekit as sk; c = sk.Bezier([[0, 0], [1, 2], [2, 0]]); assert np.allclose(c(0.5), [1, 1]); print("built from the sdist:", sk.__file__)')

part "render test (debug build with the render feature)"
VIRTUAL_ENV="$fresh" maturin develop --quiet --profile dev --features render -m crates/splinekit-py/Cargo.toml
in_fresh python -m pytest -q tests -k "render or png or xdg"

part "the tour notebook: executed (nbclient), exported (nbconvert), its views in headless Chromium (.ci/notebook.sh)"
env PATH="$bare_path" bash .ci/notebook.sh "$fresh"
part "done"
