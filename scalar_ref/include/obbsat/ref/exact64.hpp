// Method exact on double corners: true iff the closed regions of `a` and `b`,
// every corner double taken exactly (obbsat/oracle/contact64.hpp says which
// set four corners stand for), share a point (touching counts), for every
// pair of finite rect64.
//
// Contract: the certified fast path certify(a, b) of obbsat/ref/certified64.hpp
// in double; a pair it proves separated is false, one it proves intersecting
// is true, and every other pair is answered by the exact oracle
// oracle::intersects(a, b) of obbsat/oracle/contact64.hpp, in the same call.
// The answer is the oracle's for every pair.
//
// It lives in obbsat::oracle (scalar_ref/oracle/exact64.cpp), since its slow
// path is the oracle.
#pragma once

#include <obbsat/rect64.hpp>

namespace obbsat::ref {

/// Method exact on double corners, as stated above; throws std::invalid_argument
/// for a non-finite coordinate that reaches the slow path.
bool exact(const rect64& a, const rect64& b);

}  // namespace obbsat::ref
