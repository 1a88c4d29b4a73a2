// The verdict kernels of one instruction set (this_isa.hpp): kernels_of<that
// backend>(), one row per method of method_catalogue.hpp on corners and on
// poses, and the scene queries' helpers (bounds, strip sweep, pose corners).
#include "dispatch/kernel_table.hpp"
#include "lanes/backend_isa/this_isa.hpp"
#include "lanes/batch_kernel.hpp"
#include "lanes/bounds_lanes.hpp"
#include "lanes/certified_lanes.hpp"
#include "lanes/conservative_lanes.hpp"
#include "lanes/fused_multiply_add.hpp"
#include "lanes/largest_index_lanes.hpp"
#include "lanes/pose_batch.hpp"
#include "lanes/pose_corner_lanes.hpp"
#include "lanes/pose_lanes.hpp"
#include "lanes/sat4_centered_lanes.hpp"
#include "lanes/sat4_double_lanes.hpp"
#include "lanes/sat4_lanes.hpp"
#include "lanes/strip_sweep_lanes.hpp"

#include <cstring>

namespace obbsat::detail {

namespace {

void fused_multiply_add_lanes(const float* x, const float* y, const float* z, std::size_t count, float* out) {
    using batch = lanes<isa_arch>;
    constexpr std::size_t width = batch::size;
    for (std::size_t i = 0; i < count; i += width) {
        alignas(64) float staged[3][width] = {};
        const std::size_t n = count - i < width ? count - i : width;
        std::memcpy(staged[0], x + i, n * sizeof(float));
        std::memcpy(staged[1], y + i, n * sizeof(float));
        std::memcpy(staged[2], z + i, n * sizeof(float));
        const batch fused = fused_multiply_add<isa_arch>(batch::load_aligned(staged[0]), batch::load_aligned(staged[1]),
                                                         batch::load_aligned(staged[2]));
        fused.store_aligned(staged[0]);
        std::memcpy(out + i, staged[0], n * sizeof(float));
    }
}

/// The entry points of one catalogue row on corners, instantiated for this
/// ISA; all null when the row does not run on corners.
template <class Row>
constexpr method_kernels kernels_of_row() {
    using corners = typename Row::corners;
    method_kernels k{};
    if constexpr (offered<corners>) {
        static_assert(corners::template lanes<isa_arch>::has_slow_path == Row::has_slow_path,
                      "a method's lanes and its catalogue row agree on the slow path");
        k.stream = stream_batch<isa_arch, corners::template lanes>;
        k.indexed = indexed_batch<isa_arch, corners::template lanes>;
        k.indexed_records = indexed_records_batch<isa_arch, corners::template lanes, pair_fetch::into_l1>;
        k.indexed_records_near = indexed_records_batch<isa_arch, corners::template lanes, pair_fetch::none>;
        k.indexed_records_far = indexed_records_batch<isa_arch, corners::template lanes, pair_fetch::into_l2>;
    }
    return k;
}

/// The entry points of one catalogue row on poses, instantiated for this
/// ISA; all null when the row does not run on poses.
template <class Row>
constexpr pose_method_kernels pose_kernels_of_row() {
    using poses = typename Row::poses;
    pose_method_kernels k{};
    if constexpr (offered<poses>) {
        static_assert(poses::template lanes<isa_arch>::has_slow_path == Row::has_slow_path,
                      "a method's lanes and its catalogue row agree on the slow path");
        k.stream = record_stream_batch<isa_arch, poses::template lanes, pose_records_of>;
        k.indexed = record_indexed_batch<isa_arch, poses::template lanes, pose_records_of, pair_fetch::into_l1>;
        k.stream_soa = pose_stream_soa_batch<isa_arch, poses::template lanes>;
        k.indexed_near = record_indexed_batch<isa_arch, poses::template lanes, pose_records_of, pair_fetch::none>;
        k.indexed_far = record_indexed_batch<isa_arch, poses::template lanes, pose_records_of, pair_fetch::into_l2>;
    }
    return k;
}

template <class... Rows>
constexpr kernel_table table_of(type_list<Rows...>) {
    kernel_table t{};
    ((t.methods[row_of(Rows::id)] = kernels_of_row<Rows>()), ...);
    ((t.pose_methods[row_of(Rows::id)] = pose_kernels_of_row<Rows>()), ...);
    t.fused_multiply_add = fused_multiply_add_lanes;
    t.pose_corners = pose_corners_batch<isa_arch>;
    t.strip_sweep = strip_sweep_lanes<isa_arch>;
    t.bounds = bounds_batch<isa_arch>;
    t.largest_index = largest_index_lanes<isa_arch>;
    return t;
}

}  // namespace

template <>
const kernel_table& kernels_of<this_backend>() {
    static constexpr kernel_table table = table_of(method_catalogue{});
    static_assert(!__builtin_constant_p(follows_catalogue(table, method_catalogue{})) ||
                      follows_catalogue(table, method_catalogue{}),
                  "the table holds the catalogue's rows");
    return table;
}

}  // namespace obbsat::detail
