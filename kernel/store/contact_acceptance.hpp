// Whether every row of a caller's array of poses is accepted by contacts
// (ref::pose_accepted: c·c + s·s a normal finite number of the rows' type),
// in one pass the compiler turns into vector code. Used by the pair lists'
// contacts on the caller's rows and by the scene query's contacts; a store's
// records are checked in the backend's lanes instead
// (lanes/contact_acceptance_lanes.hpp).
#pragma once

#include <cstddef>
#include <limits>

namespace obbsat::detail {

/// Whether each of `count` rows `stride` reals apart (c and s at reals 4 and
/// 5) has c·c + s·s a normal finite Real; false where a square is NaN. One OR
/// of two compares a pose and no branch: a fold of strict min and max picks
/// would wait on each pick's latency and is not vectorized without fast-math.
/// A caller whose stride is a constant gets code for that stride once this
/// inlines.
template <class Real>
inline bool poses_all_accepted(const Real* rows, std::size_t stride, std::size_t count) {
    constexpr Real least = std::numeric_limits<Real>::min(), largest = std::numeric_limits<Real>::max();
    unsigned rejected = 0;
    for (std::size_t row = 0; row < count; ++row) {
        const Real c = rows[stride * row + 4], s = rows[stride * row + 5];
        const Real square = (c * c) + (s * s);
        rejected |= static_cast<unsigned>(!(square >= least)) | static_cast<unsigned>(!(square <= largest));
    }
    return rejected == 0;
}

}  // namespace obbsat::detail
