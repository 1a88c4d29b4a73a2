# Builds a project that pulls obbsat in with add_subdirectory (see
# subdirectory_consumer/CMakeLists.txt, which checks at configure time that
# obbsat's tests, benchmarks and install rules stay off), then runs it.
source "$(dirname "$0")/package_test_support.sh"

binary=$work/build
configure subdirectory-configure "$OBBSAT_PACKAGE_SOURCE_DIR/tests/package/subdirectory_consumer" "$binary" \
  -DOBBSAT_CHECKOUT_DIR="$OBBSAT_PACKAGE_SOURCE_DIR"
build subdirectory-build "$binary"
[ ! -e "$binary/obbsat/tests" ] || fail "obbsat's tests were configured under add_subdirectory"
[ ! -e "$binary/obbsat/bench" ] || fail "obbsat's benchmarks were configured under add_subdirectory"
expect_minimal_output "$binary/consumer"
echo "add_subdirectory consumer: configured without tests or benchmarks, output as expected"
