// The scalar backend: the reference of each method applied one pair at a time.
#include "kernel_table.hpp"

#include <obbsat/oracle/contact.hpp>
#include <obbsat/ref/conservative.hpp>
#include <obbsat/ref/sat4.hpp>
#include <obbsat/ref/sat4_centered.hpp>
#include <obbsat/ref/sat4_double.hpp>

#include <cmath>

namespace obbsat::detail {

namespace {

using reference_fn = bool (*)(const rect&, const rect&);

// The scalar path decides every pair with the method's reference; for the
// exact method that reference is the oracle itself, so every pair counts as
// decided on the exact path.
template <reference_fn Reference>
constexpr bool is_exact_reference() {
    return Reference == &oracle::intersects;
}

template <reference_fn Reference>
std::size_t exact_count(std::size_t count) {
    return is_exact_reference<Reference>() ? count : 0;
}

template <reference_fn Reference>
std::size_t stream_pairs(const soa_view& a, const soa_view& b, std::size_t count, std::uint8_t* verdicts) {
    for (std::size_t i = 0; i < count; ++i) {
        verdicts[i] = Reference(a.at(i), b.at(i)) ? 1 : 0;
    }
    return exact_count<Reference>(count);
}

template <reference_fn Reference>
std::size_t indexed_pairs(const soa_view& rects, const pair_index* pairs, std::size_t count,
                          std::uint8_t* verdicts) {
    for (std::size_t i = 0; i < count; ++i) {
        verdicts[i] = Reference(rects.at(pairs[i].a), rects.at(pairs[i].b)) ? 1 : 0;
    }
    return exact_count<Reference>(count);
}

template <reference_fn Reference>
std::size_t indexed_records(const rect* records, const pair_index* pairs, std::size_t count,
                            std::uint8_t* verdicts) {
    for (std::size_t i = 0; i < count; ++i) {
        verdicts[i] = Reference(records[pairs[i].a], records[pairs[i].b]) ? 1 : 0;
    }
    return exact_count<Reference>(count);
}

void fused_multiply_add(const float* x, const float* y, const float* z, std::size_t count, float* out) {
    for (std::size_t i = 0; i < count; ++i) {
        out[i] = std::fma(x[i], y[i], z[i]);
    }
}

}  // namespace

const kernel_table& scalar_kernels() {
    // Rows in the order of obbsat::method.
    static const kernel_table table = {
        {stream_pairs<ref::sat4>, stream_pairs<ref::sat4_centered>, stream_pairs<ref::sat4_double>,
         stream_pairs<ref::conservative>, stream_pairs<oracle::intersects>},
        {indexed_pairs<ref::sat4>, indexed_pairs<ref::sat4_centered>, indexed_pairs<ref::sat4_double>,
         indexed_pairs<ref::conservative>, indexed_pairs<oracle::intersects>},
        {indexed_records<ref::sat4>, indexed_records<ref::sat4_centered>,
         indexed_records<ref::sat4_double>, indexed_records<ref::conservative>,
         indexed_records<oracle::intersects>},
        fused_multiply_add,
    };
    return table;
}

}  // namespace obbsat::detail
