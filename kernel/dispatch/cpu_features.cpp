#include "dispatch/cpu_features.hpp"

#if OBBSAT_WITH_X86_KERNELS
#include <xsimd/config/xsimd_cpuid.hpp>
#endif

#include <cstdint>

namespace obbsat::detail {

namespace {

#if OBBSAT_WITH_X86_KERNELS
// XCR0: which register states the OS saves on a context switch. A CPU may
// have AVX-512 while its OS does not enable it; xsimd's probe reads only CPUID.
std::uint64_t os_saved_state() {
    unsigned eax = 0, ebx = 0, ecx = 0, edx = 0;
    __asm__("cpuid" : "=a"(eax), "=b"(ebx), "=c"(ecx), "=d"(edx) : "a"(1), "c"(0));
    const bool osxsave = (ecx >> 27) & 1u;
    if (!osxsave) {
        return 0;
    }
    unsigned lo = 0, hi = 0;
    __asm__("xgetbv" : "=a"(lo), "=d"(hi) : "c"(0));
    return (static_cast<std::uint64_t>(hi) << 32) | lo;
}
#endif

cpu_features probe() {
    cpu_features f;
#if OBBSAT_WITH_X86_KERNELS
    const auto arch = xsimd::available_architectures();
    const std::uint64_t xcr0 = os_saved_state();
    const bool ymm_saved = (xcr0 & 0x6u) == 0x6u;           // SSE and AVX state
    const bool zmm_saved = ymm_saved && (xcr0 & 0xe0u) == 0xe0u;  // opmask, ZMM0-15 high, ZMM16-31
    f.sse2 = arch.sse2;
    f.avx2 = arch.avx2 && arch.fma3_avx2 && ymm_saved;
    f.avx512 = arch.avx512f && arch.avx512cd && arch.avx512dq && arch.avx512bw && zmm_saved;
#endif
    return f;
}

}  // namespace

const cpu_features& this_cpu() {
    static const cpu_features features = probe();
    return features;
}

}  // namespace obbsat::detail
