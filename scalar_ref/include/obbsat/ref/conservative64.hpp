// Method conservative on double corners: the article's four axes in double,
// each projection's rounding error bounded, so that a pair is called apart only
// when the exact projections of its double corners are apart on one of the
// axes. It never misses a collision; near contacts may be reported as
// collisions.
//
// Contract, the exact double operations in order (u = 2^-53), those of
// obbsat/ref/conservative.hpp in double with its constants for double:
//   1. K = the largest |coordinate| over the eight corners.
//   2. scale = (K · 2^513) · c with c = 0x1.004p-563 = 2^-563 (1 + 2^-10): the
//      first product is exact below 2^511 and +inf from there on, where no
//      axis can prove anything; so scale = 8u·K·(1 + 2^-10), rounded once.
//   3. The axes of sat4, each component one double subtraction:
//      A.UR − A.UL, A.UR − A.LR, B.UL − B.LL, B.UL − B.UR.
//   4. The scalar of corner p on axis a is fma(p.x, a.x, p.y · a.y).
//   5. Per rectangle, min and max of its four scalars folded UL, UR, LR, LL
//      with min-pick u < v ? u : v and max-pick u > v ? u : v.
//   6. margin = fma(scale, max-pick(|a.x|, |a.y|), 2^-1000).
//   7. The axis proves the pair apart iff
//        max-pick(minB − maxA, minA − maxB) > margin
//      (false when either side is NaN). The pair collides iff no axis proves
//      it apart.
//
// The proven margin: a scalar is within (2u + u²)(|p.x a.x| + |p.y a.y|) +
// 2^-1074 of the exact dot product, so each computed extent end is off by at
// most E = (2u + u²)·K·(|a.x| + |a.y|) + 2^-1074, and 2E <= (8u + 4u²)·K·
// max(|a.x|, |a.y|) + 2^-1072 < margin. A computed difference above the margin
// means an exact gap between the exact projections of more than margin − 2E > 0:
// the axis separates the exact quads. So conservative never reports a colliding
// pair apart; it reports a separated pair colliding only when on each of the
// four axes the exact gap is at most margin + 2E < 2·margin, about
// 2^-49·K·|axis| (at UTM coordinates near 6e6 with 20 m sides, below 2e-7 m).
// With K < 2^511 no product overflows (|p·a| <= 2K²).
#pragma once

#include <obbsat/rect64.hpp>

namespace obbsat::ref {

/// Method conservative on double corners: false only when some axis proves the pair apart.
bool conservative(const rect64& a, const rect64& b);

}  // namespace obbsat::ref
