#!/usr/bin/env bash
# Side-by-side evaluation speed: splinekit, curvo, truck-geometry, scipy and Splipy, one run;
# then the query benchmarks of issue 14 that curvo can answer, splinekit beside curvo in one
# process (src/bin/queries.rs: curve-curve intersection, projections onto the bicubic patch
# and onto a wavy curve; answers checked against each other; the OpenCASCADE ratios of the
# same shapes come from bench/ocp/speed.py).
# Usage: bash bench/peers/run.sh [QUERY_REPEATS]   (installs scipy and splipy with pip if missing;
# QUERY_REPEATS defaults to 11; curvo's surface projections take ~12 s a repeat)
set -euo pipefail
cd "$(dirname "$0")"
cargo build --release --quiet
python3 -c "import scipy, splipy" 2>/dev/null || python3 -m pip install --quiet scipy numpy splipy
{
  ./target/release/splinekit-peers
  python3 scipy_bench.py
} > results.tsv
python3 - <<'PY'
rows = [l.rstrip("\n").split("\t") for l in open("results.tsv")]
ours = {r[1]: float(r[2]) for r in rows if r[0] == "splinekit"}
print(f"{'library':<20} {'workload':<26} {'ns/eval':>9} {'× splinekit':>12}  checksum")
for lib, what, ns, check in rows:
    print(f"{lib:<20} {what:<26} {float(ns):>9.2f} {float(ns) / ours[what]:>12.1f}  {check}")
PY
echo
./target/release/queries "${1:-11}"
