#!/usr/bin/env bash
# Records what the command line makes of every example document, so that a refactoring
# can be checked byte for byte: `bash tools/behaviour_snapshot.sh BIN OUT [EXTRA_DIR]`
# writes into OUT, for each JSON document of examples/scenes, examples/shapes,
# fuzz/seeds/document and EXTRA_DIR (e.g. every registry kind's example document): eval
# (curve samples or a surface grid, two derivatives), tessellate (.obj, .glb; .svg for
# curves; an adaptive .obj at tolerance 0.01), convert to STEP with its report, each with its
# standard error and exit status; and subdivide-surface of every cage in examples/meshes by
# every scheme (2 steps, and with --limit). Two snapshots of one binary compared show output
# that changes from run to run (hash order, threads).
# `bash tools/behaviour_snapshot.sh --compare A B` compares two such folders byte for byte,
# but for the folder's name inside messages and STEP's FILE_NAME (the time of writing).
set -uo pipefail
if [ "${1:-}" = --compare ]; then
    a="$2"; b="$3"; bad=0
    for f in "$a"/*; do
        g="$b/${f#"$a"/}"
        if ! cmp -s <(grep -av FILE_NAME "$f" | sed "s#$a/##g") <(grep -av FILE_NAME "$g" | sed "s#$b/##g"); then
            echo "differs: ${f#"$a"/}"; bad=1
        fi
    done
    [ "$(ls "$a" | wc -l)" = "$(ls "$b" | wc -l)" ] || { echo "file counts differ"; bad=1; }
    [ $bad = 0 ] && echo "same: $(ls "$a" | wc -l) outputs"
    exit $bad
fi
bin="$(realpath "$1")"; out="$2"; extra="${3:-}"
mkdir -p "$out"
docs=(examples/scenes/*.json examples/shapes/*.json fuzz/seeds/document/*.json)
[ -n "$extra" ] && docs+=("$extra"/*.json)
for doc in "${docs[@]}"; do
    name="$(echo "$doc" | tr '/' '_')"
    o="$out/$name"
    run() { local tag="$1"; shift; "$bin" "$@" >"$o.$tag.out" 2>"$o.$tag.err"; echo $? >"$o.$tag.rc"; }
    run eval_curve eval --samples 17 --derivatives 2 "$doc"
    run eval_surface eval --grid 5,5 --derivatives 2 "$doc"
    run obj tessellate -o "$o.obj" "$doc"
    run glb tessellate -o "$o.glb" "$doc"
    run svg tessellate -o "$o.svg" "$doc"
    run step convert -o "$o.step" --report "$o.report.json" "$doc"
    run adaptive tessellate --tolerance 0.01 -o "$o.adaptive.obj" "$doc"
done
# Subdivision of every example cage by every scheme, and with vertices on the limit.
for mesh in examples/meshes/*.obj; do
    for scheme in catmull-clark loop bilinear doo-sabin; do
        o="$out/$(echo "$mesh" | tr '/' '_').$scheme"
        run() { local tag="$1"; shift; "$bin" "$@" >"$o.$tag.out" 2>"$o.$tag.err"; echo $? >"$o.$tag.rc"; }
        run steps subdivide-surface --scheme "$scheme" --triangulate --steps 2 -o "$o.obj" "$mesh"
        run limit subdivide-surface --scheme "$scheme" --triangulate --steps 2 --limit -o "$o.limit.obj" "$mesh"
    done
done
echo "$(ls "$out" | wc -l) files in $out"
