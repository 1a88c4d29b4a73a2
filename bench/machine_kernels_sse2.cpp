// Machine kernels at the x86-64 baseline: 4-lane SSE2, no FMA.
#include "machine_kernels.hpp"
#include "machine_kernels_body.hpp"

#include <emmintrin.h>

namespace obbsat_bench::machine {

namespace {

struct sse2_traits {
    using vec = __m128;
    static constexpr unsigned lanes = 4;
    static vec load(const float* p) { return _mm_load_ps(p); }
    static void store(float* p, vec v) { _mm_storeu_ps(p, v); }
    static vec set1(float x) { return _mm_set1_ps(x); }
    static vec add(vec a, vec b) { return _mm_add_ps(a, b); }
    static vec mul(vec a, vec b) { return _mm_mul_ps(a, b); }
    static vec max(vec a, vec b) { return _mm_max_ps(a, b); }
};

void mul_add(float* state, std::size_t rounds, float m, float c) {
    mul_add_body<sse2_traits>(state, rounds, m, c);
}
void add_max(float* state, std::size_t rounds, float m, float c) {
    add_max_body<sse2_traits>(state, rounds, m, c);
}
float read_sum(const float* data, std::size_t count, std::size_t passes) {
    return read_sum_body<sse2_traits>(data, count, passes);
}
float sum_records(const float* records, const std::uint32_t* indices, std::size_t count) {
    return sum_records_body<sse2_traits>(records, indices, count);
}

}  // namespace

kernel_set sse2_kernels() {
    return kernel_set{"sse2",   sse2_traits::lanes,
                      nullptr,  mul_add,
                      add_max,  read_sum,
                      read_chains * sse2_traits::lanes, sum_records};
}

}  // namespace obbsat_bench::machine
