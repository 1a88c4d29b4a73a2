#!/usr/bin/env bash
# Builds the fuzz targets (CMake preset "fuzz", clang with libFuzzer,
# AddressSanitizer and UndefinedBehaviorSanitizer) if needed, then runs one
# target for a number of seconds and prints how many inputs it executed.
#   bash tests/fuzz/run.sh fuzz_backends 600
#   bash tests/fuzz/run.sh fuzz_csv 30
# Inputs found are kept in build-fuzz/corpus/TARGET (the seeds stay in
# tests/fuzz/corpus/TARGET, untouched); a failing input is written to
# build-fuzz/artifacts/ and the exit status is non-zero. OBBSAT_ISA_KERNELS,
# when set, is the list of x86 kernels the first configure compiles
# (kernel/CMakeLists.txt; .ci/run passes the ones this CPU runs).
set -euo pipefail
cd "$(dirname "$0")/../.."

usage() { echo "usage: bash tests/fuzz/run.sh fuzz_backends|fuzz_pose_backends|fuzz_csv SECONDS" >&2; exit 2; }
[ $# -eq 2 ] || usage
target=$1
seconds=$2
case "$target" in
  fuzz_backends) max_len=2048 ;;
  fuzz_pose_backends) max_len=2048 ;;
  fuzz_csv) max_len=4096 ;;
  *) usage ;;
esac
[[ "$seconds" =~ ^[1-9][0-9]*$ ]] || usage

# clang and its libFuzzer runtime (Debian packages).
packages=(cmake make clang libclang-rt-14-dev libxsimd-dev libgtest-dev libgmp-dev)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "installing: ${missing[*]}"
  sudo_cmd=()
  [ "$(id -u)" -ne 0 ] && sudo_cmd=(sudo)
  "${sudo_cmd[@]}" apt-get update -qq
  DEBIAN_FRONTEND=noninteractive "${sudo_cmd[@]}" apt-get install -y -qq "${missing[@]}" >/dev/null
fi

build=build-fuzz
if [ ! -f "$build/CMakeCache.txt" ]; then
  isa_args=()
  [ -z "${OBBSAT_ISA_KERNELS:-}" ] || isa_args=("-DOBBSAT_ISA_KERNELS=$OBBSAT_ISA_KERNELS")
  cmake --preset fuzz "${isa_args[@]}" >/dev/null
fi
cmake --build --preset fuzz >/dev/null

corpus=$build/corpus/$target
artifacts=$build/artifacts
log=$build/$target.log
mkdir -p "$corpus" "$artifacts"

status=0
"$build/tests/fuzz/$target" -max_total_time="$seconds" -max_len="$max_len" -timeout=20 \
  -rss_limit_mb=2048 -print_final_stats=1 -artifact_prefix="$artifacts/$target-" \
  "$corpus" "tests/fuzz/corpus/$target" > "$log" 2>&1 || status=$?

executed=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -n 1)
done_line=$(grep -E '^#[0-9]+[[:space:]]+DONE' "$log" | tail -n 1 || true)
if [ "$status" -ne 0 ]; then
  tail -n 40 "$log" >&2
  echo "$target: FAILED after ${executed:-an unknown number of} inputs (status $status); log $log" >&2
  exit 1
fi
echo "$target: ${executed:-?} inputs in $seconds s, no failure; corpus $(ls "$corpus" | wc -l) files"
echo "  ${done_line:-no DONE line}"
