# Sourced by the package tests. The build that runs them passes its facts in
# OBBSAT_PACKAGE_* variables (see CMakeLists.txt here). Each test works in a
# scratch directory that is removed when it passes and kept, with its path
# printed, when it fails.
set -euo pipefail

for variable in OBBSAT_PACKAGE_CMAKE OBBSAT_PACKAGE_SOURCE_DIR OBBSAT_PACKAGE_BUILD_DIR \
    OBBSAT_PACKAGE_CONFIG OBBSAT_PACKAGE_GENERATOR OBBSAT_PACKAGE_CXX OBBSAT_PACKAGE_LIBDIR \
    OBBSAT_PACKAGE_VERSION; do
  if [ -z "${!variable:-}" ]; then
    echo "FAIL: $variable is not set; run this test through ctest" >&2
    exit 1
  fi
done

cmake=$OBBSAT_PACKAGE_CMAKE
exit_skipped=77

work=$(mktemp -d "${TMPDIR:-/tmp}/obbsat-package.XXXXXX")
finish() {
  local status=$?
  if [ "$status" -eq 0 ] || [ "$status" -eq "$exit_skipped" ]; then
    rm -rf "$work"
  else
    echo "scratch directory kept for inspection: $work" >&2
  fi
  exit "$status"
}
trap finish EXIT

fail() {
  echo "FAIL: $*" >&2
  exit 1
}

# run NAME COMMAND...: runs COMMAND with its output in $work/NAME.log, shown
# only when COMMAND fails.
run() {
  local log=$work/$1.log
  shift
  if ! "$@" > "$log" 2>&1; then
    cat "$log" >&2
    fail "$*"
  fi
}

# install_package PREFIX: installs the build tree that runs the test.
install_package() {
  run install "$cmake" --install "$OBBSAT_PACKAGE_BUILD_DIR" --config "$OBBSAT_PACKAGE_CONFIG" --prefix "$1"
}

# configure NAME SOURCE BINARY ARGS...: a fresh CMake project with the
# compiler and generator of the build under test.
configure() {
  local name=$1 source=$2 binary=$3
  shift 3
  run "$name" "$cmake" -S "$source" -B "$binary" -G "$OBBSAT_PACKAGE_GENERATOR" \
    -DCMAKE_CXX_COMPILER="$OBBSAT_PACKAGE_CXX" -DCMAKE_BUILD_TYPE="$OBBSAT_PACKAGE_CONFIG" "$@"
}

build() {
  run "$1" "$cmake" --build "$2" --config "$OBBSAT_PACKAGE_CONFIG" --parallel 2
}

# The three verdicts of examples/minimal, as it prints them.
expected_minimal_output='0 1 collide
0 2 apart
0 3 collide'

# expect_minimal_output PROGRAM: runs it and compares its whole output.
expect_minimal_output() {
  local output
  output=$("$1") || fail "$1 exited with status $?"
  [ "$output" = "$expected_minimal_output" ] ||
    fail "$1 printed:
$output
expected:
$expected_minimal_output"
}
