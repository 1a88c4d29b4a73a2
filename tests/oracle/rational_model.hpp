// An independent exact model of what two quads share, in GMP rationals, to
// cross-check the oracle. It follows the same reading of a quad as a point
// set (see obbsat/oracle/quad_region.hpp) but reaches every answer by another
// route: explicit segment intersection, point-in-polygon by ray crossing, and
// the area of the intersection by polygon clipping. The corners may be float
// (a rect) or any exact rationals (the true corners of a pose).
#pragma once

#include <obbsat/rect.hpp>

#include <gmpxx.h>

#include <array>
#include <vector>

namespace obbsat::test {

struct rational_point {
    mpq_class x;
    mpq_class y;
};

/// A quad as a closed set: a point (1 corner), a segment (2) or a simple polygon
/// (3-4 corners, either winding, possibly with one reflex corner).
struct rational_region {
    std::vector<rational_point> outline;
};

/// Four corners in cyclic order, as exact rationals.
using rational_corners = std::array<rational_point, 4>;

/// The set four corners in cyclic order stand for, read as quad_region.hpp reads float corners.
rational_region rational_region_of(const rational_corners& corners);

/// The set the four corners of `r` stand for.
rational_region rational_region_of(const rect& r);

/// 'S' (no common point), 'T' (common points, no common interior point) or 'O'.
char rational_contact(const rational_region& a, const rational_region& b);

/// rational_contact of the regions of two rects.
char rational_contact(const rect& a, const rect& b);

}  // namespace obbsat::test
