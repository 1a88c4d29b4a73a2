// What a contact between two colliding rectangles is: the plain data that the
// contact reference (obbsat/ref/contact.hpp) and the batch entry points
// (obbsat/contact.hpp) fill, one `contact` per pair (`contact64` on double
// boxes).
//
// Every float is computed as obbsat/ref/contact.hpp states, so every backend
// gives the same bits.
#pragma once

#include <cstdint>

namespace obbsat {

/// Which kind of feature of a box a contact point comes from.
enum class feature_type : std::uint8_t {
    vertex = 0,  ///< a corner, numbered 0 to 3 as UL, UR, LR, LL
    face = 1,    ///< an edge, numbered 0 to 3: edge k runs from corner k to corner (k + 1) mod 4
};

/// The features of A and of B that made one contact point (as Box2D's
/// b2ContactFeature): one is a face and the other a vertex. The same while the
/// same corner stays in contact with the same edge, so a solver can carry its
/// impulses over from one step to the next by matching keys.
struct contact_feature {
    std::uint8_t index_a;  ///< corner or edge of A, 0 to 3
    feature_type type_a;
    std::uint8_t index_b;  ///< corner or edge of B, 0 to 3
    feature_type type_b;
};

/// One point of a contact manifold.
struct contact_point {
    float x;           ///< position, on B's boundary when A holds the reference face, else on A's
    float y;
    float separation;  ///< signed distance along the normal from the reference face; < 0 when penetrating
    contact_feature feature;
};

/// The contact of a pair (A, B): all zero bits in unused points.
struct contact {
    float nx;  ///< unit normal pointing from A to B (the reference face's normal, negated when the face is B's)
    float ny;
    /// Penetration along the normal: minus the separation of the reference
    /// face, >= 0 when the boxes overlap, 0 when they touch, < 0 when apart.
    float depth;
    std::uint32_t point_count;  ///< 0, 1 or 2: 0 when the pair is apart by more than the margin
    contact_point points[2];    ///< points[0, point_count) are meaningful
};

/// One point of a contact manifold of two double boxes (as contact_point, in double).
struct contact_point64 {
    double x;  ///< position, on B's boundary when A holds the reference face, else on A's
    double y;
    double separation;  ///< signed distance along the normal from the reference face; < 0 when penetrating
    contact_feature feature;
};

/// The contact of a pair (A, B) of double boxes (obbsat/pose_records64.hpp,
/// rect_records64.hpp): the fields of `contact`, computed in double as
/// obbsat/ref/contact.hpp states; all zero bits in unused points.
struct contact64 {
    double nx;  ///< unit normal pointing from A to B
    double ny;
    double depth;  ///< penetration along the normal: > 0 overlapping, 0 touching, < 0 apart
    std::uint32_t point_count;  ///< 0, 1 or 2: 0 when the pair is apart by more than the margin
    contact_point64 points[2];  ///< points[0, point_count) are meaningful
};

static_assert(sizeof(contact_feature) == 4, "a feature key is four bytes");
static_assert(sizeof(contact) == 48, "a contact is 48 bytes");

}  // namespace obbsat
