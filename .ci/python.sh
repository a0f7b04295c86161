#!/usr/bin/env bash
# The Python package: installs it the way the README says (pip install ./crates/splinekit-py,
# maturin's build with the workspace's `python` profile) into the project's venv
# (.ci/install-python.sh), runs its pytest suite against scipy and geomdl and a quick pass
# of the benchmark, then the render test on a debug build with the `render` feature
# (which reuses the workspace's debug build of wgpu). The error tests compare messages
# with the command-line binary given as $1 (default target/debug/splinekit).
set -euo pipefail
cd "$(dirname "$0")/.."
root="$(pwd)"
cli="${1:-target/debug/splinekit}"
test -x "$cli" || { echo "python.sh: $cli is missing (cargo build -p splinekit-cli)" >&2; exit 1; }
python="$(bash .ci/install-python.sh | tail -n 1)"
venv="$(dirname "$(dirname "$python")")"
# The maturin build backend is called by name: the venv's bin goes first on PATH.
export PATH="$venv/bin:$PATH"
"$python" -m pip install --quiet --disable-pip-version-check --no-build-isolation --force-reinstall --no-deps ./crates/splinekit-py
(cd crates/splinekit-py && SPLINEKIT_CLI="$root/$cli" "$python" -m pytest -q tests)
env -u OPENBLAS_CORETYPE -u OPENBLAS_L2_SIZE "$python" bench/python/bench.py --quick --repeat 1
VIRTUAL_ENV="$venv" maturin develop --quiet --profile dev --features render -m crates/splinekit-py/Cargo.toml
(cd crates/splinekit-py && "$python" -m pytest -q tests -k render)
