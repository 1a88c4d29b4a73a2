// The plain data of a scene: points, rectangles given by their four corners,
// and pairs of rectangle indices.
//
// A rectangle is four float32 corners UL, UR, LR, LL, adjacent in that cyclic
// order; either winding is accepted. Nothing here checks that the corners form
// a true rectangle: the methods answer for the quadrilateral as given.
#pragma once

#include <cstdint>

namespace obbsat {

/// A point or vector in the plane, in float32.
struct point {
    float x;
    float y;
};

/// Four corners in cyclic order: upper-left, upper-right, lower-right, lower-left.
struct rect {
    point ul;
    point ur;
    point lr;
    point ll;
};

/// A candidate pair: rectangle `a` tested against rectangle `b`, as 0-based indices.
struct pair_index {
    std::uint32_t a;
    std::uint32_t b;
};

}  // namespace obbsat
