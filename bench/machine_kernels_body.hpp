// The bodies of the machine kernels, written once over a vector traits type
// that each instruction-set source defines in its own anonymous namespace.
// Every function here is a template instantiated only with such a TU-local
// type, so each instantiation has internal linkage and the linker can never
// pick one compiled for a wider ISA where a narrower one was meant.
//
// Traits: vec, lanes, load (aligned), store (unaligned), set1, add, mul, max,
// and fma (a * b + c, fused) when has_fma.
#pragma once

#include "machine_kernels.hpp"

#include <cstddef>
#include <cstdint>

namespace obbsat_bench::machine {

template <class T>
float horizontal_sum(const typename T::vec* acc, std::size_t count) {
    float total = 0.0f;
    for (std::size_t k = 0; k < count; ++k) {
        float lanes[T::lanes];
        T::store(lanes, acc[k]);
        for (unsigned l = 0; l < T::lanes; ++l) {
            total += lanes[l];
        }
    }
    return total;
}

template <class T>
void load_chains(const float* state, typename T::vec* acc) {
#pragma GCC unroll 16
    for (std::size_t k = 0; k < arithmetic_chains; ++k) {
        acc[k] = T::load(state + k * T::lanes);
    }
}

template <class T>
void store_chains(float* state, const typename T::vec* acc) {
#pragma GCC unroll 16
    for (std::size_t k = 0; k < arithmetic_chains; ++k) {
        T::store(state + k * T::lanes, acc[k]);
    }
}

template <class T>
void fma_body(float* state, std::size_t rounds, float m, float c) {
    typename T::vec acc[arithmetic_chains];
    load_chains<T>(state, acc);
    const auto vm = T::set1(m);
    const auto vc = T::set1(c);
    for (std::size_t r = 0; r < rounds; ++r) {
#pragma GCC unroll 16
        for (std::size_t k = 0; k < arithmetic_chains; ++k) {
            acc[k] = T::fma(acc[k], vm, vc);
        }
    }
    store_chains<T>(state, acc);
}

template <class T>
void mul_add_body(float* state, std::size_t rounds, float m, float c) {
    typename T::vec acc[arithmetic_chains];
    load_chains<T>(state, acc);
    const auto vm = T::set1(m);
    const auto vc = T::set1(c);
    for (std::size_t r = 0; r < rounds; ++r) {
#pragma GCC unroll 16
        for (std::size_t k = 0; k < arithmetic_chains; k += 2) {
            acc[k] = T::mul(acc[k], vm);
            acc[k + 1] = T::add(acc[k + 1], vc);
        }
    }
    store_chains<T>(state, acc);
}

template <class T>
void add_max_body(float* state, std::size_t rounds, float m, float c) {
    typename T::vec acc[arithmetic_chains];
    load_chains<T>(state, acc);
    const auto vm = T::set1(m);
    const auto vc = T::set1(c);
    for (std::size_t r = 0; r < rounds; ++r) {
#pragma GCC unroll 16
        for (std::size_t k = 0; k < arithmetic_chains; k += 2) {
            acc[k] = T::add(acc[k], vc);
            acc[k + 1] = T::max(acc[k + 1], vm);
        }
    }
    store_chains<T>(state, acc);
}

/// Independent accumulators of read_sum: two loads per cycle into adds of
/// 3-4 cycles latency need at least 8 in flight.
inline constexpr std::size_t read_chains = 8;

template <class T>
float read_sum_body(const float* data, std::size_t count, std::size_t passes) {
    typename T::vec acc[read_chains];
    for (auto& a : acc) {
        a = T::set1(0.0f);
    }
    for (std::size_t p = 0; p < passes; ++p) {
        for (std::size_t i = 0; i < count; i += read_chains * T::lanes) {
#pragma GCC unroll 8
            for (std::size_t k = 0; k < read_chains; ++k) {
                acc[k] = T::add(acc[k], T::load(data + i + k * T::lanes));
            }
        }
    }
    return horizontal_sum<T>(acc, read_chains);
}

/// Records decided per loop step of sum_records: independent loads in flight.
inline constexpr std::size_t record_chains = 4;

template <class T>
float sum_records_body(const float* records, const std::uint32_t* indices, std::size_t count) {
    static_assert(record_floats % T::lanes == 0, "a record must be whole vectors");
    constexpr std::size_t vectors_per_record = record_floats / T::lanes;
    typename T::vec acc[record_chains];
    for (auto& a : acc) {
        a = T::set1(0.0f);
    }
    std::size_t i = 0;
    for (; i + record_chains <= count; i += record_chains) {
#pragma GCC unroll 4
        for (std::size_t k = 0; k < record_chains; ++k) {
            const float* record = records + std::size_t{indices[i + k]} * record_floats;
            for (std::size_t v = 0; v < vectors_per_record; ++v) {
                acc[k] = T::add(acc[k], T::load(record + v * T::lanes));
            }
        }
    }
    for (; i < count; ++i) {
        const float* record = records + std::size_t{indices[i]} * record_floats;
        for (std::size_t v = 0; v < vectors_per_record; ++v) {
            acc[0] = T::add(acc[0], T::load(record + v * T::lanes));
        }
    }
    return horizontal_sum<T>(acc, record_chains);
}

}  // namespace obbsat_bench::machine
