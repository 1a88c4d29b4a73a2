// pair_finder's kept candidates when rows come, go and change places
// between calls (box_view::with_ids; the state is kept_pairs' "by id" part).
//
// A call whose ids differ from the last call's carries the kept candidates
// over instead of running a full query, at a cost of the change plus a few
// linear passes (no sort of all rows, no sweep):
//   1. Match: each row's id against the last call's (id_rows): same
//      position, moved, new, or gone.
//   2. Slots: each slot's row is mapped to this call's (one pass over the
//      slots); a gone row's slot is emptied (order_ holds no_row there): its
//      kept pairs stay in place, are tested with the others on a record far
//      from everything (kept_pairs.cpp) and their verdicts cleared
//      (kept_pairs::dropped), or, for a float method, never pass the bounds
//      filter (NaN bounds). A new row gets a slot after the last, with its
//      record, its widened bounds and its strips on the full query's grid.
//   3. The new slots' candidates: each new slot is looked up in the strips
//      it touches, among the full query's entries (each strip's own entries
//      and visitors, sorted by quantized lo_x; see pair_search.hpp) and among
//      the slots added since (added_entries, kept sorted by merging each
//      call's few in), each search started where the key would lie in the
//      strip (seek). A pair is taken in the strip holding the larger of the
//      two lowest strips, as the sweep takes it, so it is found once; a pair
//      of two new slots is taken from the earlier slot. The widened bounds
//      decide, exactly as in the sweep. The new slots are cut into units
//      for the pool (work_shares.hpp), their pairs appended in unit order.
//   4. by_caller, the kept candidates sorted in the caller's rows, is
//      carried to this call's rows: the pairs of rows that changed places
//      against the others (out_of_order.hpp: none when rows are appended or
//      erased, a few when one is swapped into a hole) are mapped and sorted
//      apart with the new slots' pairs, and the kept pairs are tested; then
//      one pass over by_caller maps each pair to this call's rows (their
//      order is kept), merges the sorted ones in, drops those of gone rows,
//      and reads the answer on the way (answer_by_id, kept_carry.cpp, in
//      units for the pool too).
// A change of more than an eighth of the rows, or empty and added slots
// passing a quarter of the slots, makes the call a full query instead, which
// lays the slots out anew (and keeps again: the scene is the same by id).
#include "scene/pair_search.hpp"

#include "dispatch/backend_registry.hpp"
#include "sort/few_pairs_sort.hpp"
#include "scene/out_of_order.hpp"
#include "scene/search_common.hpp"
#include "sort/pair_sort.hpp"
#include "support/work_shares.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

namespace obbsat::detail {

namespace {

/// New slots below which a unit of their candidates' search costs more to
/// hand to another thread than it saves (a slot's search takes some 0.6 µs).
constexpr std::size_t min_new_slots_per_unit = 64;

/// Fetches row `id`'s pair filters into the cache, where its set gives them.
void fetch_filters(const query_input& input, std::size_t id) {
    const bool in_a = id < input.a_count;
    const pair_filters& f = in_a ? input.a_filters : input.b_filters;
    const std::size_t i = in_a ? id : id - input.a_count;
    if (f.categories != nullptr) {
        __builtin_prefetch(f.categories + i);
    }
    if (f.masks != nullptr) {
        __builtin_prefetch(f.masks + i);
    }
    if (f.groups != nullptr) {
        __builtin_prefetch(f.groups + i);
    }
}

/// Where seek() first looks for `key` among one strip's sorted keys: where
/// it would lie if the keys were spread evenly between the first and the
/// last (they are quantized x positions).
template <class Key>
const Key* first_probe(const Key* begin, const Key* end, Key key) {
    if (end - begin < 2 || key <= *begin) {
        return begin;
    }
    const Key first = *begin;
    const Key last = *(end - 1);
    if (key > last) {
        return end - 1;
    }
    const auto count = static_cast<std::size_t>(end - begin);
    const double share = static_cast<double>(key - first) / static_cast<double>(last - first);
    return begin + std::min(count - 1, static_cast<std::size_t>(share * static_cast<double>(count - 1)));
}

/// std::lower_bound over one strip's sorted keys, started at first_probe,
/// then galloping to the answer: a probe or two where a binary search takes
/// a dozen dependent reads.
template <class Key>
const Key* seek(const Key* begin, const Key* end, Key key) {
    if (begin == end || key <= *begin) {
        return begin;
    }
    if (key > *(end - 1)) {
        return end;
    }
    // first < key <= last: the answer lies in (begin, end - 1].
    const auto count = static_cast<std::size_t>(end - begin);
    const auto at = static_cast<std::size_t>(first_probe(begin, end, key) - begin);
    if (begin[at] < key) {
        // Forward: the answer is past `at`.
        std::size_t step = 1;
        std::size_t low = at;  // begin[low] < key
        while (low + step < count && begin[low + step] < key) {
            low += step;
            step *= 2;
        }
        return std::lower_bound(begin + low + 1, begin + std::min(count, low + step + 1), key);
    }
    // Backward: begin[at] >= key, the answer is at or before `at`.
    std::size_t step = 1;
    std::size_t high = at;  // begin[high] >= key
    while (high >= step && begin[high - step] >= key) {
        high -= step;
        step *= 2;
    }
    return std::lower_bound(begin + (high >= step ? high - step : 0), begin + high, key);
}

}  // namespace

void pair_search::match_ids(const query_input& input) {
    ids_followed_ = false;
    rows_changed_ = false;
    if (!input.with_ids) {
        return;
    }
    const bool self = input.b == nullptr;
    const bool follow = ids_a_.ready() && (self || ids_b_.ready()) && ids_self_ == self && ids_kind_ == input.kind;
    ids_a_.match(input.a_ids, input.a_count, follow, self ? "" : "a: ", match_a_);
    if (!self) {
        ids_b_.match(input.b_ids, input.b_count, follow, "b: ", match_b_);
    }
    ids_followed_ = follow;
    rows_changed_ = follow && !(match_a_.unchanged() && (self || match_b_.unchanged()));
}

void pair_search::commit_ids(const query_input& input) {
    if (!input.with_ids) {
        ids_a_.clear();
        ids_b_.clear();
        return;
    }
    ids_a_.commit(input.a_ids, match_a_);
    if (self_) {
        ids_b_.clear();
    } else {
        ids_b_.commit(input.b_ids, match_b_);
    }
    ids_self_ = self_;
    ids_kind_ = kind_;
}

void pair_search::abandon_kept() {
    kept_.ready = false;
    kept_.keep = false;
    if (kept_.by_id) {
        have_order_ = false;  // the order's slots are no query's rows
    }
    ids_a_.clear();
    ids_b_.clear();
}

void pair_search::map_last_rows() {
    const row_match& ma = match_a_;
    const std::size_t last_a = ma.last_count;
    now_of_last_.resize(last_a + (self_ ? 0 : match_b_.last_count));
    std::copy(ma.now_of_last.begin(), ma.now_of_last.end(), now_of_last_.begin());
    if (!self_) {
        const auto offset = static_cast<std::uint32_t>(a_count_);
        for (std::size_t r = 0; r < match_b_.last_count; ++r) {
            const std::uint32_t now = match_b_.now_of_last[r];
            now_of_last_[last_a + r] = now == no_row ? no_row : now + offset;
        }
    }
}

void pair_search::carry_probe_over() {
    // The last call's widened bounds, moved to this call's rows; a new row's
    // bounds hold everything, so that it counts as calm.
    const float inf = std::numeric_limits<float>::infinity();
    std::vector<signed_bounds> moved(n_, signed_bounds{{-inf, -inf, -inf, -inf}});
    for (std::size_t r = 0; r < now_of_last_.size(); ++r) {
        if (now_of_last_[r] != no_row) {
            moved[now_of_last_[r]] = kept_.last[r];
        }
    }
    kept_.last.resize(n_);
    std::copy(moved.begin(), moved.end(), kept_.last.begin());
}

void pair_search::start_changes() {
    // The slots are the full query's order: slot k holds row order_[k].
    kept_.by_id = true;
    kept_.slots = slots_;
    kept_.full_slots = slots_;
    kept_.empty_slots = 0;
    kept_.rows = slots_;
    // Each strip's widest entry, own entries and visitors alike.
    const unsigned q_bits = grid_.q_bits;
    kept_.full_reach.assign(grid_.strips, 0);
    for (std::size_t k = 0; k < slots_; ++k) {
        std::uint32_t& reach = kept_.full_reach[keys_[k] >> q_bits];
        reach = std::max(reach, q_hi_[k] - std::min(q_lo_[k], q_hi_[k]));
    }
    const std::size_t visits = visit_keys_.size() - 1;
    for (std::size_t v = 0; v < visits; ++v) {
        const std::uint32_t k = visit_ids_[v];
        std::uint32_t& reach = kept_.full_reach[visit_keys_[v] >> q_bits];
        reach = std::max(reach, q_hi_[k] - std::min(q_lo_[k], q_hi_[k]));
    }
    kept_.added_reach.assign(grid_.strips, 0);
    kept_.added_entries.clear();
    kept_.added_begin.assign(grid_.strips + 1, 0);
    kept_.widened.resize(slots_);
    for (std::size_t k = 0; k < slots_; ++k) {
        kept_.widened[k] = signed_bounds{{in_lo_x_[k], in_lo_y_[k], -in_hi_x_[k], -in_hi_y_[k]}};
    }
    kept_.dropped.assign((kept_.pairs.size() + 63) / 64, 0);
}

bool pair_search::absorb_changes(const query_input& input) {
    const row_match& ma = match_a_;
    const std::size_t last_a = ma.last_count;
    const std::size_t last_n = last_a + (self_ ? 0 : match_b_.last_count);
    if (last_n != (kept_.by_id ? kept_.rows : slots_)) {
        return false;  // not the layout of the last call's rows
    }
    if (!rows_changed_) {
        return true;  // the rows are the last call's, in their places
    }
    std::vector<std::uint32_t> fresh(ma.fresh.begin(), ma.fresh.end());
    std::size_t gone_count = ma.gone.size();
    if (!self_) {
        for (const std::uint32_t r : match_b_.fresh) {
            fresh.push_back(r + static_cast<std::uint32_t>(a_count_));
        }
        gone_count += match_b_.gone.size();
    }
    // The policy: a change of more than an eighth of the rows, or empty and
    // added slots passing a quarter of the slots, is a full query's job.
    // Rows matched in order (the side-by-side walk of id_rows) need no look
    // for rows out of order: a pass over every row that finds none.
    const bool in_order = ma.in_order && (self_ || match_b_.in_order);
    const std::size_t moved_rows =
        in_order ? 0 : mark_out_of_order(now_of_last_.data(), now_of_last_.size(), true, no_row, kept_.row_moved);
    const std::size_t change = moved_rows + fresh.size() + gone_count;
    const std::size_t slots_before = kept_.by_id ? kept_.slots : slots_;
    const std::size_t added_before = kept_.by_id ? kept_.slots - kept_.full_slots : 0;
    const std::size_t empty_before = kept_.by_id ? kept_.empty_slots : 0;
    if (8 * change > n_ ||
        4 * (added_before + empty_before + fresh.size() + gone_count) > slots_before + fresh.size()) {
        return false;
    }
    const auto start = clock_type::now();
    if (!kept_.by_id) {
        start_changes();
    }
    // Step 2: each slot names its row now, or no_row when the row is gone;
    // the new rows get slots after the last.
    std::uint32_t* const order = order_.data();
    const std::uint32_t* const now_of = now_of_last_.data();
    for (std::size_t k = 0; k < kept_.slots; ++k) {
        const std::uint32_t row = order[k];
        order[k] = row == no_row ? no_row : now_of[row];
    }
    kept_.empty_slots += gone_count;
    kept_.rows = n_;
    const std::size_t first_new = kept_.slots;
    add_slots(input, fresh);
    // Step 3: the new slots' candidates, appended to the kept ones.
    const std::size_t kept_before = kept_.pairs.size();
    find_new_candidates(input, first_new);
    // Step 4: by_caller in this call's rows, with the new candidates.
    kept_.moved_pairs.clear();
    for (std::size_t i = kept_before; i < kept_.pairs.size(); ++i) {
        const pair_index caller = caller_pair(kept_.pairs[i]);
        kept_.moved_pairs.push_back(tagged_pair{caller.a, caller.b, static_cast<std::uint32_t>(i)});
    }
    sort_moved_pairs(last_a, moved_rows != 0);
    kept_.answer_parts = 0;  // the shares of the answer are marked anew
    stats_.order_seconds = seconds_since(start);
    return true;
}

void pair_search::add_slots(const query_input& input, const std::vector<std::uint32_t>& fresh) {
    const std::size_t first = kept_.slots;
    const std::size_t count = fresh.size();
    const std::size_t slots = first + count;
    kept_.slots = slots;
    slots_ = slots;
    for (auto* v : {&order_, &keys_, &q_lo_, &q_hi_, &strip_hi_}) {
        v->resize(slots);
    }
    for (auto* v : {&in_lo_x_, &in_lo_y_, &in_hi_x_, &in_hi_y_}) {
        v->resize(slots);
    }
    records_.resize(slots);
    side_.resize(slots);
    kept_.now.resize(slots);
    kept_.widened.resize(slots);
    if (count == 0) {
        return;
    }
    const bounds_fn bounds = kernels_for(ran_).bounds;
    const unsigned q_bits = grid_.q_bits;
    std::vector<std::uint64_t> entries;
    bounds_run b;
    for (std::size_t run_begin = first; run_begin < slots; run_begin += bounds_run::size) {
        const std::size_t run_end = std::min(slots, run_begin + bounds_run::size);
        for (std::size_t k = run_begin; k < run_end; ++k) {
            const std::uint32_t row = fresh[k - first];
            order_[k] = row;
            copy_row(input, row, records_[k].v);
            side_[k] = row >= a_count_ && !self_ ? 1 : 0;
        }
        // The bounds the refresh computes (the same function on the same
        // floats), widened as the full query widened the others.
        bounds(kind_, records_[run_begin].v, run_end - run_begin, b.lo_x, b.lo_y, b.hi_x, b.hi_y);
        widen_bounds(b, run_end - run_begin, kept_.margin, kept_.typical_extent);
        for (std::size_t k = run_begin; k < run_end; ++k) {
            const std::size_t r = k - run_begin;
            in_lo_x_[k] = b.lo_x[r];
            in_lo_y_[k] = b.lo_y[r];
            in_hi_x_[k] = b.hi_x[r];
            in_hi_y_[k] = b.hi_y[r];
            kept_.widened[k] = signed_bounds{{b.lo_x[r], b.lo_y[r], -b.hi_x[r], -b.hi_y[r]}};
            q_lo_[k] = grid_.q_of(b.lo_x[r]);
            q_hi_[k] = grid_.q_of(b.hi_x[r]);
            keys_[k] = grid_.key_of(b.lo_x[r], b.lo_y[r]);
            const std::uint32_t low = keys_[k] >> q_bits;
            strip_hi_[k] = std::max(grid_.strip_of(b.hi_y[r]), low);
            const std::uint32_t reach = q_hi_[k] - std::min(q_lo_[k], q_hi_[k]);
            for (std::uint32_t s = low; s <= strip_hi_[k]; ++s) {
                const std::uint64_t key = (std::uint64_t{s} << q_bits) | q_lo_[k];
                entries.push_back((key << 32) | k);
                kept_.added_reach[s] = std::max(kept_.added_reach[s], reach);
            }
        }
    }
    // The added entries: those of empty slots dropped, the new ones merged in.
    std::sort(entries.begin(), entries.end());
    std::vector<std::uint64_t>& merged = kept_.added_spare;
    merged.clear();
    merged.reserve(kept_.added_entries.size() + entries.size());
    const std::uint32_t* const order = order_.data();
    auto old = kept_.added_entries.begin();
    auto add = entries.begin();
    while (old != kept_.added_entries.end() || add != entries.end()) {
        if (add == entries.end() || (old != kept_.added_entries.end() && *old < *add)) {
            if (order[*old & 0xffffffffu] != no_row) {
                merged.push_back(*old);
            }
            ++old;
        } else {
            merged.push_back(*add++);
        }
    }
    kept_.added_entries.swap(merged);
    // Where each strip's entries start, so that a search looks in one strip's few.
    const std::size_t strips = grid_.strips;
    kept_.added_begin.assign(strips + 1, 0);
    for (const std::uint64_t e : kept_.added_entries) {
        ++kept_.added_begin[((e >> 32) >> q_bits) + 1];
    }
    for (std::size_t t = 0; t < strips; ++t) {
        kept_.added_begin[t + 1] += kept_.added_begin[t];
    }
}

bool pair_search::follow_filters(const query_input& input) {
    std::vector<std::uint32_t> changed_a, changed_b;
    if (!kept_filters_.changed_rows(input, match_a_, self_ ? nullptr : &match_b_, changed_a, changed_b)) {
        return false;
    }
    if (changed_a.empty() && changed_b.empty()) {
        return true;
    }
    rematch_as_new(match_a_, changed_a);
    rematch_as_new(match_b_, changed_b);
    rows_changed_ = true;
    return true;
}

void pair_search::find_new_candidates(const query_input& input, std::size_t first_new) {
    const unsigned q_bits = grid_.q_bits;
    const std::uint32_t* const order = order_.data();
    const std::uint32_t* const keys = keys_.data();
    const std::uint64_t* const added = kept_.added_entries.data();
    const std::uint32_t* const added_begin = kept_.added_begin.data();
    const signed_bounds* const widened = kept_.widened.data();
    const auto offset = static_cast<std::uint32_t>(a_count_);
    const bool filtered = input.filtered();
    // The slots in reach of a batch of new slots are gathered first
    // (sequential reads of the strips' sorted keys), each one's widened
    // bounds and row fetched ahead, and tested after, with no branch on the
    // outcome: the random reads of a whole batch overlap (they are most of
    // this step's cost). The new slots are cut into units taken as they come
    // (work_shares.hpp), each finding its pairs apart; the units' pairs are
    // appended in unit order, so the kept list does not depend on the threads.
    constexpr std::size_t batch = 32;
    const std::size_t new_slots = kept_.slots - first_new;
    const std::size_t threads = parts_for(n_, options_.threads, min_boxes_per_part);
    const std::size_t units = units_for(new_slots, threads, min_new_slots_per_unit);
    if (kept_.unit_near.size() < units) {
        kept_.unit_near.resize(units);
        kept_.unit_found.resize(units);
        kept_.unit_flags.resize(units);
    }
    run_units(units, threads, [&](std::size_t unit) {
        const auto [unit_begin, unit_end] = share_of(new_slots, unit, units);
        std::vector<std::uint32_t>& near = kept_.unit_near[unit];
        std::vector<pair_index>& found_pairs = kept_.unit_found[unit];
        std::vector<std::uint8_t>& flags = kept_.unit_flags[unit];
        found_pairs.clear();
        std::size_t near_end[batch];
        const auto consider = [&](std::uint32_t y) {
            __builtin_prefetch(widened + y);
            __builtin_prefetch(order + y);
            near.push_back(y);
        };
        // Where the entries that may reach slot x in strip t start: reach to the left of x's lo.
        const auto from_key = [&](std::uint32_t x, std::uint32_t t, std::uint32_t reach) {
            const std::uint32_t q_lo = q_lo_[x];
            return (t << q_bits) | (q_lo > reach ? q_lo - reach : 0);
        };
        for (std::size_t batch_begin = first_new + unit_begin; batch_begin < first_new + unit_end;
             batch_begin += batch) {
            const std::size_t batch_end = std::min(first_new + unit_end, batch_begin + batch);
            // The first probe of each of the batch's searches, fetched before
            // any search: each is a read at a random place of a strip's keys
            // (and of the visitors' slots), and fetched together they overlap.
            for (std::size_t xs = batch_begin; xs < batch_end; ++xs) {
                const auto x = static_cast<std::uint32_t>(xs);
                const std::uint32_t low = keys[x] >> q_bits;
                for (std::uint32_t t = low; t <= strip_hi_[x]; ++t) {
                    __builtin_prefetch(first_probe(keys + own_begin_[t], keys + own_begin_[t + 1],
                                                   from_key(x, t, kept_.full_reach[t])));
                    if (t == low) {
                        const std::uint32_t* const visits = visit_keys_.data();
                        const std::uint32_t* const v = first_probe(visits + visit_begin_[t], visits + visit_begin_[t + 1],
                                                                   from_key(x, t, kept_.full_reach[t]));
                        __builtin_prefetch(v);
                        __builtin_prefetch(visit_ids_.data() + (v - visits));
                    }
                }
            }
            near.clear();
            for (std::size_t xs = batch_begin; xs < batch_end; ++xs) {
                const auto x = static_cast<std::uint32_t>(xs);
                const std::uint32_t low = keys[x] >> q_bits;
                const std::uint32_t high = strip_hi_[x];
                const std::uint32_t q_hi = q_hi_[x];
                for (std::uint32_t t = low; t <= high; ++t) {
                    const std::uint32_t strip_key = t << q_bits;
                    const std::uint32_t hi_key = strip_key | q_hi;
                    // The full query's entries of strip t: its own, and on x's lowest strip its visitors.
                    {
                        const std::uint32_t lo_key = from_key(x, t, kept_.full_reach[t]);
                        const std::uint32_t* const begin = keys + own_begin_[t];
                        const std::uint32_t* const end = keys + own_begin_[t + 1];
                        for (const std::uint32_t* k = seek(begin, end, lo_key); k != end && *k <= hi_key; ++k) {
                            consider(static_cast<std::uint32_t>(k - keys));
                        }
                        if (t == low) {
                            const std::uint32_t* const vbegin = visit_keys_.data() + visit_begin_[t];
                            const std::uint32_t* const vend = visit_keys_.data() + visit_begin_[t + 1];
                            for (const std::uint32_t* v = seek(vbegin, vend, lo_key); v != vend && *v <= hi_key;
                                 ++v) {
                                consider(visit_ids_[static_cast<std::size_t>(v - visit_keys_.data())]);
                            }
                        }
                    }
                    // The slots added since, in the strip holding the larger of the two lowest strips.
                    {
                        const std::uint64_t lo_key = std::uint64_t{from_key(x, t, kept_.added_reach[t])} << 32;
                        const std::uint64_t hi_entry = (std::uint64_t{hi_key} << 32) | 0xffffffffu;
                        const std::uint64_t* const strip_end = added + added_begin[t + 1];
                        for (const std::uint64_t* e = seek(added + added_begin[t], strip_end, lo_key);
                             e != strip_end && *e <= hi_entry; ++e) {
                            const auto y = static_cast<std::uint32_t>(*e & 0xffffffffu);
                            if (t == std::max(low, keys[y] >> q_bits)) {
                                consider(y);
                            }
                        }
                    }
                }
                near_end[xs - batch_begin] = near.size();
            }
            // First the widened bounds, the sweep's test; and not an empty
            // slot, x itself, a new slot that finds x itself, or one of the
            // same set. With filters, the rows of the pairs that pass have
            // their filters fetched here, to arrive while the others are
            // tested: three random reads a pair, read only for these.
            flags.resize(near.size());
            std::size_t from = 0;
            for (std::size_t xs = batch_begin; xs < batch_end; ++xs) {
                const auto x = static_cast<std::uint32_t>(xs);
                const signed_bounds bx = widened[x];
                const std::uint8_t x_side = side_[x];
                for (std::size_t i = from; i < near_end[xs - batch_begin]; ++i) {
                    const std::uint32_t y = near[i];
                    const signed_bounds& by = widened[y];
                    const bool overlap = (by.v[0] <= -bx.v[2]) & (bx.v[0] <= -by.v[2]) & (by.v[1] <= -bx.v[3]) &
                                         (bx.v[1] <= -by.v[3]);
                    const bool other = (y != x) & !((y >= first_new) & (y < x)) & (order[y] != no_row) &
                                       (self_ || side_[y] != x_side);
                    flags[i] = (overlap & other) ? 1 : 0;
                    if (filtered && flags[i] != 0) {
                        fetch_filters(input, order[y]);
                    }
                }
                from = near_end[xs - batch_begin];
            }
            // Then the filters, as the sweep drops a filtered pair before it
            // keeps it. Each pair is put in the caller's order, as the sweep
            // puts its candidates (flush_candidates).
            from = 0;
            for (std::size_t xs = batch_begin; xs < batch_end; ++xs) {
                const auto x = static_cast<std::uint32_t>(xs);
                const std::size_t at = found_pairs.size();
                found_pairs.resize(at + (near_end[xs - batch_begin] - from));
                pair_index* const out = found_pairs.data() + at;
                std::size_t found = 0;
                const std::uint32_t x_row = order[x];
                const filter_values x_filters = filtered ? filter_of(input, x_row) : filter_values{};
                for (std::size_t i = from; i < near_end[xs - batch_begin]; ++i) {
                    const std::uint32_t y = near[i];
                    const std::uint32_t y_row = order[y];
                    const bool candidate = flags[i] != 0;
                    const bool passes =
                        !filtered || !candidate || filters_pass(x_filters, filter_of(input, y_row)) != 0;
                    const bool swap = self_ ? x_row > y_row : x_row >= offset;
                    out[found] = swap ? pair_index{y, x} : pair_index{x, y};
                    found += (candidate & passes) ? 1u : 0u;
                }
                found_pairs.resize(at + found);
                from = near_end[xs - batch_begin];
            }
        }
    });
    for (std::size_t unit = 0; unit < units; ++unit) {
        kept_.pairs.insert(kept_.pairs.end(), kept_.unit_found[unit].begin(), kept_.unit_found[unit].end());
    }
}

void pair_search::sort_moved_pairs(std::size_t last_a_count, bool any_moved) {
    // Rows that keep their order against each other keep their pairs' order:
    // those pairs are mapped where they lie when the answer is read
    // (answer_by_id); the pairs of moved rows are mapped here and sorted
    // apart with the new ones (moved_pairs), to be merged in then.
    const std::uint32_t b_last = self_ ? 0u : static_cast<std::uint32_t>(last_a_count);
    const std::uint32_t b_now = self_ ? 0u : static_cast<std::uint32_t>(a_count_);
    const std::uint32_t* const now_of = now_of_last_.data();
    if (any_moved) {
        // The moved rows as bits (12.5 kB at 100k rows, in the first-level
        // cache where the bytes were not): every kept pair's second row is
        // looked up at a random place. The kept pairs are read in shares,
        // one a thread: this pass reads all of them for the few thousand of
        // moved rows.
        const std::vector<std::uint8_t>& moved_rows = kept_.row_moved;
        std::vector<std::uint64_t>& bits = kept_.moved_bits;
        bits.assign((moved_rows.size() + 63) / 64, 0);
        for (std::size_t r = 0; r < moved_rows.size(); ++r) {
            bits[r / 64] |= static_cast<std::uint64_t>(moved_rows[r] != 0) << (r % 64);
        }
        const std::size_t parts = parts_for(n_, options_.threads, min_boxes_per_part);
        if (kept_.unit_moved.size() < parts) {
            kept_.unit_moved.resize(parts);
        }
        run_parts(parts, [&](std::size_t share) {
            const auto [begin, end] = share_of(kept_.by_caller.size(), share, parts);
            const tagged_pair* const kept = kept_.by_caller.data();
            const std::uint64_t* const moved = bits.data();
            const auto is_moved = [moved](std::uint32_t row) {
                return static_cast<unsigned>(moved[row / 64] >> (row % 64)) & 1u;
            };
            std::vector<tagged_pair>& found = kept_.unit_moved[share];
            found.clear();
            for (std::size_t j = begin; j < end; ++j) {
                const tagged_pair& p = kept[j];
                if (kept_pairs::is_gap(p)) {
                    continue;
                }
                const std::uint32_t la = p.a;
                const std::uint32_t lb = p.b + b_last;
                if ((is_moved(la) | is_moved(lb)) == 0 || now_of[la] == no_row || now_of[lb] == no_row) {
                    continue;
                }
                std::uint32_t a = now_of[la];
                std::uint32_t b = now_of[lb] - b_now;
                if (self_ && a > b) {
                    // The caller's order of the two changed: the method is
                    // asked the other way round (each tag is one share's).
                    std::swap(a, b);
                    pair_index& kept_pair = kept_.pairs[p.tag];
                    std::swap(kept_pair.a, kept_pair.b);
                }
                found.push_back(tagged_pair{a, b, p.tag});
            }
        });
        for (std::size_t share = 0; share < parts; ++share) {
            kept_.moved_pairs.insert(kept_.moved_pairs.end(), kept_.unit_moved[share].begin(),
                                     kept_.unit_moved[share].end());
        }
    }
    // Sorted by a sort that costs passes over these few pairs, not over the
    // rows (sort/few_pairs_sort.hpp): the answer's sort counted a table the
    // size of the rows for a few thousand pairs.
    sort_few_pairs(kept_.moved_pairs, kept_.moved_order);
    kept_.remap_pending = true;
    kept_.remap_any_moved = any_moved;
    kept_.remap_last_a = last_a_count;
}

}  // namespace obbsat::detail
