// Steps 2 to 5 of the scene query (pair_search.hpp) strip by strip, for a
// plain float query on one thread: each strip's records copied into the
// query's order, their bounds, their visits to the strips above, the merge
// with the strip's own visitors and the sweep, in one go while the strip's
// entries are in the cache. The steps taken one at a time write every
// rectangle's sweep bounds to arrays of the whole scene (records_copy.cpp)
// and read them back in each strip's merge (sweep.cpp), visitors at random;
// here they pass through two buffers of a strip each (strip_entries).
#include "scene/pair_search.hpp"

#include "dispatch/backend_registry.hpp"
#include "scene/search_common.hpp"
#include "sort/radix_sort.hpp"
#include "support/fetch_ahead.hpp"

#include <algorithm>
#include <limits>
#include <new>
#include <numeric>
#include <utility>

namespace obbsat::detail {

void pair_search::strip_entries::make_room(std::size_t count) {
    if (id.size() < count) {
        // Grown with room to spare: the next strips are about as large.
        const std::size_t size = std::max(count, 2 * id.size());
        for (auto* v : {&q_lo, &q_hi, &id}) {
            v->resize(size);
        }
        for (auto* v : {&store, &lo_x, &lo_y, &hi_x, &hi_y}) {
            v->resize(size);
        }
    }
}

void pair_search::strip_entries::take(std::size_t to, const strip_entries& from, std::size_t at) {
    q_lo[to] = from.q_lo[at];
    q_hi[to] = from.q_hi[at];
    id[to] = from.id[at];
    store[to] = from.store[at];
    lo_x[to] = from.lo_x[at];
    lo_y[to] = from.lo_y[at];
    hi_x[to] = from.hi_x[at];
    hi_y[to] = from.hi_y[at];
}

void pair_search::strip_entries::sort_visitors() {
    // Rare (a strip with visitors from more than one strip below, or rows
    // changed while the query read them): sorted through a copy.
    const std::size_t first = own;
    std::vector<std::uint32_t> by_q(visitors);
    std::iota(by_q.begin(), by_q.end(), static_cast<std::uint32_t>(first));
    std::stable_sort(by_q.begin(), by_q.end(), [this](std::uint32_t x, std::uint32_t y) { return q_lo[x] < q_lo[y]; });
    strip_entries sorted;
    sorted.make_room(visitors);
    for (std::size_t i = 0; i < visitors; ++i) {
        sorted.take(i, *this, by_q[i]);
    }
    for (std::size_t i = 0; i < visitors; ++i) {
        take(first + i, sorted, i);
    }
}

bool pair_search::far_visit::later(const far_visit& x, const far_visit& y) {
    return x.strip != y.strip ? x.strip > y.strip : x.q_lo != y.q_lo ? x.q_lo > y.q_lo : x.id > y.id;
}

void pair_search::far_visit::put(strip_entries& to, std::size_t at) const {
    to.q_lo[at] = q_lo;
    to.q_hi[at] = q_hi;
    to.id[at] = id;
    to.store[at] = store;
    to.lo_x[at] = lo_x;
    to.lo_y[at] = lo_y;
    to.hi_x[at] = hi_x;
    to.hi_y[at] = hi_y;
}

std::size_t pair_search::copy_own_entries(const query_input& input, std::uint32_t strip, strip_entries& here) {
    const std::size_t own_first = own_begin_[strip];
    const std::size_t own = here.own;
    const bounds_fn bounds = kernels_for(ran_).bounds;
    const double y_low = grid_.y_low, y_scale = grid_.y_scale, x_low = grid_.x_low, x_scale = grid_.x_scale;
    const std::uint32_t q_top = grid_.q_max, strip_top = grid_.strips - 1;
    const auto second_store = static_cast<std::uint32_t>(self_ ? n_ : a_count_);
    if (climbing_.size() < own + 1) {
        climbing_.resize(std::max(own + 1, 2 * climbing_.size()));
    }
    std::size_t near = 0;
    for (std::size_t run = 0; run < own; run += bounds_run::size) {
        const std::size_t run_end = std::min(own, run + bounds_run::size);
        for (std::size_t i = run; i < run_end; ++i) {
            const std::size_t k = own_first + i;
            if (k + random_rows_ahead < n_) {
                fetch_into_l2(record_at(input, order_[k + random_rows_ahead]));
            }
            ::new (static_cast<void*>(&records_[k])) record;  // its memory may have held the sort's words
            copy_row(input, order_[k], records_[k].v);
        }
        if (filtered_) {
            for (std::size_t i = run; i < run_end; ++i) {
                filters_[own_first + i] = filter_of(input, order_[own_first + i]);
            }
        }
        bounds_run b;
        bounds(kind_, records_[own_first + run].v, run_end - run, b.lo_x, b.lo_y, b.hi_x, b.hi_y);
        // The grid's maps on locals and pointers that alias nothing, as in
        // store_sweep_bounds, so that the loop takes no branch and reads
        // nothing again after each store.
        const std::size_t count = run_end - run;
        std::uint32_t* __restrict const q_lo = here.q_lo.data() + run;
        std::uint32_t* __restrict const q_hi = here.q_hi.data() + run;
        std::uint32_t* __restrict const ids = here.id.data() + run;
        float* __restrict const store = here.store.data() + run;
        float* __restrict const lo_x = here.lo_x.data() + run;
        float* __restrict const lo_y = here.lo_y.data() + run;
        float* __restrict const hi_x = here.hi_x.data() + run;
        float* __restrict const hi_y = here.hi_y.data() + run;
        const std::uint32_t* __restrict const rows = order_.data() + own_first + run;
        alignas(64) std::uint32_t high[bounds_run::size];
        for (std::size_t r = 0; r < count; ++r) {
            q_lo[r] = strip_grid::clamped_floor((static_cast<double>(b.lo_x[r]) - x_low) * x_scale, q_top);
            q_hi[r] = strip_grid::clamped_floor((static_cast<double>(b.hi_x[r]) - x_low) * x_scale, q_top);
            high[r] = strip_grid::clamped_floor((static_cast<double>(b.hi_y[r]) - y_low) * y_scale, strip_top);
            ids[r] = static_cast<std::uint32_t>(own_first + run + r);
            store[r] = rows[r] >= second_store ? 1.0f : 0.0f;
            lo_x[r] = b.lo_x[r];
            lo_y[r] = b.lo_y[r];
            hi_x[r] = b.hi_x[r];
            hi_y[r] = b.hi_y[r];
        }
        // Whether a rectangle visits the strip above is as random as the
        // scene: each one writes itself to the next slot, which the next
        // visitor overwrites if this one was none (visits.cpp). A highest
        // strip below this one (rows changed between the order's read and
        // this one) is taken as this one: no visit.
        std::uint32_t* __restrict const climbing = climbing_.data();
        for (std::size_t r = 0; r < count; ++r) {
            const std::uint32_t top = std::max(high[r], strip);
            climbing[near] = static_cast<std::uint32_t>(run + r);
            near += top != strip ? 1u : 0u;
            if (top > strip + 1) {
                far_visits_.push_back(far_visit{strip + 2, top, q_lo[r], q_hi[r], ids[r], store[r], lo_x[r], lo_y[r],
                                                hi_x[r], hi_y[r]});
                std::push_heap(far_visits_.begin(), far_visits_.end(), far_visit::later);
            }
        }
    }
    return near;
}

void pair_search::copy_and_sweep(const query_input& input, const pair_chunk_sink* emit) {
    const std::uint32_t strips = grid_.strips;
    records_.resize(n_);
    if (filtered_) {
        filters_.resize(n_);
    }
    own_begin_.resize(strips + 1);
    bucket_starts(keys_.data(), n_, grid_.q_bits, strips, 0, n_, own_begin_.data());
    if (parts_.empty()) {
        parts_.resize(1);
    }
    start_part(parts_[0], 0, strips);
    strip_entries* here = &strip_entries_[0];
    strip_entries* above = &strip_entries_[1];
    here->visitors = 0;
    above->visitors = 0;
    far_visits_.clear();
    std::size_t visits = 0;
    sweep_units(1, 1, emit, [&](part& p, const flush_callback& after_flush, const std::atomic<bool>& failed) {
        for (std::uint32_t s = 0; s < strips && !failed.load(); ++s) {
            const std::size_t own = own_begin_[s + 1] - own_begin_[s];
            here->own = own;
            // Visitors from two or more strips below come after those from
            // the strip just below; either run is in order, both together
            // only once sorted.
            const std::size_t near_visitors = here->visitors;
            here->make_room(own + near_visitors + 1);
            while (!far_visits_.empty() && far_visits_.front().strip == s) {
                std::pop_heap(far_visits_.begin(), far_visits_.end(), far_visit::later);
                far_visit& visit = far_visits_.back();
                const std::size_t at = own + here->visitors;
                here->make_room(at + 2);
                visit.put(*here, at);
                ++here->visitors;
                if (visit.high > s) {
                    ++visit.strip;
                    std::push_heap(far_visits_.begin(), far_visits_.end(), far_visit::later);
                } else {
                    far_visits_.pop_back();
                }
            }
            const std::size_t near = copy_own_entries(input, s, *here);
            if (near_visitors > 0 && here->visitors > near_visitors) {
                here->sort_visitors();
            }
            visits += here->visitors;
            if (own > 0 && own + here->visitors >= 2) {
                merge_strip(*here, p);
                sweep_merged(p, own + here->visitors, after_flush);
            }
            // The visits to the strip above go after its own rectangles, in
            // this strip's key order: sorted by q_lo, as the keys are made
            // from the same bounds. Were they not (rows changed while the
            // query read them), they are sorted.
            const std::size_t above_own = s + 1 < strips ? own_begin_[s + 2] - own_begin_[s + 1] : 0;
            above->own = above_own;
            above->make_room(above_own + near + 1);
            unsigned sorted = 1;
            for (std::size_t j = 0; j < near; ++j) {
                above->take(above_own + j, *here, climbing_[j]);
                sorted &= j == 0 || here->q_lo[climbing_[j - 1]] <= here->q_lo[climbing_[j]] ? 1u : 0u;
            }
            std::swap(here, above);
            here->visitors = near;
            above->visitors = 0;
            if (sorted == 0) {
                here->sort_visitors();
            }
        }
    });
    stats_.strips = strips;
    stats_.visits = visits;
}

void pair_search::merge_strip(const strip_entries& entries, part& p) {
    // By quantized lo_x, a rectangle before a visitor on equal keys, without
    // a branch (which side comes next is as random as the scene): a side
    // that has run out reads as the largest key, and every read stays in the
    // buffer (the entry after the last visitor is spare).
    const std::size_t own = entries.own;
    const std::size_t end = own + entries.visitors;
    make_strip_room(p, end);
    constexpr std::uint32_t none = std::numeric_limits<std::uint32_t>::max();
    const std::uint32_t* const from_q_lo = entries.q_lo.data();
    const std::uint32_t* const from_q_hi = entries.q_hi.data();
    const std::uint32_t* const from_id = entries.id.data();
    const float* const from_store = entries.store.data();
    const float* const from_lo_x = entries.lo_x.data();
    const float* const from_lo_y = entries.lo_y.data();
    const float* const from_hi_x = entries.hi_x.data();
    const float* const from_hi_y = entries.hi_y.data();
    float* const q_lo = p.q_lo.data();
    float* const q_hi = p.q_hi.data();
    std::int32_t* const ids = p.id.data();
    float* const starts = p.starts.data();
    float* const store = p.store.data();
    float* const lo_x = p.lo_x.data();
    float* const lo_y = p.lo_y.data();
    float* const hi_x = p.hi_x.data();
    float* const hi_y = p.hi_y.data();
    std::size_t o = 0;
    std::size_t v = own;
    for (std::size_t e = 0; e < end; ++e) {
        const std::uint32_t own_q = o < own ? from_q_lo[o] : none;
        const std::uint32_t visit_q = v < end ? from_q_lo[v] : none;
        const std::size_t take_own = own_q <= visit_q ? 1u : 0u;
        const std::size_t own_mask = 0u - take_own;
        const std::size_t k = (o & own_mask) | (v & ~own_mask);
        o += take_own;
        v += 1u - take_own;
        q_lo[e] = static_cast<float>(from_q_lo[k]);
        q_hi[e] = static_cast<float>(from_q_hi[k]);
        ids[e] = static_cast<std::int32_t>(from_id[k]);
        starts[e] = static_cast<float>(take_own);
        store[e] = from_store[k];
        lo_x[e] = from_lo_x[k];
        lo_y[e] = from_lo_y[k];
        hi_x[e] = from_hi_x[k];
        hi_y[e] = from_hi_y[k];
    }
}

}  // namespace obbsat::detail
