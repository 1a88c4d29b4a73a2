// The batch drivers of the methods on double poses: walk a batch one vector
// of pairs at a time, load each lane's two poses from their 64-byte
// pose_records64 records (read in wide pieces and transposed in registers,
// pose64_record_transpose.hpp), run the method's lane test, store the
// verdicts, and settle the lanes the fast path left undecided one by one. The
// last, partial vector repeats its last pair in the unused lanes, so nothing
// past the caller's arrays is read or written.
#pragma once

#include "dispatch/pose_soa64_view.hpp"
#include "lanes/batch_kernel.hpp"
#include "lanes/pose64_lanes.hpp"
#include "support/fetch_ahead.hpp"

#include <obbsat/pose_records64.hpp>
#include <obbsat/rect_pose64.hpp>

#include <cstddef>
#include <cstdint>

namespace obbsat::detail {
namespace {

constexpr std::size_t pose64_record_doubles = pose_records64::record_doubles;

/// Pose `index` of pose_records64 records, as the store's operator[] reads it.
inline rect_pose64 pose64_at(const double* records, std::size_t index) {
    const double* r = records + index * pose64_record_doubles;
    return rect_pose64{{r[0], r[1]}, {r[2], r[3]}, {r[4], r[5]}};
}

/// verdicts[i] = Method(a[first(i)], b[second(i)]) for i < count, a and b
/// pose_records64 records; returns the lanes settled exactly. The records of
/// pairs ahead are fetched as Fetch says (fetch_ahead.hpp).
template <class Arch, template <class> class Method, pair_fetch Fetch, class First, class Second>
std::size_t pose64_batch(const double* a, const double* b, First first, Second second, std::size_t count,
                         std::uint8_t* verdicts) {
    constexpr std::size_t width = lanes64<Arch>::size;
    using transpose = pose64_record_transpose<Arch>;
    std::size_t settled = 0;
    auto poses_of_pair = [&](std::size_t i) {
        return make_lane_pair(pose64_at(a, first(i)), pose64_at(b, second(i)));
    };
    // One vector of pairs, pair_of(lane) giving each lane's pair; inlined into
    // the loop, as pose_batch's (its comment says why).
    auto run = [&](std::size_t i, std::size_t valid, const auto& pair_of) __attribute__((always_inline)) {
        const lane_verdicts v = Method<Arch>::collide(
            transpose::load([&](std::size_t lane) { return a + pose64_record_doubles * first(pair_of(lane)); }),
            transpose::load([&](std::size_t lane) { return b + pose64_record_doubles * second(pair_of(lane)); }));
        settled += finish_vector<width, Method, Arch>(v, verdicts + i, valid,
                                                      [&](std::size_t lane) { return poses_of_pair(i + lane); });
    };
    std::size_t i = 0;
    for (; i + width <= count; i += width) {
        if constexpr (Fetch != pair_fetch::none) {
            constexpr std::size_t ahead = pairs_ahead<Fetch>;
            if (i + width + ahead <= count) {
                for (std::size_t k = i + ahead; k < i + ahead + width; ++k) {
                    fetch_record<Fetch>(a + pose64_record_doubles * first(k));
                    fetch_record<Fetch>(b + pose64_record_doubles * second(k));
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
std::size_t pose64_indexed_batch(const double* records, const pair_index* pairs, std::size_t count,
                                 std::uint8_t* verdicts) {
    return pose64_batch<Arch, Method, Fetch>(
        records, records, [pairs](std::size_t i) { return pairs[i].a; }, [pairs](std::size_t i) { return pairs[i].b; },
        count, verdicts);
}

/// verdicts[i] = Method(a[i], b[i]) for i < count: consecutive records, no index read.
template <class Arch, template <class> class Method>
std::size_t pose64_stream_batch(const double* a, const double* b, std::size_t count, std::uint8_t* verdicts) {
    auto same = [](std::size_t i) { return i; };
    return pose64_batch<Arch, Method, pair_fetch::none>(a, b, same, same, count, verdicts);
}

/// The poses [first, first + width) of a view, one vector per field; the caller guarantees they exist.
template <class Arch>
OBBSAT_LANE_INLINE pose64_lanes<Arch> load_consecutive_poses64(const pose_soa64_view& v, std::size_t first) {
    using batch = lanes64<Arch>;
    return pose64_lanes<Arch>{batch::load_unaligned(v.fields[0] + first), batch::load_unaligned(v.fields[1] + first),
                              batch::load_unaligned(v.fields[2] + first), batch::load_unaligned(v.fields[3] + first),
                              batch::load_unaligned(v.fields[4] + first), batch::load_unaligned(v.fields[5] + first)};
}

/// The poses at first + min(lane, valid - 1) of a view: a partial last vector
/// with its last pose repeated, staged in a local array (once per batch).
template <class Arch>
pose64_lanes<Arch> load_last_poses64(const pose_soa64_view& v, std::size_t first, std::size_t valid) {
    constexpr std::size_t width = lanes64<Arch>::size;
    alignas(64) double staged[pose_field_count][width];
    pose_soa64_view local{};
    for (unsigned f = 0; f < pose_field_count; ++f) {
        for (std::size_t lane = 0; lane < width; ++lane) {
            staged[f][lane] = v.fields[f][first + (lane < valid ? lane : valid - 1)];
        }
        local.fields[f] = staged[f];
    }
    return load_consecutive_poses64<Arch>(local, 0);
}

/// verdicts[i] = Method(a[i], b[i]) for i < count over two pose_soa64 views:
/// every field is read as a vector, nothing is transposed.
template <class Arch, template <class> class Method>
std::size_t pose64_stream_soa_batch(const pose_soa64_view& a, const pose_soa64_view& b, std::size_t count,
                                    std::uint8_t* verdicts) {
    constexpr std::size_t width = lanes64<Arch>::size;
    std::size_t settled = 0;
    auto finish = [&](const lane_verdicts& v, std::size_t i, std::size_t valid) __attribute__((always_inline)) {
        settled += finish_vector<width, Method, Arch>(v, verdicts + i, valid, [&](std::size_t lane) {
            return make_lane_pair(pose64_at(a, i + lane), pose64_at(b, i + lane));
        });
    };
    std::size_t i = 0;
    for (; i + width <= count; i += width) {
        finish(Method<Arch>::collide(load_consecutive_poses64<Arch>(a, i), load_consecutive_poses64<Arch>(b, i)), i,
               width);
    }
    if (i < count) {
        const std::size_t valid = count - i;
        finish(Method<Arch>::collide(load_last_poses64<Arch>(a, i, valid), load_last_poses64<Arch>(b, i, valid)), i,
               valid);
    }
    return settled;
}

}  // namespace
}  // namespace obbsat::detail
