// What the CPU and the operating system let this process run. Compiled at the
// baseline ISA only: this is what decides whether any wider code may run.
#pragma once

namespace obbsat::detail {

struct cpu_features {
    bool sse2 = false;
    bool avx2 = false;    // AVX2 and FMA3 instructions and the OS saves YMM state
    bool avx512 = false;  // AVX-512 F, CD, DQ, BW and the OS saves ZMM state
};

/// The features of the CPU this process runs on, probed once.
const cpu_features& this_cpu();

}  // namespace obbsat::detail
