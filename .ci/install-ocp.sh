#!/usr/bin/env bash
# OpenCASCADE through OCP (pip cadquery-ocp-novtk) in a virtual environment, for the
# comparison of geometric queries (bench/ocp/queries.py). Idempotent: does nothing when the
# venv already imports OCP. Prints the venv's python on its last line.
set -euo pipefail
venv="${SPLINEKIT_OCP_VENV:-$HOME/.cache/splinekit/ocp-venv}"
if ! "$venv/bin/python" -c "import OCP.Geom" >/dev/null 2>&1; then
    rm -rf "$venv"
    mkdir -p "$(dirname "$venv")"
    python3 -m venv "$venv"
    "$venv/bin/pip" install --quiet --disable-pip-version-check "cadquery-ocp-novtk==8.0.1.1.0"
fi
echo "$venv/bin/python"
