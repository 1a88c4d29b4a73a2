// Method exact on double poses: true iff the closed rectangles of `a` and `b`,
// every stored double taken exactly (obbsat/rect_pose64.hpp), share a point
// (touching counts), for every valid pair of finite poses.
//
// Contract: the certified fast path certify(a, b) of
// obbsat/ref/pose_conservative64.hpp in double arithmetic; a pair it proves
// separated is false, a pair it proves intersecting is true, and every other
// pair is answered by the exact oracle oracle::intersects(a, b)
// (obbsat/oracle/pose_contact64.hpp), in the same call. The answer is the
// oracle's for every pair; which path ran changes only the time taken.
//
// It lives in obbsat::oracle (scalar_ref/oracle/pose_exact64.cpp), since its
// slow path is the oracle.
#pragma once

#include <obbsat/rect_pose64.hpp>

namespace obbsat::ref {

/// Method exact on double poses, as stated above. Poses must be valid (a
/// store checks them); an invalid pose that reaches the slow path throws
/// std::invalid_argument.
bool exact(const rect_pose64& a, const rect_pose64& b);

}  // namespace obbsat::ref
