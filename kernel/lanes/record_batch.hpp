// The batch driver over fixed-size records, for every record type whose
// lanes are read by transposing whole records in registers: float poses
// (pose_batch.hpp), double poses (pose64_batch.hpp) and double corners
// (corner64_lanes.hpp). It walks a batch one vector of pairs at a time, loads
// each lane's two records, runs the method's lane test, stores the verdicts
// and settles the lanes the fast path left undecided one by one. The last,
// partial vector repeats its last pair in the unused lanes, so nothing past
// the caller's arrays is read or written.
//
// A record type is a class template Records<Arch> giving
//   value                  the element type of the records' array;
//   width                  pairs per vector;
//   record(records, i)     the address of record i (fetched ahead);
//   load<InCache>(records, index)
//                          the lanes' values of records[index(lane)]; InCache
//                          when the records are read from the caches (the
//                          list fetches nothing ahead), as
//                          record_transpose::assemble uses it;
//   at(records, i)         record i as the scalar slow path takes it.
#pragma once

#include "lanes/batch_kernel.hpp"
#include "support/fetch_ahead.hpp"

#include <obbsat/rect.hpp>

#include <cstddef>
#include <cstdint>

namespace obbsat::detail {
namespace {

/// verdicts[i] = Method(a[first(i)], b[second(i)]) for i < count over records
/// of type Records; returns the lanes settled exactly. The records of pairs
/// ahead are fetched as Fetch says (fetch_ahead.hpp).
template <class Arch, template <class> class Method, template <class> class Records, pair_fetch Fetch, class First,
          class Second>
std::size_t record_batch(const typename Records<Arch>::value* a, const typename Records<Arch>::value* b, First first,
                         Second second, std::size_t count, std::uint8_t* verdicts) {
    using records = Records<Arch>;
    constexpr std::size_t width = records::width;
    constexpr bool in_cache = Fetch == pair_fetch::none;
    std::size_t settled = 0;
    auto records_of_pair = [&](std::size_t i) { return make_lane_pair(records::at(a, first(i)), records::at(b, second(i))); };
    // One vector of pairs, pair_of(lane) giving each lane's pair. Inlined
    // into the loop, with first and second held by value: called out of line,
    // or reading the pair list through references, the loop reloaded its
    // pointers from memory after every verdict store (a byte store may alias
    // anything), 1.9-2.0 against 1.65 ns per pair for local on float poses at
    // 256K pairs.
    auto run = [&](std::size_t i, std::size_t valid, const auto& pair_of) __attribute__((always_inline)) {
        const lane_verdicts v = Method<Arch>::collide(
            records::template load<in_cache>(a, [&](std::size_t lane) { return first(pair_of(lane)); }),
            records::template load<in_cache>(b, [&](std::size_t lane) { return second(pair_of(lane)); }));
        settled += finish_vector<width, Method, Arch>(v, verdicts + i, valid,
                                                      [&](std::size_t lane) { return records_of_pair(i + lane); });
    };
    std::size_t i = 0;
    for (; i + width <= count; i += width) {
        if constexpr (Fetch != pair_fetch::none) {
            constexpr std::size_t ahead = pairs_ahead<Fetch>;
            if (i + width + ahead <= count) {
                for (std::size_t k = i + ahead; k < i + ahead + width; ++k) {
                    fetch_record<Fetch>(records::record(a, first(k)));
                    fetch_record<Fetch>(records::record(b, second(k)));
                }
            }
        }
        run(i, width, [&](std::size_t lane) { return i + lane; });
    }
    if (i < count) {
        const std::size_t valid = count - i;
        run(i, valid, [&](std::size_t lane) { return i + (lane < valid ? lane : valid - 1); });
    }
    return settled;
}

/// verdicts[i] = Method(records[pairs[i].a], records[pairs[i].b]) for i < count;
/// the records of pairs ahead are fetched as Fetch says.
template <class Arch, template <class> class Method, template <class> class Records, pair_fetch Fetch>
std::size_t record_indexed_batch(const typename Records<Arch>::value* records, const pair_index* pairs,
                                 std::size_t count, std::uint8_t* verdicts) {
    return record_batch<Arch, Method, Records, Fetch>(
        records, records, [pairs](std::size_t i) { return pairs[i].a; }, [pairs](std::size_t i) { return pairs[i].b; },
        count, verdicts);
}

/// verdicts[i] = Method(a[i], b[i]) for i < count: consecutive records, no index read.
template <class Arch, template <class> class Method, template <class> class Records>
std::size_t record_stream_batch(const typename Records<Arch>::value* a, const typename Records<Arch>::value* b,
                                std::size_t count, std::uint8_t* verdicts) {
    auto same = [](std::size_t i) { return i; };
    return record_batch<Arch, Method, Records, pair_fetch::none>(a, b, same, same, count, verdicts);
}

}  // namespace
}  // namespace obbsat::detail
