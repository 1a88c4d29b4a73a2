// The batch kernels of one instruction set. This file is compiled once per
// SIMD row of backend_catalogue.hpp (see cmake/obbsat_isa.cmake) with
// OBBSAT_ISA_NAME set to the backend's name and with that ISA's compiler
// flags; it defines kernels_of<that backend>(), one row per method of
// method_catalogue.hpp.
#include "dispatch/backend_catalogue.hpp"
#include "lanes/batch_kernel.hpp"
#include "lanes/bounds_lanes.hpp"
#include "lanes/certified_lanes.hpp"
#include "lanes/conservative_lanes.hpp"
#include "lanes/fused_multiply_add.hpp"
#include "dispatch/kernel_table.hpp"
#include "lanes/largest_index_lanes.hpp"
#include "methods/method_catalogue.hpp"
#include "lanes/pose_batch.hpp"
#include "lanes/pose_corner_lanes.hpp"
#include "lanes/pose_lanes.hpp"
#include "lanes/sat4_centered_lanes.hpp"
#include "lanes/sat4_double_lanes.hpp"
#include "lanes/sat4_lanes.hpp"
#include "lanes/strip_sweep_lanes.hpp"

#ifndef OBBSAT_ISA_NAME
#error "OBBSAT_ISA_NAME must name the backend of this translation unit"
#endif

#define OBBSAT_CONCAT_INNER(a, b) a##b
#define OBBSAT_CONCAT(a, b) OBBSAT_CONCAT_INNER(a, b)

namespace obbsat::detail {

using this_backend = OBBSAT_CONCAT(OBBSAT_ISA_NAME, _backend);
using isa_arch = this_backend::arch;
static_assert(lanes<isa_arch>::size == this_backend::lanes, "the catalogue's lane width is the arch's");

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

/// The entry points of one catalogue row on corners, instantiated for this ISA.
template <class Row>
constexpr method_kernels kernels_of_row() {
    using corners = typename Row::corners;
    if constexpr (offered<corners>) {
        static_assert(corners::template lanes<isa_arch>::has_slow_path == Row::has_slow_path,
                      "a method's lanes and its catalogue row agree on the slow path");
        return method_kernels{stream_batch<isa_arch, corners::template lanes>,
                              indexed_batch<isa_arch, corners::template lanes>,
                              indexed_records_batch<isa_arch, corners::template lanes, pair_fetch::into_l1>,
                              indexed_records_batch<isa_arch, corners::template lanes, pair_fetch::none>,
                              indexed_records_batch<isa_arch, corners::template lanes, pair_fetch::into_l2>};
    } else {
        return method_kernels{nullptr, nullptr, nullptr, nullptr, nullptr};
    }
}

/// The entry points of one catalogue row on poses, instantiated for this ISA.
template <class Row>
constexpr pose_method_kernels pose_kernels_of_row() {
    using poses = typename Row::poses;
    if constexpr (offered<poses>) {
        static_assert(poses::template lanes<isa_arch>::has_slow_path == Row::has_slow_path,
                      "a method's lanes and its catalogue row agree on the slow path");
        return pose_method_kernels{pose_stream_batch<isa_arch, poses::template lanes>,
                                   pose_indexed_batch<isa_arch, poses::template lanes, pair_fetch::into_l1>,
                                   pose_stream_soa_batch<isa_arch, poses::template lanes>,
                                   pose_indexed_batch<isa_arch, poses::template lanes, pair_fetch::none>,
                                   pose_indexed_batch<isa_arch, poses::template lanes, pair_fetch::into_l2>};
    } else {
        return pose_method_kernels{nullptr, nullptr, nullptr, nullptr, nullptr};
    }
}

template <class... Rows>
constexpr kernel_table table_of(type_list<Rows...>) {
    return kernel_table{{kernels_of_row<Rows>()...},
                        {pose_kernels_of_row<Rows>()...},
                        fused_multiply_add_lanes,
                        pose_corners_batch<isa_arch>,
                        strip_sweep_lanes<isa_arch>,
                        bounds_batch<isa_arch>,
                        largest_index_lanes<isa_arch>};
}

}  // namespace

template <>
const kernel_table& kernels_of<this_backend>() {
    static const kernel_table table = table_of(method_catalogue{});
    return table;
}

}  // namespace obbsat::detail
