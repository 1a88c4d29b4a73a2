// Method conservative on poses, and the certified fast path of method exact
// on poses: local's offsets and reaches (obbsat/ref/local.hpp, steps 1 to 4)
// with a proven bound on their rounding, so that an axis claims "apart" (or
// "overlap") only when the exact geometry of the poses agrees.
//
// Contract, the exact float32 operations in order (u = 2^-24), after steps 1
// to 4 of local:
//   6. gap_k = |w_k| − r_k per axis, rounded once.
//   7. D = |dx| + |dy|; Ra = the larger of |ca|, |sa| and Rb of |cb|, |sb|
//      (exact); Ha = hxa + hya, Hb = hxb + hyb; T = (D + (Ra·Ha)) + (Rb·Hb);
//      Sa = Ra·T, Sb = Rb·T.
//   8. When Sa <= 2^100, Sb <= 2^100 (false for a NaN) and Ra, Rb are both in
//      [2^-40, 2^62]: margin_a = (2^-19·Sa) + 2^-140 for A's two axes and
//      margin_b = (2^-19·Sb) + 2^-140 for B's two; otherwise both are +inf and
//      the pair proves nothing.
//   9. An axis proves the pair apart iff gap_k > its side's margin,
//      overlapping on that axis iff gap_k < −(its side's margin).
//      conservative(a, b): false iff some axis proves the pair apart.
//      certify(a, b): separated iff some axis proves it apart; intersecting
//      iff all four prove overlap; otherwise neither (the exact oracle decides).
//
// Why a claim is always true (docs/exact.md has the full derivation): the
// exact slack of an axis is |w*| − r* with w*, r* the exact values of step 4
// on the exact center difference. On an axis of side X (A or B, the other O)
// each w has at most three roundings over terms bounded by |dx·cX| + |dy·sX|,
// so it errs by at most γ3·D·RX (γk = ku/(1−ku)); each r by at most
// γ5·2RX·(Ra·Ha + Rb·Hb), since every term of a reach is a half extent times
// cX² + sX² (at most 2RX²) or a product of the two rotations (at most 2RX·RO).
// So an axis of side X errs by at most about 10u·RX·T: the gap is measured in
// units of X's rotation, and so is its margin, which keeps a short rotation's
// axes useful beside a long one. A product below the normal range errs by at
// most 2^-150 more: with Ra, Rb >= 2^-40 the relative margin covers those
// scaled by a half extent, and 2^-140 the rest. So the computed gap is within
// 3.02u·D·RX + 10.01u·RX·(Ra·Ha + Rb·Hb) + 2^-149·(Ha + Hb) + 2^-148 of the exact
// slack, below margin/(1+u) ≈ 32u·RX·T, even after the roundings of T and SX.
// A rounded gap beyond ±margin therefore has an exact slack of the same sign.
// SX <= 2^100 keeps every product with a center difference or a half extent
// in X's gaps finite, R <= 2^62 the rotation products themselves (na, p, q
// below 2^125): with tiny half extents the S stay small while R·R alone may
// overflow.
#pragma once

#include <obbsat/rect_pose.hpp>
#include <obbsat/ref/certified.hpp>
#include <obbsat/ref/local.hpp>

namespace obbsat::ref {

/// Step 6 for each axis, A.x, A.y, B.x, B.y.
void pose_gaps(const pose_axes& axes, float gap[4]);

/// The margins of step 8: for A's two axes and for B's two.
struct pose_margins {
    float a;
    float b;
};

/// Steps 7 and 8 (both +inf when the pair proves nothing).
pose_margins margins_of(const rect_pose& a, const rect_pose& b, const pose_axes& axes);

/// Method conservative on poses: false only when some axis proves the pair apart.
bool conservative(const rect_pose& a, const rect_pose& b);

/// The certified fast path of method exact on poses, step 9.
certified_verdict certify(const rect_pose& a, const rect_pose& b);

}  // namespace obbsat::ref
