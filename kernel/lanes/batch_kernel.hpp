// The batch drivers: walk a batch one vector of pairs at a time, load each
// lane's two rectangles, run a method's lane test, store the verdicts. The
// last, partial vector is staged through local buffers so that nothing past
// the caller's arrays is read or written.
#pragma once

#include "support/fetch_ahead.hpp"
#include "dispatch/kernel_table.hpp"
#include "lanes/lanes.hpp"
#include "lanes/record_transpose.hpp"

#include <cstddef>
#include <cstdint>

namespace obbsat::detail {
namespace {

/// Loads rectangles [first, first + width) of a view; the caller guarantees they exist.
template <class Arch>
quad_lanes<Arch> load_consecutive(const soa_view& v, std::size_t first) {
    quad_lanes<Arch> q;
    for (unsigned c = 0; c < coord_count; ++c) {
        q.c[c] = lanes<Arch>::load_unaligned(v.coords[c] + first);
    }
    return q;
}

/// Staging area for one vector of rectangles picked lane by lane.
template <class Arch>
struct staged_quads {
    static constexpr std::size_t width = lanes<Arch>::size;
    alignas(64) float values[coord_count][width];

    void put(std::size_t lane, const soa_view& v, std::size_t index) {
        for (unsigned c = 0; c < coord_count; ++c) {
            values[c][lane] = v.coords[c][index];
        }
    }

    quad_lanes<Arch> load() const {
        quad_lanes<Arch> q;
        for (unsigned c = 0; c < coord_count; ++c) {
            q.c[c] = lanes<Arch>::load_aligned(values[c]);
        }
        return q;
    }
};

/// Stores one vector's verdicts (the first `valid` lanes); lanes the fast
/// path left undecided are settled one by one with rect_at(lane) giving the
/// lane's two rectangles. Returns how many lanes were settled that way.
template <std::size_t Width, template <class> class Method, class Arch, class RectsAt>
OBBSAT_LANE_INLINE std::size_t finish_vector(const lane_verdicts& v, std::uint8_t* out, std::size_t valid,
                                             const RectsAt& rects_at) {
    store_verdicts<Width>(v.hit, out, valid);
    if constexpr (Method<Arch>::has_slow_path) {
        std::size_t settled = 0;
        for (unsigned unsure = v.unsure; unsure != 0; unsure &= unsure - 1) {
            const std::size_t lane = static_cast<std::size_t>(__builtin_ctz(unsure));
            if (lane < valid) {
                const auto ab = rects_at(lane);
                out[lane] = Method<Arch>::decide_exactly(ab.first, ab.second) ? 1 : 0;
                ++settled;
            }
        }
        return settled;
    } else {
        (void)rects_at;
        return 0;
    }
}

/// verdicts[i] = Method(a[i], b[i]) for i < count; returns the lanes settled exactly.
template <class Arch, template <class> class Method>
std::size_t stream_batch(const soa_view& a, const soa_view& b, std::size_t count, std::uint8_t* verdicts) {
    constexpr std::size_t width = lanes<Arch>::size;
    std::size_t settled = 0;
    std::size_t i = 0;
    for (; i + width <= count; i += width) {
        const lane_verdicts v = Method<Arch>::collide(load_consecutive<Arch>(a, i), load_consecutive<Arch>(b, i));
        settled += finish_vector<width, Method, Arch>(v, verdicts + i, width, [&](std::size_t lane) {
            return make_lane_pair(rect_at(a, i + lane), rect_at(b, i + lane));
        });
    }
    if (i < count) {
        // Partial vector: repeat the last pair in the unused lanes.
        staged_quads<Arch> sa, sb;
        for (std::size_t lane = 0; lane < width; ++lane) {
            const std::size_t k = (i + lane < count) ? i + lane : count - 1;
            sa.put(lane, a, k);
            sb.put(lane, b, k);
        }
        const lane_verdicts v = Method<Arch>::collide(sa.load(), sb.load());
        settled += finish_vector<width, Method, Arch>(v, verdicts + i, count - i, [&](std::size_t lane) {
            return make_lane_pair(rect_at(a, i + lane), rect_at(b, i + lane));
        });
    }
    return settled;
}

/// verdicts[i] = Method(rects[pairs[i].a], rects[pairs[i].b]) for i < count;
/// returns the lanes settled exactly.
template <class Arch, template <class> class Method>
std::size_t indexed_batch(const soa_view& rects, const pair_index* pairs, std::size_t count,
                          std::uint8_t* verdicts) {
    constexpr std::size_t width = lanes<Arch>::size;
    staged_quads<Arch> sa, sb;
    std::size_t settled = 0;
    for (std::size_t i = 0; i < count; i += width) {
        const std::size_t valid = (count - i < width) ? count - i : width;
        for (std::size_t lane = 0; lane < width; ++lane) {
            // A partial vector repeats its last pair in the unused lanes.
            const pair_index& p = pairs[i + (lane < valid ? lane : valid - 1)];
            sa.put(lane, rects, p.a);
            sb.put(lane, rects, p.b);
        }
        const lane_verdicts v = Method<Arch>::collide(sa.load(), sb.load());
        settled += finish_vector<width, Method, Arch>(v, verdicts + i, valid, [&](std::size_t lane) {
            return make_lane_pair(rect_at(rects, pairs[i + lane].a), rect_at(rects, pairs[i + lane].b));
        });
    }
    return settled;
}

/// verdicts[i] = Method(records[pairs[i].a], records[pairs[i].b]) for i < count;
/// returns the lanes settled exactly. The records of pairs ahead are fetched
/// as Fetch says (fetch_ahead.hpp).
template <class Arch, template <class> class Method, pair_fetch Fetch>
std::size_t indexed_records_batch(const rect* records, const pair_index* pairs, std::size_t count,
                                  std::uint8_t* verdicts) {
    constexpr std::size_t width = lanes<Arch>::size;
    // A list that fetches nothing ahead reads records the caches hold.
    constexpr bool in_cache = Fetch == pair_fetch::none;
    std::size_t settled = 0;
    auto rects_of = [&](std::size_t pair) { return make_lane_pair(records[pairs[pair].a], records[pairs[pair].b]); };
    std::size_t i = 0;
    for (; i + width <= count; i += width) {
        const pair_index* p = pairs + i;
        if constexpr (Fetch != pair_fetch::none) {
            constexpr std::size_t ahead = pairs_ahead<Fetch>;
            if (i + width + ahead <= count) {
                for (std::size_t k = ahead; k < ahead + width; ++k) {
                    fetch_record<Fetch>(records + p[k].a);
                    fetch_record<Fetch>(records + p[k].b);
                }
            }
        }
        const lane_verdicts v = Method<Arch>::collide(
            record_transpose<Arch>::template load<in_cache>([&](std::size_t lane) { return records + p[lane].a; }),
            record_transpose<Arch>::template load<in_cache>([&](std::size_t lane) { return records + p[lane].b; }));
        settled += finish_vector<width, Method, Arch>(v, verdicts + i, width,
                                                      [&](std::size_t lane) { return rects_of(i + lane); });
    }
    if (i < count) {
        // Partial vector: repeat the last pair in the unused lanes.
        const std::size_t valid = count - i;
        auto pair_at = [&](std::size_t lane) { return pairs[i + (lane < valid ? lane : valid - 1)]; };
        const lane_verdicts v = Method<Arch>::collide(
            record_transpose<Arch>::template load<in_cache>([&](std::size_t lane) { return records + pair_at(lane).a; }),
            record_transpose<Arch>::template load<in_cache>([&](std::size_t lane) { return records + pair_at(lane).b; }));
        settled += finish_vector<width, Method, Arch>(v, verdicts + i, valid,
                                                      [&](std::size_t lane) { return rects_of(i + lane); });
    }
    return settled;
}

}  // namespace
}  // namespace obbsat::detail
