// The one geometric predicate of the exact oracle: on which side of the line
// through p and q the point r lies, decided exactly for every finite float.
//
// The determinant (q - p) x (r - p) of three float points can need several
// hundred bits (a coordinate near 1e38 minus one near 1e-45), so it is first
// evaluated in double with a rigorous error bound, and only when that bound
// cannot fix the sign is it recomputed exactly. The result never depends on
// which of the two paths ran.
#pragma once

#include <obbsat/rect.hpp>

namespace obbsat::oracle {

/// +1 if p, q, r turn counter-clockwise (r left of the line p -> q), -1 if clockwise,
/// 0 if collinear (or two of them coincide); exact for all finite floats.
int orientation(point p, point q, point r);

/// The same sign as `orientation`, always by the exact path (for tests and diagnostics).
int orientation_exact(point p, point q, point r);

/// How many terms sign_of_exact_sum takes at the most: enough for the sixteen of a
/// pose oracle slack (pose_contact.hpp), six products of three floats split in two.
inline constexpr int exact_sum_max_terms = 16;

/// +1, -1 or 0: the sign of the exact sum terms[0] + ... + terms[count-1] of at most
/// exact_sum_max_terms finite doubles whose rounded partial sums stay finite (products of
/// two or three floats, the latter as two doubles, always do); throws std::invalid_argument
/// for a count out of range.
int sign_of_exact_sum(const double* terms, int count);

}  // namespace obbsat::oracle
