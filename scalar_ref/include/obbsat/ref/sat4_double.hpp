// Method sat4_double: the article's test with float input and double
// arithmetic, the accuracy baseline among the float-style methods.
//
// Contract: every corner coordinate is converted to double (exactly), then
// sat4's steps run in the order sat4.hpp states, each operation rounded to
// double: axes by subtraction, scalars (x * ax) + (y * ay) without FMA, min
// and max picks folded UL, UR, LR, LL, overlap iff minB <= maxA and maxB >= minA.
// A product of a float coordinate and a double axis component is not always
// exact, so this method is more accurate than sat4, not exact.
#pragma once

#include <obbsat/rect.hpp>

namespace obbsat::ref {

/// Method sat4_double: true iff no axis separates a and b, in double arithmetic.
bool sat4_double(const rect& a, const rect& b);

}  // namespace obbsat::ref
