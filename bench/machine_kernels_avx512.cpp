// Machine kernels for AVX-512 F: 16 lanes. Compiled with -mavx512f -mfma.
// A random record is 32 bytes, so sum_records loads it as one 256-bit vector.
#include "machine_kernels.hpp"
#include "machine_kernels_body.hpp"

#include <immintrin.h>

namespace obbsat_bench::machine {

namespace {

struct avx512_traits {
    using vec = __m512;
    static constexpr unsigned lanes = 16;
    static vec load(const float* p) { return _mm512_load_ps(p); }
    static void store(float* p, vec v) { _mm512_storeu_ps(p, v); }
    static vec set1(float x) { return _mm512_set1_ps(x); }
    static vec add(vec a, vec b) { return _mm512_add_ps(a, b); }
    static vec mul(vec a, vec b) { return _mm512_mul_ps(a, b); }
    // Zero-masking with every lane on is plain vmaxps; _mm512_max_ps itself
    // trips GCC 12's -Wmaybe-uninitialized on its internal undefined vector.
    static vec max(vec a, vec b) { return _mm512_maskz_max_ps(0xffff, a, b); }
    static vec fma(vec a, vec b, vec c) { return _mm512_fmadd_ps(a, b, c); }
};

struct record_traits {
    using vec = __m256;
    static constexpr unsigned lanes = 8;
    static vec load(const float* p) { return _mm256_load_ps(p); }
    static void store(float* p, vec v) { _mm256_storeu_ps(p, v); }
    static vec set1(float x) { return _mm256_set1_ps(x); }
    static vec add(vec a, vec b) { return _mm256_add_ps(a, b); }
};

void fma(float* state, std::size_t rounds, float m, float c) {
    fma_body<avx512_traits>(state, rounds, m, c);
}
void mul_add(float* state, std::size_t rounds, float m, float c) {
    mul_add_body<avx512_traits>(state, rounds, m, c);
}
void add_max(float* state, std::size_t rounds, float m, float c) {
    add_max_body<avx512_traits>(state, rounds, m, c);
}
float read_sum(const float* data, std::size_t count, std::size_t passes) {
    return read_sum_body<avx512_traits>(data, count, passes);
}
float sum_records(const float* records, const std::uint32_t* indices, std::size_t count) {
    return sum_records_body<record_traits>(records, indices, count);
}

}  // namespace

kernel_set avx512_kernels() {
    return kernel_set{"avx512", avx512_traits::lanes,
                      fma,      mul_add,
                      add_max,  read_sum,
                      read_chains * avx512_traits::lanes, sum_records};
}

}  // namespace obbsat_bench::machine
