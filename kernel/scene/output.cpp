// Step 6 of the scene query (pair_search.hpp): the found pairs as one list sorted by (a, b).
#include "scene/pair_search.hpp"

#include "scene/search_common.hpp"
#include "sort/pair_sort.hpp"
#include "support/work_shares.hpp"

#include <algorithm>
#include <utility>
#include <vector>

namespace obbsat::detail {

void pair_search::sort_found() {
    const auto start = clock_type::now();
    // The sweep's units, in unit order, as one source per thread: sort_pairs
    // runs one share of its scatter per source. Pairs are unique, so the
    // sorted answer does not depend on how units are grouped.
    const std::size_t parts =
        std::max<std::size_t>(1, std::min(used_parts_, parts_for(n_, options_.threads, min_boxes_per_part)));
    std::vector<pair_source<pair_index>> sources(parts);
    for (std::size_t i = 0; i < used_parts_; ++i) {
        const pair_source<pair_index> spans = parts_[i].found.spans();
        pair_source<pair_index>& into = sources[i * parts / used_parts_];
        into.insert(into.end(), spans.begin(), spans.end());
    }
    if (sort_scratch_.size() < parts) {
        sort_scratch_.resize(parts);
    }
    // The last answer's pairs are dropped first, so that sort_pairs writes
    // every element anew (resize) before it scatters: a pair_finder's last
    // answer has left the caches, and scattering over it cost about 4 ns a
    // box more at 100k boxes (2 pairs a box) than over memory just written.
    pairs_.clear();
    sort_pairs(sources, self_ ? n_ : a_count_, pairs_, sort_scratch_);
    for (part& p : parts_) {
        p.found.clear();
    }
    stats_.pairs = pairs_.size();
    stats_.output_seconds += seconds_since(start);
}

const std::vector<pair_index>& pair_search::answer_plainly(const query_input& input) {
    // kept_.keep is false: the bounds themselves, not widened (see widen), so the
    // method is asked of the same candidates as in find_pairs.
    run(input, pair_chunk_sink{});
    sort_found();
    kept_.last_candidates = stats_.candidates;
    return pairs_;
}

std::vector<pair_index> pair_search::collect_once(const query_input& input) {
    one_shot_ = true;
    run(input, pair_chunk_sink{});
    // The scene's working memory goes before the sorted copy of the pairs is
    // made, so that the peak is the larger of the two, not their sum; unless
    // it is kept for a next query (keep_working_memory_up_to).
    if (working_bytes() > keep_memory_up_to_) {
        free_working_memory();
    }
    sort_found();
    return std::move(pairs_);
}

}  // namespace obbsat::detail
