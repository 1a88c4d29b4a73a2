// The exact oracle for poses: how two rect_poses, taken exactly as their
// stored floats give them (rect_pose.hpp), relate as closed sets, in the
// classes of contact.hpp:
//
//   separated    they share no point;
//   touching     they share a point but no interior point (a pose with a zero
//                half extent, a segment or a point, has no interior, so any
//                contact with one is touching);
//   overlapping  both have positive area and some point is interior to both.
//
// No tolerance anywhere: every decision is the exact sign of a sum of
// products of stored floats.
//
// Why four axes are complete. Write a pose as C + a·u + b·v, |a| <= hx,
// |b| <= hy, with u = (c, s) and v = (−s, c), so u ⟂ v and |u| = |v|. A and B
// share a point iff 0 lies in K = B − A, the Minkowski sum of the point
// d = Cb − Ca and the four segments [−hx, hx]·u and [−hy, hy]·v of each pose.
// K is a convex polygon, a segment or a point, and its edges run along
// u_a, v_a, u_b, v_b; since each pose's u and v are perpendicular, the normal
// of every edge direction is itself one of these four axes. K is cut out by
// the slabs {x : |(x − d)·n| <= r(n)} across these axes (r(n) the half width
// of K along n): a polygon by those across its edge normals, a segment by the
// slab across it and the one along it, a point by two perpendicular ones. So
//   - A and B are disjoint iff on some axis n the slack r(n) − |d·n| is < 0;
//   - when both have positive area, their interiors meet iff 0 is interior to
//     K (int B − int A = int K for convex bodies), iff every slack is > 0;
//   - otherwise (all slacks >= 0, some zero, or a pose without area) they touch.
//
// The slacks, with n = c² + s² the squared length of a rotation vector,
// p = u_a·u_b = ca·cb + sa·sb and q = v_a·u_b = ca·sb − sa·cb:
//   A's u:  hxa·na + hxb·|p| + hyb·|q| − |d·(ca, sa)|
//   A's v:  hya·na + hxb·|q| + hyb·|p| − |d·(−sa, ca)|
//   B's u:  hxb·nb + hxa·|p| + hya·|q| − |d·(cb, sb)|
//   B's v:  hyb·nb + hxa·|q| + hya·|p| − |d·(−sb, cb)|
// Each is a sum of at most six products of three stored floats and four of
// two, d·n taken as xb·nx − xa·nx + yb·ny − ya·ny (never as a rounded
// difference). Its sign is found in double with a rigorous error bound, and
// only when the bound cannot fix it by exact expansion arithmetic
// (sign_of_exact_sum in orientation.hpp); the answer never depends on which
// path ran. The signs of p and q are exact in double already: each is one
// rounding of two exact products.
#pragma once

#include <obbsat/oracle/contact.hpp>
#include <obbsat/rect_pose.hpp>

#include <array>

namespace obbsat::oracle {

/// nullptr for a valid pose, else what makes it invalid: a value that is not finite, a
/// negative half extent, or the rotation vector (0, 0).
const char* pose_defect(const rect_pose& p);

/// How the poses `a` and `b` relate; symmetric. Throws std::invalid_argument for an invalid
/// pose (see pose_defect).
contact classify(const rect_pose& a, const rect_pose& b);

/// The same answer as classify, every slack always by the exact path (for tests and timing).
contact classify_exact(const rect_pose& a, const rect_pose& b);

/// True iff the closed sets of `a` and `b` share a point (touching counts); throws as classify.
bool intersects(const rect_pose& a, const rect_pose& b);

/// The exact sign of each slack (−1, 0 or +1), on A's u, A's v, B's u, B's v in that order:
/// the pair is separated iff some sign is −1; throws as classify.
std::array<int, 4> slack_signs(const rect_pose& a, const rect_pose& b);

/// One axis's terms as the slacks above sum them, each evaluated in double (a few roundings):
/// the slack is reach_a + reach_b − |offset|. For pictures and messages; the signs above decide.
struct axis_terms {
    double offset;   ///< d·n, d = B's center − A's center (its difference rounded once)
    double reach_a;  ///< A's half width along n, times |n| (on A's u, A's v, B's u, B's v:
                     ///< hxa·na, hya·na, hxa·|p| + hya·|q|, hxa·|q| + hya·|p|)
    double reach_b;  ///< B's, the same way round
};

/// The terms of the four axes, in the order of slack_signs; throws as classify.
std::array<axis_terms, 4> terms_of_axes(const rect_pose& a, const rect_pose& b);

}  // namespace obbsat::oracle
