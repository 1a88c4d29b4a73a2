# docs/api.md shows examples/minimal/minimal.cpp inline; the package tests build
# and run that file, so the copy in the document must stay identical to it.
source "$(dirname "$0")/package_test_support.sh"

doc=$OBBSAT_PACKAGE_SOURCE_DIR/docs/api.md
example=$OBBSAT_PACKAGE_SOURCE_DIR/examples/minimal/minimal.cpp
awk '/^## A first program$/ { in_section = 1; next }
     in_section && /^```cpp$/ { in_code = 1; next }
     in_code && /^```$/ { exit }
     in_code { print }' "$doc" > "$work/inline.cpp"
[ -s "$work/inline.cpp" ] || fail "$doc has no C++ block under '## A first program'"
diff -u "$example" "$work/inline.cpp" >&2 || fail "the example in $doc differs from $example (diff above)"
echo "docs/api.md shows examples/minimal/minimal.cpp as it is"
