// The engine of the scene queries (obbsat/find_pairs.hpp): bounds, order,
// sweep, the method's kernels, the answer in the caller's indices. It keeps
// every buffer and the last order between calls; find_pairs and
// find_pairs_each, which make one per call, borrow the buffers of the last
// one (spare_search.hpp). Internal to the library.
// Each step has a file of its own, named below; nothing of it is compiled
// with ISA flags (the backends' kernels are reached through kernels_for).
//
// How it finds the candidates:
//   1. Bounds of every rectangle (obbsat/ref/bounds.hpp), in the caller's order,
//      a vector of records at a time in the backend's lanes (bounds_lanes.hpp).
//      [bounds_pass.cpp]
//   2. The scene is cut into horizontal strips (strip_grid.hpp). Each
//      rectangle is sorted by (lowest strip it touches, quantized lo_x); that
//      order is the query's own [order.cpp], and the records are copied into
//      it, so that rectangles near each other in the plane are near each
//      other in memory [records_copy.cpp].
//   3. A rectangle taller than its strip also visits the strips above, up to
//      the one holding its hi_y; visits are sorted the same way. [visits.cpp]
//   4. In each strip the rectangles that start there and the visitors are
//      merged by quantized lo_x and swept: every later entry whose quantized
//      lo_x is at most this entry's quantized hi_x is tested on the full
//      bounds. A pair is taken in the strip holding the larger of its two
//      lo_y (the first strip both touch), i.e. never between two visitors,
//      so each pair whose bounds overlap is found exactly once. [sweep.cpp]
//      With pair filters (obbsat/pair_filters.hpp), the candidates each
//      call of the sweep kernel finds are filtered at once, over the
//      filters copied into the query's order with the records, so a
//      filtered pair never reaches step 5; a query with no filters takes
//      none of this (filtered_, chosen once per query). [sweep.cpp]
//   5. Candidates go to the method's indexed kernel in blocks, over the
//      reordered records; the colliding ones are mapped back. [sweep.cpp]
//   6. The answer: the found pairs streamed to the caller's sink as they
//      come [sweep.cpp], or sorted into one list [output.cpp].
// The query's rows are read through query_input.hpp; run() in
// pair_search.cpp takes the steps in turn. A plain float query takes the
// copy of step 2 and steps 3 to 5 strip by strip instead, each strip's
// entries written straight to their places in the swept strip, with no
// arrays of the whole scene between the steps [strip_pass.cpp]. On several
// threads it does so in units of consecutive strips taken as they come; a
// unit finds its first strip's visitors in the strips below it that a
// rectangle may reach from (the tallest rectangle decides how many), whose
// records whichever of the two units comes to them first copies. A scene
// whose tallest rectangle reaches too far for that takes the steps one at
// a time.
//
// A persistent query (collect, for pair_finder) answers its first call on a
// scene as a plain query; later full queries widen every bounds by a
// margin before step 2 and keeps the candidates of the widened bounds
// instead of testing them. While each rectangle's bounds stay inside its
// widened bounds (an exact float comparison), those candidates hold every
// pair whose bounds overlap now, so the next call refreshes the records in
// the kept order, takes the kept candidates whose bounds overlap now (the
// same pairs a sweep would give; an exact method takes every kept one, as
// its verdict on the others is "apart" anyway), tests them, and reads the
// answer in the caller's order through a permutation kept with them: no
// sort, no sweep, no output sort. A rectangle that left its widened bounds makes the call a
// full query again, which builds new candidates. When the kept candidates
// answered no call (a miss), keeping pauses: full queries are plain ones,
// whose bounds pass (probe_motion) checks each box against the last call's
// bounds widened by the margin; two calm calls in a row resume keeping. A
// paused query builds its own grid when the last one was made for widened
// bounds, and takes a repair of the order or a new sort, whichever it last
// timed cheaper. Its state is kept_pairs
// (kept_pairs.hpp); its steps are in kept_pairs.cpp (the policy, collect,
// and keeping the candidates) and kept_answer.cpp (their test and answer).
// Rows with ids (box_view::with_ids) may come, go and change places between
// calls: id_rows.hpp matches a call's ids with the last call's, and
// kept_changes.cpp carries the kept candidates over to this call's rows.
// Whether keeping pays at all is measured (kept_costs.hpp): a full query that
// keeps and the calls its candidates answer are weighed against plain
// queries, and where they cost more the finder rests, answering by plain
// queries for a while (find_pairs_stats::kept_resting).
#pragma once

#include "scene/filter_values.hpp"
#include "scene/kept_filters.hpp"
#include "scene/id_rows.hpp"
#include "scene/kept_pairs.hpp"
#include "scene/pair_blocks.hpp"
#include "scene/query_input.hpp"
#include "sort/pair_sort.hpp"
#include "sort/radix_sort.hpp"
#include "support/scratch_vector.hpp"
#include "scene/strip_grid.hpp"

#include <obbsat/collide.hpp>
#include <obbsat/find_pairs.hpp>
#include <obbsat/method.hpp>
#include <obbsat/rect.hpp>
#include <obbsat/rect_records.hpp>
#include <obbsat/ref/bounds.hpp>

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <exception>
#include <functional>
#include <memory>
#include <vector>

namespace obbsat::detail {

class pair_search {
public:
    explicit pair_search(const collide_options& options);

    /// The query the steps run on: `input` itself for float rows; for double
    /// rows (query_input::doubles), checks the method and every row not
    /// checked (invalid_input naming the row and field), and points the float
    /// rows at each rectangle's float bounds rounded outward
    /// (obbsat/ref/bounds64.hpp) as an axis-aligned corner row, held here
    /// until the next call. [double_bounds.cpp]
    query_input bound_doubles(const query_input& input);

    /// Runs the query and hands the colliding pairs, in the caller's indices,
    /// to `emit` in chunks, one call at a time.
    void run(const query_input& input, const pair_chunk_sink& emit);

    /// Runs the query and returns its pairs sorted by (a, b); keeps the
    /// candidates of widened bounds for the next call.
    const std::vector<pair_index>& collect(const query_input& input);

    /// Runs the query once and hands over its pairs: the per-thread buffers
    /// are released before the sorted copy is made, and nothing is kept.
    std::vector<pair_index> collect_once(const query_input& input);

    /// Runs the query and sorts its pairs by (a, b) into `out`, in the
    /// memory `out` holds; `out` changes only once the query has run (every
    /// row checked). [find_contacts.cpp]
    void collect_into(const query_input& input, std::vector<pair_index>& out);

    const find_pairs_stats& stats() const { return stats_; }

    /// The caller's executor (collide_options::executor), or nullptr; the
    /// public entry points put it in scope (support/executor_scope.hpp).
    const executor* caller_executor() const { return options_.executor; }
    const collide_options& options() const { return options_; }

    /// Swaps this query's working memory (its per-rectangle and per-unit
    /// buffers, not what they mean: every one is sized and written anew by
    /// each query) with `other`'s. A query that keeps nothing between calls
    /// borrows the memory of an earlier one this way (spare_search.hpp).
    void swap_working_memory(pair_search& other);
    /// Bytes of working memory held (the buffers swap_working_memory swaps).
    std::size_t working_bytes();
    /// collect_once frees its working memory before the sorted copy of the
    /// pairs is made unless it holds at most `bytes` (kept for a next query).
    void keep_working_memory_up_to(std::size_t bytes) { keep_memory_up_to_ = bytes; }

private:
    /// collect() once the rows' ids (if any) are matched and taken.
    const std::vector<pair_index>& collect_matched(const query_input& input);
    /// What answered a collect() call, for keep_costs (kept_costs.hpp): a
    /// scene's first call, a plain query, a plain query that ends a cycle
    /// of keeping to weigh it, a full query that keeps, kept candidates.
    enum class call_path { first, plain, judged, kept, carried };
    call_path call_path_ = call_path::plain;
    /// Gives keep_costs the cost of the call collect() just answered.
    void weigh_call(double seconds);
    /// The cost of a call from its stats and wall time; null: its wall time.
    /// Tests set a model of counts here, so that the finder's choices do not
    /// depend on the machine.
    using call_cost = double (*)(const find_pairs_stats& stats, double seconds);
    call_cost call_cost_ = nullptr;
    /// Tests take the steps one at a time (tests/scene/test_pair_search_steps.cpp).
    friend struct pair_search_test_access;
    /// Calls f(mine, others) on each buffer of working memory, this query's and `other`'s.
    template <class F>
    void each_buffer(pair_search& other, const F& f);
    /// Frees the per-rectangle working memory, not the units' pairs (collect_once).
    void free_working_memory();

    struct record {
        float v[8];
    };
    /// A double row in the query's order: a pose record (cx, cy, hx, hy, c, s, 0, 0) or a rect64.
    struct record64 {
        double v[8];
    };
    /// One unit of the sweep (a run of strips, work_shares.hpp), what it
    /// found and its working memory; for a query that keeps its candidates,
    /// one thread's share.
    struct part {
        std::uint32_t first_strip = 0;
        std::uint32_t end_strip = 0;
        // One strip's entries, merged by quantized lo_x (see strip_view.hpp).
        std::vector<std::int32_t> id;
        std::vector<float> q_lo, q_hi, starts, store, lo_x, lo_y, hi_x, hi_y;
        // Candidates in the query's order, and the kernel's verdicts on them.
        std::vector<pair_index> candidates;
        std::size_t candidate_count = 0;
        std::vector<std::uint8_t> verdicts;
        // Colliding pairs in the caller's indices.
        pair_blocks found;
        kept_share keep;  ///< this share of the kept candidates (kept_pairs.hpp)
        std::size_t tested = 0;
        std::size_t slow_path = 0;
        double kernel_seconds = 0;
    };

    /// The bounds of a run of at most bounds_run rectangles, in struct-of-arrays form.
    struct bounds_run {
        static constexpr std::size_t size = 256;
        alignas(64) float lo_x[size];
        alignas(64) float lo_y[size];
        alignas(64) float hi_x[size];
        alignas(64) float hi_y[size];
    };
    /// Entry r of a run of bounds as signed_bounds.
    static signed_bounds signed_bounds_of(const bounds_run& b, std::size_t r) {
        return signed_bounds{{b.lo_x[r], b.lo_y[r], -b.hi_x[r], -b.hi_y[r]}};
    }

    // The query (pair_search.cpp).
    void set_query(const query_input& input);

    // Step 1, bounds (bounds_pass.cpp).
    /// The bounds of rectangles [begin, end) of the input, end - begin <= bounds_run::size,
    /// through the backend's kernel where the rows are 32-byte records.
    void input_bounds(const query_input& input, std::size_t begin, std::size_t end, bounds_run& out) const;
    /// Widens `count` bounds by the kept candidates' margin while a query keeps them.
    void widen(bounds_run& b, std::size_t count) const;
    /// Widens `count` bounds, each by `margin` times its larger extent or `typical`, whichever is larger.
    static void widen_bounds(bounds_run& b, std::size_t count, float margin, float typical);
    void measure_extent(const query_input& input, std::size_t parts, bool with_keys);
    /// While keeping is paused: checks `count` bounds of this call, from rectangle `first` in the
    /// caller's order, against the last call's widened ones (`compare`; clears `inside` if one
    /// lies outside), and stores them widened for the next call (kept_pairs::last).
    void probe_motion(const bounds_run& b, std::size_t first, std::size_t count, bool compare, unsigned& inside);

    // Step 2, the order (order.cpp) and the records in it (records_copy.cpp).
    bool same_scene_as_last() const;
    /// The grid was made for widened bounds and this query widens nothing.
    bool grid_too_wide() const { return grid_widened_ && !(kept_.keep && kept_.margin > 0.0f); }
    void order_boxes(const query_input& input, std::size_t parts);
    bool repair_order(std::size_t parts);
    void copy_records(const query_input& input, std::size_t parts);
    /// The bounds of entries [run_begin, run_end) of the query's order, `b` from
    /// its entry 0, as the sweep reads them: in_lo_x_ .. in_hi_y_, q_lo_, q_hi_, strip_hi_.
    void store_sweep_bounds(const bounds_run& b, std::size_t run_begin, std::size_t run_end);
    /// A double query that keeps nothing and computes no contacts: nothing
    /// after the order reads a float row (records_, or bound_doubles' rows);
    /// the sort works in records64_'s memory and copy_double_records fills it.
    bool double_records_only() const { return doubles_ && !kept_.keep; }
    /// copy_records of rows [begin, end) of the order for a double query that
    /// keeps nothing and computes no contacts: the double records, and their
    /// bounds computed again from them.
    void copy_double_records(const query_input& input, std::size_t begin, std::size_t end);

    // Step 3, visits (visits.cpp).
    void collect_visits(std::size_t parts);
    /// Makes room for the visit counts of `units` units of the order, which
    /// copy_records takes as it copies (count_visits), so that collect_visits
    /// needs no pass of its own to count them.
    void start_visit_counts(std::size_t units);
    /// Counts the visits of rectangles [begin, end) of the order, unit `unit` of start_visit_counts'.
    void count_visits(std::size_t unit, std::size_t begin, std::size_t end);

    // Steps 4 and 5, the sweep and the method's kernels (sweep.cpp).
    void sweep(std::size_t parts, const pair_chunk_sink* emit);
    /// Called after each flush of candidates inside a strip: hands the found
    /// pairs on if the query streams them; false when the query is to stop.
    using flush_callback = std::function<bool()>;
    /// Sweeps the strips of one unit (p.first_strip to p.end_strip), stopping
    /// early once `failed` is set.
    using unit_sweep = std::function<void(part& p, const flush_callback& after_flush, const std::atomic<bool>& failed)>;
    /// Resets what unit `p` found, for strips [first_strip, end_strip).
    static void start_part(part& p, std::uint32_t first_strip, std::uint32_t end_strip);
    /// Starts parts_[0, units) (start_part) on runs of consecutive strips of
    /// about entries / units entries each: the rectangles whose lowest strip
    /// it is, and the visits to it if `visits_before` (visit_begin_) is given.
    void cut_strips_into_units(std::size_t units, std::size_t entries, const std::uint32_t* visits_before);
    /// Runs `sweep_unit` on parts_[0, units) over `parts` threads, then tests what is
    /// left of each unit's candidates, hands its pairs to `emit` (if not null), and
    /// adds the units' counts to stats_; the first exception of a unit is rethrown.
    void sweep_units(std::size_t units, std::size_t parts, const pair_chunk_sink* emit, const unit_sweep& sweep_unit);
    /// Sweeps one strip, its candidates flushed in blocks; after each flush
    /// inside the strip calls after_flush(), and stops if it returns false.
    void sweep_strip(std::uint32_t strip, part& p, const flush_callback& after_flush) const;
    /// Room in p's strip arrays for m entries and their sentinels.
    static void make_strip_room(part& p, std::size_t m);
    /// Sweeps the m entries merged into p's strip arrays (make_strip_room), as sweep_strip.
    void sweep_merged(part& p, std::size_t m, const flush_callback& after_flush) const;
    void flush_candidates(part& p) const;
    /// Drops from `count` candidates those the pair filters refuse, keeping
    /// the others in order at the front; returns how many are left.
    std::size_t drop_filtered(pair_index* candidates, std::size_t count) const;
    /// Pair `q` of the query's order in the caller's indices (in a query
    /// across two sets, b counted from the second set's first rectangle).
    pair_index caller_pair(pair_index q) const {
        return pair_index{order_[q.a], order_[q.b] - (self_ ? 0u : static_cast<std::uint32_t>(a_count_))};
    }
    /// The method's verdicts on `count` pairs of the query's records.
    void test_pairs(part& p, const pair_index* pairs, std::size_t count, std::uint8_t* verdicts) const;
    void test_candidates(part& p, std::size_t count) const;

    // Steps 2 (the records' copy) to 5 strip by strip, on one thread (strip_pass.cpp).
    /// The visitors of one strip from the strips below, sorted by q_lo, in
    /// structure-of-arrays form. Two are kept: the strip being swept and the
    /// one above, which its rectangles' visits fill.
    struct strip_visitors {
        std::vector<std::uint32_t> q_lo, q_hi, id;
        std::vector<float> store, lo_x, lo_y, hi_x, hi_y;
        std::size_t count = 0;
        /// Room for `entries` entries, what they hold kept.
        void make_room(std::size_t entries);
        /// Entry `to` := entry `at` of `from`.
        void take(std::size_t to, const strip_visitors& from, std::size_t at);
        /// Sorts the entries by q_lo, equal ones kept in their order.
        void sort_by_q_lo();
        /// Merges the two runs [0, second) and [second, count), each sorted by
        /// q_lo, into `spare`, and swaps the result in (spare gets the old arrays).
        void merge_runs(std::size_t second, strip_visitors& spare);
    };
    /// A visit to a strip beyond the one just above a rectangle's lowest,
    /// waiting for its strip (a heap by strip, then q_lo, then rectangle);
    /// once taken, it waits again for the next strip, up to `high`.
    struct far_visit {
        std::uint32_t strip, high, q_lo, q_hi, id;
        float store, lo_x, lo_y, hi_x, hi_y;
        /// The heap's order: x after y.
        static bool later(const far_visit& x, const far_visit& y);
        /// Writes this visit as entry `at` of `to`.
        void put(strip_visitors& to, std::size_t at) const;
    };
    /// The working memory of one unit of the strip pass: the visitors of its
    /// strip and of the one above, the buffer strip_visitors::merge_runs
    /// merges into, the visits beyond the strip above (a heap), the places of
    /// a strip's entries (place_strip) and of those that climb (copy_own_entries).
    struct strip_pass_memory {
        strip_visitors visitors[2];
        strip_visitors merged;
        std::vector<far_visit> far_visits;
        std::vector<std::uint32_t> own_at, visitor_at, own_q, climbing;
    };
    /// The query takes steps 2 to 5 strip by strip (copy_and_sweep): a plain
    /// float query, on one thread or, over units of consecutive strips, on
    /// more when the tallest rectangle reaches few strips (strip_reach). Else
    /// the steps are taken one at a time, each over units shared by the
    /// threads; pair_finder's kept candidates (kept_pairs.hpp) and the double
    /// rows read the arrays of the whole scene they write.
    bool sweeps_strip_by_strip(std::size_t parts) const {
        return !doubles_ && !kept_.keep && (parts == 1 || strip_pass_units(parts) > 0);
    }
    /// Strips above its lowest a rectangle may reach, from the largest
    /// height the bounds pass saw (tallest_), at most grid_.strips.
    std::uint32_t strip_reach() const;
    /// Units of the strip pass on `parts` > 1 threads; 0 when the visitors
    /// each unit gathers from below its first strip (incoming_visitors) would
    /// cost too much of the pass.
    std::size_t strip_pass_units(std::size_t parts) const;
    /// copy_records, collect_visits and sweep, one strip after the other, in
    /// units of consecutive strips taken as they come: for each strip the
    /// places of its entries in the merge, its records copied and bounded
    /// straight into their places, its visits to the strips above kept for
    /// them, and the strip swept. Fills records_ (and filters_), own_begin_
    /// and stats' strips and visits; leaves the scene's sweep arrays
    /// (in_lo_x_ ... strip_hi_, side_) and visits unwritten.
    void copy_and_sweep(const query_input& input, std::size_t parts, const pair_chunk_sink* emit);
    /// The rows below each unit's first strip that its rectangles may visit
    /// from (strip_reach of them): region u of unit u > 0 holds strips
    /// [lowest[u], parts_[u].first_strip), all of them the last strips of
    /// unit u - 1, so regions do not overlap; each is copied once, by
    /// whichever of the two units comes to it first (claim), and read by
    /// both. claims[u]: 0 none, 1 being copied, 2 copied.
    struct boundary_regions {
        std::vector<std::uint32_t> lowest;
        std::vector<std::uint32_t> starting;  ///< per strip: the region it starts, 0 for none
        std::unique_ptr<std::atomic<unsigned char>[]> claims;
    };
    /// Sweeps the strips of unit `p` strip by strip, in `memory`; returns the visits to them.
    std::size_t copy_and_sweep_unit(const query_input& input, part& p, strip_pass_memory& memory,
                                    boundary_regions& regions, const flush_callback& after_flush,
                                    const std::atomic<bool>& failed);
    /// The visitors of strip `first` from the rectangles of the strips below
    /// it (their records copied, copy_region), sorted by q_lo, in
    /// memory.visitors[0]; their visits beyond `first` in memory.far_visits.
    void incoming_visitors(std::uint32_t first, strip_pass_memory& memory) const;
    /// Cuts the boundary regions of `units` units (parts_, cut) and marks
    /// their strips in copied_before_: copy_own_entries copies none of them.
    void mark_boundary_regions(std::size_t units, boundary_regions& regions);
    /// Returns once region `unit` is copied: copies it if no unit has
    /// claimed it yet, else waits for the unit copying it (a strip's rows).
    void copy_region(const query_input& input, std::size_t unit, boundary_regions& regions);
    /// Records (and filters) of entries [begin, end) of the order, copied from the rows.
    void copy_rows(const query_input& input, std::size_t begin, std::size_t end);
    /// The places in the merged strip of its `own` rectangles (memory.own_at,
    /// by their keys) and of its visitors (memory.visitor_at); writes the
    /// visitors there in p's strip arrays, with room for the sentinels.
    void place_strip(const strip_visitors& visitors, std::size_t own_first, std::size_t own, part& p,
                     strip_pass_memory& memory) const;
    /// Copies the records of the `own` rectangles whose lowest strip is
    /// `strip` into records_, and their entries to their places in p
    /// (place_strip); lists in memory.climbing the places of those that
    /// visit the strip above, and puts their visits beyond it in
    /// memory.far_visits. Returns how many climb.
    std::size_t copy_own_entries(const query_input& input, std::uint32_t strip, std::size_t own, part& p,
                                 strip_pass_memory& memory);
    /// The `near` entries of p that climb (memory.climbing) as the visitors
    /// of the strip above; false if they are not sorted by q_lo.
    static bool climb(const part& p, std::size_t near, const strip_pass_memory& memory, strip_visitors& above);

    // The answer as one sorted list (output.cpp).
    void sort_found();
    /// The answer of a query that keeps nothing, over bounds not widened.
    const std::vector<pair_index>& answer_plainly(const query_input& input);

    // pair_finder's kept candidates (see the top of this file): kept_pairs.cpp.
    /// Copies the rows into the kept order and checks that each one's bounds lie in its widened
    /// bounds; with `keep_bounds`, also stores the bounds in kept_.now for test_kept's filter.
    bool refresh_records(const query_input& input, std::size_t parts, bool keep_bounds);
    void keep_candidates(std::size_t parts);
    // Their test and the answer read from them: kept_answer.cpp.
    /// Marks, for an answer from kept candidates in `parts` shares, the share of each kept candidate.
    void mark_answer_shares(std::size_t parts);
    /// `shares`: the shares of the answer to count (answer_from_kept), 1 for answer_by_id.
    void test_kept(std::size_t parts, bool unfiltered, std::size_t shares);
    void answer_from_kept(std::size_t parts);

    // Rows that came, went or changed places, by id: kept_changes.cpp.
    /// Matches this call's ids against the last call's (match_a_, match_b_);
    /// throws invalid_input on a duplicate id before anything changes.
    void match_ids(const query_input& input);
    /// Takes this call's ids as the last call's.
    void commit_ids(const query_input& input);
    /// After a call that failed: the kept candidates and the ids are forgotten.
    void abandon_kept();
    /// Carries the kept candidates over to this call's rows (their slots, the
    /// pairs of new rows, by_caller in this call's rows); false when the
    /// change is too large to pay, and then nothing has changed.
    bool absorb_changes(const query_input& input);
    /// now_of_last_ from this call's match (rows_changed_).
    void map_last_rows();
    /// While keeping is paused: the last call's probe bounds (kept_pairs::last) moved to this call's rows.
    void carry_probe_over();
    /// The first change since the full query: the slots are its order; each strip's reach.
    void start_changes();
    /// Slots for the rows now in `fresh` (combined rows), with their records and widened bounds.
    void add_slots(const query_input& input, const std::vector<std::uint32_t>& fresh);
    /// Kept candidates of the slots from `first_new` on, against every slot whose widened bounds they meet
    /// and whose filters let the pair through.
    void find_new_candidates(const query_input& input, std::size_t first_new);
    /// Rows matched by id whose pair filters changed since the kept candidates' become new rows
    /// (kept_filters.hpp); false when filters were given or taken away.
    bool follow_filters(const query_input& input);
    /// The kept pairs of rows that changed places against the others (kept_.row_moved; `any_moved`: there
    /// are some), mapped to this call's rows through now_of_last_, sorted with the new ones (moved_pairs).
    void sort_moved_pairs(std::size_t last_a_count, bool any_moved);
    /// The answer of a call whose rows changed, read while by_caller is carried to this call's rows,
    /// in units for the pool: kept_carry.cpp.
    void answer_by_id();

    collide_options options_;
    find_pairs_stats stats_;
    bool self_ = true;
    std::size_t a_count_ = 0;
    std::size_t n_ = 0;
    store_kind kind_ = store_kind::poses;
    backend ran_ = backend::scalar;

    // The grid and the order of the last query, for the next one.
    strip_grid grid_;
    bool grid_widened_ = false;  ///< grid_ was made for bounds widened by a margin
    bool have_order_ = false;
    std::size_t ordered_n_ = 0;
    std::size_t ordered_a_count_ = 0;
    store_kind ordered_kind_ = store_kind::poses;
    bool ordered_self_ = true;

    bounds_extent extent_{};
    scratch_vector<std::uint32_t> key_by_id_;  ///< on the last grid, in the caller's order (repeat queries)
    bool keys_by_id_fresh_ = false;            ///< key_by_id_ holds this query's keys, so the order may be repaired

    // The query's order: keys_ sorted, order_[k] the caller's index of rectangle k.
    scratch_vector<std::uint32_t> keys_, order_;
    // A repair of the last order (repair_order): which rectangles changed
    // strips, in the last order; those that stayed and those that moved.
    scratch_vector<std::uint8_t> changed_strip_;
    scratch_vector<std::uint32_t> stay_keys_, stay_ids_, moved_keys_, moved_ids_;
    radix_buffer packed_, spare_;
    radix_bucket_buffers sort_buckets_;  ///< the buckets of the sorts on several threads

    // Per rectangle, in the query's order.
    scratch_records<record> records_;
    /// A double query (query_input::doubles): its rows in the query's order,
    /// which the double method reads (test_pairs), and the float rows its
    /// sweep runs on (bound_doubles), in the caller's order. The rows are
    /// copied rather than read in place through order_ (possible for a
    /// pose_records64): on the 1M-box uniform scene at UTM coordinates,
    /// exact, one thread, the copy took 306 to 430 ms against 475 to 489 ms
    /// in place (best of 5, a busy machine), as the candidates of the sweep
    /// then read rows far apart in the caller's order.
    bool doubles_ = false;
    store_kind double_kind_ = store_kind::poses;
    scratch_records<record64> records64_;
    scratch_records<record> double_bounds_;
    double double_bounds_seconds_ = 0;  ///< bound_doubles' time, counted in stats_.bounds_seconds
    /// collect_once: nothing of this query serves a next one, so a double
    /// query's float rows (double_bounds_) go once the order is made.
    bool one_shot_ = false;
    std::size_t keep_memory_up_to_ = 0;  ///< keep_working_memory_up_to
    scratch_vector<float> in_lo_x_, in_lo_y_, in_hi_x_, in_hi_y_;
    scratch_vector<std::uint32_t> q_lo_, q_hi_, strip_hi_;
    scratch_vector<std::uint8_t> side_;  ///< 1 for a rectangle of the second store
    /// The query carries pair filters (query_input::filtered): filters_ holds
    /// each rectangle's, and the sweep drops the pairs they refuse.
    bool filtered_ = false;
    scratch_vector<filter_values> filters_;

    // Strips: own_begin_[s] is the first rectangle whose lowest strip is s;
    // visits sorted by (strip, q_lo), visit_begin_[s] the first visit of s.
    std::vector<std::uint32_t> own_begin_, visit_begin_;
    scratch_vector<std::uint32_t> visit_keys_, visit_ids_;
    scratch_vector<std::uint32_t> far_keys_, far_ids_;  ///< visits beyond the strip above a rectangle's lowest, before the merge
    scratch_vector<std::uint32_t> near_keys_, near_ids_;  ///< visits to the strip above, before the merge (when there are far ones)
    /// Visits of the rectangles of one unit of the order: to the strip just above its lowest, and beyond.
    struct visit_counts {
        std::size_t near = 0;
        std::size_t far = 0;
    };
    std::vector<visit_counts> unit_visits_;  ///< per unit (start_visit_counts), while visits_counted_
    bool visits_counted_ = false;            ///< copy_records counted this query's visits

    std::vector<part> parts_;
    std::vector<strip_pass_memory> pass_memory_;  ///< copy_and_sweep: one per unit
    std::vector<unsigned char> copied_before_;  ///< per strip: in a boundary region (copy_region)
    float tallest_ = 0;  ///< measure_extent: the largest height of a rectangle's bounds (before widening)
    std::size_t used_parts_ = 0;  ///< sweep units of the last query; their found pairs are its answer
    std::vector<pair_index> pairs_;
    std::vector<pair_sort_scratch<pair_index>> sort_scratch_;

    kept_pairs kept_;  ///< pair_finder's kept candidates and the policy that keeps them
    kept_filters kept_filters_;  ///< the pair filters kept_ was built with (kept_filters.hpp)

    // The rows' ids (pair_finder with ids): the last call's, and this call's match against them.
    id_rows ids_a_, ids_b_;
    row_match match_a_, match_b_;
    bool ids_self_ = true;  ///< the last call with ids was a query within one set
    store_kind ids_kind_ = store_kind::poses;
    bool ids_followed_ = false;  ///< this call's ids were matched against the last call's
    bool rows_changed_ = false;  ///< and some row is not the one its position held
    std::size_t slots_ = 0;      ///< entries of the kept order (kept_.slots while kept_.by_id, else n_)
    std::vector<std::uint32_t> now_of_last_;  ///< the last call's rows (a before b) -> this call's (map_last_rows)
    bool probe_carried_ = false;  ///< kept_.last was moved to this call's rows (carry_probe_over)
};

}  // namespace obbsat::detail
