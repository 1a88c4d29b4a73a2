// The batch kernels of one instruction set. This file is compiled once per
// SIMD row of backend_catalogue.hpp (see cmake/obbsat_isa.cmake) with
// OBBSAT_ISA_NAME set to the backend's name and with that ISA's compiler
// flags; it defines kernels_of<that backend>(), one row per method of
// method_catalogue.hpp, and double_kernels_of<that backend>() and
// corner64_kernels_of<that backend>() for the double poses and corners
// (dispatch/double_kernel_table.hpp). Everything else here is private to this object
// (README.md).
#include "dispatch/backend_catalogue.hpp"
#include "dispatch/double_kernel_table.hpp"
#include "dispatch/kernel_table.hpp"
#include "lanes/batch_kernel.hpp"
#include "lanes/bounds_lanes.hpp"
#include "lanes/certified_lanes.hpp"
#include "lanes/conservative_lanes.hpp"
#include "lanes/contact_batch.hpp"
#include "lanes/corner64_lanes.hpp"
#include "lanes/fused_multiply_add.hpp"
#include "lanes/largest_index_lanes.hpp"
#include "lanes/pose_batch.hpp"
#include "lanes/pose_corner_lanes.hpp"
#include "lanes/pose_lanes.hpp"
#include "lanes/pose64_batch.hpp"
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

/// The entry points of one method on double poses but its plain pair list, instantiated for this ISA.
template <template <class> class Method>
constexpr pose64_method_kernels pose64_kernels_of() {
    return pose64_method_kernels{record_indexed_batch<isa_arch, Method, pose64_records_of, pair_fetch::into_l1>,
                                 record_indexed_batch<isa_arch, Method, pose64_records_of, pair_fetch::into_l2>,
                                 record_stream_batch<isa_arch, Method, pose64_records_of>,
                                 pose64_stream_soa_batch<isa_arch, Method>};
}

/// The pair lists of one method on double corners that fetch ahead, instantiated for this ISA.
template <template <class> class Method>
constexpr corner64_method_kernels corner64_kernels_of_method() {
    return corner64_method_kernels{record_indexed_batch<isa_arch, Method, corner64_records_of, pair_fetch::into_l1>,
                                   record_indexed_batch<isa_arch, Method, corner64_records_of, pair_fetch::into_l2>};
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

// The double-pose lanes live in this object too: a second object per ISA would
// instantiate the same xsimd templates for the same architecture (README.md).
template <>
const double_kernel_table& double_kernels_of<this_backend>() {
    static constexpr double_kernel_table table{
        record_indexed_batch<isa_arch, pose_exact64_lanes, pose64_records_of, pair_fetch::none>,
        record_indexed_batch<isa_arch, pose_conservative64_lanes, pose64_records_of, pair_fetch::none>,
        record_indexed_batch<isa_arch, local64_lanes, pose64_records_of, pair_fetch::none>,
        pose64_kernels_of<pose_exact64_lanes>(), pose64_kernels_of<pose_conservative64_lanes>(),
        pose64_kernels_of<local64_lanes>()};
    return table;
}

// So do the double-corner lanes, for the same reason.
template <>
const corner64_kernel_table& corner64_kernels_of<this_backend>() {
    static constexpr corner64_kernel_table table{
        record_indexed_batch<isa_arch, corner_exact64_lanes, corner64_records_of, pair_fetch::none>,
        record_indexed_batch<isa_arch, corner_conservative64_lanes, corner64_records_of, pair_fetch::none>,
        corner64_kernels_of_method<corner_exact64_lanes>(), corner64_kernels_of_method<corner_conservative64_lanes>()};
    return table;
}

template <>
const contact_kernel_table& contact_kernels_of<this_backend>() {
    static constexpr contact_kernel_table table = contact_table_of<isa_arch>();
    return table;
}

}  // namespace obbsat::detail
