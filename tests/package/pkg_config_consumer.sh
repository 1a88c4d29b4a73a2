# Installs the build tree into a scratch prefix and builds examples/minimal
# with nothing but the compiler and pkg-config, as a Makefile user would.
source "$(dirname "$0")/package_test_support.sh"

pkg_config=$(command -v pkg-config || true)
if [ -z "$pkg_config" ]; then
  echo "SKIPPED: pkg-config is not installed (Debian package pkg-config)"
  exit "$exit_skipped"
fi

prefix=$work/prefix
install_package "$prefix"
export PKG_CONFIG_PATH=$prefix/$OBBSAT_PACKAGE_LIBDIR/pkgconfig

modversion=$("$pkg_config" --modversion obbsat) || fail "pkg-config does not find obbsat in $PKG_CONFIG_PATH"
[ "$modversion" = "$OBBSAT_PACKAGE_VERSION" ] || fail "obbsat.pc says version $modversion"

cflags=$("$pkg_config" --cflags obbsat)
libs=$("$pkg_config" --libs obbsat)
# Static libraries: the libraries come after the sources that use them.
# shellcheck disable=SC2086
run compile "$OBBSAT_PACKAGE_CXX" -std=c++17 $cflags \
  "$OBBSAT_PACKAGE_SOURCE_DIR/examples/minimal/minimal.cpp" -o "$work/minimal" $libs
expect_minimal_output "$work/minimal"
echo "pkg-config consumer: built with '$cflags' and '$libs', output as expected"
