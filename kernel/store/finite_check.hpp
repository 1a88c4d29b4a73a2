// The invariants the stores share: finite coordinates, and for a pose
// non-negative half extents and a rotation other than (0, 0). The predicates
// are branch-free, so that a pass over many rows checks at copy speed; the
// require_ functions name the offender once a pass found one.
#pragma once

#include <obbsat/rect.hpp>

#include <cstddef>
#include <cstdint>
#include <cstring>

namespace obbsat::detail {

/// True iff none of values[0, count) is a NaN or an infinity: a float is not
/// finite exactly when its exponent bits are all ones, and adding one to that
/// exponent then carries into the top bit.
inline bool all_finite(const float* values, std::size_t count) {
    std::uint32_t carried = 0;
    for (std::size_t i = 0; i < count; ++i) {
        std::uint32_t bits;
        std::memcpy(&bits, values + i, sizeof bits);
        carried |= (bits & 0x7f800000u) + 0x00800000u;
    }
    return (carried & 0x80000000u) == 0;
}

/// True iff the six floats cx, cy, hx, hy, c, s at `v` are a valid pose, the
/// rule require_valid_pose (obbsat/pose_records.hpp) enforces.
inline bool valid_pose_row(const float* v) {
    return all_finite(v, 6) & !(v[2] < 0.0f) & !(v[3] < 0.0f) & !((v[4] == 0.0f) & (v[5] == 0.0f));
}

/// Throws invalid_input naming rectangle `index` and the first non-finite coordinate of `r`.
void require_finite(const rect& r, std::size_t index);

/// Throws invalid_input when index >= size, naming both.
void require_index(std::size_t index, std::size_t size);

}  // namespace obbsat::detail
