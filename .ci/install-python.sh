#!/usr/bin/env bash
# The Python tools for crates/splinekit-py in a virtual environment: maturin (builds the
# extension), pytest, and the oracles and peers of the tests and benchmarks (numpy, scipy,
# geomdl, splipy). Pinned versions; idempotent: does nothing when the venv already has
# them all. Prints the venv's python on its last line.
set -euo pipefail
venv="${SPLINEKIT_PY_VENV:-$HOME/.cache/splinekit/py-venv}"
packages=(maturin==1.16.0 pytest==9.2.0 numpy==2.4.6 scipy==1.17.1 geomdl==5.4.0 splipy==1.10.1)
stamp="$venv/.splinekit-packages"
if [ "$(cat "$stamp" 2>/dev/null)" != "${packages[*]}" ] || ! "$venv/bin/python" -c "import maturin, pytest, numpy, scipy, geomdl, splipy" >/dev/null 2>&1; then
    rm -rf "$venv"
    mkdir -p "$(dirname "$venv")"
    python3 -m venv "$venv"
    "$venv/bin/pip" install --quiet --disable-pip-version-check "${packages[@]}" >&2
    echo "${packages[*]}" > "$stamp"
fi
echo "$venv/bin/python"
