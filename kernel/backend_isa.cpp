// The batch kernels of one instruction set. This file is compiled once per
// SIMD backend (see cmake/obbsat_isa.cmake) with OBBSAT_ISA_ARCH set to the
// xsimd architecture and OBBSAT_ISA_NAME to the backend's name, and with that
// ISA's compiler flags; it defines <name>_kernels().
#include "batch_kernel.hpp"
#include "certified_lanes.hpp"
#include "kernel_table.hpp"
#include "sat4_centered_lanes.hpp"
#include "sat4_double_lanes.hpp"
#include "sat4_lanes.hpp"

#ifndef OBBSAT_ISA_ARCH
#error "OBBSAT_ISA_ARCH must name the xsimd architecture of this translation unit"
#endif

#define OBBSAT_CONCAT_INNER(a, b) a##b
#define OBBSAT_CONCAT(a, b) OBBSAT_CONCAT_INNER(a, b)

namespace obbsat::detail {

using isa_arch = xsimd::OBBSAT_ISA_ARCH;

const kernel_table& OBBSAT_CONCAT(OBBSAT_ISA_NAME, _kernels)() {
    // Rows in the order of obbsat::method.
    static const kernel_table table = {
        {stream_batch<isa_arch, sat4_lanes>, stream_batch<isa_arch, sat4_centered_lanes>,
         stream_batch<isa_arch, sat4_double_lanes>, stream_batch<isa_arch, conservative_lanes>,
         stream_batch<isa_arch, exact_lanes>},
        {indexed_batch<isa_arch, sat4_lanes>, indexed_batch<isa_arch, sat4_centered_lanes>,
         indexed_batch<isa_arch, sat4_double_lanes>, indexed_batch<isa_arch, conservative_lanes>,
         indexed_batch<isa_arch, exact_lanes>},
        {indexed_records_batch<isa_arch, sat4_lanes>, indexed_records_batch<isa_arch, sat4_centered_lanes>,
         indexed_records_batch<isa_arch, sat4_double_lanes>, indexed_records_batch<isa_arch, conservative_lanes>,
         indexed_records_batch<isa_arch, exact_lanes>},
    };
    return table;
}

}  // namespace obbsat::detail
