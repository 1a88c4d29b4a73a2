// The batch drivers of the methods on poses: walk a batch one vector of pairs
// at a time, load each lane's two poses from their 32-byte records (read whole
// and transposed in registers, as corner records are), run the method's lane
// test, store the verdicts. The last, partial vector repeats its last pair in
// the unused lanes, so nothing past the caller's arrays is read or written.
#pragma once

#include "lanes/batch_kernel.hpp"
#include "lanes/pose_lanes.hpp"
#include "store/pose_record.hpp"
#include "dispatch/pose_soa_view.hpp"
#include "lanes/record_transpose.hpp"

#include <obbsat/rect_pose.hpp>

#include <cstddef>
#include <cstdint>

namespace obbsat::detail {
namespace {

/// The poses of records[index(lane)] for every lane; InCache as in record_transpose::assemble.
template <class Arch, bool InCache = false, class Index>
OBBSAT_LANE_INLINE pose_lanes<Arch> load_poses(const float* records, const Index& index) {
    return poses_of<Arch>(record_transpose<Arch>::template load<InCache>([&](std::size_t lane) {
        return reinterpret_cast<const rect*>(records + pose_record_floats * index(lane));
    }));
}

/// verdicts[i] = Method(a[first(i)], b[second(i)]) for i < count; returns the
/// lanes settled exactly. The records of pairs ahead are fetched as Fetch
/// says (fetch_ahead.hpp).
template <class Arch, template <class> class Method, pair_fetch Fetch, class First, class Second>
std::size_t pose_batch(const float* a, const float* b, First first, Second second,
                       std::size_t count, std::uint8_t* verdicts) {
    constexpr std::size_t width = lanes<Arch>::size;
    // A list that fetches nothing ahead reads records the caches hold.
    constexpr bool in_cache = Fetch == pair_fetch::none;
    std::size_t settled = 0;
    auto poses_of_pair = [&](std::size_t i) { return make_lane_pair(pose_record_at(a, first(i)), pose_record_at(b, second(i))); };
    // One vector of pairs, pair_of(lane) giving each lane's pair. Inlined
    // into the loop, with first and second held by value: called out of line,
    // or reading the pair list through references, the loop reloaded its
    // pointers from memory after every verdict store (a byte store may alias
    // anything), 1.9-2.0 against 1.65 ns per pair for local at 256K pairs.
    auto run = [&](std::size_t i, std::size_t valid, const auto& pair_of) __attribute__((always_inline)) {
        const lane_verdicts v =
            Method<Arch>::collide(load_poses<Arch, in_cache>(a, [&](std::size_t lane) { return first(pair_of(lane)); }),
                                  load_poses<Arch, in_cache>(b, [&](std::size_t lane) { return second(pair_of(lane)); }));
        settled += finish_vector<width, Method, Arch>(v, verdicts + i, valid,
                                                      [&](std::size_t lane) { return poses_of_pair(i + lane); });
    };
    std::size_t i = 0;
    for (; i + width <= count; i += width) {
        if constexpr (Fetch != pair_fetch::none) {
            constexpr std::size_t ahead = pairs_ahead<Fetch>;
            if (i + width + ahead <= count) {
                for (std::size_t k = i + ahead; k < i + ahead + width; ++k) {
                    fetch_record<Fetch>(a + pose_record_floats * first(k));
                    fetch_record<Fetch>(b + pose_record_floats * second(k));
                }
            }
        }
        run(i, width, [&](std::size_t lane) { return i + lane; });
    }
    if (i < count) {
        const std::size_t valid = count - i;
        run(i, valid, [&](std::size_t lane) { return i + (lane < valid ? lane : valid - 1); });
    }
    return settled;
}

/// verdicts[i] = Method(records[pairs[i].a], records[pairs[i].b]) for i < count;
/// the records of pairs ahead are fetched as Fetch says.
template <class Arch, template <class> class Method, pair_fetch Fetch>
std::size_t pose_indexed_batch(const float* records, const pair_index* pairs, std::size_t count,
                               std::uint8_t* verdicts) {
    return pose_batch<Arch, Method, Fetch>(
        records, records, [pairs](std::size_t i) { return pairs[i].a; }, [pairs](std::size_t i) { return pairs[i].b; },
        count, verdicts);
}

/// verdicts[i] = Method(a[i], b[i]) for i < count.
template <class Arch, template <class> class Method>
std::size_t pose_stream_batch(const float* a, const float* b, std::size_t count, std::uint8_t* verdicts) {
    auto same = [](std::size_t i) { return i; };
    return pose_batch<Arch, Method, pair_fetch::none>(a, b, same, same, count, verdicts);
}

/// The poses [first, first + width) of a view, one vector per field; the caller guarantees they exist.
template <class Arch>
OBBSAT_LANE_INLINE pose_lanes<Arch> load_consecutive_poses(const pose_soa_view& v, std::size_t first) {
    using batch = lanes<Arch>;
    return pose_lanes<Arch>{batch::load_unaligned(v.fields[0] + first), batch::load_unaligned(v.fields[1] + first),
                            batch::load_unaligned(v.fields[2] + first), batch::load_unaligned(v.fields[3] + first),
                            batch::load_unaligned(v.fields[4] + first), batch::load_unaligned(v.fields[5] + first)};
}

/// verdicts[i] = Method(a[i], b[i]) for i < count over two pose_soa views:
/// every field is read as a vector, nothing is transposed.
template <class Arch, template <class> class Method>
std::size_t pose_stream_soa_batch(const pose_soa_view& a, const pose_soa_view& b, std::size_t count,
                                  std::uint8_t* verdicts) {
    constexpr std::size_t width = lanes<Arch>::size;
    std::size_t settled = 0;
    std::size_t i = 0;
    for (; i + width <= count; i += width) {
        const lane_verdicts v =
            Method<Arch>::collide(load_consecutive_poses<Arch>(a, i), load_consecutive_poses<Arch>(b, i));
        settled += finish_vector<width, Method, Arch>(
            v, verdicts + i, width, [&](std::size_t lane) { return make_lane_pair(pose_at(a, i + lane), pose_at(b, i + lane)); });
    }
    if (i < count) {
        // Partial vector: the last pair repeated in the unused lanes, staged locally.
        alignas(64) float staged[2][pose_field_count][width];
        for (std::size_t lane = 0; lane < width; ++lane) {
            const std::size_t k = (i + lane < count) ? i + lane : count - 1;
            for (unsigned f = 0; f < pose_field_count; ++f) {
                staged[0][f][lane] = a.fields[f][k];
                staged[1][f][lane] = b.fields[f][k];
            }
        }
        pose_soa_view sa{}, sb{};
        for (unsigned f = 0; f < pose_field_count; ++f) {
            sa.fields[f] = staged[0][f];
            sb.fields[f] = staged[1][f];
        }
        const lane_verdicts v = Method<Arch>::collide(load_consecutive_poses<Arch>(sa, 0), load_consecutive_poses<Arch>(sb, 0));
        settled += finish_vector<width, Method, Arch>(
            v, verdicts + i, count - i, [&](std::size_t lane) { return make_lane_pair(pose_at(a, i + lane), pose_at(b, i + lane)); });
    }
    return settled;
}

}  // namespace
}  // namespace obbsat::detail
