// Writing poses into the six field arrays (cx, cy, hx, hy, c, s) of a pose
// store of arrays, float (pose_soa) or double (pose_soa64): one pose is one
// value appended to, or set in, each array. Internal to the library.
#pragma once

#include <obbsat/pose_soa.hpp>

#include <cstddef>

namespace obbsat::detail {

/// The fields of `p` in pose_field order.
template <class Real, class Pose>
void fields_of(const Pose& p, Real out[pose_field_count]) {
    out[0] = p.center.x;
    out[1] = p.center.y;
    out[2] = p.half_extents.x;
    out[3] = p.half_extents.y;
    out[4] = p.rotation.x;
    out[5] = p.rotation.y;
}

/// Appends `p` to the six arrays `fields` (vectors of Real).
template <class Real, class Fields, class Pose>
void append_fields(Fields& fields, const Pose& p) {
    Real values[pose_field_count];
    fields_of(p, values);
    for (unsigned f = 0; f < pose_field_count; ++f) {
        fields[f].push_back(values[f]);
    }
}

/// Sets pose `index` of the six arrays `fields` to `p`.
template <class Real, class Fields, class Pose>
void set_fields(Fields& fields, std::size_t index, const Pose& p) {
    Real values[pose_field_count];
    fields_of(p, values);
    for (unsigned f = 0; f < pose_field_count; ++f) {
        fields[f][index] = values[f];
    }
}

}  // namespace obbsat::detail
