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
//   - A cycle that clearly paid, at most clear_share of the last plain
//     query measured, keeps again.
//   - Otherwise that call is answered by a plain query, timed, and the
//     cycle compared with it (judge): if the cycle cost more per call, the
//     next rest_length calls are plain queries too (resting), and the next
//     rest after another cycle that does not pay is twice as long, up to
//     longest_rest; a cycle that pays makes the next rest short again.
// The first call on a scene also faults in the finder's memory, and so
// does the full query of its first cycle: the first call counts as
// first_call_share of its time, for the first first_call_cycles cycles only
// (then a plain query is timed if none was), and the first cycle's full
// query as at most full_query_cap plain queries.
// Costs are measured by pair_search::collect (wall time of a call), from
// min_boxes_weighed rows on (search_common.hpp); the decisions are here, so
// that they can be checked with given costs.
#pragma once

#include <algorithm>
#include <cstddef>
#include <vector>

namespace obbsat::detail {

class keep_costs {
public:
    /// The calls of the first rest; each rest after a cycle that did not
    /// pay doubles, up to longest_rest.
    static constexpr std::size_t first_rest = 32;
    static constexpr std::size_t longest_rest = 1024;
    /// A cycle costing at most this share of the last plain query measured
    /// per call keeps again with no plain query timed.
    static constexpr double clear_share = 0.75;
    /// A scene's first call counts as this share of its time (its memory
    /// is faulted in on the way: some 3 plain queries at 100k boxes).
    static constexpr double first_call_share = 1.0 / 3;
    /// The cycles a first call's time is taken for a plain query's.
    static constexpr std::size_t first_call_cycles = 3;
    /// The full query of a scene's first cycle counts as at most this many plain queries.
    static constexpr double full_query_cap = 3.0;
    /// Carried calls whose costs are kept for the median, the latest ones.
    static constexpr std::size_t carried_samples = 64;

    /// A new scene: nothing measured, no rest. `seconds`: its first call, a plain query.
    void new_scene(double seconds) {
        *this = keep_costs{};
        plain_seconds_ = seconds * first_call_share;
        first_cycle_next_ = true;
    }
    /// A plain query answered a call in `seconds` (not a first call).
    void plain(double seconds) {
        plain_seconds_ = seconds;
        plain_measured_ = true;
    }
    /// A full query kept candidates in `seconds`: a cycle begins.
    void kept(double seconds) {
        full_seconds_ = seconds;
        first_cycle_ = first_cycle_next_;
        first_cycle_next_ = false;
        carried_.clear();
        carried_calls_ = 0;
    }
    /// The kept candidates answered a call in `seconds`.
    void carried(double seconds) {
        if (carried_.size() < carried_samples) {
            carried_.push_back(seconds);
        } else {
            carried_[carried_calls_ % carried_samples] = seconds;
        }
        ++carried_calls_;
    }

    /// The cycle's cost per call: its full query and its carried calls at
    /// their median (a call the machine delayed counts as a typical one).
    /// 0 when no cycle was measured.
    double cycle_cost() const {
        if (carried_.empty()) {
            return 0;
        }
        std::vector<double> sorted = carried_;
        const auto middle = sorted.begin() + static_cast<std::ptrdiff_t>(sorted.size() / 2);
        std::nth_element(sorted.begin(), middle, sorted.end());
        const double carried = *middle;
        const double full = first_cycle_ ? std::min(full_seconds_, full_query_cap * plain_seconds_) : full_seconds_;
        const auto calls = static_cast<double>(carried_calls_);
        return (full + calls * carried) / (calls + 1);
    }
    /// At the end of a cycle (counted): true when it clearly paid (the next
    /// full query keeps); false when the call is to be a plain query, timed
    /// and given to judge.
    bool clearly_pays() {
        ++cycles_;
        const double cost = cycle_cost();
        const bool known = plain_measured_ || cycles_ <= first_call_cycles;
        return known && cost > 0 && cost <= clear_share * plain_seconds_;
    }
    /// The plain query that ended a cycle took `seconds`: rest if the cycle cost more per call.
    void judge(double seconds) {
        plain(seconds);
        const double cost = cycle_cost();
        carried_.clear();
        carried_calls_ = 0;
        if (cost > seconds) {
            rest_left_ = rest_length_;
            rest_length_ = std::min(2 * rest_length_, longest_rest);
            ++rests_;
        } else {
            rest_length_ = first_rest;
        }
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
    double plain_seconds_ = 0;  ///< the last plain query (a first call's counted at first_call_share); 0: none
    bool plain_measured_ = false;  ///< plain_seconds_ is a plain query's, not a first call's
    std::size_t cycles_ = 0;       ///< cycles ended on this scene
    double full_seconds_ = 0;   ///< the full query that began the cycle
    bool first_cycle_ = false;  ///< the cycle is the scene's first
    bool first_cycle_next_ = false;
    std::vector<double> carried_;     ///< the latest carried calls' costs
    std::size_t carried_calls_ = 0;   ///< carried calls of the cycle
    std::size_t rest_left_ = 0;
    std::size_t rest_length_ = first_rest;
    std::size_t rests_ = 0;
};

}  // namespace obbsat::detail
