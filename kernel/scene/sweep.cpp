// Steps 4 and 5 of the scene query (pair_search.hpp): strips swept, candidates tested, pairs streamed.
#include "scene/pair_search.hpp"

#include "dispatch/backend_registry.hpp"
#include "dispatch/double_kernel_table.hpp"
#include "dispatch/strip_view.hpp"
#include "scene/search_common.hpp"
#include "support/work_shares.hpp"

#include <algorithm>
#include <atomic>
#include <exception>
#include <functional>
#include <limits>
#include <mutex>
#include <vector>

namespace obbsat::detail {

void pair_search::test_pairs(part& p, const pair_index* pairs, std::size_t count, std::uint8_t* verdicts) const {
    const kernel_table& table = kernels_for(ran_);
    const auto kernel_start = clock_type::now();
    if (doubles_) {
        // The double method on the double rows in the query's order: the
        // backend's double lanes, or the scalar references on the scalar backend.
        const double* rows = records64_.data()->v;
        const double_kernel_table* lanes = double_kind_ == store_kind::poses ? double_kernels_for(ran_) : nullptr;
        const corner64_kernel_table* corner_lanes =
            double_kind_ == store_kind::corners ? corner64_kernels_for(ran_) : nullptr;
        if (corner_lanes != nullptr) {
            const rect64_indexed_fn kernel =
                options_.test == method::exact ? corner_lanes->exact : corner_lanes->conservative;
            p.slow_path += kernel(reinterpret_cast<const rect64*>(rows), pairs, count, verdicts);
        } else if (lanes != nullptr) {
            const pose64_indexed_fn kernel = options_.test == method::exact          ? lanes->exact
                                             : options_.test == method::conservative ? lanes->conservative
                                                                                     : lanes->local;
            p.slow_path += kernel(rows, pairs, count, verdicts);
        } else if (double_kind_ == store_kind::poses) {
            p.slow_path += scalar_pose64_indexed(options_.test, rows, pairs, count, verdicts);
        } else {
            p.slow_path += scalar_rect64_indexed(options_.test, rows, pairs, count, verdicts);
        }
    } else if (kind_ == store_kind::poses) {
        p.slow_path += table.on_poses(options_.test).indexed_near(records_.data()->v, pairs, count, verdicts);
    } else {
        p.slow_path += table.of(options_.test)
                           .indexed_records_near(reinterpret_cast<const rect*>(records_.data()), pairs, count,
                                                 verdicts);
    }
    p.kernel_seconds += seconds_since(kernel_start);
    p.tested += count;
}

void pair_search::test_candidates(part& p, std::size_t count) const {
    test_pairs(p, p.candidates.data(), count, p.verdicts.data());
}

void pair_search::flush_candidates(part& p) const {
    const std::size_t count = p.candidate_count;
    if (count == 0) {
        return;
    }
    // Methods need not be symmetric (local works in the first rectangle's
    // frame; sat4 on a degenerate quad may differ), so each candidate is put
    // in the order the caller's pair has: within one store the smaller index
    // first, across two the first store's rectangle first.
    const auto offset = static_cast<std::uint32_t>(a_count_);
    pair_index* const candidates = p.candidates.data();
    // Which way round is as random as the caller's indices: a mask, not a
    // branch that would mispredict on every other candidate.
    for (std::size_t i = 0; i < count; ++i) {
        const std::uint32_t first = candidates[i].a;
        const std::uint32_t second = candidates[i].b;
        const std::uint32_t x = order_[first];
        const std::uint32_t y = order_[second];
        const bool swap = self_ ? x > y : x >= offset;
        const std::uint32_t flip = (first ^ second) & (0u - static_cast<std::uint32_t>(swap));
        candidates[i].a = first ^ flip;
        candidates[i].b = second ^ flip;
    }
    if (kept_.keep) {
        // Past the budget of all parts a part keeps nothing more: the call
        // then answers as a plain query (collect). Whether any part sees the
        // budget passed depends only on the sum of the parts' candidates.
        if (kept_.captured_all.fetch_add(count, std::memory_order_relaxed) + count <= kept_.capture_budget) {
            p.keep.captured.insert(p.keep.captured.end(), candidates, candidates + count);
        } else {
            p.keep.over_budget = true;
        }
        p.candidate_count = 0;
        return;
    }
    test_candidates(p, count);
    pair_index* out = p.found.room(count);
    std::size_t kept = 0;
    for (std::size_t i = 0; i < count; ++i) {
        out[kept] = caller_pair(candidates[i]);
        kept += p.verdicts[i] != 0 ? 1u : 0u;
    }
    p.found.add(kept);
    p.candidate_count = 0;
}

static_assert(candidate_block / 4 >= strip_padding,
              "a block left untested keeps room enough for the sweep kernel to go on (strip_view.hpp)");

std::size_t pair_search::drop_filtered(pair_index* candidates, std::size_t count) const {
    // Kept or not as the filters say, with no branch on it: each candidate
    // is written where the next kept one goes.
    const filter_values* const filters = filters_.data();
    std::size_t kept = 0;
    for (std::size_t i = 0; i < count; ++i) {
        const pair_index c = candidates[i];
        candidates[kept] = c;
        kept += filters_pass(filters[c.a], filters[c.b]);
    }
    return kept;
}

void pair_search::make_strip_room(part& p, std::size_t m) {
    const std::size_t room = m + strip_padding;
    if (p.q_lo.size() < room) {
        p.id.resize(room);
        for (auto* v : {&p.q_lo, &p.q_hi, &p.starts, &p.store, &p.lo_x, &p.lo_y, &p.hi_x, &p.hi_y}) {
            v->resize(room);
        }
    }
}

void pair_search::sweep_strip(std::uint32_t strip, part& p, const flush_callback& after_flush) const {
    // Merge the rectangles starting in this strip with its visitors, by
    // quantized lo_x (a rectangle before a visitor on equal keys).
    const std::size_t own_begin = own_begin_[strip];
    const std::size_t own_end = own_begin_[strip + 1];
    const std::size_t visit_begin = visit_begin_[strip];
    const std::size_t visit_end = visit_begin_[strip + 1];
    const std::size_t m = (own_end - own_begin) + (visit_end - visit_begin);
    if (m < 2) {
        return;
    }
    make_strip_room(p, m);
    float* const q_lo = p.q_lo.data();
    float* const q_hi = p.q_hi.data();
    std::int32_t* const ids = p.id.data();
    float* const starts = p.starts.data();
    float* const store = p.store.data();
    float* const lo_x = p.lo_x.data();
    float* const lo_y = p.lo_y.data();
    float* const hi_x = p.hi_x.data();
    float* const hi_y = p.hi_y.data();
    const std::uint32_t* const visit_keys = visit_keys_.data();
    const std::uint32_t* const visit_ids = visit_ids_.data();
    const std::uint32_t q_mask = grid_.q_max;
    // Which side comes next is as random as the scene, so the merge selects
    // without branching: a side that has run out reads as the largest key,
    // and reads stay in bounds (the last rectangle, the visit after the last).
    constexpr std::uint32_t none = std::numeric_limits<std::uint32_t>::max();
    const std::size_t last = n_ - 1;
    std::size_t o = own_begin;
    std::size_t v = visit_begin;
    for (std::size_t e = 0; e < m; ++e) {
        const std::uint32_t own_q = o < own_end ? q_lo_[std::min(o, last)] : none;
        const std::uint32_t visit_q = v < visit_end ? (visit_keys[v] & q_mask) : none;
        const std::size_t take_own = own_q <= visit_q ? 1u : 0u;
        const std::size_t own_mask = 0u - take_own;
        const std::size_t k = (o & own_mask) | (visit_ids[v] & ~own_mask);
        o += take_own;
        v += 1u - take_own;
        q_lo[e] = static_cast<float>(q_lo_[k]);
        q_hi[e] = static_cast<float>(q_hi_[k]);
        ids[e] = static_cast<std::int32_t>(k);
        starts[e] = static_cast<float>(take_own);
        store[e] = static_cast<float>(side_[k]);
        lo_x[e] = in_lo_x_[k];
        lo_y[e] = in_lo_y_[k];
        hi_x[e] = in_hi_x_[k];
        hi_y[e] = in_hi_y_[k];
    }
    sweep_merged(p, m, after_flush);
}

void pair_search::sweep_merged(part& p, std::size_t m, const flush_callback& after_flush) const {
    for (std::size_t e = m; e < m + strip_padding; ++e) {
        p.q_lo[e] = std::numeric_limits<float>::infinity();
        p.q_hi[e] = 0;
        p.id[e] = 0;
        p.starts[e] = -1;  // never at least an entry's starts_needed (0 or 1): never taken
        p.store[e] = 0;
        p.lo_x[e] = std::numeric_limits<float>::infinity();
        p.lo_y[e] = 0;
        p.hi_x[e] = 0;
        p.hi_y[e] = 0;
    }
    const strip_view view{p.q_lo.data(), p.q_hi.data(), p.id.data(),   p.starts.data(), p.store.data(),
                          p.lo_x.data(), p.lo_y.data(), p.hi_x.data(), p.hi_y.data(),   m, !self_};
    const strip_sweep_fn sweep_kernel = kernels_for(ran_).strip_sweep;
    sweep_cursor cursor;
    while (cursor.e + 1 < m) {
        const std::size_t before = p.candidate_count;
        const std::size_t found = sweep_kernel(view, cursor, p.candidates.data() + before, candidate_block - before);
        p.candidate_count += filtered_ ? drop_filtered(p.candidates.data() + before, found) : found;
        // The kernel stops inside the strip only when fewer than a vector's
        // width of slots are left; with filters it may have stopped there and
        // then dropped many, so the block is tested only once it is at least
        // three quarters full, and the sweep goes on filling it otherwise.
        if (cursor.e + 1 < m && candidate_block - p.candidate_count < candidate_block / 4) {
            // A full block inside the strip: tested now, and the pairs found
            // handed on, however many the strip holds.
            flush_candidates(p);
            if (!after_flush()) {
                return;
            }
        }
    }
}

void pair_search::start_part(part& p, std::uint32_t first_strip, std::uint32_t end_strip) {
    p.first_strip = first_strip;
    p.end_strip = end_strip;
    p.candidate_count = 0;
    p.found.clear();
    p.keep.captured.clear();
    p.keep.over_budget = false;
    p.tested = 0;
    p.slow_path = 0;
    p.kernel_seconds = 0;
}

void pair_search::cut_strips_into_units(std::size_t units, std::size_t entries, const std::uint32_t* visits_before) {
    const std::uint32_t strips = grid_.strips;
    std::uint32_t s = 0;
    for (std::size_t i = 0; i < units; ++i) {
        const std::uint32_t first = s;
        const std::size_t target = entries * (i + 1) / units;
        while (s < strips &&
               (i + 1 == units || own_begin_[s] + (visits_before != nullptr ? visits_before[s] : 0u) < target)) {
            ++s;
        }
        start_part(parts_[i], first, s);
    }
}

void pair_search::sweep(std::size_t parts, const pair_chunk_sink* emit) {
    // The strips are cut into units of about the same number of entries, a
    // few per thread, each taken by the next thread free (work_shares.hpp):
    // a thread slowed by other work on its core sweeps fewer. Each unit
    // keeps what it finds (parts_[unit]), so nothing depends on which thread
    // swept it. A query that keeps its candidates (pair_finder) keeps them
    // per thread's share (kept_share), one unit a share.
    const std::size_t entries = n_ + stats_.visits;
    const std::size_t units = kept_.keep ? parts : units_for(entries, parts, min_entries_per_unit);
    if (parts_.size() < units) {
        parts_.resize(units);
    }
    cut_strips_into_units(units, entries, visit_begin_.data());
    kept_.capture_budget = kept_.margin > 0.0f
                               ? kept_budget_factor * kept_.last_candidates + n_ + units * candidate_block
                               : std::numeric_limits<std::size_t>::max();
    kept_.captured_all.store(0, std::memory_order_relaxed);
    sweep_units(units, parts, emit, [this](part& p, const flush_callback& after_flush, const std::atomic<bool>& failed) {
        for (std::uint32_t strip = p.first_strip; strip < p.end_strip && !failed.load(); ++strip) {
            sweep_strip(strip, p, after_flush);
        }
    });
}

void pair_search::sweep_units(std::size_t units, std::size_t parts, const pair_chunk_sink* emit,
                              const unit_sweep& sweep_unit) {
    used_parts_ = units;
    std::mutex emit_mutex;
    std::vector<std::exception_ptr> failures(units);
    std::atomic<bool> failed{false};
    run_units(units, parts, [&](std::size_t index) {
        part& p = parts_[index];
        try {
            // Each unit sizes its own blocks, on the thread that sweeps it, not the caller for all before.
            if (p.candidates.size() < candidate_block) {
                p.candidates.resize(candidate_block);
                p.verdicts.resize(candidate_block);
            }
            // Pairs are found only by a flush, at most candidate_block at a
            // time: handing them over once a flush may not fit under
            // emit_block keeps every chunk, and what a part holds, within it.
            const auto hand_over = [&](bool all) {
                if (emit != nullptr && (all || p.found.size() > emit_block - candidate_block) && !p.found.empty()) {
                    const std::lock_guard<std::mutex> lock(emit_mutex);
                    if (!failed.load()) {
                        for (const pair_span<pair_index>& span : p.found.spans()) {
                            (*emit)(span.data, span.size);
                        }
                    }
                    p.found.clear();
                }
            };
            const flush_callback after_flush = [&] {
                hand_over(false);
                return !failed.load();
            };
            sweep_unit(p, after_flush, failed);
            flush_candidates(p);
            hand_over(true);
        } catch (...) {
            failures[index] = std::current_exception();
            failed.store(true);
        }
    });
    for (const std::exception_ptr& failure : failures) {
        if (failure) {
            std::rethrow_exception(failure);
        }
    }
    for (std::size_t i = 0; i < units; ++i) {
        stats_.candidates += parts_[i].tested;
        stats_.slow_path_pairs += parts_[i].slow_path;
        stats_.kernel_seconds += parts_[i].kernel_seconds;
    }
}

}  // namespace obbsat::detail
