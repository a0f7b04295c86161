#!/usr/bin/env bash
# Side-by-side evaluation speed: splinekit, curvo, truck-geometry, scipy and Splipy, one run;
# then the query benchmarks of issue 14 that curvo can answer, splinekit beside curvo in one
# process (src/bin/queries.rs: curve-curve intersection, projections onto the bicubic patch
# and onto a wavy curve; answers checked against each other; the OpenCASCADE ratios of the
# same shapes come from bench/ocp/speed.py).
# Usage: [PYTHON=python] bash bench/peers/run.sh [QUERY_REPEATS]   (installs scipy and splipy with pip if missing;
# QUERY_REPEATS defaults to 11; curvo's surface projections take ~12 s a repeat)
set -euo pipefail
cd "$(dirname "$0")"
cargo build --release --quiet
python="${PYTHON:-python3}"   # PYTHON=…/py-venv/bin/python uses the venv of .ci/install-python.sh
"$python" -c "import scipy, splipy" 2>/dev/null || "$python" -m pip install --quiet scipy numpy splipy
{
  ./target/release/splinekit-peers
  "$python" scipy_bench.py
} > results.tsv
python3 - <<'PY'
rows = [l.rstrip("\n").split("\t") for l in open("results.tsv")]
ours = {r[1]: float(r[2]) for r in rows if r[0] == "splinekit"}
floor = {r[1]: float(r[2]) for r in rows if r[0].startswith("floor")}
print(f"{'library':<22} {'workload':<32} {'ns/eval':>9} {'× splinekit':>12} {'× floor':>8}  checksum")
for lib, what, ns, check in rows:
    f = f"{float(ns) / floor[what]:8.1f}" if what in floor else " " * 8
    print(f"{lib:<22} {what:<32} {float(ns):>9.2f} {float(ns) / ours[what]:>12.1f} {f}  {check}")
PY
echo
./target/release/queries "${1:-11}"
