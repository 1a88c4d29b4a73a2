// The begin/end events of a pair_finder (obbsat/find_pairs.hpp): after each
// call, the pairs of its answer that were not in the last call's answer
// (began) and those of the last call's answer that are not in this one
// (ended). Rows are matched by position: pair (i, j) of one call is pair
// (i, j) of the next, whatever the row counts, so a pair that involves a row
// that no longer exists ends, and a pair of a new row begins. Across a change
// of the kind of query (within one set, across two), positions mean other
// things: every pair of the last answer ends and every pair of this one
// begins. The first call after events were turned on has no last answer:
// every pair began, none ended.
//
// Cost: one linear merge of the last answer and this one (both sorted by
// (a, b)), which also copies this answer into a second buffer that then
// becomes the last one (a swap): no allocation once the buffers have grown.
// Memory: 16 bytes per pair of the largest answer (the last answer and the
// spare buffer), plus 8 per event.
#pragma once

#include <obbsat/rect.hpp>

#include <vector>

namespace obbsat::detail {

class pair_events {
public:
    /// Takes `answer` (sorted by (a, b), each pair once) as the answer of the
    /// call just made; `cross` tells whether it was a query across two sets.
    void update(const std::vector<pair_index>& answer, bool cross);

    const std::vector<pair_index>& began() const { return began_; }
    const std::vector<pair_index>& ended() const { return ended_; }

private:
    std::vector<pair_index> last_;   ///< the last answer
    std::vector<pair_index> spare_;  ///< becomes the last answer at the next update
    std::vector<pair_index> began_;
    std::vector<pair_index> ended_;
    bool has_last_ = false;
    bool last_cross_ = false;
};

}  // namespace obbsat::detail
