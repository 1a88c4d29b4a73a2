// What a method saw along the article's four axes for one pair: the extents it
// projected, whether they overlapped, and which axis separated, so a drawing
// can show the reason for the verdict.
//
// The float and double methods (sat4, sat4_centered, sat4_double) are replayed
// step by step through their references' own step functions, so in their own
// arithmetic and operation order. The certified methods (conservative, exact)
// decide from exact signs, so their axes are judged exactly (with the oracle's
// exact sum): an axis separates iff every corner of one rect lies strictly
// before every corner of the other.
// When the four axes do not separate a pair such a method calls apart, the
// normals of the quads' edges are tried next, as the certified test does.
// Extents are kept in double for drawing; for the float methods they are the
// float scalars the method compared, which may be infinite after overflow.
#pragma once

#include <obbsat/method.hpp>
#include <obbsat/rect.hpp>

#include <string>
#include <vector>

namespace obbsat::svg {

/// One projection axis and both rects' extents on it.
struct axis_view {
    std::string label;       ///< "1".."4" for the article's axes, "n" for an edge normal
    std::string definition;  ///< e.g. "A.UR-A.UL" or "normal of B.LR-B.LL"
    double axis_x = 0;       ///< the axis vector as the method computed it
    double axis_y = 0;
    double origin_x = 0;  ///< scalars are dot(corner - origin, axis)
    double origin_y = 0;
    double a_min = 0;  ///< A's extent
    double a_max = 0;
    double b_min = 0;  ///< B's extent
    double b_max = 0;
    bool overlap = true;  ///< the method's verdict for this axis alone
};

/// A method's view of one pair.
struct method_view {
    std::string arithmetic;       ///< how the axes were judged: "float", "double", "exact signs", ...
    std::vector<axis_view> axes;  ///< the four article axes, then an edge normal if one was needed
    int separating = -1;          ///< index in axes of the separating axis shown, -1 for none
    std::string note;             ///< a remark when the axes alone do not explain the verdict
};

/// The view of method `m` on the pair (a, b), whose verdict the library gave as
/// `collides`. Throws std::logic_error if the replayed steps contradict it.
method_view view_of_method(method m, const rect& a, const rect& b, bool collides);

}  // namespace obbsat::svg
