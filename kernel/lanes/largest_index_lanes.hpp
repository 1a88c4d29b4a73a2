// The largest index of a pair list, one vector of indices at a time: the pass
// that checks a list against its store before any verdict is written, at
// load speed (a pair is two 32-bit indices, and only their maximum matters).
#pragma once

#include "lanes/lanes.hpp"

#include <obbsat/rect.hpp>

#include <cstddef>
#include <cstdint>

namespace obbsat::detail {
namespace {

/// The largest of pairs[i].a and pairs[i].b over i < count; 0 when count is 0.
template <class Arch>
std::uint32_t largest_index_lanes(const pair_index* pairs, std::size_t count) {
    static_assert(sizeof(pair_index) == 2 * sizeof(std::uint32_t), "a pair is two packed 32-bit indices");
    using batch = xsimd::batch<std::uint32_t, Arch>;
    constexpr std::size_t width = batch::size;
    if (count == 0) {
        return 0;  // pairs may be null then
    }
    const std::uint32_t* index = &pairs[0].a;
    const std::size_t words = 2 * count;
    // Two accumulators: the max of one vector does not wait on the last.
    batch even(std::uint32_t{0}), odd(std::uint32_t{0});
    std::size_t i = 0;
    for (; i + 2 * width <= words; i += 2 * width) {
        even = xsimd::max(even, batch::load_unaligned(index + i));
        odd = xsimd::max(odd, batch::load_unaligned(index + i + width));
    }
    alignas(64) std::uint32_t lanes_of[width];
    xsimd::max(even, odd).store_aligned(lanes_of);
    std::uint32_t largest = 0;
    for (const std::uint32_t v : lanes_of) {
        largest = v > largest ? v : largest;
    }
    for (; i < words; ++i) {
        largest = index[i] > largest ? index[i] : largest;
    }
    return largest;
}

}  // namespace
}  // namespace obbsat::detail
