// The distance of a pair of boxes and a closest point on each: the plain data
// that the distance reference (obbsat/ref/distance.hpp) and the batch entry
// points (obbsat/contact.hpp) fill, one per pair.
#pragma once

namespace obbsat {

/// How far apart two boxes A and B are. For a pair that overlaps or touches
/// (its verdict, as obbsat/ref/distance.hpp states it, is "colliding"), every
/// field is +0.
struct closest_points {
    float distance;  ///< Euclidean distance between the closed boxes, > 0 for separated pairs
    float ax, ay;    ///< a point of A at that distance from B
    float bx, by;    ///< a point of B at that distance from A
};

/// The distance of two double boxes and a closest point on each: the fields
/// of closest_points, computed in double as obbsat/ref/distance.hpp states.
struct closest_points64 {
    double distance;  ///< Euclidean distance between the closed boxes, > 0 for separated pairs
    double ax, ay;    ///< a point of A at that distance from B
    double bx, by;    ///< a point of B at that distance from A
};

static_assert(sizeof(closest_points) == 20, "closest points are five floats");

}  // namespace obbsat
