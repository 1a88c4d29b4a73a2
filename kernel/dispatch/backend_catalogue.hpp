// The one list of backends, best first, the scalar path last. Each row names
// the backend, the xsimd architecture its kernels are instantiated for (and
// so its lane width), and the check that this CPU and its OS can run it. The
// dispatcher's registry (backend.cpp), the per-ISA kernel tables
// (lanes/backend_isa/, compiled once per SIMD row by cmake/obbsat_isa.cmake) and
// the kernel-table declarations are derived from this list.
//
// Nothing here is SIMD code: the rows are constants and CPU checks, compiled
// at the baseline ISA.
#pragma once

#include "dispatch/cpu_features.hpp"
#include "support/type_list.hpp"

#include <obbsat/backend.hpp>

#include <xsimd/xsimd.hpp>

#include <cstddef>

namespace obbsat::detail {

/// Lanes of one float vector of an xsimd architecture.
template <class Arch>
constexpr unsigned float_lanes_of() {
    return static_cast<unsigned>(Arch::alignment() / sizeof(float));
}

struct avx512_backend {
    static constexpr backend id = backend::avx512;
    static constexpr const char* name = "avx512";
    static constexpr bool simd = true;
    using arch = xsimd::avx512bw;
    static constexpr unsigned lanes = float_lanes_of<arch>();
    static bool runs_here() { return this_cpu().avx512; }
};

struct avx2_backend {
    static constexpr backend id = backend::avx2;
    static constexpr const char* name = "avx2";
    static constexpr bool simd = true;
    using arch = xsimd::avx2;
    static constexpr unsigned lanes = float_lanes_of<arch>();
    static bool runs_here() { return this_cpu().avx2; }
};

struct sse2_backend {
    static constexpr backend id = backend::sse2;
    static constexpr const char* name = "sse2";
    static constexpr bool simd = true;
    using arch = xsimd::sse2;
    static constexpr unsigned lanes = float_lanes_of<arch>();
    static bool runs_here() { return this_cpu().sse2; }
};

/// The scalar references, one pair at a time: runs everywhere.
struct scalar_backend {
    static constexpr backend id = backend::scalar;
    static constexpr const char* name = "scalar";
    static constexpr bool simd = false;
    static constexpr unsigned lanes = 1;
    static bool runs_here() { return true; }
};

/// Every backend, best first; the dispatcher walks it in this order.
using backend_catalogue = type_list<avx512_backend, avx2_backend, sse2_backend, scalar_backend>;

constexpr bool every_backend_listed_once() {
    constexpr auto ids = backend_catalogue::map([](auto row) { return decltype(row)::id; });
    const backend all[] = {backend::scalar, backend::sse2, backend::avx2, backend::avx512};
    for (const backend b : all) {
        unsigned seen = 0;
        for (const backend id : ids) {
            seen += id == b ? 1u : 0u;
        }
        if (seen != 1) {
            return false;
        }
    }
    return ids.size() == std::size(all) && ids[ids.size() - 1] == backend::scalar;
}

static_assert(every_backend_listed_once(), "each backend once, the scalar path last");

}  // namespace obbsat::detail
