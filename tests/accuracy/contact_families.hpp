// The pair families the contact accuracy is measured on: each places B
// against A in double (a face along a face, a corner into a face, ...), then
// rounds the poses to float; the corner form of a pair is its poses' corners
// computed in double and rounded to float, as a user holding corners has them.
// The double families (make_contact_pairs64) are the same placements kept in
// double, their corners computed in double, as a user of the double stores
// holds them; there the parallel faces tilt down to below one ulp of an angle
// and the far families reach 1e15.
#pragma once

#include <obbsat/rect.hpp>
#include <obbsat/rect64.hpp>
#include <obbsat/rect_pose.hpp>
#include <obbsat/rect_pose64.hpp>

#include <cstdint>
#include <random>
#include <string>
#include <vector>

namespace obbsat::accuracy {

enum class contact_family {
    face_parallel,     ///< a face of B along a face of A, parallel within 1e-3 rad, or exactly
    corner_into_face,  ///< a corner of B pushed into a face of A, B turned well away from A
    corner_corner,     ///< a corner of B at a corner of A, along A's diagonal
    deep_inside,       ///< a small B wholly (or almost) inside A
    exact_touching,    ///< integer rotations and sizes: faces or corners touching exactly
    zero_extents,      ///< segments and points (a zero half extent on A, B or both)
    tiny,              ///< the mixed placements scaled by 1e-6
    huge,              ///< the mixed placements scaled by 1e6
    far_1e6,           ///< the mixed placements moved to about 1e6 from the origin
    far_1e7,           ///< the mixed placements moved to about 1e7 from the origin
    random,            ///< random poses near each other that collide
    far_utm,           ///< the mixed placements moved to 1e5 to 1e7 from the origin (UTM-like; double only)
    far_1e15,          ///< the mixed placements moved to 1e9 to 1e15 from the origin (double only)
    axes_tie,          ///< B on A's axes overlapping equally along both, moved by a few ulps (double only)
};

inline constexpr contact_family all_contact_families[] = {
    contact_family::face_parallel, contact_family::corner_into_face, contact_family::corner_corner,
    contact_family::deep_inside,   contact_family::exact_touching,   contact_family::zero_extents,
    contact_family::tiny,          contact_family::huge,             contact_family::far_1e6,
    contact_family::far_1e7,       contact_family::random};

/// The families measured in double: the float ones but the two fixed
/// distances, which the two far ranges replace, and a tie of A's faces.
inline constexpr contact_family all_contact_families64[] = {
    contact_family::face_parallel, contact_family::axes_tie,         contact_family::corner_into_face,
    contact_family::corner_corner,
    contact_family::deep_inside,   contact_family::exact_touching,   contact_family::zero_extents,
    contact_family::tiny,          contact_family::huge,             contact_family::far_utm,
    contact_family::far_1e15,      contact_family::random};

/// The family's name as the tables print it.
const char* contact_family_name(contact_family family);

struct pose_pair {
    rect_pose a;
    rect_pose b;
};

struct pose_pair64 {
    rect_pose64 a;
    rect_pose64 b;
};

/// `count` pairs of `family`, the same for the same seed.
std::vector<pose_pair> make_contact_pairs(contact_family family, std::size_t count, std::uint64_t seed);

/// `count` pairs of `family` in double, the same for the same seed.
std::vector<pose_pair64> make_contact_pairs64(contact_family family, std::size_t count, std::uint64_t seed);

/// The corners of pose `p`, computed in double and rounded to float (UL, UR, LR, LL).
rect corners_of(const rect_pose& p);

/// The corners of double pose `p`, computed in double (UL, UR, LR, LL).
rect64 corners_of(const rect_pose64& p);

}  // namespace obbsat::accuracy
