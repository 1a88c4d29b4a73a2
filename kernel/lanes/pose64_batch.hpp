// The methods on double poses in batches: the pose_records64 records as the
// record driver (record_batch.hpp) reads them, and the driver over two
// pose_soa64 views, which reads every field as a vector. The last, partial
// vector repeats its last pair in the unused lanes, so nothing past the
// caller's arrays is read or written.
#pragma once

#include "dispatch/pose_soa64_view.hpp"
#include "lanes/batch_kernel.hpp"
#include "lanes/pose64_lanes.hpp"
#include "lanes/record_batch.hpp"

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

/// Double poses in their 64-byte records, as record_batch.hpp reads them
/// (wide pieces transposed in registers, pose64_record_transpose.hpp).
template <class Arch>
struct pose64_records_of {
    using value = double;
    static constexpr std::size_t width = lanes64<Arch>::size;

    static const double* record(const double* records, std::size_t index) {
        return records + pose64_record_doubles * index;
    }

    /// Every load reads whole cache lines, so whether they are cached changes nothing.
    template <bool InCache, class Index>
    static OBBSAT_LANE_INLINE pose64_lanes<Arch> load(const double* records, const Index& index) {
        return pose64_record_transpose<Arch>::load([&](std::size_t lane) { return record(records, index(lane)); });
    }

    static rect_pose64 at(const double* records, std::size_t index) { return pose64_at(records, index); }
};

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
