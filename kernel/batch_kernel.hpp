// The batch drivers: walk a batch one vector of pairs at a time, load each
// lane's two rectangles, run a method's lane test, store the verdicts. The
// last, partial vector is staged through local buffers so that nothing past
// the caller's arrays is read or written.
#pragma once

#include "kernel_table.hpp"
#include "lanes.hpp"
#include "record_transpose.hpp"

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

/// verdicts[i] = Method(a[i], b[i]) for i < count.
template <class Arch, template <class> class Method>
void stream_batch(const soa_view& a, const soa_view& b, std::size_t count, std::uint8_t* verdicts) {
    constexpr std::size_t width = lanes<Arch>::size;
    std::size_t i = 0;
    for (; i + width <= count; i += width) {
        const unsigned hit = Method<Arch>::collide(load_consecutive<Arch>(a, i), load_consecutive<Arch>(b, i));
        store_verdicts<width>(hit, verdicts + i, width);
    }
    if (i < count) {
        // Partial vector: repeat the last pair in the unused lanes.
        staged_quads<Arch> sa, sb;
        for (std::size_t lane = 0; lane < width; ++lane) {
            const std::size_t k = (i + lane < count) ? i + lane : count - 1;
            sa.put(lane, a, k);
            sb.put(lane, b, k);
        }
        const unsigned hit = Method<Arch>::collide(sa.load(), sb.load());
        store_verdicts<width>(hit, verdicts + i, count - i);
    }
}

/// verdicts[i] = Method(rects[pairs[i].a], rects[pairs[i].b]) for i < count.
template <class Arch, template <class> class Method>
void indexed_batch(const soa_view& rects, const pair_index* pairs, std::size_t count,
                   std::uint8_t* verdicts) {
    constexpr std::size_t width = lanes<Arch>::size;
    staged_quads<Arch> sa, sb;
    for (std::size_t i = 0; i < count; i += width) {
        const std::size_t valid = (count - i < width) ? count - i : width;
        for (std::size_t lane = 0; lane < width; ++lane) {
            // A partial vector repeats its last pair in the unused lanes.
            const pair_index& p = pairs[i + (lane < valid ? lane : valid - 1)];
            sa.put(lane, rects, p.a);
            sb.put(lane, rects, p.b);
        }
        const unsigned hit = Method<Arch>::collide(sa.load(), sb.load());
        store_verdicts<width>(hit, verdicts + i, valid);
    }
}

/// How many pairs ahead the records of a pair are prefetched: far enough to
/// hide a DRAM access behind the work on the pairs in between.
constexpr std::size_t prefetch_distance = 16;

/// verdicts[i] = Method(records[pairs[i].a], records[pairs[i].b]) for i < count.
template <class Arch, template <class> class Method>
void indexed_records_batch(const rect* records, const pair_index* pairs, std::size_t count,
                           std::uint8_t* verdicts) {
    constexpr std::size_t width = lanes<Arch>::size;
    std::size_t i = 0;
    for (; i + width <= count; i += width) {
        const pair_index* p = pairs + i;
        if (i + width + prefetch_distance <= count) {
            for (std::size_t k = prefetch_distance; k < prefetch_distance + width; ++k) {
                __builtin_prefetch(records + p[k].a);
                __builtin_prefetch(records + p[k].b);
            }
        }
        const unsigned hit = Method<Arch>::collide(
            record_transpose<Arch>::load([&](std::size_t lane) { return records + p[lane].a; }),
            record_transpose<Arch>::load([&](std::size_t lane) { return records + p[lane].b; }));
        store_verdicts<width>(hit, verdicts + i, width);
    }
    if (i < count) {
        // Partial vector: repeat the last pair in the unused lanes.
        const std::size_t valid = count - i;
        auto pair_at = [&](std::size_t lane) { return pairs[i + (lane < valid ? lane : valid - 1)]; };
        const unsigned hit = Method<Arch>::collide(
            record_transpose<Arch>::load([&](std::size_t lane) { return records + pair_at(lane).a; }),
            record_transpose<Arch>::load([&](std::size_t lane) { return records + pair_at(lane).b; }));
        store_verdicts<width>(hit, verdicts + i, valid);
    }
}

}  // namespace
}  // namespace obbsat::detail
