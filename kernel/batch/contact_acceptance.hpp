// Whether every row of a caller's array of poses is accepted by contacts
// (ref::pose_accepted: c·c + s·s a normal finite float), in one pass the
// compiler turns into vector code. The stores' records are checked in the
// backend's lanes instead (contact_acceptance_lanes.hpp).
#pragma once

#include <cstddef>
#include <limits>

namespace obbsat::detail {

/// Whether each of `count` records `Stride` reals apart (c and s at reals 4
/// and 5, every value finite) has c·c + s·s a normal finite Real. One OR of
/// two compares a pose and no branch: a fold of strict min and max picks
/// would wait on each pick's latency and is not vectorized without fast-math.
template <std::size_t Stride, class Real>
bool poses_all_accepted(const Real* records, std::size_t count) {
    constexpr Real least = std::numeric_limits<Real>::min(), largest = std::numeric_limits<Real>::max();
    unsigned rejected = 0;
    for (std::size_t row = 0; row < count; ++row) {
        const Real c = records[Stride * row + 4], s = records[Stride * row + 5];
        const Real square = (c * c) + (s * s);  // of finite reals: never NaN
        rejected |= static_cast<unsigned>(square < least) | static_cast<unsigned>(square > largest);
    }
    return rejected == 0;
}

}  // namespace obbsat::detail
