// The scalar backend: the reference of each method applied one pair at a time.
#include "kernel_table.hpp"

#include <obbsat/ref/sat4.hpp>
#include <obbsat/ref/sat4_centered.hpp>
#include <obbsat/ref/sat4_double.hpp>

namespace obbsat::detail {

namespace {

using reference_fn = bool (*)(const rect&, const rect&);

template <reference_fn Reference>
void stream_pairs(const soa_view& a, const soa_view& b, std::size_t count, std::uint8_t* verdicts) {
    for (std::size_t i = 0; i < count; ++i) {
        verdicts[i] = Reference(a.at(i), b.at(i)) ? 1 : 0;
    }
}

template <reference_fn Reference>
void indexed_pairs(const soa_view& rects, const pair_index* pairs, std::size_t count,
                   std::uint8_t* verdicts) {
    for (std::size_t i = 0; i < count; ++i) {
        verdicts[i] = Reference(rects.at(pairs[i].a), rects.at(pairs[i].b)) ? 1 : 0;
    }
}

template <reference_fn Reference>
void indexed_records(const rect* records, const pair_index* pairs, std::size_t count,
                     std::uint8_t* verdicts) {
    for (std::size_t i = 0; i < count; ++i) {
        verdicts[i] = Reference(records[pairs[i].a], records[pairs[i].b]) ? 1 : 0;
    }
}

}  // namespace

const kernel_table& scalar_kernels() {
    // Rows in the order of obbsat::method.
    static const kernel_table table = {
        {stream_pairs<ref::sat4>, stream_pairs<ref::sat4_centered>, stream_pairs<ref::sat4_double>},
        {indexed_pairs<ref::sat4>, indexed_pairs<ref::sat4_centered>, indexed_pairs<ref::sat4_double>},
        {indexed_records<ref::sat4>, indexed_records<ref::sat4_centered>,
         indexed_records<ref::sat4_double>},
    };
    return table;
}

}  // namespace obbsat::detail
