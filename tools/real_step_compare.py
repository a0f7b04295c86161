#!/usr/bin/env python3
"""Measures every real CAD part of tests/step/real/ with `splinekit measure` and compares
it with OpenCASCADE's reading of the same file (occ_reference.json): faces, solids, the
exact area and volume, and the watertight mesh's open edges.

    cargo build --release -p splinekit-cli
    python3 tools/real_step_compare.py target/release/splinekit [FILE …]

Prints one line per file, relative errors against OpenCASCADE and the seconds taken; exits
1 when a file fails to read. The debug-sized subset is checked in CI by
crates/splinekit-cli/tests/real_step.rs.
"""
import json
import os
import subprocess
import sys
import time

HERE = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "tests", "step", "real")


def main():
    binary = sys.argv[1]
    reference = json.load(open(os.path.join(HERE, "occ_reference.json")))
    files = sys.argv[2:] or sorted(k for k in reference if not k.startswith("_"))
    failed = 0
    for name in files:
        ref = reference[name]
        start = time.perf_counter()
        run = subprocess.run([binary, "measure", os.path.join(HERE, name)], capture_output=True, text=True)
        seconds = time.perf_counter() - start
        if run.returncode != 0:
            print(f"{name:42s} FAILED: {run.stderr.strip()}")
            failed += 1
            continue
        m = json.loads(run.stdout)
        parts = m["objects"] if "objects" in m else [m]
        faces = sum(p["faces"] for p in parts)
        area = sum(p["area"] for p in parts)
        volumes = [s["volume"] for p in parts for s in p["solids"]]
        volume = sum(v for v in volumes if v is not None)
        open_edges = sum(p["mesh"]["open_edges"] for p in parts)
        ra, rv = ref["area"], ref["volume_total"]
        print(
            f"{name:42s} faces {faces}/{ref['counts']['faces']} solids {len(volumes)}/{ref['counts']['solids']}"
            f" area {abs(area - ra) / ra:.1e} volume {abs(volume - rv) / abs(rv):.1e}"
            f" open edges {open_edges} {seconds:.1f} s (OpenCASCADE read+mesh {ref['times_s']['read_plus_transfer'] + ref['times_s']['mesh']:.2f} s)"
        )
    sys.exit(1 if failed else 0)


if __name__ == "__main__":
    main()
