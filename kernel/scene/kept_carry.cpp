// The answer of a pair_finder call whose rows changed by id (step 4 at the
// top of kept_changes.cpp): one pass over the kept candidates sorted in the
// last call's rows (kept_pairs::by_caller) maps each to this call's rows,
// drops those of gone rows, leaves those of moved rows to moved_pairs (sorted
// apart), merges those in, and reads the colliding pairs on the way. What it
// writes is by_caller for the next call.
//
// With more than one thread the pass is cut into units taken as they come
// (support/work_shares.hpp). Unit u reads share u of by_caller and the moved
// pairs whose keys lie from the first kept pair of its share up to the first
// of the next share's, so what it writes follows unit u - 1's in the
// caller's order. Where it writes is known before any unit runs: after the
// kept pairs of the shares before it and the moved pairs before its range.
// The pairs it drops leave a gap at its end, filled with gap entries (rows
// no_row, kept_pairs::is_gap) that every reader of by_caller skips, and
// listed (kept_pairs::gaps) so that the next pass leaves them out of its
// places: gaps do not pile up from call to call. Each unit's answer goes to
// a buffer of its own and is copied into place once every unit's count is
// known. The answer does not depend on the units; only the gaps do.
#include "scene/pair_search.hpp"

#include "scene/search_common.hpp"
#include "support/work_shares.hpp"

#include <algorithm>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

namespace obbsat::detail {

namespace {

/// Kept pairs below which a unit of the carry costs more to hand to another
/// thread than it saves (a unit of this many takes some 50 µs).
constexpr std::size_t min_kept_per_carry_unit = 16384;

std::uint64_t order_key(const tagged_pair& p) { return (std::uint64_t{p.a} << 32) | p.b; }

/// What the carry reads, shared by its units.
struct carry_input {
    const tagged_pair* kept;      ///< by_caller, in the last call's rows
    const std::uint32_t* now_of;  ///< each last row's row now, or no_row
    const std::uint8_t* moved;    ///< rows of the last call that changed places; null when none did
    const std::uint64_t* verdicts;
    std::uint32_t b_last;         ///< the first b row among the last call's rows (0 for one set)
    std::uint32_t b_now;          ///< the same among this call's rows
};

enum class kept_fate { gap, gone, moved, kept };

/// What becomes of kept pair p: a gap entry, a pair of a gone row, one of a
/// moved row (in moved_pairs), or a pair kept in place, then `mapped` to this call's rows.
/// carry_range decides the same, written out with one branch for every fate
/// but the kept one (its loop runs on instructions, so each branch counts).
kept_fate fate_of(const carry_input& in, const tagged_pair& p, tagged_pair& mapped) {
    if (kept_pairs::is_gap(p)) {
        return kept_fate::gap;
    }
    const std::uint32_t a = in.now_of[p.a];
    const std::uint32_t b = in.now_of[p.b + in.b_last];
    if ((a == no_row) | (b == no_row)) {
        return kept_fate::gone;
    }
    if (in.moved != nullptr && (in.moved[p.a] | in.moved[p.b + in.b_last]) != 0) {
        return kept_fate::moved;
    }
    mapped = tagged_pair{a, b - in.b_now, p.tag};
    return kept_fate::kept;
}

/// The key in this call's rows of the first kept pair in place of kept[from, end), or the largest key if none.
std::uint64_t first_key_from(const carry_input& in, std::size_t from, std::size_t end) {
    tagged_pair mapped{};
    for (std::size_t j = from; j < end; ++j) {
        if (fate_of(in, in.kept[j], mapped) == kept_fate::kept) {
            return order_key(mapped);
        }
    }
    return std::numeric_limits<std::uint64_t>::max();
}

struct carry_count {
    std::size_t written = 0;  ///< pairs written to `into`
    std::size_t found = 0;    ///< of those, the colliding ones, written to `out`
    std::size_t gone = 0;     ///< pairs of gone rows, their tags written to `gone`
};

/// The carry of kept[begin, end) with the sorted moved pairs [side, side_end)
/// merged in: every pair taken is written to `into`, and the colliding ones
/// to out[0, found). Each pair is written where the next colliding one goes
/// (at most at out[out_last]) and counted if it collides: no branch on the
/// verdicts. The tags of pairs of gone rows are written to gone[0, gone_count), to be
/// marked dropped once the units have ended (an atomic mark here, shared
/// between units, stalled the loop at each). `any_moved`: in.moved is set.
/// A kept pair takes one branch that is rarely taken for its fate (gap,
/// gone, moved) and one for the merge (the next moved pair's key is held
/// apart): the loop runs on instructions, not on memory, so each one counts.
template <bool any_moved>
carry_count carry_range(const carry_input& in, std::size_t begin, std::size_t end, const tagged_pair* side,
                        const tagged_pair* side_end, tagged_pair* into, pair_index* out, std::size_t out_last,
                        std::uint32_t* gone) {
    // Plain locals: the stores below may alias anything the loop reads.
    const tagged_pair* const kept = in.kept;
    const std::uint32_t* const now_of = in.now_of;
    const std::uint8_t* const moved = in.moved;
    const std::uint64_t* const verdicts = in.verdicts;
    const std::uint32_t b_last = in.b_last;
    const std::uint32_t b_now = in.b_now;
    std::size_t written = 0;
    std::size_t found = 0;
    std::size_t gone_count = 0;
    const auto take = [&](const tagged_pair& p) __attribute__((always_inline)) {
        into[written++] = p;
        out[std::min(found, out_last)] = pair_index{p.a, p.b};
        found += static_cast<std::size_t>((verdicts[p.tag / 64] >> (p.tag % 64)) & 1u);
    };
    constexpr std::uint64_t no_key = std::numeric_limits<std::uint64_t>::max();
    std::uint64_t next_side = side != side_end ? order_key(*side) : no_key;
    constexpr std::size_t ahead = 32;
    for (std::size_t j = begin; j < end; ++j) {
        if (j + ahead < end && !kept_pairs::is_gap(kept[j + ahead])) {
            // The second rows and the verdicts are in no order: fetched ahead, they arrive in parallel.
            __builtin_prefetch(now_of + kept[j + ahead].b + b_last);
            __builtin_prefetch(verdicts + kept[j + ahead].tag / 64);
        }
        const tagged_pair p = kept[j];
        if (__builtin_expect(kept_pairs::is_gap(p), 0)) {
            continue;
        }
        const std::uint32_t a = now_of[p.a];
        const std::uint32_t b = now_of[p.b + b_last];
        const bool lost = (a == no_row) | (b == no_row);
        bool set_aside = lost;
        if (any_moved) {
            set_aside |= (moved[p.a] | moved[p.b + b_last]) != 0;
        }
        if (__builtin_expect(set_aside, 0)) {
            if (lost) {
                // A gone row's pair: dropped for good, and never answers again.
                gone[gone_count++] = p.tag;
            }
            continue;  // a moved row's pair is among the moved pairs
        }
        const tagged_pair mapped{a, b - b_now, p.tag};
        const std::uint64_t key = order_key(mapped);
        if (__builtin_expect(key > next_side, 0)) {
            // Kept and moved pairs never share a key.
            do {
                take(*side++);
            } while (side != side_end && order_key(*side) < key);
            next_side = side != side_end ? order_key(*side) : no_key;
        }
        take(mapped);
    }
    while (side != side_end) {
        take(*side++);
    }
    return carry_count{written, found, gone_count};
}

/// carry_range for `in`, moved rows or none.
carry_count carry_range(const carry_input& in, std::size_t begin, std::size_t end, const tagged_pair* side,
                        const tagged_pair* side_end, tagged_pair* into, pair_index* out, std::size_t out_last,
                        std::uint32_t* gone) {
    return in.moved != nullptr ? carry_range<true>(in, begin, end, side, side_end, into, out, out_last, gone)
                               : carry_range<false>(in, begin, end, side, side_end, into, out, out_last, gone);
}

}  // namespace

std::size_t kept_pairs::gap_entries_before(std::size_t position) const {
    std::size_t count = 0;
    for (const auto& [begin, end] : gaps) {
        if (begin < position) {
            count += std::min(end, position) - begin;
        }
    }
    return count;
}

void pair_search::answer_by_id() {
    const auto start = clock_type::now();
    const std::size_t kept_count = kept_.by_caller.size();
    const std::vector<tagged_pair>& side = kept_.moved_pairs;
    // The answer holds at most the pairs the test called colliding (those of
    // gone rows are not taken).
    std::size_t colliding = 0;
    for (std::size_t i = 0; i < used_parts_; ++i) {
        colliding += parts_[i].keep.colliding;
    }
    kept_.dropped.resize((kept_.pairs.size() + 63) / 64, 0);
    const carry_input in{kept_.by_caller.data(),
                         now_of_last_.data(),
                         kept_.remap_any_moved ? kept_.row_moved.data() : nullptr,
                         kept_.verdicts.data(),
                         self_ ? 0u : static_cast<std::uint32_t>(kept_.remap_last_a),
                         self_ ? 0u : static_cast<std::uint32_t>(a_count_)};

    // The units: unit u reads by_caller from kept_begin[u], the moved pairs
    // from side_begin[u], and writes by_caller's next contents from place[u].
    const std::size_t units = units_for(kept_count, used_parts_, min_kept_per_carry_unit);
    std::vector<std::size_t> kept_begin(units + 1), side_begin(units + 1), place(units + 1);
    for (std::size_t u = 0; u <= units; ++u) {
        kept_begin[u] = u == units ? kept_count : share_of(kept_count, u, units).first;
        if (u == 0 || u == units) {
            side_begin[u] = u == 0 ? 0 : side.size();
        } else {
            const std::uint64_t key = first_key_from(in, kept_begin[u], kept_count);
            const auto at = std::lower_bound(side.begin(), side.end(), key, [](const tagged_pair& p, std::uint64_t k) {
                return order_key(p) < k;
            });
            side_begin[u] = std::max(side_begin[u - 1], static_cast<std::size_t>(at - side.begin()));
        }
        place[u] = kept_begin[u] - kept_.gap_entries_before(kept_begin[u]) + side_begin[u];
    }
    std::vector<tagged_pair>& next = kept_.by_caller_spare;
    next.resize(place[units]);
    std::vector<carry_count> counts(units);
    if (kept_.unit_gone.size() < units) {
        kept_.unit_gone.resize(units);
    }
    for (std::size_t u = 0; u < units; ++u) {
        kept_.unit_gone[u].resize(kept_begin[u + 1] - kept_begin[u]);  // at most one a kept pair, left unwritten
    }
    if (units == 1) {
        // The answer is written in place: sized for the colliding pairs and
        // one more place, where every pair after the last colliding one is
        // written, it grows by a few places a call, where sizing it for every
        // kept pair filled the growth with zeros on each call.
        pairs_.resize(colliding + 1);
        counts[0] = carry_range(in, 0, kept_count, side.data(), side.data() + side.size(), next.data(),
                                pairs_.data(), colliding, kept_.unit_gone[0].data());
    } else {
        if (kept_.unit_answers.size() < units) {
            kept_.unit_answers.resize(units);
        }
        const tagged_pair gap = kept_pairs::gap_pair(kept_.pairs.size());
        run_units(units, used_parts_, [&](std::size_t u) {
            // Its answer holds at most the pairs it writes; grown, never shrunk, so rarely zeroed.
            std::vector<pair_index>& answer = kept_.unit_answers[u];
            const std::size_t most = place[u + 1] - place[u];
            if (answer.size() < most + 1) {
                answer.resize(most + 1);
            }
            counts[u] = carry_range(in, kept_begin[u], kept_begin[u + 1], side.data() + side_begin[u],
                                    side.data() + side_begin[u + 1], next.data() + place[u], answer.data(), most, kept_.unit_gone[u].data());
            std::fill(next.begin() + static_cast<std::ptrdiff_t>(place[u] + counts[u].written),
                      next.begin() + static_cast<std::ptrdiff_t>(place[u + 1]), gap);
        });
    }
    std::size_t found = 0;
    std::vector<std::size_t> answer_at(units + 1, 0);
    for (std::size_t u = 0; u < units; ++u) {
        found += counts[u].found;
        answer_at[u + 1] = found;
    }
    for (std::size_t u = 0; u < units; ++u) {
        for (std::size_t i = 0; i < counts[u].gone; ++i) {
            const std::uint32_t tag = kept_.unit_gone[u][i];
            kept_.dropped[tag / 64] |= std::uint64_t{1} << (tag % 64);
        }
    }
    if (found > colliding) {
        throw std::logic_error("obbsat: the answer from kept candidates carried over found " + std::to_string(found) +
                               " colliding pairs where the test counted " + std::to_string(colliding));
    }
    // The gaps the units left, but none after the last one's pairs.
    kept_.gaps.clear();
    kept_.gap_entries = 0;
    for (std::size_t u = 0; u + 1 < units; ++u) {
        const std::size_t gap_begin = place[u] + counts[u].written;
        if (gap_begin < place[u + 1]) {
            kept_.gaps.emplace_back(gap_begin, place[u + 1]);
            kept_.gap_entries += place[u + 1] - gap_begin;
        }
    }
    next.resize(place[units - 1] + counts[units - 1].written);
    kept_.by_caller.swap(next);
    pairs_.resize(found);
    if (units > 1) {
        run_units(units, used_parts_, [&](std::size_t u) {
            std::copy(kept_.unit_answers[u].begin(),
                      kept_.unit_answers[u].begin() + static_cast<std::ptrdiff_t>(counts[u].found),
                      pairs_.begin() + static_cast<std::ptrdiff_t>(answer_at[u]));
        });
    }
    kept_.remap_pending = false;
    kept_.answer_parts = 0;  // by_caller changed: the shares of an answer are marked anew
    stats_.pairs = found;
    stats_.kept_candidates = kept_.by_caller.size() - kept_.gap_entries;
    stats_.output_seconds += seconds_since(start);
}

}  // namespace obbsat::detail
