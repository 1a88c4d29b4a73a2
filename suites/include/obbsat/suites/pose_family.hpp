// The families of hard cases for the methods on poses (local, conservative
// and exact on pose_records; obbsat/method.hpp): pairs of rect_poses, each
// family one way of putting a real share of its pairs on, or within a few
// float steps of, the boundary between separated, touching and overlapping
// as the pose oracle (obbsat/oracle/pose_contact.hpp) judges it.
//
// "On contact" below means: B's center placed, in double, where B touches A
// along one of A's own axes (at a random slide across it), rounded to float
// and then moved -4..4 float steps in x and in y independently.
#pragma once

#include <cstdint>
#include <string_view>
#include <vector>

namespace obbsat::suites {

enum class pose_family : std::uint8_t {
    near,             ///< two poses of sizes 2^-3 .. 2^5 drawn near each other: mostly clear of contact
    contact,          ///< on contact: gaps and overlaps of a few float steps
    integer_contact,  ///< integer centers, half extents 0..5 and rotation vectors like (3, 4), (5, 12): exact contacts
    far,              ///< on contact, 2^13 .. 2^25 (about 1e4 .. 3e7) from the origin
    rotation_scale,   ///< rotation vectors of length 2^-30 .. 2^31, half extents scaled inversely, on contact
    zero_extents,     ///< segments and points (half extents of 0), on contact
    slivers,          ///< one half extent 2^-24 .. 2^-9 times the other, on contact
    near_parallel,    ///< B's rotation vector within 4 float steps of A's per component, on contact
    tiny,             ///< on contact, every length scaled by 2^-60 .. 2^-39
    huge,             ///< on contact, every length scaled by 2^40 .. 2^61
};

/// The family's name, e.g. "rotation_scale".
const char* pose_family_name(pose_family f);

/// The pose family called `name`; throws obbsat::invalid_input listing the names otherwise.
pose_family parse_pose_family(std::string_view name);

/// Every pose family, in declaration order.
const std::vector<pose_family>& all_pose_families();

}  // namespace obbsat::suites
