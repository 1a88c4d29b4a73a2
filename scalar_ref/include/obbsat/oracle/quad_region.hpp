// The closed point set a rect's four float corners stand for, as the exact
// oracle understands it.
//
// The outline UL -> UR -> LR -> LL -> UL is taken exactly as the floats give it:
//   - all four corners equal: that point;
//   - all four corners on one line: the segment they span;
//   - a simple outline (it meets itself only where neighbouring edges share a
//     corner; repeated corners are dropped first): the closed region it bounds.
//     That region is convex, or has one reflex corner (float rounding of a thin
//     rectangle can push a corner inwards) and is then split into two triangles
//     along the diagonal from the reflex corner;
//   - an outline that crosses itself (a "bow-tie" from rounding) or doubles back
//     along itself: its convex hull, the smallest convex set holding the corners.
// Every region is thus a union of at most two closed convex pieces whose
// interiors are disjoint, and a piece is a point, a segment or a convex polygon.
#pragma once

#include <obbsat/rect.hpp>

#include <cstdint>

namespace obbsat::oracle {

/// How the corners of a rect were read (see the file comment).
enum class quad_form : std::uint8_t { point, segment, convex, concave, non_simple };

/// A closed convex piece: 1 corner (a point), 2 (a segment) or 3-4 (a polygon with
/// positive area), counter-clockwise, no two equal, no three collinear.
struct convex_piece {
    std::uint8_t count;
    point corners[4];
};

/// The region of a rect: the union of `piece_count` (1 or 2) convex pieces.
struct quad_region {
    quad_form form;
    std::uint8_t piece_count;
    convex_piece pieces[2];
};

/// The region the corners of `r` stand for; throws std::invalid_argument if a
/// coordinate is not finite.
quad_region region_of(const rect& r);

/// "point", "segment", "convex", "concave" or "non_simple".
const char* quad_form_name(quad_form form);

}  // namespace obbsat::oracle
