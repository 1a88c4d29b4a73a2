// A sort of a few pairs by (a, b) (sort/few_pairs_sort.hpp).
#include "sort/few_pairs_sort.hpp"

#include "support/bit_width.hpp"

#include <algorithm>

namespace obbsat::detail {

namespace {

/// Bits of the key one counting pass sorts by: a table of 4096 counts (16 KB) stays in the first cache.
constexpr unsigned digit_bits = 12;
constexpr std::size_t digit_values = std::size_t{1} << digit_bits;

}  // namespace

void sort_few_pairs(std::vector<tagged_pair>& pairs, few_pairs_sort_scratch& scratch) {
    const std::size_t n = pairs.size();
    if (n < 2) {
        return;
    }
    std::uint32_t a_any = 0;
    std::uint32_t b_any = 0;
    for (const tagged_pair& p : pairs) {
        a_any |= p.a;
        b_any |= p.b;
    }
    const unsigned b_bits = bits_for(b_any);
    const unsigned key_bits = bits_for(a_any) + b_bits;
    const unsigned passes = (key_bits + digit_bits - 1) / digit_bits;
    const auto key_of = [b_bits](const tagged_pair& p) { return (std::uint64_t{p.a} << b_bits) | p.b; };
    std::vector<tagged_pair>& spare = scratch.spare;
    spare.resize(n);
    // Every pass's counts from one read of the pairs: each pass is stable,
    // so a digit's counts do not depend on the order the earlier passes left.
    std::vector<std::uint32_t>& counts = scratch.counts;
    counts.assign(passes * digit_values, 0);
    const std::uint64_t digit_mask = digit_values - 1;
    for (std::size_t i = 0; i < n; ++i) {
        const std::uint64_t key = key_of(pairs[i]);
        for (unsigned d = 0; d < passes; ++d) {
            ++counts[d * digit_values + ((key >> (d * digit_bits)) & digit_mask)];
        }
    }
    tagged_pair* from = pairs.data();
    tagged_pair* to = spare.data();
    for (unsigned d = 0; d < passes; ++d) {
        std::uint32_t* const place = counts.data() + d * digit_values;
        std::uint32_t sum = 0;
        for (std::size_t v = 0; v < digit_values; ++v) {
            const std::uint32_t here = place[v];
            place[v] = sum;
            sum += here;
        }
        const unsigned shift = d * digit_bits;
        for (std::size_t i = 0; i < n; ++i) {
            to[place[(key_of(from[i]) >> shift) & digit_mask]++] = from[i];
        }
        std::swap(from, to);
    }
    if (from != pairs.data()) {
        pairs.swap(spare);  // an odd number of passes left the sorted pairs in spare
    }
}

}  // namespace obbsat::detail
