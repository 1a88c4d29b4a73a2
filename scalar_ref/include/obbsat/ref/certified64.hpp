// The certified separating-edge test on double corners: the fast path of
// method exact on rect64 (obbsat/ref/exact64.hpp).
//
// Contract: the steps of obbsat/ref/certified.hpp, word for word, on the
// double corners of two rect64 with every operation in double (no FMA), with
//   step 2's guard: decide nothing unless 2^-900 <= area <= 2^1000 for the
//                   pair and 2^-900 <= area for each quad;
//   step 3's bound: bound = area · 2^-49 for the pair, own_bound = area ·
//                   2^-49 per quad (2^-49 = 16u, u = 2^-53).
//
// Why the bound holds: the argument of certified.hpp does not use the
// exactness of any product, only that every difference and product rounds
// once: with u = 2^-53 the computed d is within (3 + 16u)·u·2wh(1 + u)^3 of
// the exact one, under 6.001u·area, and bound = 16u·area. Underflow: a
// difference landing below 2^-1022 is exact, a product errs by at most
// 2^-1075 more, and bound >= 2^-949. Overflow: area <= 2^1000 bounds every
// product by 2^1000·(1 + u)^3; an infinite width makes area +inf or NaN and
// fails the guard. docs/exact.md, section 8.
#pragma once

#include <obbsat/rect64.hpp>
#include <obbsat/ref/certified.hpp>

namespace obbsat::ref {

/// The certified separating-edge test on (a, b) in double, as specified above.
certified_verdict certify(const rect64& a, const rect64& b);

}  // namespace obbsat::ref
