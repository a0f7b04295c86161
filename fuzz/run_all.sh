#!/usr/bin/env bash
# Runs every fuzz target for RUNS executions (or SECONDS seconds each, whichever ends
# first) from the committed seeds; logs in fuzz/logs/. Usage: fuzz/run_all.sh RUNS SECONDS
set -euo pipefail
cd "$(dirname "$0")"
runs=${1:-10000000}
seconds=${2:-1200}
mkdir -p logs
export RUSTC_BOOTSTRAP=1
sanitizer=${FUZZ_SANITIZER:-address}
cargo fuzz build -O -s "$sanitizer"
for target in document evaluate obj_subdivision mesh_writers fast_paths; do
    mkdir -p "corpus/$target"
    cargo fuzz run -O -s "$sanitizer" "$target" "corpus/$target" "seeds/$target" -- \
        -runs="$runs" -max_total_time="$seconds" -max_len=8192 -rss_limit_mb=2048 -timeout=20 \
        -print_final_stats=1 > "logs/$target.log" 2>&1 || { echo "$target failed (fuzz/logs/$target.log):"; tail -n 40 "logs/$target.log"; exit 1; }
    grep -E "stat::number_of_executed_units|Done" "logs/$target.log" | tail -2
done
