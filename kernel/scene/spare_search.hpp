// The working memory of the one-shot scene queries (find_pairs,
// find_pairs_each), kept between calls. A query of a million boxes works in
// some 100 MB, and fresh memory costs the calling thread a page fault and a
// cleared page per page it touches, on every call (about a tenth of a cold
// query's time). So a query borrows the memory the last one left, if no
// other call holds it, and leaves its own when it is done and none is left
// already: two queries at once each work in their own. Only what each query
// sizes and writes anew is borrowed (pair_search::swap_working_memory),
// never an order, a grid or kept candidates, so an answer does not depend on
// which query ran before. At most one query's memory is kept, and none of a
// query whose working memory is above spare_search_limit; release_scratch()
// (obbsat/find_pairs.hpp) frees it. Internal to the library.
#pragma once

#include "scene/pair_search.hpp"

#include <obbsat/collide.hpp>

#include <cstddef>

namespace obbsat::detail {

/// The most working memory kept between calls: a query of about ten million boxes.
constexpr std::size_t spare_search_limit = std::size_t{1} << 30;

/// The working memory of a double query (query_input::doubles) a row, about:
/// 1M rect_pose64 rows of the uniform scene took 121 bytes a row in
/// find_pairs, 153 in find_contacts64, 100k rows 142 and 174.
constexpr std::size_t double_query_bytes_per_row = 192;

/// Whether a double query over `rows` rows fits spare_search_limit, so that
/// the memory it works in is kept for the next query: such a query frees
/// none of it before its answer is sorted (find_pairs.cpp).
constexpr bool double_query_kept(std::size_t rows) {
    return rows <= spare_search_limit / double_query_bytes_per_row;
}

/// A scene query in the working memory the last one left (see the top of this file).
class spare_search {
public:
    explicit spare_search(const collide_options& options);
    /// Leaves the query's working memory for the next one (none above spare_search_limit).
    ~spare_search();
    spare_search(const spare_search&) = delete;
    spare_search& operator=(const spare_search&) = delete;

    pair_search& get() { return search_; }

private:
    pair_search search_;
};

/// Bytes of working memory kept for the next query.
std::size_t spare_search_bytes();

/// Frees the working memory kept for the next query; a query running now keeps its own until it ends.
void release_spare_search();

}  // namespace obbsat::detail
