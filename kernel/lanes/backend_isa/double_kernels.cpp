// The double-precision verdict kernels of one instruction set (this_isa.hpp):
// double_kernels_of<that backend>() for the double poses and
// corner64_kernels_of<that backend>() for the double corners
// (dispatch/double_kernel_table.hpp).
#include "dispatch/double_kernel_table.hpp"
#include "lanes/backend_isa/this_isa.hpp"
#include "lanes/batch_kernel.hpp"
#include "lanes/corner64_lanes.hpp"
#include "lanes/pose64_batch.hpp"

namespace obbsat::detail {

namespace {

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

}  // namespace

// The double-pose verdicts of this ISA: the pose store's three methods, each on
// every pair list.
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

// The double-corner verdicts of this ISA.
template <>
const corner64_kernel_table& corner64_kernels_of<this_backend>() {
    static constexpr corner64_kernel_table table{
        record_indexed_batch<isa_arch, corner_exact64_lanes, corner64_records_of, pair_fetch::none>,
        record_indexed_batch<isa_arch, corner_conservative64_lanes, corner64_records_of, pair_fetch::none>,
        corner64_kernels_of_method<corner_exact64_lanes>(), corner64_kernels_of_method<corner_conservative64_lanes>()};
    return table;
}

}  // namespace obbsat::detail
