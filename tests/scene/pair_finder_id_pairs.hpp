// A pair_finder's answer read as id pairs (box_view::with_ids), for the tests
// that check its id events against the differences of consecutive answers.
#pragma once

#include <obbsat/find_pairs.hpp>

#include <algorithm>
#include <cstdint>
#include <iterator>
#include <utility>
#include <vector>

namespace obbsat_test {

inline bool id_less(const obbsat::id_pair& x, const obbsat::id_pair& y) {
    return x.a < y.a || (x.a == y.a && x.b < y.b);
}

/// The answer read as id pairs, sorted: the smaller id first within one set (b_ids nullptr), a's id first across two.
inline std::vector<obbsat::id_pair> by_id(const std::vector<obbsat::pair_index>& pairs,
                                          const std::vector<std::uint64_t>& a_ids,
                                          const std::vector<std::uint64_t>* b_ids) {
    std::vector<obbsat::id_pair> out;
    for (const obbsat::pair_index& p : pairs) {
        std::uint64_t x = a_ids[p.a];
        std::uint64_t y = b_ids != nullptr ? (*b_ids)[p.b] : a_ids[p.b];
        if (b_ids == nullptr && x > y) {
            std::swap(x, y);
        }
        out.push_back(obbsat::id_pair{x, y});
    }
    std::sort(out.begin(), out.end(), id_less);
    return out;
}

/// The id pairs of x not in y (both sorted by id_less).
inline std::vector<obbsat::id_pair> minus(const std::vector<obbsat::id_pair>& x, const std::vector<obbsat::id_pair>& y) {
    std::vector<obbsat::id_pair> out;
    std::set_difference(x.begin(), x.end(), y.begin(), y.end(), std::back_inserter(out), id_less);
    return out;
}

}  // namespace obbsat_test
