// The state of pair_finder's kept candidates (the policy described at the
// top of pair_search.hpp), apart from the plain query's: one place for what
// it keeps between calls and what each thread's share of it holds. Its steps
// are in kept_pairs.cpp and kept_answer.cpp. Internal to the library.
#pragma once

#include "scene/id_rows.hpp"
#include "scene/kept_costs.hpp"
#include "sort/few_pairs_sort.hpp"
#include "sort/pair_sort.hpp"
#include "support/scratch_vector.hpp"

#include <obbsat/rect.hpp>

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

namespace obbsat::detail {

/// Bounds as (lo_x, lo_y, -hi_x, -hi_y): two overlap iff one's entry is at
/// most the other's with halves swapped and negated, in all four places.
struct signed_bounds {
    float v[4];
};

/// What pair_search keeps for pair_finder's later calls.
struct kept_pairs {
    // The policy.
    /// Set while a full query keeps its candidates instead of testing them;
    /// `margin` then sets the widening of its bounds (pair_search::widen).
    bool keep = false;
    /// `pairs` hold the candidates of the last full query's widened bounds,
    /// and the next call on the same scene may answer from them.
    bool ready = false;
    float margin = 0;                   ///< each box widened by margin times its larger extent or typical_extent
    float typical_extent = 0;           ///< about the median of the boxes' larger extents, from the last query
    /// The same of this query's boxes, measured with its extent, applied when it ends.
    float measured_typical_extent = 0;
    double margin_share = 1.0 / 16;     ///< margin of the next full query that follows motion
    std::size_t calls = 0;              ///< calls answered by the kept candidates
    /// Set after a miss: kept candidates that answered no call before a box
    /// left its widened bounds. Full queries then keep nothing (plain queries)
    /// and probe the motion instead, until it would let keeping pay again.
    bool paused = false;
    /// While paused: `last` holds the last call's bounds, widened as a full
    /// query would widen them, one entry per rectangle in the caller's order.
    bool probe_ready = false;
    std::size_t calm_calls = 0;         ///< paused calls in a row whose bounds lay inside the last call's widened ones
    /// Whether this paused call probes: after a probe that failed, the next
    /// probe_skip calls do not, and the wait doubles up to max_probe_wait,
    /// so that a scene that never calms pays for few probes.
    bool probing = false;
    std::size_t probe_skip = 0;
    std::size_t probe_wait = 0;
    /// While paused: the last time of the bounds and order steps with a
    /// repair of the order tried, and with the order sorted anew (0: not
    /// measured); the cheaper is taken, the other measured again now and then.
    double repair_seconds = 0;
    double sort_seconds = 0;
    std::size_t paused_orders = 0;
    scratch_vector<signed_bounds> last; ///< (lo_x, lo_y, -hi_x, -hi_y) of the last call, widened, in the caller's order

    /// After a miss: keeping pauses, with no probe, wait or order timing yet.
    void pause() {
        paused = true;
        probe_ready = false;
        calm_calls = 0;
        probe_skip = 0;
        probe_wait = 0;
        repair_seconds = 0;
        sort_seconds = 0;
        paused_orders = 0;
    }
    /// The next full query keeps again (calm motion, or a new scene).
    void resume() {
        paused = false;
        probe_ready = false;
        calm_calls = 0;
    }
    std::size_t last_candidates = 0;    ///< candidates of the last full query, for the budget of kept ones
    /// What keeping and plain queries cost, measured, and whether keeping rests (kept_costs.hpp).
    keep_costs costs;

    // The budget of a full query that keeps its candidates: the pairs it may
    // keep, counted over all parts, so that whether it keeps them does not
    // depend on the threads.
    std::size_t capture_budget = 0;
    mutable std::atomic<std::size_t> captured_all{0};

    // The kept candidates.
    /// The bounds themselves, one 16-byte entry per rectangle in the query's
    /// order, so that a candidate's test reads two and compares them in one
    /// vector (the query's in_lo_x... then hold the widened bounds).
    scratch_vector<signed_bounds> now;
    std::vector<pair_index> pairs;         ///< in the query's order, as the kernel takes them
    /// (a, b) in the caller's indices, sorted; tag: index into pairs. After
    /// a call whose rows changed on several threads (kept_carry.cpp) it may
    /// hold gap entries (is_gap), in the runs listed in `gaps`, which every
    /// reader skips; they are out of order.
    std::vector<tagged_pair> by_caller;
    /// Bit i % 64 of word i / 64: the verdict on pairs[i]; one more word, always
    /// zero, is the verdict of gap entries (gap_pair), so that reading the
    /// answer takes none of them with no test of its own.
    std::vector<std::uint64_t> verdicts;
    /// The runs [begin, end) of by_caller that hold gap entries, in order, and their entries in all.
    std::vector<std::pair<std::size_t, std::size_t>> gaps;
    std::size_t gap_entries = 0;
    /// The gap entries of by_caller before `position`.
    std::size_t gap_entries_before(std::size_t position) const;
    /// A gap entry of by_caller while `pair_count` pairs are kept: rows no_row,
    /// tag the first pair of the always-zero word of verdicts.
    static tagged_pair gap_pair(std::size_t pair_count) {
        return tagged_pair{no_row, no_row, static_cast<std::uint32_t>(64 * ((pair_count + 63) / 64))};
    }
    static bool is_gap(const tagged_pair& p) { return p.a == no_row; }
    /// For share s > 0 of an answer in answer_parts shares (share_of over
    /// by_caller), words [(s - 1) W, s W) with W the words of verdicts: bit i
    /// set iff pairs[i] is in share s. The test counts each share's colliding
    /// pairs with them, so every share of the answer is written where it
    /// belongs, with no copy.
    std::vector<std::uint64_t> answer_marks;
    std::size_t answer_parts = 0;  ///< 0 while answer_marks marks nothing
    std::vector<pair_sort_scratch<tagged_pair>> tag_scratch;

    // Rows that came, went or changed places (pair_finder with ids; the
    // steps are in kept_changes.cpp). The kept order's positions ("slots")
    // then no longer are the rows of a full query: a gone row's slot stays,
    // empty (order_ holds no_row there), and a new row gets a slot after the
    // last. The kept candidates stay where they are; those of an empty slot
    // are skipped (its bounds in `now` are NaN) and dropped from by_caller.
    /// Set once a call has changed the rows since the last full query.
    bool by_id = false;
    std::size_t slots = 0;         ///< slots of the kept order, empty ones counted (records_, order_...)
    std::size_t full_slots = 0;    ///< of those, the full query's (in its strips); the rest were added since
    std::size_t empty_slots = 0;   ///< slots of rows gone since the full query
    std::size_t rows = 0;          ///< rows of the last call (slots less the empty ones)
    /// The widest quantized x extent (q_hi - q_lo) of any entry of each
    /// strip, among the full query's entries and among those added since:
    /// a search for the entries that reach x starts that far to its left.
    std::vector<std::uint32_t> full_reach, added_reach;
    /// The slots added since the full query, an entry for each strip each
    /// touches (key: strip, then quantized lo_x), sorted by key.
    std::vector<std::uint64_t> added_entries;  ///< key << 32 | slot
    std::vector<std::uint64_t> added_spare;    ///< added_entries' next contents while they are merged
    std::vector<std::uint32_t> added_begin;    ///< added_begin[s]: the first of added_entries in strip s
    /// Each unit's slots within reach of a batch of new slots, before their
    /// test, and the new candidates it found (kept_changes.cpp).
    std::vector<std::vector<std::uint32_t>> unit_near;
    std::vector<std::vector<pair_index>> unit_found;
    std::vector<std::vector<std::uint8_t>> unit_flags;  ///< of each slot within reach, whether its bounds meet
    /// Rows of the last call whose place in the order of rows changed
    /// against the others (kept_changes.cpp): their pairs are sorted apart.
    std::vector<std::uint8_t> row_moved;
    /// Bit i % 64 of word i / 64: pairs[i] belongs to a gone row (dropped from
    /// by_caller); the test skips it. Empty until a row has gone.
    std::vector<std::uint64_t> dropped;
    /// The widened bounds of each slot as (lo_x, lo_y, -hi_x, -hi_y), for the
    /// search of new slots' candidates: one read per slot looked at.
    scratch_vector<signed_bounds> widened;
    std::vector<tagged_pair> by_caller_spare;  ///< by_caller's next contents while it is rebuilt
    std::vector<tagged_pair> moved_pairs;      ///< kept pairs of moved rows and new ones, in rows now
    std::vector<std::uint64_t> moved_bits;     ///< row_moved as bits, while moved_pairs are gathered
    std::vector<std::vector<tagged_pair>> unit_moved;  ///< each share's kept pairs of moved rows, gathered apart
    /// Each unit's share of the answer while by_caller is carried on several threads (kept_carry.cpp).
    std::vector<std::vector<pair_index>> unit_answers;
    /// Each unit's tags of kept pairs of gone rows, marked in `dropped` once the units have ended.
    std::vector<scratch_vector<std::uint32_t>> unit_gone;
    few_pairs_sort_scratch moved_order;        ///< working memory of moved_pairs' sort
    /// Set while by_caller is in the last call's rows, to be carried to this
    /// call's as the answer is read (pair_search::answer_by_id).
    bool remap_pending = false;
    bool remap_any_moved = false;
    std::size_t remap_last_a = 0;  ///< rows of a in the last call
};

/// One thread's share of the kept candidates (a member of each part of the sweep).
struct kept_share {
    /// Candidates kept instead of tested (a query that keeps them).
    std::vector<pair_index> captured;
    bool over_budget = false;  ///< the query's candidates passed capture_budget
    scratch_vector<tagged_pair> tagged;  ///< written whole before it is read: never zeroed
    /// The kept candidates' positions in a block under test.
    std::vector<std::uint32_t> slots;
    std::size_t colliding = 0;  ///< kept candidates the method called colliding
    /// Of those, how many fall in each share of the answer past the first.
    std::vector<std::size_t> colliding_in_share;
};

}  // namespace obbsat::detail
