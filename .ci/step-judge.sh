#!/usr/bin/env bash
# OpenCASCADE judges splinekit's STEP export (tests/step/ocp_judge.py): the exact forms
# and a set of example documents are converted with their reports, then read by OCP's
# STEPControl_Reader and evaluated at the reported parameters. Then the import: files OCP
# writes are read back by splinekit (tests/step/ocp_writes.py).
# usage: .ci/step-judge.sh PATH/TO/splinekit
set -euo pipefail
cd "$(dirname "$0")/.."
bin="$1"
py="$(bash .ci/install-ocp.sh | tail -n 1)"
out=target/step-judge
rm -rf "$out" && mkdir -p "$out"
args=()
# The examples quick to approximate in a debug build (the animated blending surfaces
# with moved patches take minutes; they pass the same check in release builds).
for f in tests/step/shapes/{exact_forms,trimmed_faces,natural_bounds,seam_faces}.json examples/scenes/{trimmed_surface,bezier_surface,bspline_polygon,nurbs_torus,surface_of_revolution,torus_gaussian_curvature,coons_patch,rose_and_blending_copy,heart_transformed,seashell,mobius,klein_bottle,sweep_trefoil}.json; do
    n=$(basename "$f" .json)
    "$bin" convert "$f" -o "$out/$n.step" --report "$out/$n.report.json" 2>"$out/$n.log"
    args+=("$out/$n.step" "$out/$n.report.json")
done
# A blending surface over a triangulation leaves one item per triangle, each paired in the
# report with samples of its own triangle (at 1e-4: the debug build's jets are slow).
"$bin" convert tests/step/shapes/blending_octahedron.json -o "$out/blending_octahedron.step" --tolerance 1e-4 \
    --report "$out/blending_octahedron.report.json" 2>"$out/blending_octahedron.log"
args+=("$out/blending_octahedron.step" "$out/blending_octahedron.report.json")
"$py" tests/step/ocp_judge.py "${args[@]}" 2>/dev/null | grep -E '^(ok|FAIL|[0-9]+ passed)'

# The other way: STEP files that OpenCASCADE writes (splines, rational ones, a revolution,
# an extrusion, a plate with a hole, a box) come back with the same geometry and trims.
"$py" tests/step/ocp_writes.py "$bin" "$out/from-occ" 2>/dev/null | grep -E '^(ok|FAIL|[0-9]+ passed)'
