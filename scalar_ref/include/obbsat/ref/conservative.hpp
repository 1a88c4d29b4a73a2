// Method conservative: the article's four axes, each projection's rounding
// error bounded, so that a pair is called apart only when the exact
// projections of its float corners are apart on one of the axes. It never
// misses a collision; near contacts may be reported as collisions.
//
// Contract, the exact float32 operations in order (u = 2^-24):
//   1. K = the largest |coordinate| over the eight corners (a max of exact
//      absolute values: the fold order cannot change it).
//   2. scale = (K * 2^66) * c with c = 0x1.004p-87 = 2^-87 (1 + 2^-10): the
//      first product is exact below 2^62 and +inf from there on, where no
//      axis can prove anything.
//   3. The axes of sat4 (obbsat/ref/sat4.hpp, step 1), each component one
//      float subtraction: A.UR - A.UL, A.UR - A.LR, B.UL - B.LL, B.UL - B.UR.
//   4. The scalar of corner p on axis a is fma(p.x, a.x, p.y * a.y): the
//      product p.y * a.y rounded, then one fused multiply-add rounded once.
//   5. Per rectangle, min and max of its four scalars folded UL, UR, LR, LL
//      with min-pick u < v ? u : v and max-pick u > v ? u : v, as in sat4.
//   6. margin = fma(scale, max-pick(|a.x|, |a.y|), 2^-140).
//   7. The axis proves the pair apart iff
//        max-pick(minB - maxA, minA - maxB) > margin
//      (false when either side is NaN). The pair collides iff no axis proves
//      it apart; the test stops at the first axis that does.
//
// Why "apart" is always true: the axis (a.x, a.y) is a float vector taken as
// given, and any direction on which the exact corner sets of A and B project
// to disjoint intervals separates the closed quads, convex or not. A scalar
// is within (2u + u^2)(|p.x a.x| + |p.y a.y|) + 2^-149 of the exact dot
// product, so the computed extents are off by at most
// E = (2u + u^2) K (|a.x| + |a.y|) + 2^-149 at each end; 2E is at most
// (8u + 4u^2) K max(|a.x|, |a.y|) + 2^-148, and margin exceeds it (the factor
// 1 + 2^-10 covers the roundings of scale and margin, the 2^-140 term the
// products below the normal range). A rounded difference above a float margin
// means an exact difference above it, because rounding is monotonic; so the
// exact gap is positive. With K < 2^62 nothing overflows. The full derivation
// is in docs/exact.md.
#pragma once

#include <obbsat/ref/sat4.hpp>

namespace obbsat::ref {

/// scale of step 2 for the pair.
float conservative_scale(const rect& a, const rect& b);

/// The fused scalar of `corner` on `axis`, step 4: fma(x, ax, y * ay).
float fused_scalar_on_axis(point corner, point axis);

/// min and max of the four fused scalars of `r` on `axis`, folded UL, UR, LR, LL.
extent project_rect_fused(const rect& r, point axis);

/// margin of step 6 for one axis.
float conservative_margin(point axis, float scale);

/// Step 7 on one axis: true iff the extents are proven apart.
bool proven_apart(extent a, extent b, float margin);

/// Method conservative: false only when some axis proves the pair apart.
bool conservative(const rect& a, const rect& b);

}  // namespace obbsat::ref
