// The orientation predicate of the exact oracle for double points: on which
// side of the line through p and q the point r lies, decided exactly for
// every finite double.
//
// The determinant (q − p) × (r − p) is first evaluated in double and kept when
// Shewchuk's bound A for orient2d, (3 + 16u)·u·(|left| + |right|) with
// u = 2^-53, fixes its sign; that bound holds for double input as long as no
// product overflows (then the magnitude is not finite and the filter is
// skipped) and is not spoilt by underflow (a product below 2^-1022 errs by at
// most 2^-1075, and the filter is used only when the magnitude is at least
// 2^-900, where the bound exceeds that by far). Otherwise the six products of
// the expanded determinant are summed exactly (product_sum.hpp). The result
// never depends on which path ran.
#pragma once

#include <obbsat/rect64.hpp>

namespace obbsat::oracle {

/// +1 if p, q, r turn counter-clockwise (r left of the line p -> q), −1 if clockwise,
/// 0 if collinear (or two of them coincide); exact for all finite doubles.
int orientation(point64 p, point64 q, point64 r);

/// The same sign as `orientation`, always by the exact path (for tests).
int orientation_exact(point64 p, point64 q, point64 r);

}  // namespace obbsat::oracle
