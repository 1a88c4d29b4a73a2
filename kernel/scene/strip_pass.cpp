// Steps 2 to 5 of the scene query (pair_search.hpp) strip by strip, for a
// plain float query, on one thread or over units of consecutive strips on
// several (copy_and_sweep, at the end): each strip's records copied into the
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
#include "support/fetch_ahead.hpp"
#include "support/work_shares.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <new>
#include <numeric>
#include <thread>
#include <utility>

namespace obbsat::detail {

namespace {

/// The share of the scene's records the units of the strip pass on several
/// threads may read again, in all, to find their first strip's visitors
/// (strip_pass_units). Reading one costs its bounds, a small part of what a
/// box costs the query: on the 1M-box uniform scene (317 strips, a reach of
/// 1 strip, 32 units) the units read 10% of the records again (29% when the
/// reach came from the largest extent rounded up to a power of two: 3
/// strips). A scene whose tallest rectangle reaches much further takes the
/// steps one at a time.
constexpr double strip_pass_read_again = 1.0;

/// Room for `count` entries in each of `arrays`, grown with room to spare
/// (the next strips are about as large), what they hold kept.
template <class... Vectors>
void grow_to(std::size_t count, Vectors*... arrays) {
    const std::size_t size = std::max(count, 2 * std::min({arrays->size()...}));
    if (std::min({arrays->size()...}) < count) {
        (arrays->resize(size), ...);
    }
}

/// starts[s] for s in [0, strips]: the first index of sorted `keys` whose
/// strip (key >> shift) is at least s, n if none; what bucket_starts writes,
/// found by a lower bound for each strip instead of reading every key, run
/// for `lanes` strips at once, each step taking no branch on the data, so
/// that the searches' loads overlap: a few hundred strips over a million keys.
void strip_starts(const std::uint32_t* keys, std::size_t n, unsigned shift, std::uint32_t strips,
                  std::uint32_t* starts) {
    constexpr std::size_t lanes = 8;
    for (std::size_t s = 0; s <= strips; s += lanes) {
        std::uint64_t target[lanes];
        std::size_t base[lanes];
        for (std::size_t t = 0; t < lanes; ++t) {
            target[t] = static_cast<std::uint64_t>(s + t) << shift;
            base[t] = 0;
        }
        for (std::size_t left = n; left > 1;) {
            const std::size_t half = left / 2;
            for (std::size_t t = 0; t < lanes; ++t) {
                base[t] = keys[base[t] + half] < target[t] ? base[t] + half : base[t];
            }
            left -= half;
        }
        for (std::size_t t = 0; t < lanes && s + t <= strips; ++t) {
            starts[s + t] = static_cast<std::uint32_t>(n == 0 ? 0 : base[t] + (keys[base[t]] < target[t] ? 1u : 0u));
        }
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

void pair_search::place_strip(const strip_visitors& visitors, std::size_t own_first, std::size_t own, part& p,
                              strip_pass_memory& memory) const {
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
    grow_to(own + 1, &memory.own_at, &memory.own_q);
    grow_to(count, &memory.visitor_at);
    std::uint32_t* const own_at = memory.own_at.data();
    std::uint32_t* const visitor_at = memory.visitor_at.data();
    std::uint32_t* const own_q = memory.own_q.data();
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

void pair_search::copy_rows(const query_input& input, std::size_t begin, std::size_t end) {
    for (std::size_t k = begin; k < end; ++k) {
        if (k + random_rows_ahead < n_) {
            fetch_into_l2(record_at(input, order_[k + random_rows_ahead]));
        }
        ::new (static_cast<void*>(&records_[k])) record;  // its memory may have held the sort's words
        copy_row(input, order_[k], records_[k].v);
    }
    if (filtered_) {
        for (std::size_t k = begin; k < end; ++k) {
            filters_[k] = filter_of(input, order_[k]);
        }
    }
}

std::size_t pair_search::copy_own_entries(const query_input& input, std::uint32_t strip, std::size_t own, part& p,
                                          strip_pass_memory& memory) {
    const std::size_t own_first = own_begin_[strip];
    const bounds_fn bounds = kernels_for(ran_).bounds;
    const double y_low = grid_.y_low, y_scale = grid_.y_scale, x_low = grid_.x_low, x_scale = grid_.x_scale;
    const std::uint32_t q_top = grid_.q_max, strip_top = grid_.strips - 1;
    const auto second_store = static_cast<std::uint32_t>(self_ ? n_ : a_count_);
    grow_to(own + 1, &memory.climbing);
    std::size_t near = 0;
    for (std::size_t run = 0; run < own; run += bounds_run::size) {
        const std::size_t run_end = std::min(own, run + bounds_run::size);
        if (copied_before_[strip] == 0) {
            // copy_rows' loop, written out: called here run by run, the
            // copy of one thread's strip pass cost a call per run, and
            // inlined (always_inline) GCC 12 dropped its fetch ahead.
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
        const std::uint32_t* __restrict const at = memory.own_at.data() + run;
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
        std::uint32_t* __restrict const climbing = memory.climbing.data();
        for (std::size_t r = 0; r < count; ++r) {
            const std::uint32_t top = std::max(high[r], strip);
            climbing[near] = at[r];
            near += top != strip ? 1u : 0u;
            if (top > strip + 1) {
                const std::size_t e = at[r];
                memory.far_visits.push_back(far_visit{strip + 2, top, static_cast<std::uint32_t>(q_lo[e]),
                                                static_cast<std::uint32_t>(q_hi[e]),
                                                static_cast<std::uint32_t>(ids[e]), store[e], lo_x[e], lo_y[e],
                                                hi_x[e], hi_y[e]});
                std::push_heap(memory.far_visits.begin(), memory.far_visits.end(), far_visit::later);
            }
        }
    }
    return near;
}

bool pair_search::climb(const part& p, std::size_t near, const strip_pass_memory& memory, strip_visitors& above) {
    // In this strip's key order, so sorted by q_lo as the keys are made from
    // the same bounds; were they not (rows changed while the query read
    // them), the caller sorts them.
    above.make_room(near + 1);
    above.count = near;
    unsigned sorted = 1;
    float last_q = 0;
    for (std::size_t j = 0; j < near; ++j) {
        const std::size_t e = memory.climbing[j];
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

std::uint32_t pair_search::strip_reach() const {
    // A rectangle of height h over strips of height 1 / y_scale spans at
    // most floor(h * y_scale) + 1 strips above its lowest; a little more
    // covers the rounding of the bounds and of their maps to strips. Most
    // scenes' strips are twice their mean height: one strip, the one below.
    const double reach = std::floor(static_cast<double>(tallest_) * grid_.y_scale * (1.0 + 1e-6)) + 1.0;
    return reach < static_cast<double>(grid_.strips) ? static_cast<std::uint32_t>(reach) : grid_.strips;
}

std::size_t pair_search::strip_pass_units(std::size_t parts) const {
    // Each unit but the first reads again the rows of the strips below its
    // first that a rectangle may reach from (incoming_visitors): worth it
    // while that stays a small share of the scene's rows; a scene with a
    // rectangle through many strips takes the steps one at a time instead.
    const std::size_t units = units_for(n_, parts, min_entries_per_unit);
    const double read_again =
        static_cast<double>(units - 1) * static_cast<double>(strip_reach()) / static_cast<double>(grid_.strips);
    return read_again <= strip_pass_read_again ? units : 0;
}

void pair_search::incoming_visitors(std::uint32_t first, strip_pass_memory& memory) const {
    // The records of the strips below were copied before the units started
    // (copy_boundary_rows), and no unit writes them: their bounds are
    // computed here again, by the same kernel, so they are the same.
    const std::uint32_t reach = strip_reach();
    const std::uint32_t lowest = first > reach ? first - reach : 0u;
    const std::size_t begin = own_begin_[lowest];
    const std::size_t end = own_begin_[first];
    const bounds_fn bounds = kernels_for(ran_).bounds;
    const auto second_store = static_cast<std::uint32_t>(self_ ? n_ : a_count_);
    strip_visitors& here = memory.visitors[0];
    here.count = 0;
    here.make_room(end - begin + 1);
    memory.far_visits.clear();
    // From one strip, the visitors come in its key order, so by q_lo (the
    // keys are made from the same bounds); from several, each strip's do.
    bool sorted = true;
    std::uint32_t last_q = 0;
    bounds_run b;
    for (std::size_t run = begin; run < end; run += bounds_run::size) {
        const std::size_t count = std::min(end - run, bounds_run::size);
        bounds(kind_, records_[run].v, count, b.lo_x, b.lo_y, b.hi_x, b.hi_y);
        for (std::size_t r = 0; r < count; ++r) {
            const std::uint32_t high = grid_.strip_of(b.hi_y[r]);
            if (high < first) {
                continue;
            }
            const auto k = static_cast<std::uint32_t>(run + r);
            const far_visit visit{first + 1,
                                  high,
                                  grid_.q_of(b.lo_x[r]),
                                  grid_.q_of(b.hi_x[r]),
                                  k,
                                  order_[k] >= second_store ? 1.0f : 0.0f,
                                  b.lo_x[r],
                                  b.lo_y[r],
                                  b.hi_x[r],
                                  b.hi_y[r]};
            visit.put(here, here.count);
            ++here.count;
            sorted = sorted && last_q <= visit.q_lo;
            last_q = visit.q_lo;
            if (high > first) {
                memory.far_visits.push_back(visit);
                std::push_heap(memory.far_visits.begin(), memory.far_visits.end(), far_visit::later);
            }
        }
    }
    if (!sorted) {
        here.sort_by_q_lo();
    }
}

std::size_t pair_search::copy_and_sweep_unit(const query_input& input, part& p, strip_pass_memory& memory,
                                             boundary_regions& regions, const flush_callback& after_flush,
                                             const std::atomic<bool>& failed) {
    strip_visitors* here = &memory.visitors[0];
    strip_visitors* above = &memory.visitors[1];
    if (p.first_strip > 0 && p.first_strip < p.end_strip) {
        // The regions below this unit's first strip within reach: its own,
        // and those of the units below while theirs end within reach.
        const std::uint32_t reach = strip_reach();
        const std::uint32_t lowest = p.first_strip > reach ? p.first_strip - reach : 0u;
        for (std::size_t u = static_cast<std::size_t>(&p - parts_.data()); u > 0 && parts_[u].first_strip > lowest;
             --u) {
            copy_region(input, u, regions);
        }
        incoming_visitors(p.first_strip, memory);
    } else {
        here->count = 0;
        memory.far_visits.clear();
    }
    above->count = 0;
    std::vector<far_visit>& far_visits = memory.far_visits;
    std::size_t visits = 0;
    for (std::uint32_t s = p.first_strip; s < p.end_strip && !failed.load(); ++s) {
        if (regions.starting[s] != 0) {
            copy_region(input, regions.starting[s], regions);
        }
        const std::size_t own_first = own_begin_[s];
        const std::size_t own = own_begin_[s + 1] - own_first;
        // Visitors from two or more strips below come after those from
        // the strip just below; either run is in order, both together
        // only once sorted.
        const std::size_t near_visitors = here->count;
        while (!far_visits.empty() && far_visits.front().strip == s) {
            std::pop_heap(far_visits.begin(), far_visits.end(), far_visit::later);
            far_visit& visit = far_visits.back();
            here->make_room(here->count + 1);
            visit.put(*here, here->count);
            ++here->count;
            if (visit.high > s) {
                ++visit.strip;
                std::push_heap(far_visits.begin(), far_visits.end(), far_visit::later);
            } else {
                far_visits.pop_back();
            }
        }
        if (near_visitors > 0 && here->count > near_visitors) {
            here->merge_runs(near_visitors, memory.merged);
        }
        visits += here->count;
        const std::size_t m = own + here->count;
        place_strip(*here, own_first, own, p, memory);
        const std::size_t near = copy_own_entries(input, s, own, p, memory);
        const bool climbers_sorted = climb(p, near, memory, *above);
        if (own > 0 && m >= 2) {
            sweep_merged(p, m, after_flush);
        }
        std::swap(here, above);
        above->count = 0;
        if (!climbers_sorted) {
            here->sort_by_q_lo();
        }
    }
    return visits;
}

void pair_search::mark_boundary_regions(std::size_t units, boundary_regions& regions) {
    // Region u reaches down strip_reach strips from unit u's first, but not
    // below unit u - 1's first: the strips further down lie in the regions
    // of the units below (a unit fewer strips high than the reach reads
    // several regions).
    const std::uint32_t strips = grid_.strips;
    copied_before_.assign(strips, 0);
    regions.lowest.assign(units, 0);
    regions.starting.assign(strips, 0);
    regions.claims.reset(new std::atomic<unsigned char>[units]);
    const std::uint32_t reach = strip_reach();
    for (std::size_t u = 0; u < units; ++u) {
        regions.claims[u].store(0, std::memory_order_relaxed);
        if (u == 0) {
            continue;
        }
        const std::uint32_t first = parts_[u].first_strip;
        const std::uint32_t lowest = std::max(first > reach ? first - reach : 0u, parts_[u - 1].first_strip);
        regions.lowest[u] = lowest;
        if (lowest < first) {
            std::fill(copied_before_.begin() + lowest, copied_before_.begin() + first, 1);
            regions.starting[lowest] = static_cast<std::uint32_t>(u);
        }
    }
}

void pair_search::copy_region(const query_input& input, std::size_t unit, boundary_regions& regions) {
    std::atomic<unsigned char>& claim = regions.claims[unit];
    unsigned char seen = 0;
    if (claim.compare_exchange_strong(seen, 1, std::memory_order_acquire)) {
        copy_rows(input, own_begin_[regions.lowest[unit]], own_begin_[parts_[unit].first_strip]);
        claim.store(2, std::memory_order_release);
        return;
    }
    // The other unit is copying it (a strip's rows): a short wait, unless
    // its thread lost its core, which the yields give back.
    for (unsigned k = 1; claim.load(std::memory_order_acquire) != 2; ++k) {
        if ((k & 63u) == 0) {
            std::this_thread::yield();
        }
    }
}

void pair_search::copy_and_sweep(const query_input& input, std::size_t parts, const pair_chunk_sink* emit) {
    const std::uint32_t strips = grid_.strips;
    records_.resize(n_);
    if (filtered_) {
        filters_.resize(n_);
    }
    own_begin_.resize(strips + 1);
    strip_starts(keys_.data(), n_, grid_.q_bits, strips, own_begin_.data());
    // Units of consecutive strips of about the same number of rectangles, a
    // few per thread, taken as they come (work_shares.hpp); each keeps what
    // it finds (parts_[unit]), so nothing depends on which thread took it.
    const std::size_t units = parts == 1 ? 1 : strip_pass_units(parts);
    if (parts_.size() < units) {
        parts_.resize(units);
    }
    if (pass_memory_.size() < units) {
        pass_memory_.resize(units);
    }
    cut_strips_into_units(units, n_, nullptr);
    boundary_regions regions;
    mark_boundary_regions(units, regions);
    std::vector<std::size_t> visits(units);
    sweep_units(units, parts, emit, [&](part& p, const flush_callback& after_flush, const std::atomic<bool>& failed) {
        const auto unit = static_cast<std::size_t>(&p - parts_.data());
        visits[unit] = copy_and_sweep_unit(input, p, pass_memory_[unit], regions, after_flush, failed);
    });
    stats_.strips = strips;
    stats_.visits = std::accumulate(visits.begin(), visits.end(), std::size_t{0});
}

}  // namespace obbsat::detail
