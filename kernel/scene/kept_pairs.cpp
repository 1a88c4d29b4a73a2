// pair_finder's kept candidates (kept_pairs.hpp): the policy that keeps them, the refreshed records, the kept list.
#include "scene/pair_search.hpp"

#include "dispatch/backend_registry.hpp"
#include "scene/search_common.hpp"
#include "sort/pair_sort.hpp"
#include "support/fetch_ahead.hpp"
#include "support/work_shares.hpp"

#include <obbsat/method.hpp>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <vector>

namespace obbsat::detail {

namespace {

/// Writes `count` 32-byte records from `from` to `to` (both 16-byte aligned)
/// with non-temporal stores where the CPU has them: lines written whole are
/// not read in first. finish_streams orders them before what follows.
template <class Record>
void stream_records(const Record* from, std::size_t count, Record* to) {
    static_assert(sizeof(Record) == 32, "two 16-byte stores a record");
#if defined(__SSE2__)
    for (std::size_t k = 0; k < count; ++k) {
        _mm_stream_ps(to[k].v, _mm_load_ps(from[k].v));
        _mm_stream_ps(to[k].v + 4, _mm_load_ps(from[k].v + 4));
    }
#else
    std::memcpy(to, from, count * sizeof(Record));
#endif
}

void finish_streams() {
#if defined(__SSE2__)
    _mm_sfence();
#endif
}

/// The record of the empty slot `slot` (refresh_records).
void empty_slot_record(store_kind kind, std::size_t slot, float* v) {
    const float x = std::ldexp(1.0f, 40) + static_cast<float>(slot % (std::size_t{1} << 20)) * std::ldexp(1.0f, 20);
    const float y = std::ldexp(1.0f, 40);
    const float h = std::ldexp(1.0f, 18);
    if (kind == store_kind::poses) {
        const float pose[8] = {x, y, h, h, 1.0f, 0.0f, 0.0f, 0.0f};
        std::memcpy(v, pose, sizeof pose);
    } else {
        const float quad[8] = {x - h, y + h, x + h, y + h, x + h, y - h, x - h, y - h};
        std::memcpy(v, quad, sizeof quad);
    }
}

}  // namespace

const std::vector<pair_index>& pair_search::collect(const query_input& input) {
    // The ids are matched first: a duplicate id is refused before anything changes.
    // The call is timed whole, the id match with it: keep_costs weighs what
    // keeping costs against a plain query (kept_costs.hpp).
    const auto start = clock_type::now();
    match_ids(input);
    set_query(input);
    commit_ids(input);
    try {
        const std::vector<pair_index>& found = collect_matched(input);
        weigh_call(seconds_since(start));
        return found;
    } catch (...) {
        abandon_kept();
        throw;
    }
}

void pair_search::weigh_call(double seconds) {
    const double cost = call_cost_ != nullptr ? call_cost_(stats_, seconds) : seconds;
    keep_costs& costs = kept_.costs;
    switch (call_path_) {
        case call_path::first:
            costs.new_scene(cost);
            break;
        case call_path::plain:
            costs.plain(cost);
            break;
        case call_path::judged:
            // The last plain query weighing a cycle that did not pay: the rest begins with it.
            stats_.kept_resting = costs.judge(cost);
            break;
        case call_path::kept:
            costs.kept(cost);
            break;
        case call_path::carried:
            costs.carried(cost);
            break;
    }
}

const std::vector<pair_index>& pair_search::collect_matched(const query_input& input) {
    const std::size_t parts = parts_for(n_, options_.threads, min_boxes_per_part);
    call_path_ = call_path::plain;
    if (kept_.ready && !(ids_followed_ ? follow_filters(input) : kept_filters_.same_as(input))) {
        // Kept candidates hold only the pairs their filters let through
        // (kept_filters.hpp): compared by id when the rows carry ids (a row
        // whose filters changed is then a new row), else by position.
        kept_.ready = false;
    }
    probe_carried_ = false;
    if (rows_changed_ && (kept_.ready || kept_.paused)) {
        // Only the kept candidates' carry and a paused probe read the last
        // rows' rows now (a plain query, one that rests say, does not).
        map_last_rows();
    }
    // The kept candidates serve rows matched by position (the last call's
    // rows, none moved since the full query), or rows matched by id, carried
    // over to this call's rows (kept_changes.cpp).
    const bool by_position = !kept_.by_id && !rows_changed_ && same_scene_as_last();
    // Double rows are not carried over rows that came and went (a gone row's
    // slot holds a far float box, not a double one): such a call is a full query.
    if (kept_.ready && n_ >= 2 && (by_position || (ids_followed_ && !input.doubles && absorb_changes(input)))) {
        const auto start = clock_type::now();
        // An exact method calls a pair colliding only if the two rectangles
        // share a point, so only if their bounds overlap (the bounds hold the
        // rectangles): its verdict on a kept pair whose bounds do not overlap
        // is false, the answer of leaving the pair out. It tests every kept
        // pair, which costs less than the filter, and needs no bounds of this
        // call beyond the check that they fit. Kept pairs of rows gone since
        // (kept_changes.cpp) never answer: their verdicts are cleared
        // (kept_pairs::dropped), and the filter drops them anyway.
        const bool exact = guarantee_of(options_.test) == method_guarantee::exact;
        const bool fits = refresh_records(input, parts, !exact);
        stats_.bounds_seconds += seconds_since(start);
        if (fits) {
            ++kept_.calls;
            stats_.reused_order = true;
            stats_.reused_candidates = true;
            stats_.kept_candidates = kept_.by_caller.size() - kept_.gap_entries;
            stats_.strips = grid_.strips;
            stats_.visits = visit_keys_.size() - 1;
            used_parts_ = parts;
            call_path_ = call_path::carried;
            if (kept_.remap_pending) {
                test_kept(parts, exact, 1);
                answer_by_id();
                kept_filters_.take(input);  // the kept candidates' filters, in this call's rows
            } else {
                test_kept(parts, exact, parts);
                answer_from_kept(parts);
            }
            return pairs_;
        }
        if (kept_.calls == 0) {
            // A miss: the kept candidates answered no call, so keeping cost
            // a full query that keeps and a refresh for nothing. Full
            // queries keep nothing until the motion is calm again.
            kept_.pause();
        }
    }
    if (kept_.by_id || rows_changed_) {
        // The order's slots are not this call's rows: the full query sorts
        // anew, on a grid of its own; a paused one probes the motion against
        // the last call's bounds carried over to these rows.
        have_order_ = false;
        if (rows_changed_ && kept_.paused && kept_.probe_ready && kept_.last.size() == now_of_last_.size()) {
            carry_probe_over();
            probe_carried_ = true;
        }
    }
    // The kept candidates served some calls and serve no more: a cycle of
    // keeping ended (kept_costs.hpp).
    const bool cycle_ended = kept_.ready && kept_.calls > 0;
    // A full query that keeps its candidates. The margin follows the motion:
    // kept candidates that served only a few calls widen the next ones, and
    // candidates that outlived many calls narrow them.
    if (kept_.ready && kept_.margin > 0.0f) {
        if (kept_.calls < 4) {
            kept_.margin_share = std::min(kept_.margin_share * 2, 1.0 / 2);
        } else if (kept_.calls > 64) {
            kept_.margin_share = std::max(kept_.margin_share / 2, 1.0 / 256);
        }
    }
    kept_.ready = false;
    kept_.calls = 0;
    if (!same_scene_as_last() && !ids_followed_) {
        // The first call on a scene knows no motion yet, and pairs kept from
        // bounds not widened would serve no call after a move: it answers
        // as a plain query, and the next call keeps the pairs of widened
        // bounds. Rows matched by id to the last call's are the same scene.
        kept_.resume();
        call_path_ = call_path::first;
        return answer_plainly(input);
    }
    if (kept_.paused) {
        // Keeping is paused: a plain query, whose bounds pass probes the
        // motion (probe_motion). After calm_calls_to_resume calm calls in a
        // row the next full query keeps again.
        kept_.probing = kept_.probe_skip == 0;
        if (!kept_.probing) {
            --kept_.probe_skip;
            kept_.probe_ready = false;  // the next probe has no last bounds to compare with
        }
        answer_plainly(input);
        stats_.kept_paused = true;
        if (kept_.calm_calls >= calm_calls_to_resume) {
            kept_.resume();
        }
        return pairs_;
    }
    // Below min_boxes_weighed rows a call takes so little time that the
    // clock's noise would decide: such a finder keeps, as it always did.
    const bool weighs = call_cost_ != nullptr || n_ >= min_boxes_weighed;
    if (weighs && cycle_ended && !kept_.costs.clearly_pays()) {
        kept_.costs.start_judging();
    }
    if (weighs && kept_.costs.judging()) {
        // Whether the cycle that ended paid is not clear: this call and the
        // next are plain queries, timed, and the cycle weighed against them
        // (weigh_call); then a full query keeps again unless it cost more.
        call_path_ = call_path::judged;
        return answer_plainly(input);
    }
    if (weighs && kept_.costs.rest_call()) {
        // The last cycle cost more per call than a plain query: plain
        // queries answer until the rest is over, then a full query keeps
        // again and its cycle is weighed anew.
        answer_plainly(input);
        stats_.kept_resting = true;
        return pairs_;
    }
    kept_.margin = static_cast<float>(kept_.margin_share);
    kept_.keep = true;
    try {
        run(input, pair_chunk_sink{});
    } catch (...) {
        kept_.keep = false;
        throw;
    }
    kept_.keep = false;
    if (used_parts_ == 0) {
        pairs_.clear();
        return pairs_;
    }
    bool over_budget = false;
    for (std::size_t i = 0; i < used_parts_; ++i) {
        over_budget |= parts_[i].keep.over_budget;
    }
    if (over_budget) {
        // The widened bounds met too many others: this call answers as a
        // plain query, and the next full query widens less.
        for (std::size_t i = 0; i < used_parts_; ++i) {
            std::vector<pair_index>().swap(parts_[i].keep.captured);
        }
        kept_.margin_share = std::max(kept_.margin_share / 4, 1.0 / 256);
        return answer_plainly(input);
    }
    keep_candidates(used_parts_);
    kept_filters_.take(input);
    kept_.ready = true;
    call_path_ = call_path::kept;
    test_kept(used_parts_, false, used_parts_);
    kept_.last_candidates = stats_.candidates;
    answer_from_kept(used_parts_);
    return pairs_;
}

bool pair_search::refresh_records(const query_input& input, std::size_t parts, bool keep_bounds) {
    // The records in the kept order with this call's rows; every rectangle's
    // bounds must lie inside its widened bounds. A row that fails its check
    // makes this false too: the full query names it.
    const bounds_fn bounds = kernels_for(ran_).bounds;
    const bool check_a = !input.a_checked;
    const bool check_b = !input.b_checked;
    std::vector<unsigned char> fits(parts, 1);
    const std::size_t slots = slots_;
    if (input.doubles) {
        records64_.resize(slots);  // the last full query may have read float rows
    }
    const bool stream = slots * sizeof(record) > store_bytes_from_dram;
    run_parts(parts, [&](std::size_t share) {
        const auto [begin, end] = share_of(slots, share, parts);
        constexpr std::size_t ahead = random_rows_ahead;
        bounds_run b;
        bool ok = true;
        // Plain locals: the record stores may alias anything the loop reads.
        const query_input in = input;
        const std::uint32_t* const order = order_.data();
        record* const records = records_.data();
        // Records read from DRAM by the test are written past the cache: a
        // run is staged here, its bounds computed from the stage, and then
        // streamed out, so no old record is read in before it is overwritten.
        alignas(64) record stage[bounds_run::size];
        for (std::size_t run_begin = begin; run_begin < end && ok; run_begin += bounds_run::size) {
            const std::size_t run_end = std::min(end, run_begin + bounds_run::size);
            record* const into = stream ? stage : records + run_begin;
            for (std::size_t k = run_begin; k < run_end; ++k) {
                if (k + ahead < end && order[k + ahead] != no_row) {
                    fetch_into_l2(record_at(in, order[k + ahead]));
                }
                const std::uint32_t id = order[k];
                if (id == no_row) {
                    // The slot of a gone row (kept_changes.cpp): its pairs are
                    // tested with the others and their verdicts dropped, so
                    // it holds a valid box far from everything, apart from
                    // every other gone row's (a square of half side 2^18 at
                    // x = 2^40 + (k mod 2^20) 2^20, y = 2^40, all exact).
                    empty_slot_record(kind_, k, into[k - run_begin].v);
                    continue;
                }
                if (id < in.a_count ? check_a : check_b) {
                    ok &= valid_row(in.kind, record_at(in, id));
                }
                copy_row(in, id, into[k - run_begin].v);
                if (in.doubles) {
                    copy_double_row(in, id, records64_[k].v);  // what the double method reads
                }
            }
            bounds(kind_, into[0].v, run_end - run_begin, b.lo_x, b.lo_y, b.hi_x, b.hi_y);
            if (stream) {
                stream_records(stage, run_end - run_begin, records + run_begin);
            }
            for (std::size_t k = run_begin; k < run_end; ++k) {
                const std::size_t r = k - run_begin;
                const unsigned inside = static_cast<unsigned>(b.lo_x[r] >= in_lo_x_[k]) &
                                        static_cast<unsigned>(b.lo_y[r] >= in_lo_y_[k]) &
                                        static_cast<unsigned>(b.hi_x[r] <= in_hi_x_[k]) &
                                        static_cast<unsigned>(b.hi_y[r] <= in_hi_y_[k]);
                ok &= (inside | static_cast<unsigned>(order[k] == no_row)) != 0;
            }
            if (keep_bounds) {
                for (std::size_t k = run_begin; k < run_end; ++k) {
                    kept_.now[k] = signed_bounds_of(b, k - run_begin);
                }
                if (kept_.empty_slots > 0) {
                    // An empty slot's bounds meet none: its kept pairs are never taken.
                    const float none = std::numeric_limits<float>::quiet_NaN();
                    for (std::size_t k = run_begin; k < run_end; ++k) {
                        if (order[k] == no_row) {
                            kept_.now[k] = signed_bounds{{none, none, none, none}};
                        }
                    }
                }
            }
        }
        if (stream) {
            finish_streams();
        }
        fits[share] = ok ? 1 : 0;
    });
    return std::find(fits.begin(), fits.end(), 0) == fits.end();
}

void pair_search::keep_candidates(std::size_t parts) {
    // The parts' candidates one after the other, in the sweep's order, and
    // each one's pair in the caller's indices tagged with its position.
    const auto start = clock_type::now();
    std::vector<std::size_t> offsets(parts + 1, 0);
    for (std::size_t i = 0; i < parts; ++i) {
        offsets[i + 1] = offsets[i] + parts_[i].keep.captured.size();
    }
    kept_.pairs.resize(offsets[parts]);
    std::vector<pair_source<tagged_pair>> sources;
    run_parts(parts, [&](std::size_t share) {
        part& p = parts_[share];
        std::copy(p.keep.captured.begin(), p.keep.captured.end(),
                  kept_.pairs.begin() + static_cast<std::ptrdiff_t>(offsets[share]));
        p.keep.tagged.resize(p.keep.captured.size());
        for (std::size_t i = 0; i < p.keep.captured.size(); ++i) {
            const pair_index caller = caller_pair(p.keep.captured[i]);
            p.keep.tagged[i] = tagged_pair{caller.a, caller.b, static_cast<std::uint32_t>(offsets[share] + i)};
        }
        p.keep.captured.clear();
    });
    for (std::size_t i = 0; i < parts; ++i) {
        sources.push_back({{parts_[i].keep.tagged.data(), parts_[i].keep.tagged.size()}});
    }
    if (kept_.tag_scratch.size() < parts) {
        kept_.tag_scratch.resize(parts);
    }
    sort_pairs(sources, self_ ? n_ : a_count_, kept_.by_caller, kept_.tag_scratch);
    for (std::size_t i = 0; i < parts; ++i) {
        parts_[i].keep.tagged.clear();
    }
    stats_.kept_candidates = kept_.pairs.size();
    kept_.gaps.clear();
    kept_.gap_entries = 0;
    kept_.answer_parts = 0;
    kept_.dropped.clear();
    stats_.output_seconds += seconds_since(start);
}

}  // namespace obbsat::detail
