// Which SIMD backends of backend_catalogue.hpp have their kernels compiled into
// this build: the x86 backends listed in the CMake option OBBSAT_ISA_KERNELS
// (all of them unless a build leaves some out), none off x86. The dispatcher's
// sources, which the library compiles with the OBBSAT_WITH_*_KERNELS
// definitions, ask here before they name a per-ISA table; a backend left out
// stays in the registry (its name parses) but never resolves.
#pragma once

#include "dispatch/backend_catalogue.hpp"

#include <type_traits>

#if !defined(OBBSAT_WITH_SSE2_KERNELS) || !defined(OBBSAT_WITH_AVX2_KERNELS) || !defined(OBBSAT_WITH_AVX512_KERNELS)
#error "the library defines OBBSAT_WITH_SSE2_KERNELS, OBBSAT_WITH_AVX2_KERNELS and OBBSAT_WITH_AVX512_KERNELS"
#endif

namespace obbsat::detail {

/// Whether Row (a row of backend_catalogue.hpp) has its kernel tables in this build.
template <class Row>
constexpr bool kernels_compiled() {
    if constexpr (!Row::simd) {
        return true;
    } else if constexpr (std::is_same_v<Row, sse2_backend>) {
        return OBBSAT_WITH_SSE2_KERNELS != 0;
    } else if constexpr (std::is_same_v<Row, avx2_backend>) {
        return OBBSAT_WITH_AVX2_KERNELS != 0;
    } else {
        static_assert(std::is_same_v<Row, avx512_backend>, "every SIMD row of the catalogue is named here");
        return OBBSAT_WITH_AVX512_KERNELS != 0;
    }
}

}  // namespace obbsat::detail
