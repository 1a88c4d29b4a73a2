// The exact oracle for double poses: how two rect_pose64, taken exactly as
// their stored doubles give them (obbsat/rect_pose64.hpp), relate as closed
// sets, in the classes of contact.hpp (separated, touching, overlapping).
//
// The four axes are complete for the same reason as for float poses (see
// pose_contact.hpp): with n = c² + s², p = ca·cb + sa·sb, q = ca·sb − sa·cb
// and d = Cb − Ca, the pair is separated iff one of the slacks
//   A's u:  hxa·na + hxb·|p| + hyb·|q| − |d·(ca, sa)|
//   A's v:  hya·na + hxb·|q| + hyb·|p| − |d·(−sa, ca)|
//   B's u:  hxb·nb + hxa·|p| + hya·|q| − |d·(cb, sb)|
//   B's v:  hyb·nb + hxa·|q| + hya·|p| − |d·(−sb, cb)|
// is negative; overlapping iff both have positive area and all four are
// positive; touching otherwise.
//
// Every sign here (of p, q, d·axis and each slack) is the exact sign of a sum
// of at most ten products of up to three stored doubles, d·axis written as
// xb·ax − xa·ax + yb·ay − ya·ay (never a rounded difference), decided by
// sign_of_product_sum (product_sum.hpp): no filter, no tolerance, no range
// limit; every finite valid pose is answered exactly. Method exact on double
// poses (obbsat/ref/pose_exact64.hpp) puts a certified filter in front.
#pragma once

#include <obbsat/oracle/contact.hpp>
#include <obbsat/rect_pose64.hpp>

#include <array>

namespace obbsat::oracle {

/// nullptr for a valid pose, else what makes it invalid: a value that is not finite, a
/// negative half extent, or the rotation vector (0, 0).
const char* pose_defect(const rect_pose64& p);

/// How the poses `a` and `b` relate; symmetric. Throws std::invalid_argument for an
/// invalid pose (see pose_defect).
contact classify(const rect_pose64& a, const rect_pose64& b);

/// True iff the closed sets of `a` and `b` share a point (touching counts); throws as classify.
bool intersects(const rect_pose64& a, const rect_pose64& b);

/// The exact sign of each slack (−1, 0 or +1), on A's u, A's v, B's u, B's v in that
/// order: the pair is separated iff some sign is −1; throws as classify.
std::array<int, 4> slack_signs(const rect_pose64& a, const rect_pose64& b);

}  // namespace obbsat::oracle
