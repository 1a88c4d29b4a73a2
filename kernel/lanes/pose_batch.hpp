// The methods on float poses in batches: the pose records as the record
// driver (record_batch.hpp) reads them, each lane's 32-byte record read whole
// and transposed in registers as corner records are; and the driver over two
// pose_soa views, which reads every field as a vector.
#pragma once

#include "lanes/batch_kernel.hpp"
#include "lanes/pose_lanes.hpp"
#include "store/pose_record.hpp"
#include "dispatch/pose_soa_view.hpp"
#include "lanes/record_batch.hpp"
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

/// Float poses in their 32-byte records, as record_batch.hpp reads them.
template <class Arch>
struct pose_records_of {
    using value = float;
    static constexpr std::size_t width = lanes<Arch>::size;

    static const float* record(const float* records, std::size_t index) {
        return records + pose_record_floats * index;
    }

    template <bool InCache, class Index>
    static OBBSAT_LANE_INLINE pose_lanes<Arch> load(const float* records, const Index& index) {
        return load_poses<Arch, InCache>(records, index);
    }

    static rect_pose at(const float* records, std::size_t index) { return pose_record_at(records, index); }
};

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
