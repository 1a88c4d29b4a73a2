# Installs the build tree into a scratch prefix, then works as a user of the
# installed package would: builds examples/ with find_package (warnings are
# errors, so the public headers must be clean under strict flags), runs the
# examples, checks the package's version rules and the obbsat::oracle target.
source "$(dirname "$0")/package_test_support.sh"

prefix=$work/prefix
install_package "$prefix"

config_dir=$prefix/$OBBSAT_PACKAGE_LIBDIR/cmake/obbsat
for file in obbsatConfig.cmake obbsatConfigVersion.cmake obbsatTargets.cmake; do
  [ -f "$config_dir/$file" ] || fail "not installed: $config_dir/$file"
done
for header in obbsat.hpp collide.hpp rect.hpp ref/sat4.hpp oracle/contact.hpp; do
  [ -f "$prefix/include/obbsat/$header" ] || fail "not installed: include/obbsat/$header"
done
[ ! -e "$prefix/include/obbsat/suites" ] || fail "the hard-case suites' headers were installed"
# A package that names the source or build tree only works on this machine.
if grep -rlF -e "$OBBSAT_PACKAGE_SOURCE_DIR" -e "$OBBSAT_PACKAGE_BUILD_DIR" "$config_dir" \
    "$prefix/$OBBSAT_PACKAGE_LIBDIR/pkgconfig"; then
  fail "installed package files name the source or build tree (files above)"
fi

examples=$work/examples
configure examples-configure "$OBBSAT_PACKAGE_SOURCE_DIR/examples" "$examples" \
  -DCMAKE_PREFIX_PATH="$prefix" -DCMAKE_CXX_FLAGS="${OBBSAT_PACKAGE_STRICT_FLAGS:-}"
build examples-build "$examples"

expect_minimal_output "$examples/minimal/minimal"

# scene: a short run (it checks its last frame against a brute force and fails
# on a difference); the digest of all its pairs must not depend on the backend.
scene_output=$("$examples/scene/scene" 2) || fail "scene exited with status $?"
grep -q '^t=  2s ' <<< "$scene_output" || fail "scene did not report second 2:
$scene_output"
grep -q '^check: .* a brute force' <<< "$scene_output" || fail "scene did not check against a brute force:
$scene_output"
digest=$(grep '^pair digest ' <<< "$scene_output") || fail "scene printed no digest"
scalar_digest=$(OBBSAT_BACKEND=scalar "$examples/scene/scene" 2 | grep '^pair digest ') ||
  fail "scene on the scalar backend failed"
[ "$digest" = "$scalar_digest" ] || fail "scene: $digest, but with OBBSAT_BACKEND=scalar $scalar_digest"

# files: write a scene, answer it, check the answers against the scalar reference.
files=$examples/files/files
cd "$work"
run files-scene "$files" scene R.csv P.csv 500 4000 7
run files-collide "$files" collide R.csv P.csv V.txt
run files-verify "$files" verify R.csv P.csv V.txt
if [ "${OBBSAT_PACKAGE_WITH_PROGRAM:-0}" = 1 ]; then
  run program-collide "$prefix/bin/obbsat" collide --rects R.csv --pairs P.csv --out V_program.txt
  cmp -s V.txt V_program.txt || fail "files and the installed obbsat program disagree on P.csv"
fi
printf '0,0,1,0,1,1,0,1\n# a comment\n0,0,1,0,1,1,0\n' > bad.csv
if "$files" collide bad.csv P.csv V_bad.txt 2> bad.err; then
  fail "files accepted a rectangle line with 7 fields"
fi
grep -q '^files: bad.csv:3: ' bad.err || fail "files named no file:line: $(cat bad.err)"
[ ! -e V_bad.txt ] || fail "files wrote output for bad input"

# Version rules while the major version is 0: the same minor version only, so
# an older minor version is refused too (SameMajorVersion would accept it).
consumer=$OBBSAT_PACKAGE_SOURCE_DIR/tests/package/find_package_consumer
version=$OBBSAT_PACKAGE_VERSION
major=${version%%.*}
minor=$(cut -d. -f2 <<< "$version")
requests=("$version" "$major.$minor" "$major.$((minor + 1))" "$((major + 1)).0")
if [ "$minor" -gt 0 ]; then
  requests+=("$major.$((minor - 1))")
fi
for request in "${requests[@]}"; do
  case $request in
    "$version"|"$major.$minor") wanted=TRUE ;;
    *) wanted=FALSE ;;
  esac
  configure "request-$request" "$consumer" "$work/request-$request" \
    -DCMAKE_PREFIX_PATH="$prefix" -DOBBSAT_REQUEST="$request"
  grep -q "obbsat $request: found=$wanted\$" "$work/request-$request.log" ||
    fail "find_package(obbsat $request) on $version: wanted found=$wanted; see $work/request-$request.log"
done
build oracle-consumer-build "$work/request-$version"
oracle_output=$("$work/request-$version/oracle_consumer") || fail "oracle_consumer exited with status $?"
[ "$oracle_output" = "STO" ] || fail "oracle_consumer printed '$oracle_output', expected 'STO'"

# A component the package lacks is an error that names it.
if "$cmake" -S "$consumer" -B "$work/request-component" -DCMAKE_PREFIX_PATH="$prefix" \
    -DOBBSAT_REQUEST="$version" -DOBBSAT_COMPONENT=no_such_part > "$work/component.log" 2>&1; then
  fail "find_package(obbsat REQUIRED COMPONENTS no_such_part) succeeded"
fi
grep -q "no_such_part" "$work/component.log" || fail "the missing component was not named; see $work/component.log"
echo "installed package, examples, version rules and obbsat::oracle: all as expected"
