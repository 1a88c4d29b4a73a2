// Whether every pose of a store is accepted by contacts (ref::pose_accepted:
// c·c + s·s a normal finite float, or double for pose_records64), a vector
// of records at a time: each contact call checks its whole store before
// anything is written, and one pose at a time that check took 7% of a
// contact call on 4K pairs over 2K poses. Private to each per-ISA object
// (README.md).
#pragma once

#include "lanes/contact_lanes.hpp"
#include "lanes/pose64_record_transpose.hpp"
#include "lanes/record_transpose.hpp"

#include <obbsat/rect.hpp>

#include <cstddef>
#include <limits>
#include <type_traits>

namespace obbsat::detail {
namespace {

/// Whether each of `count` records of eight reals (cx, cy, hx, hy, c, s, 0,
/// 0; every value finite) has c·c + s·s a normal finite Real. The records
/// are read whole and transposed as the contact lanes read them; the least
/// and the largest square are kept per lane and compared once at the end.
template <class Arch, class Real>
bool pose_records_accepted(const Real* records, std::size_t count) {
    using batch = real_lanes<Arch, Real>;
    constexpr std::size_t width = batch::size;
    constexpr Real least_normal = std::numeric_limits<Real>::min(), largest = std::numeric_limits<Real>::max();
    auto square = [](Real c, Real s) { return (c * c) + (s * s); };
    batch lo(largest), hi(least_normal);
    std::size_t row = 0;
    for (; row + width <= count; row += width) {
        batch c, s;
        if constexpr (std::is_same<Real, float>::value) {
            const quad_lanes<Arch> q = record_transpose<Arch>::template load<false>(
                [&](std::size_t lane) { return reinterpret_cast<const rect*>(records + 8 * (row + lane)); });
            c = q.c[4];
            s = q.c[5];
        } else {
            const pose64_lanes<Arch> p =
                pose64_record_transpose<Arch>::load([&](std::size_t lane) { return records + 8 * (row + lane); });
            c = p.c;
            s = p.s;
        }
        const batch q = (c * c) + (s * s);
        lo = min_pick(q, lo);
        hi = max_pick(q, hi);
    }
    bool accepted = lane_bits((lo < batch(least_normal)) | (hi > batch(largest))) == 0;
    for (; row < count; ++row) {
        const Real q = square(records[8 * row + 4], records[8 * row + 5]);
        accepted = accepted && q >= least_normal && q <= largest;
    }
    return accepted;
}

}  // namespace
}  // namespace obbsat::detail
