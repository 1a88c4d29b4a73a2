// One strip of a scene query's sweep, as the sweep kernels read it: its
// entries sorted by quantized lo_x, in structure-of-arrays form, followed by
// `strip_padding` sentinel entries whose q_lo and lo_x are +inf and whose
// starts is -1, so that a kernel may read whole vectors past the last entry
// and never take one: the bounds alone would not keep them out, since an
// entry whose bounds are infinite overlaps every bounds there are.
// Internal to the library.
#pragma once

#include <obbsat/rect.hpp>

#include <cstddef>
#include <cstdint>

namespace obbsat::detail {

/// Sentinel entries after the last one: the widest backend's lane count.
constexpr std::size_t strip_padding = 16;

// Every array the kernels compare is float, so that one vector mask type
// serves every test: quantized positions are integers below 2^24, exact in
// float, and the two flags are 0 or 1.

struct strip_view {
    const float* q_lo;        ///< quantized lo_x, ascending; sentinels hold +inf
    const float* q_hi;        ///< quantized hi_x
    const std::int32_t* id;   ///< the rectangle, in the query's order
    const float* starts;      ///< 1 if the rectangle's lowest strip is this one, 0 for a visitor from below, -1 for a sentinel
    const float* store;       ///< 0 for the first store, 1 for the second
    const float* lo_x;
    const float* lo_y;
    const float* hi_x;
    const float* hi_y;
    std::size_t size;  ///< entries, not counting the sentinels
    bool cross;        ///< a query across two stores: pairs must mix them
};

/// Where a sweep stopped: entry e, next tested against entries from f on.
struct sweep_cursor {
    std::size_t e = 0;
    std::size_t f = 1;
};

/// Tests entry pairs from `cursor` on and writes each pair (id[e], id[f]),
/// e < f, whose bounds overlap, that is not two visitors, and (cross) that
/// mixes the stores, to `out`; stops at the end of the strip or when the
/// next step might not fit in the slots of `capacity` left (fewer than a
/// vector's width on a SIMD backend; the scalar one stops at strip_padding),
/// so any capacity of at least strip_padding makes progress. Returns the pairs written
/// and leaves `cursor` where the next call resumes. The pairs and their order
/// are the same on every backend.
using strip_sweep_fn = std::size_t (*)(const strip_view& strip, sweep_cursor& cursor, pair_index* out,
                                       std::size_t capacity);

}  // namespace obbsat::detail
