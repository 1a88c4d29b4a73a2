// The plain data of a scene in double precision: points and rectangles given
// by their four corners, for coordinates that float32 would round (UTM metres
// near 1e6 lie 0.0625 apart in float32, 1.2e-10 apart in double).
//
// A rect64 is four double corners UL, UR, LR, LL, adjacent in that cyclic
// order; either winding is accepted. Every stored double is taken exactly, and
// nothing checks that the corners form a true rectangle: a method answers for
// the quadrilateral as given, as on obbsat::rect (obbsat/rect.hpp).
#pragma once

namespace obbsat {

/// A point or vector in the plane, in double.
struct point64 {
    double x;
    double y;
};

/// Four double corners in cyclic order: upper-left, upper-right, lower-right, lower-left.
struct rect64 {
    point64 ul;
    point64 ur;
    point64 lr;
    point64 ll;
};

}  // namespace obbsat
