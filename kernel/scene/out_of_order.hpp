// Which entries of a sequence to set aside so that the others increase: for
// pair_finder's rows that come, go and change places (kept_changes.cpp: the
// last call's rows by their rows now; pair_events.cpp: the rows by their
// ids). The pairs of entries set aside are sorted apart and merged in, so
// the fewer the better, but any set that leaves the others increasing is
// correct. Internal to the library.
//
// Two passes: an entry out of order with a neighbour (a row swapped with a
// far one, a row carried into a hole) is set aside with the neighbour it
// breaks with; then a greedy pass over the rest, from the front or from the
// back, whichever sets fewer aside, takes what is left out of order (a
// block moved as a whole). Rows appended, removed or inserted set nothing
// aside.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace obbsat::detail {

/// Sets marks[i] = 1 for the entries to set aside among values[0, count),
/// skipping (and leaving unmarked) those equal to `skip` when `skips`;
/// returns how many.
template <class Value>
std::size_t mark_out_of_order(const Value* values, std::size_t count, bool skips, Value skip,
                              std::vector<std::uint8_t>& marks) {
    marks.assign(count, 0);
    const auto takes_part = [&](std::size_t i) { return !skips || values[i] != skip; };
    std::size_t marked = 0;
    std::size_t previous = count;  // the last entry that takes part, none yet
    for (std::size_t i = 0; i < count; ++i) {
        if (!takes_part(i)) {
            continue;
        }
        if (previous != count && values[previous] > values[i]) {
            marked += marks[previous] == 0 ? 1u : 0u;
            marked += marks[i] == 0 ? 1u : 0u;
            marks[previous] = 1;
            marks[i] = 1;
        }
        previous = i;
    }
    if (marked == 0) {
        return 0;
    }
    // The rest: a greedy pass from each end, the one that sets fewer aside.
    const auto greedy = [&](bool forward, bool apply) {
        std::size_t count_out = 0;
        bool any = false;
        Value bound{};
        for (std::size_t j = 0; j < count; ++j) {
            const std::size_t i = forward ? j : count - 1 - j;
            if (!takes_part(i) || marks[i] == 1) {
                continue;
            }
            const Value v = values[i];
            const bool out = any && (forward ? v < bound : v > bound);
            if (out) {
                ++count_out;
                if (apply) {
                    marks[i] = 2;
                }
            } else {
                bound = v;
                any = true;
            }
        }
        return count_out;
    };
    const std::size_t forward = greedy(true, false);
    const std::size_t backward = forward == 0 ? 0 : greedy(false, false);
    if (forward != 0) {
        marked += greedy(forward <= backward, true);
    }
    for (std::uint8_t& m : marks) {
        m = m != 0 ? 1 : 0;
    }
    return marked;
}

}  // namespace obbsat::detail
