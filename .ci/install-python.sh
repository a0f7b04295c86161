#!/usr/bin/env bash
# The Python tools for crates/splinekit-py in a virtual environment: maturin (builds the
# wheel and the sdist), twine and abi3audit (check them), and the test packages: pytest,
# the oracles and peers of the tests and benchmarks (numpy, scipy, geomdl, splipy), Dask
# (dask.array, dask.bag, dask.distributed) and mypy (stubtest). Pinned versions;
# idempotent: does nothing when the venv already has them all. Prints the venv's python
# on its last line.
#
# `install-python.sh --test-packages` prints the pinned test packages instead (one line),
# for the fresh venv that .ci/python.sh installs the built wheel into (matplotlib for
# `splinekit.plot`); `--notebook-packages` those that execute and export the tour notebook
# (.ci/notebook.sh);
# `install-python.sh --build-tools` makes a venv of maturin, twine and abi3audit only
# (SPLINEKIT_PY_VENV, default ~/.cache/splinekit/py-build-venv): what CI builds with.
set -euo pipefail
test_packages=(pytest==9.2.0 numpy==2.4.6 scipy==1.17.1 geomdl==5.4.0 splipy==1.10.1
    "dask[array]==2026.8.0" distributed==2026.8.0 mypy==2.4.1 matplotlib==3.11.2)
# What runs and exports the tour notebook (.ci/notebook.sh), beside the test packages.
notebook_packages=(nbclient==0.11.0 nbconvert==7.17.2 nbformat==5.11.1 ipykernel==7.4.0)
if [ "${1:-}" = "--test-packages" ]; then
    echo "${test_packages[*]}"
    exit 0
fi
if [ "${1:-}" = "--notebook-packages" ]; then
    echo "${notebook_packages[*]}"
    exit 0
fi
build_tools=(maturin==1.16.0 twine==7.0.0 abi3audit==0.0.26)
if [ "${1:-}" = "--build-tools" ]; then
    venv="${SPLINEKIT_PY_VENV:-$HOME/.cache/splinekit/py-build-venv}"
    packages=("${build_tools[@]}")
    imports="maturin, twine"
else
    venv="${SPLINEKIT_PY_VENV:-$HOME/.cache/splinekit/py-venv}"
    packages=("${build_tools[@]}" "${test_packages[@]}")
    imports="maturin, twine, pytest, numpy, scipy, geomdl, splipy, dask.array, distributed, mypy"
fi
stamp="$venv/.splinekit-packages"
if [ "$(cat "$stamp" 2>/dev/null)" != "${packages[*]}" ] || ! "$venv/bin/python" -c "import $imports" >/dev/null 2>&1; then
    rm -rf "$venv"
    mkdir -p "$(dirname "$venv")"
    python3 -m venv "$venv"
    "$venv/bin/pip" install --quiet --disable-pip-version-check "${packages[@]}" >&2
    echo "${packages[*]}" > "$stamp"
fi
echo "$venv/bin/python"
