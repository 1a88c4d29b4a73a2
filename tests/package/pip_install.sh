# Installs obbsat the way docs/python.md tells a Debian user to: a venv that
# sees the system's numpy and pybind11, `pip install --no-build-isolation` of
# the source tree (a copy of it, so that this checkout is never written to),
# then real calls from a folder where nothing but the venv can be imported.
# It builds the library once more (Release, static, into the extension).
source "$(dirname "$0")/package_test_support.sh"

python=${OBBSAT_PACKAGE_PYTHON:-}
if [ -z "$python" ] || ! [ -x "$python" ]; then
  echo "SKIPPED: no Python interpreter found ('$python')"
  exit "$exit_skipped"
fi
skip_without() {
  if ! "$python" -c "import $1" > /dev/null 2>&1; then
    echo "SKIPPED: $python cannot import $1 (Debian package $2)"
    exit "$exit_skipped"
  fi
}
skip_without venv,ensurepip python3-venv
skip_without numpy python3-numpy
skip_without pybind11 python3-pybind11

# The sources without version control, build trees or venvs. The build tree
# running this test is left out wherever it is.
source_dir=$(cd "$OBBSAT_PACKAGE_SOURCE_DIR" && pwd -P)
build_dir=$(cd "$OBBSAT_PACKAGE_BUILD_DIR" && pwd -P)
excludes=(--exclude=./.git --exclude='./build*' --exclude=./.venv --exclude='__pycache__')
case "$build_dir/" in
  "$source_dir"/*) excludes+=("--exclude=./${build_dir#"$source_dir"/}") ;;
esac
mkdir "$work/src" "$work/tmp" "$work/cwd"
tar -C "$source_dir" "${excludes[@]}" -cf - . | tar -C "$work/src" -xf - ||
  fail "copying $source_dir to $work/src"

venv=$work/venv
run venv "$python" -m venv --system-site-packages "$venv"

# The build uses the compiler and cmake of the build under test; TMPDIR holds
# setup.py's scratch folder, which must be gone afterwards. --no-index: numpy
# is already there, nothing is to be downloaded.
started=$SECONDS
run pip_install env CXX="$OBBSAT_PACKAGE_CXX" CMAKE="$cmake" TMPDIR="$work/tmp" \
  "$venv/bin/python" -m pip install --no-build-isolation --no-index --no-cache-dir \
  --disable-pip-version-check "$work/src"
echo "pip install: $((SECONDS - started)) s"
grep -q "Successfully installed obbsat-$OBBSAT_PACKAGE_VERSION" "$work/pip_install.log" ||
  fail "pip did not report installing obbsat $OBBSAT_PACKAGE_VERSION:
$(tail -5 "$work/pip_install.log")"

leftovers=$(cd "$work/src" && find . \( -name '*.egg-info' -o -path ./build -o -path ./dist \) -print)
[ -z "$leftovers" ] || fail "pip install left in the source tree: $leftovers"
leftovers=$(ls -A "$work/tmp")
[ -z "$leftovers" ] || fail "the build left in TMPDIR: $leftovers"

# -I: neither PYTHONPATH, the user site nor the working folder is searched.
check_import() {
  (cd "$work/cwd" && "$venv/bin/python" -I -c "$1" "$venv" "$OBBSAT_PACKAGE_VERSION" \
     "$OBBSAT_PACKAGE_SOURCE_DIR/python/CMakeLists.txt")
}
output=$(check_import '
import os, re, sys
import numpy as np
import obbsat

venv, version, cmake_lists = sys.argv[1:]
package_dir = os.path.dirname(os.path.realpath(obbsat.__file__))
assert package_dir.startswith(os.path.realpath(venv) + os.sep), package_dir
assert obbsat.__version__ == version, (obbsat.__version__, version)

# The installed files: the ones python/CMakeLists.txt installs, and the extension.
listed = re.search(r"set\(obbsat_python_files\s+([^)]*)\)", open(cmake_lists).read()).group(1).split()
core = os.path.basename(obbsat._core.__file__)
installed = sorted(f for f in os.listdir(package_dir) if f != "__pycache__")
assert installed == sorted(listed + [core]), installed

poses = np.array([[1, 0.5, 1, 0.5, 1, 0], [2, 1.25, 1, 0.75, 1, 0], [9.5, 9.5, 0.5, 0.5, 1, 0]], dtype=np.float32)
pairs = np.array([[0, 1], [0, 2]], dtype=np.uint32)
for method in obbsat.methods(poses=True):
    verdicts = obbsat.collide(poses, pairs, method=method, threads=2)
    assert verdicts.tolist() == [True, False], (method, verdicts)
found = obbsat.find_pairs(poses, method="exact")
assert found.dtype == np.uint32 and found.tolist() == [[0, 1]], found

rects = np.array([[[0, 1], [2, 1], [2, 0], [0, 0]], [[1, 2], [3, 2], [3, .5], [1, .5]],
                  [[9, 10], [10, 10], [10, 9], [9, 9]]], dtype=np.float32)
for backend in obbsat.backends():
    verdicts = obbsat.collide(rects, pairs, method="exact", backend=backend)
    assert verdicts.tolist() == [True, False], (backend, verdicts)
print(obbsat._core.__file__)
print("obbsat", obbsat.__version__, "from", package_dir, "backends", " ".join(obbsat.backends()))
') || fail "the installed obbsat does not import or answer wrongly"
echo "$output"
core=$(head -1 <<< "$output")

# The library is inside the extension: it needs no libobbsat at run time.
needed=$(ldd "$core") || fail "ldd $core"
if grep -qi obbsat <<< "$needed"; then
  fail "$core needs a shared obbsat library:
$needed"
fi

run pip_uninstall "$venv/bin/python" -m pip uninstall -y --disable-pip-version-check obbsat
if check_import 'import obbsat' > /dev/null 2>&1; then
  fail "obbsat still imports after pip uninstall"
fi
rm -rf "$venv"
echo "pip install of a copy of $source_dir into a venv of $python: installed, answered, uninstalled"
