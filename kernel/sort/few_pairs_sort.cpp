// A sort of a few pairs by (a, b) (sort/few_pairs_sort.hpp).
#include "sort/few_pairs_sort.hpp"

#include "support/bit_width.hpp"

#include <algorithm>

namespace obbsat::detail {

namespace {

/// Bits of the key one counting pass sorts by: a table of 2048 counts (8 KB) stays in the first cache.
constexpr unsigned digit_bits = 11;

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
    const auto key_of = [b_bits](const tagged_pair& p) { return (std::uint64_t{p.a} << b_bits) | p.b; };
    std::vector<tagged_pair>& spare = scratch.spare;
    spare.resize(n);
    std::vector<std::uint32_t>& counts = scratch.counts;
    const std::uint64_t digit_mask = (std::uint64_t{1} << digit_bits) - 1;
    tagged_pair* from = pairs.data();
    tagged_pair* to = spare.data();
    for (unsigned shift = 0; shift < key_bits; shift += digit_bits) {
        counts.assign(std::size_t{1} << digit_bits, 0);
        for (std::size_t i = 0; i < n; ++i) {
            ++counts[(key_of(from[i]) >> shift) & digit_mask];
        }
        std::uint32_t sum = 0;
        for (std::uint32_t& c : counts) {
            const std::uint32_t here = c;
            c = sum;
            sum += here;
        }
        for (std::size_t i = 0; i < n; ++i) {
            to[counts[(key_of(from[i]) >> shift) & digit_mask]++] = from[i];
        }
        std::swap(from, to);
    }
    if (from != pairs.data()) {
        pairs.swap(spare);  // an odd number of passes left the sorted pairs in spare
    }
}

}  // namespace obbsat::detail
