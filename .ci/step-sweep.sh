#!/usr/bin/env bash
# Every example document (examples/**/*.json) through `splinekit convert X -o X.step` at
# the default tolerance, then judged by OpenCASCADE (tests/step/ocp_judge.py: read with no
# failed entity, every object evaluated at the report's parameters within its tolerance,
# faces checked for validity, area and inside/outside). Prints a table: file, conversion
# time, the worst measured deviation and its tolerance, OCC's verdict. Exit 1 on any
# failure.
# usage: .ci/step-sweep.sh PATH/TO/splinekit [FILE.json ...]   (default: every example)
set -uo pipefail
cd "$(dirname "$0")/.."
bin="$1"
shift
py="$(bash .ci/install-ocp.sh | tail -n 1)"
out=target/step-sweep
rm -rf "$out" && mkdir -p "$out"
# The blending surfaces over the icosphere (80 triangles, one STEP item each) take four
# minutes each to approximate in a debug build; .ci/step-judge.sh judges the same kind of
# document, one item per triangle, on an octahedron (tests/step/shapes/blending_octahedron.json).
if [ $# -gt 0 ]; then files=("$@"); else mapfile -t files < <(find examples -name '*.json' | grep -v -e blending_sphere_moved -e blending_sphere_animated | sort); fi
failed=0
printf '| file | time (s) | objects | worst deviation / tolerance | OCC |\n| --- | ---: | ---: | --- | --- |\n'
for f in "${files[@]}"; do
    n=$(echo "${f#examples/}" | tr / _)
    n=${n%.json}
    start=$(date +%s.%N)
    if "$bin" convert "$f" -o "$out/$n.step" --report "$out/$n.report.json" 2>"$out/$n.log"; then
        secs=$(echo "$(date +%s.%N) - $start" | bc)
        dev=$("$py" tests/step/sweep_row.py "$out/$n.report.json")
        if "$py" tests/step/ocp_judge.py "$out/$n.step" "$out/$n.report.json" >"$out/$n.judge" 2>/dev/null; then
            verdict="$(tail -n 1 "$out/$n.judge")"
        else
            verdict="FAIL: $(grep -m1 FAIL "$out/$n.judge" || tail -n 1 "$out/$n.judge")"
            failed=1
        fi
    else
        secs=$(echo "$(date +%s.%N) - $start" | bc)
        dev="- | -"
        verdict="convert failed: $(tail -n 1 "$out/$n.log")"
        failed=1
    fi
    printf '| %s | %.1f | %s | %s |\n' "$f" "$secs" "$dev" "$verdict"
done
exit $failed
