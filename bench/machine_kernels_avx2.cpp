// Machine kernels for AVX2 with FMA: 8 lanes. Compiled with -mavx2 -mfma.
#include "machine_kernels.hpp"
#include "machine_kernels_body.hpp"

#include <immintrin.h>

namespace obbsat_bench::machine {

namespace {

struct avx2_traits {
    using vec = __m256;
    static constexpr unsigned lanes = 8;
    static vec load(const float* p) { return _mm256_load_ps(p); }
    static void store(float* p, vec v) { _mm256_storeu_ps(p, v); }
    static vec set1(float x) { return _mm256_set1_ps(x); }
    static vec add(vec a, vec b) { return _mm256_add_ps(a, b); }
    static vec mul(vec a, vec b) { return _mm256_mul_ps(a, b); }
    static vec max(vec a, vec b) { return _mm256_max_ps(a, b); }
    static vec fma(vec a, vec b, vec c) { return _mm256_fmadd_ps(a, b, c); }
};

void fma(float* state, std::size_t rounds, float m, float c) {
    fma_body<avx2_traits>(state, rounds, m, c);
}
void mul_add(float* state, std::size_t rounds, float m, float c) {
    mul_add_body<avx2_traits>(state, rounds, m, c);
}
void add_max(float* state, std::size_t rounds, float m, float c) {
    add_max_body<avx2_traits>(state, rounds, m, c);
}
float read_sum(const float* data, std::size_t count, std::size_t passes) {
    return read_sum_body<avx2_traits>(data, count, passes);
}
float sum_records(const float* records, const std::uint32_t* indices, std::size_t count) {
    return sum_records_body<avx2_traits>(records, indices, count);
}

}  // namespace

kernel_set avx2_kernels() {
    return kernel_set{"avx2",  avx2_traits::lanes,
                      fma,     mul_add,
                      add_max, read_sum,
                      read_chains * avx2_traits::lanes, sum_records};
}

}  // namespace obbsat_bench::machine
