// The batch kernels of one instruction set. This file is compiled once per
// SIMD backend (see cmake/obbsat_isa.cmake) with OBBSAT_ISA_ARCH set to the
// xsimd architecture and OBBSAT_ISA_NAME to the backend's name, and with that
// ISA's compiler flags; it defines <name>_kernels().
#include "batch_kernel.hpp"
#include "certified_lanes.hpp"
#include "conservative_lanes.hpp"
#include "fused_multiply_add.hpp"
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

}  // namespace

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
        fused_multiply_add_lanes,
    };
    return table;
}

}  // namespace obbsat::detail
