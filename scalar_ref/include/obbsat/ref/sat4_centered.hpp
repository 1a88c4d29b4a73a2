// Method sat4_centered: the article's second optimisation, moving the origin
// into the pair before projecting, so that precision no longer depends on how
// far the pair lies from the world origin.
//
// Contract: with o = A.UL, every corner p of A and of B becomes p - o
// (one float subtraction per coordinate, rounded), then sat4 (sat4.hpp) runs
// on the moved corners. For corners within a factor of two of o per
// coordinate the subtraction is exact (Sterbenz), so nearby geometry keeps
// every bit it had.
#pragma once

#include <obbsat/rect.hpp>

namespace obbsat::ref {

/// `r` with `origin` subtracted from every corner, per coordinate in float.
rect moved_to_origin(const rect& r, point origin);

/// Method sat4_centered: sat4 on both rectangles moved so that A.UL is the origin.
bool sat4_centered(const rect& a, const rect& b);

}  // namespace obbsat::ref
