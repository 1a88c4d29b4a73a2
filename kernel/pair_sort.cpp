#include "pair_sort.hpp"

#include <algorithm>

namespace obbsat::detail {

void sort_pairs(std::vector<pair_index>& pairs, std::size_t a_count, std::vector<pair_index>& spare,
                std::vector<std::uint32_t>& counts) {
    const std::size_t n = pairs.size();
    const auto by_a_then_b = [](const pair_index& x, const pair_index& y) {
        return x.a < y.a || (x.a == y.a && x.b < y.b);
    };
    // A comparison sort wins while the pairs are few against the buckets.
    if (n < 64 || n < a_count / 8) {
        std::sort(pairs.begin(), pairs.end(), by_a_then_b);
        return;
    }
    counts.assign(a_count + 1, 0);
    for (const pair_index& p : pairs) {
        ++counts[p.a + 1];
    }
    for (std::size_t i = 1; i <= a_count; ++i) {
        counts[i] += counts[i - 1];
    }
    spare.resize(n);
    for (const pair_index& p : pairs) {
        spare[counts[p.a]++] = p;
    }
    // counts[a] is now the end of run a; runs are short, so insertion sort.
    std::size_t begin = 0;
    for (std::size_t a = 0; a < a_count; ++a) {
        const std::size_t end = counts[a];
        for (std::size_t i = begin + 1; i < end; ++i) {
            const pair_index p = spare[i];
            std::size_t j = i;
            while (j > begin && spare[j - 1].b > p.b) {
                spare[j] = spare[j - 1];
                --j;
            }
            spare[j] = p;
        }
        begin = end;
    }
    pairs.swap(spare);
}

}  // namespace obbsat::detail
