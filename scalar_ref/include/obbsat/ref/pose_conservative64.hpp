// Method conservative on double poses, and the certified fast path of method
// exact on double poses: local64's offsets and reaches (obbsat/ref/local64.hpp,
// steps 1 to 4) with a proven bound on their rounding, so that an axis claims
// "apart" (or "overlap") only when the exact geometry of the poses agrees.
//
// Contract, the exact double operations in order (u = 2^-53), after steps 1
// to 4 of local64:
//   6. gap_k = |w_k| − r_k per axis, rounded once.
//   7. D = |dx| + |dy|; Ra = the larger of |ca|, |sa| and Rb of |cb|, |sb|
//      (exact); Ha = hxa + hya, Hb = hxb + hyb; T = (D + (Ra·Ha)) + (Rb·Hb);
//      Sa = Ra·T, Sb = Rb·T.
//   8. When Sa <= 2^1000, Sb <= 2^1000 (false for a NaN) and Ra, Rb are both
//      in [2^-500, 2^500]: margin_a = (2^-48·Sa) + 2^-1000 for A's two axes
//      and margin_b = (2^-48·Sb) + 2^-1000 for B's two; otherwise both are
//      +inf and the pair proves nothing.
//   9. An axis proves the pair apart iff gap_k > its side's margin,
//      overlapping on that axis iff gap_k < −(its side's margin).
//      conservative(a, b): false iff some axis proves the pair apart.
//      certify(a, b): separated iff some axis proves it apart; intersecting
//      iff all four prove overlap; otherwise neither (the exact oracle decides).
//
// The proven margin (docs/exact.md, section 7, has the derivation): on an axis
// of side X the computed gap is within
//   E = 12.01u·RX·T* + 2^-1072·(Ha + Hb + 1)
// of the exact gap |w*| − r* (T* the exact T, from the exact center
// difference), and margin_X >= 32u·(1 − 8u)·RX·T* + 2^-1000·(1 − u) > E. So:
//   - conservative never reports a colliding pair apart (no false negative);
//   - it reports a separated pair as colliding only when no axis's exact gap
//     exceeds margin_X + E < 2·margin_X, i.e. the rectangles are within about
//     2^-47·T*·RX (in X's rotation units) of touching along every axis, T*
//     the pair's own size (center distance plus extents), not its distance
//     from the origin: with unit rotations and T* = 100 m, below a picometre.
// Products of doubles are not exact in double (unlike products of floats), so
// every product counts one rounding here, and a product below 2^-1022 errs by
// up to 2^-1075 absolutely; Ra, Rb >= 2^-500 let the relative margin cover
// those scaled by a half extent, 2^-1000 the rest. Ra, Rb <= 2^500 and
// SX <= 2^1000 keep every product finite.
#pragma once

#include <obbsat/rect_pose64.hpp>
#include <obbsat/ref/certified.hpp>
#include <obbsat/ref/local64.hpp>

namespace obbsat::ref {

/// Step 6 for each axis, A.x, A.y, B.x, B.y.
void pose_gaps(const pose_axes64& axes, double gap[4]);

/// The margins of step 8: for A's two axes and for B's two.
struct pose_margins64 {
    double a;
    double b;
};

/// Steps 7 and 8 (both +inf when the pair proves nothing).
pose_margins64 margins_of(const rect_pose64& a, const rect_pose64& b, const pose_axes64& axes);

/// Method conservative on double poses: false only when some axis proves the pair apart.
bool conservative(const rect_pose64& a, const rect_pose64& b);

/// The certified fast path of method exact on double poses, step 9.
certified_verdict certify(const rect_pose64& a, const rect_pose64& b);

}  // namespace obbsat::ref
