// Steps 2 to 5 of the scene query (pair_search.hpp) strip by strip, for a
// plain float query on one thread: each strip's records copied into the
// query's order, their bounds, their visits to the strips above, the merge
// with the strip's visitors and the sweep, in one go while the strip's
// entries are in the cache. The steps taken one at a time write every
// rectangle's sweep bounds to arrays of the whole scene (records_copy.cpp)
// and read them back in each strip's merge (sweep.cpp), visitors at random;
// here a strip's own rectangles go from their bounds straight to their
// places in the swept strip, and only its visitors pass through a buffer
// (strip_visitors) between two strips.
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

namespace {

/// Room for `count` entries in each of `arrays`, grown with room to spare
/// (the next strips are about as large), what they hold kept.
template <class... Vectors>
void grow_to(std::size_t count, Vectors*... arrays) {
    const std::size_t size = std::max(count, 2 * std::min({arrays->size()...}));
    if (std::min({arrays->size()...}) < count) {
        (arrays->resize(size), ...);
    }
}

}  // namespace

void pair_search::strip_visitors::make_room(std::size_t entries) {
    grow_to(entries, &q_lo, &q_hi, &id);
    grow_to(entries, &store, &lo_x, &lo_y, &hi_x, &hi_y);
}

void pair_search::strip_visitors::take(std::size_t to, const strip_visitors& from, std::size_t at) {
    q_lo[to] = from.q_lo[at];
    q_hi[to] = from.q_hi[at];
    id[to] = from.id[at];
    store[to] = from.store[at];
    lo_x[to] = from.lo_x[at];
    lo_y[to] = from.lo_y[at];
    hi_x[to] = from.hi_x[at];
    hi_y[to] = from.hi_y[at];
}

void pair_search::strip_visitors::sort_by_q_lo() {
    // Rare (rows changed while the query read them): sorted through a copy.
    std::vector<std::uint32_t> by_q(count);
    std::iota(by_q.begin(), by_q.end(), 0u);
    std::stable_sort(by_q.begin(), by_q.end(), [this](std::uint32_t x, std::uint32_t y) { return q_lo[x] < q_lo[y]; });
    strip_visitors sorted;
    sorted.make_room(count);
    for (std::size_t i = 0; i < count; ++i) {
        sorted.take(i, *this, by_q[i]);
    }
    for (std::size_t i = 0; i < count; ++i) {
        take(i, sorted, i);
    }
}

void pair_search::strip_visitors::merge_runs(std::size_t second, strip_visitors& spare) {
    // Visitors from the strip below and from further down, each run sorted:
    // common where rectangles many strips tall meet (a drum's walls), so
    // merged through a buffer kept for it, which then takes this one's place.
    spare.make_room(count + 1);
    std::size_t i = 0;
    std::size_t j = second;
    for (std::size_t t = 0; t < count; ++t) {
        const bool first_run = j == count || (i < second && q_lo[i] <= q_lo[j]);
        spare.take(t, *this, first_run ? i++ : j++);
    }
    spare.count = count;
    std::swap(*this, spare);
}

bool pair_search::far_visit::later(const far_visit& x, const far_visit& y) {
    return x.strip != y.strip ? x.strip > y.strip : x.q_lo != y.q_lo ? x.q_lo > y.q_lo : x.id > y.id;
}

void pair_search::far_visit::put(strip_visitors& to, std::size_t at) const {
    to.q_lo[at] = q_lo;
    to.q_hi[at] = q_hi;
    to.id[at] = id;
    to.store[at] = store;
    to.lo_x[at] = lo_x;
    to.lo_y[at] = lo_y;
    to.hi_x[at] = hi_x;
    to.hi_y[at] = hi_y;
}

void pair_search::place_strip(const strip_visitors& visitors, std::size_t own_first, std::size_t own, part& p) {
    // The merge by quantized lo_x (a rectangle before a visitor on equal
    // keys), on the keys alone: a rectangle's key holds the q_lo its bounds
    // give (the keys are made from the same bounds), so its place is known
    // before its row is read. A merge step by step waits on each choice
    // (the next read depends on it); here each visitor finds how many own
    // rectangles go before it by a binary search of its own, independent of
    // the others', and each own rectangle is moved on by the visitors before
    // it, counted in one pass.
    const std::size_t count = visitors.count;
    make_strip_room(p, own + count);
    grow_to(own + 1, &own_at_, &own_q_);
    grow_to(count, &visitor_at_);
    std::uint32_t* const own_at = own_at_.data();
    std::uint32_t* const visitor_at = visitor_at_.data();
    std::uint32_t* const own_q = own_q_.data();
    const std::uint32_t q_mask = grid_.q_max;
    const std::uint32_t* const keys = keys_.data() + own_first;
    for (std::size_t i = 0; i < own; ++i) {
        own_q[i] = keys[i] & q_mask;
    }
    // own_at counts, for each i, the visitors that go before own rectangle i
    // and not before i - 1; then their running sum plus i is its place.
    std::fill(own_at, own_at + own + 1, 0u);
    if (own > 0) {
        // Own rectangles whose q_lo is at most a visitor's: a search whose
        // steps depend only on `own`, so it takes no branch on the data, run
        // for `lanes` visitors at once so that their chains of loads overlap.
        constexpr std::size_t lanes = 4;
        const std::uint32_t* const visitor_q = visitors.q_lo.data();
        const auto place = [&](std::size_t j, const std::uint32_t* first) {
            const std::size_t before =
                static_cast<std::size_t>(first - own_q) + (*first <= visitor_q[j] ? 1u : 0u);
            visitor_at[j] = static_cast<std::uint32_t>(j + before);
            ++own_at[before];
        };
        std::size_t j = 0;
        for (; j + lanes <= count; j += lanes) {
            const std::uint32_t* first[lanes];
            for (std::size_t t = 0; t < lanes; ++t) {
                first[t] = own_q;
            }
            for (std::size_t left = own; left > 1;) {
                const std::size_t half = left / 2;
                for (std::size_t t = 0; t < lanes; ++t) {
                    first[t] = first[t][half] <= visitor_q[j + t] ? first[t] + half : first[t];
                }
                left -= half;
            }
            for (std::size_t t = 0; t < lanes; ++t) {
                place(j + t, first[t]);
            }
        }
        for (; j < count; ++j) {
            const std::uint32_t* first = own_q;
            for (std::size_t left = own; left > 1;) {
                const std::size_t half = left / 2;
                first = first[half] <= visitor_q[j] ? first + half : first;
                left -= half;
            }
            place(j, first);
        }
    } else {
        std::iota(visitor_at, visitor_at + count, 0u);
    }
    std::uint32_t passed = 0;
    for (std::size_t i = 0; i < own; ++i) {
        passed += own_at[i];
        own_at[i] = static_cast<std::uint32_t>(i) + passed;
    }
    for (std::size_t j = 0; j < count; ++j) {
        const std::size_t e = visitor_at[j];
        p.q_lo[e] = static_cast<float>(visitors.q_lo[j]);
        p.q_hi[e] = static_cast<float>(visitors.q_hi[j]);
        p.id[e] = static_cast<std::int32_t>(visitors.id[j]);
        p.starts[e] = 0.0f;
        p.store[e] = visitors.store[j];
        p.lo_x[e] = visitors.lo_x[j];
        p.lo_y[e] = visitors.lo_y[j];
        p.hi_x[e] = visitors.hi_x[j];
        p.hi_y[e] = visitors.hi_y[j];
    }
}

std::size_t pair_search::copy_own_entries(const query_input& input, std::uint32_t strip, std::size_t own, part& p) {
    const std::size_t own_first = own_begin_[strip];
    const bounds_fn bounds = kernels_for(ran_).bounds;
    const double y_low = grid_.y_low, y_scale = grid_.y_scale, x_low = grid_.x_low, x_scale = grid_.x_scale;
    const std::uint32_t q_top = grid_.q_max, strip_top = grid_.strips - 1;
    const auto second_store = static_cast<std::uint32_t>(self_ ? n_ : a_count_);
    grow_to(own + 1, &climbing_);
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
        // Each entry to its place in the strip (place_strip). The grid's maps
        // on locals and pointers that alias nothing, as in store_sweep_bounds,
        // so that the loop takes no branch and reads nothing again after each store.
        const std::size_t count = run_end - run;
        float* __restrict const q_lo = p.q_lo.data();
        float* __restrict const q_hi = p.q_hi.data();
        std::int32_t* __restrict const ids = p.id.data();
        float* __restrict const starts = p.starts.data();
        float* __restrict const store = p.store.data();
        float* __restrict const lo_x = p.lo_x.data();
        float* __restrict const lo_y = p.lo_y.data();
        float* __restrict const hi_x = p.hi_x.data();
        float* __restrict const hi_y = p.hi_y.data();
        const std::uint32_t* __restrict const at = own_at_.data() + run;
        const std::uint32_t* __restrict const rows = order_.data() + own_first + run;
        alignas(64) std::uint32_t high[bounds_run::size];
        for (std::size_t r = 0; r < count; ++r) {
            const std::size_t e = at[r];
            q_lo[e] = static_cast<float>(
                strip_grid::clamped_floor((static_cast<double>(b.lo_x[r]) - x_low) * x_scale, q_top));
            q_hi[e] = static_cast<float>(
                strip_grid::clamped_floor((static_cast<double>(b.hi_x[r]) - x_low) * x_scale, q_top));
            high[r] = strip_grid::clamped_floor((static_cast<double>(b.hi_y[r]) - y_low) * y_scale, strip_top);
            ids[e] = static_cast<std::int32_t>(own_first + run + r);
            starts[e] = 1.0f;
            store[e] = rows[r] >= second_store ? 1.0f : 0.0f;
            lo_x[e] = b.lo_x[r];
            lo_y[e] = b.lo_y[r];
            hi_x[e] = b.hi_x[r];
            hi_y[e] = b.hi_y[r];
        }
        // Whether a rectangle visits the strip above is as random as the
        // scene: each one writes itself to the next slot, which the next
        // visitor overwrites if this one was none (visits.cpp). A highest
        // strip below this one (rows changed between the order's read and
        // this one) is taken as this one: no visit.
        std::uint32_t* __restrict const climbing = climbing_.data();
        for (std::size_t r = 0; r < count; ++r) {
            const std::uint32_t top = std::max(high[r], strip);
            climbing[near] = at[r];
            near += top != strip ? 1u : 0u;
            if (top > strip + 1) {
                const std::size_t e = at[r];
                far_visits_.push_back(far_visit{strip + 2, top, static_cast<std::uint32_t>(q_lo[e]),
                                                static_cast<std::uint32_t>(q_hi[e]),
                                                static_cast<std::uint32_t>(ids[e]), store[e], lo_x[e], lo_y[e],
                                                hi_x[e], hi_y[e]});
                std::push_heap(far_visits_.begin(), far_visits_.end(), far_visit::later);
            }
        }
    }
    return near;
}

bool pair_search::climb(const part& p, std::size_t near, strip_visitors& above) const {
    // In this strip's key order, so sorted by q_lo as the keys are made from
    // the same bounds; were they not (rows changed while the query read
    // them), the caller sorts them.
    above.make_room(near + 1);
    above.count = near;
    unsigned sorted = 1;
    float last_q = 0;
    for (std::size_t j = 0; j < near; ++j) {
        const std::size_t e = climbing_[j];
        above.q_lo[j] = static_cast<std::uint32_t>(p.q_lo[e]);
        above.q_hi[j] = static_cast<std::uint32_t>(p.q_hi[e]);
        above.id[j] = static_cast<std::uint32_t>(p.id[e]);
        above.store[j] = p.store[e];
        above.lo_x[j] = p.lo_x[e];
        above.lo_y[j] = p.lo_y[e];
        above.hi_x[j] = p.hi_x[e];
        above.hi_y[j] = p.hi_y[e];
        sorted &= last_q <= p.q_lo[e] ? 1u : 0u;
        last_q = p.q_lo[e];
    }
    return sorted != 0;
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
    strip_visitors* here = &visitors_[0];
    strip_visitors* above = &visitors_[1];
    here->count = 0;
    above->count = 0;
    far_visits_.clear();
    std::size_t visits = 0;
    sweep_units(1, 1, emit, [&](part& p, const flush_callback& after_flush, const std::atomic<bool>& failed) {
        for (std::uint32_t s = 0; s < strips && !failed.load(); ++s) {
            const std::size_t own_first = own_begin_[s];
            const std::size_t own = own_begin_[s + 1] - own_first;
            // Visitors from two or more strips below come after those from
            // the strip just below; either run is in order, both together
            // only once sorted.
            const std::size_t near_visitors = here->count;
            while (!far_visits_.empty() && far_visits_.front().strip == s) {
                std::pop_heap(far_visits_.begin(), far_visits_.end(), far_visit::later);
                far_visit& visit = far_visits_.back();
                here->make_room(here->count + 1);
                visit.put(*here, here->count);
                ++here->count;
                if (visit.high > s) {
                    ++visit.strip;
                    std::push_heap(far_visits_.begin(), far_visits_.end(), far_visit::later);
                } else {
                    far_visits_.pop_back();
                }
            }
            if (near_visitors > 0 && here->count > near_visitors) {
                here->merge_runs(near_visitors, merged_visitors_);
            }
            visits += here->count;
            const std::size_t m = own + here->count;
            place_strip(*here, own_first, own, p);
            const std::size_t near = copy_own_entries(input, s, own, p);
            const bool climbers_sorted = climb(p, near, *above);
            if (own > 0 && m >= 2) {
                sweep_merged(p, m, after_flush);
            }
            std::swap(here, above);
            above->count = 0;
            if (!climbers_sorted) {
                here->sort_by_q_lo();
            }
        }
    });
    stats_.strips = strips;
    stats_.visits = visits;
}

}  // namespace obbsat::detail
