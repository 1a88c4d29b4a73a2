// Method conservative on poses, and the certified fast path of method exact
// on poses: local's offsets and reaches (obbsat/ref/local.hpp, steps 1 to 4)
// with a proven bound on their rounding, so that an axis claims "apart" (or
// "overlap") only when the exact geometry of the poses agrees.
//
// Contract, the exact float32 operations in order (u = 2^-24), after steps 1
// to 4 of local:
//   6. gap_k = |w_k| − r_k per axis, rounded once.
//   7. D = |dx| + |dy|; R = the largest of |ca|, |sa|, |cb|, |sb| (exact);
//      H = ((hxa + hya) + hxb) + hyb; S = (D·R) + ((R·R)·H).
//   8. margin = (2^-19·S) + 2^-140 when S <= 2^100 and 2^-40 <= R <= 2^62
//      (false for a NaN S), else +inf: such a pair proves nothing.
//   9. An axis proves the pair apart iff gap_k > margin, overlapping on that
//      axis iff gap_k < −margin.
//      conservative(a, b): false iff some axis proves the pair apart.
//      certify(a, b): separated iff some axis proves it apart; intersecting
//      iff all four prove overlap; otherwise neither (the exact oracle decides).
//
// Why a claim is always true (docs/exact.md has the full derivation): the
// exact slack of an axis is |w*| − r* with w*, r* the exact values of step 4
// on the exact center difference. Each w has at most three roundings over
// terms bounded by |dx·c| + |dy·s|, so it errs by at most γ3·D·R (γk = ku/(1−ku));
// each r by at most γ5·2R²·H, since every term of a reach is a half extent
// times at most two rotation products. A product below the normal range errs
// by at most 2^-150 more, at most 2H + 6 times in one gap: with R >= 2^-40 the
// relative margin covers those scaled by H, and 2^-140 the rest. So the
// computed gap is within 3.02u·D·R + 10.01u·R²·H + 2^-146·H + 2^-147 of the
// exact slack, below margin/(1+u) ≈ 32u·S, even after S's own five roundings.
// A rounded gap beyond ±margin therefore has an exact slack of the same sign.
// S <= 2^100 keeps every product with a center difference or a half extent
// finite, R <= 2^62 the rotation products themselves (na, p, q below 2^125):
// with tiny half extents S stays small while R·R alone may overflow.
#pragma once

#include <obbsat/rect_pose.hpp>
#include <obbsat/ref/certified.hpp>
#include <obbsat/ref/local.hpp>

namespace obbsat::ref {

/// Step 6 for each axis, A.x, A.y, B.x, B.y.
void pose_gaps(const pose_axes& axes, float gap[4]);

/// Steps 7 and 8: the margin of the pair (+inf when the pair proves nothing).
float pose_margin(const rect_pose& a, const rect_pose& b, const pose_axes& axes);

/// Method conservative on poses: false only when some axis proves the pair apart.
bool conservative(const rect_pose& a, const rect_pose& b);

/// The certified fast path of method exact on poses, step 9.
certified_verdict certify(const rect_pose& a, const rect_pose& b);

}  // namespace obbsat::ref
