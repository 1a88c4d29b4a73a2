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
// With ids (box_view::with_ids) the events are id pairs instead: each
// answer is read as pairs of ids (the smaller first within one set, the id
// in a first across two), sorted by (id, id), and compared with the last
// answer read so; a gone row's pairs end, a new row's begin, a row that
// changed places keeps its pairs. A call with ids after one without, or the
// other way round, starts the events anew: every pair began, none ended.
// Reading an answer by id costs a pass over the rows (the rows whose ids do
// not increase with the row, found by a greedy pass from each end as in
// kept_changes.cpp, have their pairs sorted apart and merged in) and a pass
// over the pairs: linear when the ids mostly increase with the rows (ids
// counted up as boxes are created, with rows appended, removed and
// swap-removed), a sort of the pairs when they are in random order.
//
// Cost: one linear merge of the last answer and this one (both sorted by
// (a, b)), which also copies this answer into a second buffer that then
// becomes the last one (a swap): no allocation once the buffers have grown.
// Memory: 16 bytes per pair of the largest answer (the last answer and the
// spare buffer), plus 8 per event.
#pragma once

#include <obbsat/find_pairs.hpp>
#include <obbsat/rect.hpp>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace obbsat::detail {

class pair_events {
public:
    /// Takes `answer` (sorted by (a, b), each pair once) as the answer of the
    /// call just made; `cross` tells whether it was a query across two sets;
    /// `a_ids` (and `b_ids` across two sets) the rows' ids, or nullptr when
    /// they carry none. `a_count`, `b_count`: the rows of each set.
    void update(const std::vector<pair_index>& answer, bool cross, const std::uint64_t* a_ids,
                const std::uint64_t* b_ids, std::size_t a_count, std::size_t b_count);

    const std::vector<pair_index>& began() const { return began_; }
    const std::vector<pair_index>& ended() const { return ended_; }
    const std::vector<id_pair>& began_ids() const { return began_ids_; }
    const std::vector<id_pair>& ended_ids() const { return ended_ids_; }
    /// Whether the last call's rows carried ids.
    bool by_id() const { return has_last_ && last_by_id_; }
    /// Whether there was a call since the events were turned on.
    bool has_last() const { return has_last_; }

private:
    /// `answer` as id pairs, sorted, into `out`.
    void read_by_id(const std::vector<pair_index>& answer, bool cross, const std::uint64_t* a_ids,
                    const std::uint64_t* b_ids, std::size_t a_count, std::size_t b_count, std::vector<id_pair>& out);
    void update_by_id(const std::vector<pair_index>& answer, bool cross, const std::uint64_t* a_ids,
                      const std::uint64_t* b_ids, std::size_t a_count, std::size_t b_count);

    std::vector<pair_index> last_;   ///< the last answer
    std::vector<pair_index> spare_;  ///< becomes the last answer at the next update
    std::vector<pair_index> began_;
    std::vector<pair_index> ended_;
    bool has_last_ = false;
    bool last_cross_ = false;
    bool last_by_id_ = false;
    // With ids: the last answer as id pairs, its next contents, the events.
    std::vector<id_pair> last_ids_, spare_ids_, began_ids_, ended_ids_;
    std::vector<id_pair> unsorted_ids_;  ///< pairs of rows whose ids break the rows' order, before their sort
    std::vector<std::uint8_t> a_out_of_order_, b_out_of_order_;
};

}  // namespace obbsat::detail
