// The methods on double corners (rect_records64), one pair per lane of
// doubles (2 per SSE2 vector, 4 per AVX2, 8 per AVX-512), doing the double
// operations of their scalar references in the same order, so that verdicts
// are bit for bit theirs:
//   exact         the certified fast path of obbsat/ref/certified64.hpp (the
//                 steps of certified_lanes.hpp in double); the lanes it leaves
//                 undecided are settled by the exact oracle of
//                 obbsat/oracle/contact64.hpp, as obbsat/ref/exact64.hpp says;
//   conservative  obbsat/ref/conservative64.hpp: the steps of
//                 conservative_lanes.hpp in double, its fused projections and
//                 margin computed by fused_multiply_add (one rounding each).
// And the batch driver: a vector of pairs at a time, each lane's two records
// read whole and transposed in registers (record64_transpose.hpp).
#pragma once

#include "lanes/batch_kernel.hpp"
#include "lanes/certified_lanes.hpp"
#include "lanes/conservative_lanes.hpp"
#include "lanes/lanes.hpp"
#include "lanes/record64_transpose.hpp"

#include <obbsat/oracle/contact64.hpp>
#include <obbsat/rect.hpp>
#include <obbsat/rect64.hpp>

#include <cstddef>
#include <cstdint>

namespace obbsat::detail {
namespace {

/// One double-corner rectangle per lane.
template <class Arch>
using quad64_lanes = quad<xsimd::batch<double, Arch>>;

/// Method exact on double corners: proven lanes from the certified path in
/// double, the rest from the double oracle.
template <class Arch>
struct corner_exact64_lanes {
    static constexpr bool has_slow_path = true;

    static OBBSAT_LANE_INLINE lane_verdicts collide(const quad64_lanes<Arch>& a, const quad64_lanes<Arch>& b) {
        const auto v = certified_steps<Arch, double>::certify(a, b);
        return lane_verdicts{lane_bits(v.intersecting), lane_bits(~(v.separated | v.intersecting))};
    }

    static bool decide_exactly(const rect64& a, const rect64& b) { return oracle::intersects(a, b); }
};

/// Method conservative on double corners: conservative_lanes in double, the
/// steps of conservative64.hpp.
template <class Arch>
struct corner_conservative64_lanes : conservative_steps<Arch, double> {};

/// verdicts[i] = Method(records[pairs[i].a], records[pairs[i].b]) for i < count
/// over rect_records64 records; returns the lanes settled exactly. The last,
/// partial vector repeats its last pair in the unused lanes and stores only
/// its own verdicts, so nothing past the caller's arrays is read or written.
template <class Arch, template <class> class Method>
std::size_t corner64_indexed_batch(const rect64* records, const pair_index* pairs, std::size_t count,
                                   std::uint8_t* verdicts) {
    using transpose = record64_transpose<Arch>;
    constexpr std::size_t width = transpose::width;
    std::size_t settled = 0;
    auto rects_of = [&](std::size_t pair) { return make_lane_pair(records[pairs[pair].a], records[pairs[pair].b]); };
    // One vector of pairs from i, pair_of(lane) giving each lane's pair.
    auto run = [&](std::size_t i, std::size_t valid, const auto& pair_of) __attribute__((always_inline)) {
        const lane_verdicts v =
            Method<Arch>::collide(transpose::load([&](std::size_t lane) { return records + pairs[pair_of(lane)].a; }),
                                  transpose::load([&](std::size_t lane) { return records + pairs[pair_of(lane)].b; }));
        settled += finish_vector<width, Method, Arch>(v, verdicts + i, valid,
                                                      [&](std::size_t lane) { return rects_of(i + lane); });
    };
    std::size_t i = 0;
    for (; i + width <= count; i += width) {
        run(i, width, [&](std::size_t lane) { return i + lane; });
    }
    if (i < count) {
        const std::size_t valid = count - i;
        run(i, valid, [&](std::size_t lane) { return i + (lane < valid ? lane : valid - 1); });
    }
    return settled;
}

}  // namespace
}  // namespace obbsat::detail
