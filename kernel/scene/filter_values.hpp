// The pair filters of one rectangle as the sweep reads them
// (obbsat/pair_filters.hpp), and the rule that keeps or drops a pair.
// Internal to the library, baseline ISA.
#pragma once

#include <obbsat/pair_filters.hpp>

#include <cstddef>
#include <cstdint>

namespace obbsat::detail {

/// One rectangle's filters, 24 bytes: a candidate reads its two entries,
/// each within one cache line most of the time, in the query's order.
/// Trivial (no initializers), so that a scratch_vector holds it unwritten.
struct filter_values {
    std::uint64_t category;
    std::uint64_t mask;
    std::int32_t group;
};

/// 1 iff the filters let x and y pair: each one's category meets the
/// other's mask, and they do not share a group other than 0. No branch: the
/// filters of the candidates are as random as the scene.
inline unsigned filters_pass(const filter_values& x, const filter_values& y) {
    const unsigned bits = static_cast<unsigned>((x.category & y.mask) != 0) &
                          static_cast<unsigned>((y.category & x.mask) != 0);
    const unsigned one_group = static_cast<unsigned>(x.group == y.group) & static_cast<unsigned>(x.group != 0);
    return bits & (one_group ^ 1u);
}

/// Rectangle `i`'s filters out of the caller's arrays, each nullptr for its default.
inline filter_values filter_values_of(const pair_filters& f, std::size_t i) {
    filter_values v;
    v.category = f.categories != nullptr ? f.categories[i] : all_categories;
    v.mask = f.masks != nullptr ? f.masks[i] : all_categories;
    v.group = f.groups != nullptr ? f.groups[i] : 0;
    return v;
}

}  // namespace obbsat::detail
