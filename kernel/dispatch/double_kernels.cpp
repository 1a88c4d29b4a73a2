#include "dispatch/backend_catalogue.hpp"
#include "dispatch/double_kernel_table.hpp"

namespace obbsat::detail {

const double_kernel_table* double_kernels_for(backend resolved) {
#if OBBSAT_WITH_X86_KERNELS
    switch (resolved) {
        case backend::avx512: return &double_kernels_of<avx512_backend>();
        case backend::avx2: return &double_kernels_of<avx2_backend>();
        case backend::sse2: return &double_kernels_of<sse2_backend>();
        default: return nullptr;
    }
#else
    (void)resolved;
    return nullptr;
#endif
}

}  // namespace obbsat::detail
