// Whether pair_finder's kept candidates pay (kept_pairs.hpp), from what its
// calls measure. Internal to the library.
//
// A cycle of keeping is a full query that keeps the candidates of widened
// bounds, then the calls those candidates answer. Keeping pays when a
// cycle's calls cost less on average than plain queries (the path
// find_pairs takes, with the strip pass on one thread): a full query that
// keeps costs a few plain ones, so the calls it serves must be cheap
// enough and many enough. Where rows change a lot between calls (swap-
// removed rows carried over every call, say), the carried calls cost about
// a plain query each and the full query is never paid back.
//
// When a cycle ends (its candidates serve no more) the finder weighs it:
//   - A cycle that clearly paid, at most clear_share of a plain query (the
//     median of the latest timed), keeps again.
//   - Otherwise that call and the next are answered by plain queries,
//     timed, and the cycle compared with them and the latest (judge): if
//     the cycle cost clearly more per call (rest_share), or if its carried
//     calls alone cost nearly a plain query each (carried_share), the next
//     rest_length calls are plain queries too (resting), and the next rest
//     after another cycle that does not pay is twice as long, up to
//     longest_rest; a cycle that pays makes the next rest short again.
// Each kind of call counts at the lower median of its latest costs, so that
// a call the machine delayed counts as a typical one.
// The first call on a scene also faults in the finder's memory, and so
// does the full query of its first cycle: until a plain query is timed, a
// plain query counts as first_call_share of the first call or a
// full_query_cap-th of the cycle's full query, the larger (a first call may
// find its memory ready), for the first first_call_cycles cycles only (then
// a plain query is timed), and the first cycle's full query as at most
// full_query_cap plain queries.
// Costs are measured by pair_search::collect (wall time of a call), from
// min_boxes_weighed rows on (search_common.hpp); the decisions are here, so
// that they can be checked with given costs.
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>

namespace obbsat::detail {

/// The latest costs of one kind of call, up to `Samples` of them, and their
/// lower median: a call the machine delayed counts as a typical one.
template <std::size_t Samples>
class latest_costs {
public:
    void add(double seconds) {
        costs_[added_ % Samples] = seconds;
        ++added_;
    }
    void clear() { added_ = 0; }
    bool empty() const { return added_ == 0; }
    /// Costs added since the last clear, those no longer held counted.
    std::size_t added() const { return added_; }
    /// The lower median of the held costs; 0 when none. Allocates nothing.
    double median() const {
        const std::size_t held = std::min(added_, Samples);
        if (held == 0) {
            return 0;
        }
        std::array<double, Samples> sorted = costs_;
        const auto middle = sorted.begin() + static_cast<std::ptrdiff_t>((held - 1) / 2);
        std::nth_element(sorted.begin(), middle, sorted.begin() + static_cast<std::ptrdiff_t>(held));
        return *middle;
    }

private:
    std::array<double, Samples> costs_{};
    std::size_t added_ = 0;
};

class keep_costs {
public:
    /// The calls of the first rest; each rest after a cycle that did not
    /// pay doubles, up to longest_rest.
    static constexpr std::size_t first_rest = 32;
    static constexpr std::size_t longest_rest = 1024;
    /// A cycle costing at most this share of a plain query per call keeps
    /// again with no plain query timed.
    static constexpr double clear_share = 0.75;
    /// A scene's first call counts as this share of its time (its memory
    /// is faulted in on the way: some 3 plain queries at 100k boxes).
    static constexpr double first_call_share = 1.0 / 3;
    /// The cycles a first call's time is taken for a plain query's.
    static constexpr std::size_t first_call_cycles = 3;
    /// A cycle weighed rests only if it cost more than this many plain
    /// queries per call: where the two cost about the same, it keeps.
    static constexpr double rest_share = 1.03;
    /// A cycle weighed rests, whatever its full query cost, if its carried
    /// calls cost more than this many plain queries each (at their median):
    /// such a cycle saves too little a call to pay back its full query, and
    /// over a long cycle its cost per call comes within the clock's noise
    /// of a plain query's, where rest_share alone decided either way from
    /// run to run (spawn_swap_remove, 100k boxes: carried calls cost about
    /// a plain query each).
    static constexpr double carried_share = 0.9;
    /// Plain queries timed to weigh a cycle that did not clearly pay: two,
    /// so that one the machine delayed does not decide alone.
    static constexpr std::size_t judge_calls = 2;
    /// The full query of a scene's first cycle counts as at most this many
    /// plain queries: what later ones cost (spawn_swap_remove, 100k boxes,
    /// one thread: some 11 ms against 4.4).
    static constexpr double full_query_cap = 2.5;

    /// A new scene: nothing measured, no rest. `seconds`: its first call, a plain query.
    void new_scene(double seconds) {
        *this = keep_costs{};
        first_call_seconds_ = seconds * first_call_share;
        first_cycle_next_ = true;
    }
    /// A plain query answered a call in `seconds` (not a first call).
    void plain(double seconds) { plain_.add(seconds); }
    /// A full query kept candidates in `seconds`: a cycle begins.
    void kept(double seconds) {
        full_seconds_ = seconds;
        first_cycle_ = first_cycle_next_;
        first_cycle_next_ = false;
        carried_.clear();
    }
    /// The kept candidates answered a call in `seconds`.
    void carried(double seconds) { carried_.add(seconds); }

    /// What a plain query costs: the median of the latest ones timed, or
    /// before any, a share of the first call's time or of the cycle's full
    /// query's, the larger.
    double plain_cost() const {
        if (!plain_.empty()) {
            return plain_.median();
        }
        // A full query that keeps costs about full_query_cap plain ones: the
        // larger guess, as a first call may find its memory ready or not.
        return std::max(first_call_seconds_, full_seconds_ / full_query_cap);
    }
    /// The cycle's cost per call: its full query and its carried calls at
    /// their median. 0 when no call was carried.
    double cycle_cost() const {
        if (carried_.empty()) {
            return 0;
        }
        const double plain = plain_.empty() ? first_call_seconds_ : plain_.median();
        const double full = first_cycle_ ? std::min(full_seconds_, full_query_cap * plain) : full_seconds_;
        const auto calls = static_cast<double>(carried_.added());
        return (full + calls * carried_.median()) / (calls + 1);
    }
    /// At the end of a cycle (counted): true when it clearly paid (the next
    /// full query keeps); false when the call is to be a plain query, timed
    /// and given to judge.
    bool clearly_pays() {
        ++cycles_;
        const double cost = cycle_cost();
        const bool known = !plain_.empty() || cycles_ <= first_call_cycles;
        return known && cost > 0 && cost <= clear_share * plain_cost();
    }
    /// The cycle that just ended is weighed against the next judge_calls
    /// plain queries (judge), after clearly_pays said no.
    void start_judging() { judging_left_ = judge_calls; }
    /// Whether this call is one of the plain queries that weigh a cycle.
    bool judging() const { return judging_left_ > 0; }
    /// One of the plain queries that weigh the cycle took `seconds`; after
    /// the last, rest if the cycle cost more per call than rest_share plain
    /// queries (these with the latest), or its carried calls more than
    /// carried_share plain queries each. Returns whether a rest began.
    bool judge(double seconds) {
        plain(seconds);
        if (judging_left_ > 1) {
            --judging_left_;
            return false;
        }
        judging_left_ = 0;
        const double cost = cycle_cost();
        const double carried = carried_.median();
        carried_.clear();
        const double plain = plain_cost();
        if (cost > rest_share * plain || carried > carried_share * plain) {
            rest_left_ = rest_length_;
            rest_length_ = std::min(2 * rest_length_, longest_rest);
            ++rests_;
            return true;
        }
        rest_length_ = first_rest;
        return false;
    }
    /// Whether this call rests (a plain query where a full query would keep); counts it.
    bool rest_call() {
        if (rest_left_ == 0) {
            return false;
        }
        --rest_left_;
        return true;
    }
    /// Calls of the rest under way still to come.
    std::size_t rest_left() const { return rest_left_; }
    /// The calls the next rest will last.
    std::size_t next_rest() const { return rest_length_; }
    /// Rests begun since the scene began.
    std::size_t rests() const { return rests_; }

private:
    latest_costs<8> plain_;            ///< plain queries timed (not a first call)
    latest_costs<64> carried_;         ///< the cycle's carried calls
    double first_call_seconds_ = 0;    ///< the scene's first call, counted at first_call_share
    double full_seconds_ = 0;          ///< the full query that began the cycle
    bool first_cycle_ = false;         ///< the cycle is the scene's first
    bool first_cycle_next_ = false;
    std::size_t cycles_ = 0;           ///< cycles ended on this scene
    std::size_t judging_left_ = 0;     ///< plain queries still to time for the cycle being weighed
    std::size_t rest_left_ = 0;
    std::size_t rest_length_ = first_rest;
    std::size_t rests_ = 0;
};

}  // namespace obbsat::detail
