// The double-pose kernels of one instruction set, compiled once per SIMD
// backend beside backend_isa.cpp (kernel/CMakeLists.txt adds it to each
// per-ISA object) with that backend's OBBSAT_ISA_NAME and flags; it defines
// double_kernels_of<that backend>(). Everything else here is private to this
// object (README.md).
#include "dispatch/backend_catalogue.hpp"
#include "dispatch/double_kernel_table.hpp"
#include "lanes/pose64_lanes.hpp"

#ifndef OBBSAT_ISA_NAME
#error "OBBSAT_ISA_NAME must name the backend of this translation unit"
#endif

#define OBBSAT_DOUBLE_CONCAT_INNER(a, b) a##b
#define OBBSAT_DOUBLE_CONCAT(a, b) OBBSAT_DOUBLE_CONCAT_INNER(a, b)

namespace obbsat::detail {

using double_isa_backend = OBBSAT_DOUBLE_CONCAT(OBBSAT_ISA_NAME, _backend);
using double_isa_arch = double_isa_backend::arch;

template <>
const double_kernel_table& double_kernels_of<double_isa_backend>() {
    static constexpr double_kernel_table table{pose64_indexed_batch<double_isa_arch, pose_exact64_lanes>,
                                               pose64_indexed_batch<double_isa_arch, pose_conservative64_lanes>,
                                               pose64_indexed_batch<double_isa_arch, local64_lanes>};
    return table;
}

}  // namespace obbsat::detail
