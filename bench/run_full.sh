#!/usr/bin/env bash
# Builds obbsat in Release and runs the whole benchmark suite, keeping the
# results per machine and date under bench/results/ so a regression shows up
# in a diff:
#   <machine>_<date>.json         obbsat_bench, Google Benchmark JSON
#   <machine>_<date>.md           the same as markdown tables (summarize.py)
#   <machine>_<date>_limits.json  obbsat_machine_limits: the roofline's ceilings
# <machine> is a slug of the CPU model and core count (set OBBSAT_BENCH_MACHINE
# to name it yourself). Files appear only once their run has succeeded.
#
# Usage: bench/run_full.sh [extra obbsat_bench arguments, e.g. --benchmark_filter=...]
# Environment: OBBSAT_BUILD_DIR (default build-release), OBBSAT_BENCH_JOBS (default 2).
# About 10 minutes on 2 cores with three methods (each adds about 2.5), before
# the whole-scene rows (scene/, frame/, peer_scene/, peer_frame/), whose 10^6
# and 4·10^6-box rows add more, not yet measured (OBBSAT_BENCH_SCENE_BOXES picks
# their sizes); give it an otherwise idle machine, since the 2-thread rows
# need both cores.
set -euo pipefail

repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${OBBSAT_BUILD_DIR:-$repo/build-release}"
jobs="${OBBSAT_BENCH_JOBS:-2}"

cpu_slug() {
    local model
    model="$(grep -m1 '^model name' /proc/cpuinfo 2>/dev/null | cut -d: -f2- || true)"
    [ -n "$model" ] || model="$(uname -m)"
    model="$(printf '%s' "$model" | tr '[:upper:]' '[:lower:]' |
        sed -e 's/([^)]*)//g' -e 's/ cpu / /g' -e 's/@.*$//' -e 's/[^a-z0-9]\+/-/g' -e 's/^-//' -e 's/-$//')"
    printf '%s-%sc' "$model" "$(nproc)"
}

machine="${OBBSAT_BENCH_MACHINE:-$(cpu_slug)}"
date="$(date -u +%Y-%m-%d)"
results="$repo/bench/results"
stem="$results/${machine}_${date}"

cmake -S "$repo" -B "$build" -DCMAKE_BUILD_TYPE=Release -DOBBSAT_BUILD_TESTS=OFF \
    -DOBBSAT_BUILD_BENCH=ON
cmake --build "$build" -j "$jobs" --target obbsat_bench obbsat_machine_limits

mkdir -p "$results"
work="$(mktemp -d "$build/bench-run.XXXXXX")"
trap 'rm -rf "$work"' EXIT

"$build/bench/obbsat_machine_limits" --json "$work/limits.json"

# 0.2 s per measurement, 3 repetitions reported as mean/median/stddev/cv.
"$build/bench/obbsat_bench" \
    --benchmark_min_time=0.2 \
    --benchmark_repetitions=3 \
    --benchmark_report_aggregates_only=true \
    --benchmark_out="$work/bench.json" \
    --benchmark_out_format=json \
    "$@"

python3 "$repo/bench/summarize.py" "$work/bench.json" > "$work/bench.md"

mv "$work/limits.json" "${stem}_limits.json"
mv "$work/bench.json" "${stem}.json"
mv "$work/bench.md" "${stem}.md"
echo "wrote ${stem}.json, ${stem}.md and ${stem}_limits.json"
