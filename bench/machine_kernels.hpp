// The loops obbsat_machine_limits times, once per instruction set. Each set
// lives in its own source file compiled with that set's flags only; the
// program (compiled at the baseline) calls a set's kernels only after the CPU
// check says it may. Pointers and counts only: no vector type crosses this line.
#pragma once

#include <cstddef>
#include <cstdint>

namespace obbsat_bench::machine {

/// Independent dependency chains in every arithmetic kernel: enough to hide
/// the latency of two pipes (4 cycles x 2) with room to spare, few enough to
/// stay in the 16 registers of AVX2.
inline constexpr std::size_t arithmetic_chains = 12;

/// Floats in one record of the random-access kernel (32 bytes, 32-byte aligned).
inline constexpr std::size_t record_floats = 8;

struct kernel_set {
    const char* isa;  ///< "sse2", "avx2" or "avx512"
    unsigned lanes;   ///< float lanes per vector

    /// `rounds` times, one multiply-add per chain (acc = acc * m + c), fused;
    /// null when the set has no FMA. `state` holds arithmetic_chains * lanes floats.
    void (*fma)(float* state, std::size_t rounds, float m, float c);
    /// `rounds` times, half the chains acc = acc * m, the other half acc = acc + c.
    void (*mul_add)(float* state, std::size_t rounds, float m, float c);
    /// `rounds` times, half the chains acc = acc + c, the other half acc = max(acc, m).
    void (*add_max)(float* state, std::size_t rounds, float m, float c);

    /// The sum of data[0, count) taken `passes` times with vector loads;
    /// count is a multiple of read_block floats and data is 64-byte aligned.
    float (*read_sum)(const float* data, std::size_t count, std::size_t passes);
    /// Floats read_sum consumes per step.
    std::size_t read_block;

    /// The sum of all floats of the records records[indices[i]], i < count; the
    /// loads are independent so many are in flight at once.
    float (*sum_records)(const float* records, const std::uint32_t* indices, std::size_t count);
};

/// Baseline x86-64 kernels (SSE2); always runnable on x86-64.
kernel_set sse2_kernels();
/// AVX2 + FMA kernels; call only when the CPU runs AVX2 and FMA.
kernel_set avx2_kernels();
/// AVX-512 F kernels; call only when the CPU runs AVX-512.
kernel_set avx512_kernels();

}  // namespace obbsat_bench::machine
