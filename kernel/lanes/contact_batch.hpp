// The batch drivers of contacts and distances: walk a batch one vector of pairs at a time,
// load each lane's two records (whole 32-byte float and 64-byte double records transposed in registers,
// other rows through a staging copy), run the contact lanes
// (contact_lanes.hpp), write each lane's contact (transposed back in
// registers). The last, partial vector repeats its last pair in the unused
// lanes, so nothing past the caller's arrays is read or written. Private to
// each per-ISA object (README.md).
#pragma once

#include "dispatch/contact_kernel_table.hpp"
#include "lanes/contact64_transpose.hpp"
#include "lanes/contact_acceptance_lanes.hpp"
#include "lanes/contact_compress_lanes.hpp"
#include "lanes/contact_lanes.hpp"
#include "lanes/distance_lanes.hpp"
#include "lanes/record64_transpose.hpp"
#include "lanes/record_transpose.hpp"
#include "support/fetch_ahead.hpp"

#include <obbsat/closest_points.hpp>
#include <obbsat/contact_manifold.hpp>
#include <obbsat/rect.hpp>
#include <obbsat/rect64.hpp>

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <type_traits>
#include <utility>

namespace obbsat::detail {
namespace {

/// The contact of the real type: contact (float) or contact64 (double).
template <class Real>
using contact_of_real = std::conditional_t<std::is_same<Real, float>::value, contact, contact64>;

static_assert(sizeof(contact) == 12 * sizeof(float) && sizeof(contact64) == 12 * sizeof(double),
              "a contact is twelve fields as wide as its reals (the integers' padding included)");

/// The twelve fields of a contact, each as wide as a real, in its memory order, per lane.
template <class Arch, class Real>
struct contact_fields {
    real_lanes<Arch, Real> f[12];
};

template <class Arch, class Real>
OBBSAT_LANE_INLINE contact_fields<Arch, Real> fields_of(const contact_out_lanes<Arch, Real>& c) {
    return contact_fields<Arch, Real>{{c.nx, c.ny, c.depth, c.count, c.x[0], c.y[0], c.separation[0], c.feature[0],
                                       c.x[1], c.y[1], c.separation[1], c.feature[1]}};
}

/// The contacts of one vector of pairs from each lane's two records of
/// Fields reals (fa, fb: one vector per field), A's first two fields the origin.
template <class Arch, class Real, bool Corners>
OBBSAT_LANE_INLINE contact_fields<Arch, Real> contacts_of_fields(const real_lanes<Arch, Real>* fa,
                                                                 const real_lanes<Arch, Real>* fb, Real margin) {
    const real_lanes<Arch, Real> origin_x = fa[0], origin_y = fa[1];
    if constexpr (Corners) {
        const contact_box_lanes<Arch, Real> a = contact_corner_box<Arch, Real>(fa, origin_x, origin_y);
        const contact_box_lanes<Arch, Real> b = contact_corner_box<Arch, Real>(fb, origin_x, origin_y);
        real_mask<Arch, Real> within;
        const reference_lanes<Arch, Real> ref = reference_of_boxes<Arch, Real>(a, b, margin, within);
        const contact_box_lanes<Arch, Real> incident = either_box<Arch, Real>(ref.flip, a, b);
        return fields_of<Arch, Real>(
            manifold_lanes_of<Arch, Real>(incident, ref, within, origin_x, origin_y, margin));
    } else {
        return fields_of<Arch, Real>(contact_pose_lanes_of<Arch, Real>(fa, fb, margin));
    }
}

/// Writes lane i of `c` to place(i), a contact* (contact64* for double), for
/// the first `valid` lanes: a whole vector of float contacts by three 4x4
/// transposes (each a third of every contact), of double ones by 4x4
/// transposes of doubles (contact64_transpose.hpp), a partial vector
/// through a staging copy.
template <class Arch, class Real, class Place>
OBBSAT_LANE_INLINE void store_contacts_to(const contact_fields<Arch, Real>& c, const Place& place,
                                          std::size_t valid) {
    constexpr std::size_t width = real_lanes<Arch, Real>::size;
    if constexpr (std::is_same<Real, float>::value) {
        if (valid == width) {
            auto put = [&place](std::size_t lane) { return reinterpret_cast<float*>(place(lane)); };
            using blocks = std::make_integer_sequence<unsigned, width / 4>;
            for (unsigned third = 0; third < 3; ++third) {
                record_transpose<Arch>::store_half(c.f + 4 * third, third, put, blocks{});
            }
            return;
        }
    } else if (valid == width) {
        contact64_transpose<Arch>::store(c.f, place);
        return;
    }
    alignas(64) Real staged[12][width];
    for (int f = 0; f < 12; ++f) {
        c.f[f].store_aligned(staged[f]);
    }
    for (std::size_t lane = 0; lane < valid; ++lane) {
        Real row[12];
        for (int f = 0; f < 12; ++f) {
            row[f] = staged[f][lane];
        }
        std::memcpy(place(lane), row, sizeof row);
    }
}

/// Writes a whole vector of float contacts without points (count 0, every
/// point field zero) from their normal and depth at out[0 .. width): one 4x4
/// transpose gives each contact's first 16 bytes, (nx, ny, depth, 0), in a
/// 128-bit block, and every 64 (AVX-512) or 32 (AVX2) bytes of the answer is
/// then one register of those blocks and zeros, stored whole. Every contact
/// of a scene's pairs is first written so, and this is a third of the
/// stores, and of the shuffles, of the general transposes of store_contacts.
template <class Arch>
OBBSAT_LANE_INLINE void store_contacts_without_points(const lanes<Arch>& nx, const lanes<Arch>& ny,
                                                      const lanes<Arch>& depth, contact* out) {
    using transpose = record_transpose<Arch>;
    constexpr std::size_t width = lanes<Arch>::size;
    float* to = reinterpret_cast<float*>(out);
    const typename transpose::reg firsts[4] = {nx, ny, depth, lanes<Arch>(0.0f)};
    lanes<Arch> block[4];  // block j of block[k]: contact 4j + k's first 16 bytes
    transpose::transpose4(firsts, block);
    // Contacts 4j to 4j + 3 are 48 floats: three AVX-512 registers, the
    // nonzero blocks at quads 0 and 3, 6, 9; or six AVX2 ones.
    if constexpr (width == 16) {
#ifdef __AVX512F__
        auto put = [&](auto j) {
            constexpr int at = static_cast<int>(decltype(j)::value);
            constexpr int twice = at | (at << 2) | (at << 4) | (at << 6);
            _mm512_storeu_ps(to + 48 * at, _mm512_maskz_shuffle_f32x4(0xf00f, block[0], block[1], twice));
            _mm512_storeu_ps(to + 48 * at + 16, _mm512_maskz_shuffle_f32x4(0x0f00, block[2], block[2], twice));
            _mm512_storeu_ps(to + 48 * at + 32, _mm512_maskz_shuffle_f32x4(0x00f0, block[3], block[3], twice));
        };
        put(std::integral_constant<unsigned, 0>{});
        put(std::integral_constant<unsigned, 1>{});
        put(std::integral_constant<unsigned, 2>{});
        put(std::integral_constant<unsigned, 3>{});
#endif
    } else if constexpr (width == 8) {
#ifdef __AVX__
        const __m256 zero = _mm256_setzero_ps();
        auto put = [&](auto j) {
            constexpr int at = static_cast<int>(decltype(j)::value);
            float* four = to + 48 * at;
            _mm256_storeu_ps(four, _mm256_permute2f128_ps(block[0], block[0], 0x80 | at));
            _mm256_storeu_ps(four + 8, _mm256_permute2f128_ps(block[1], block[1], 0x08 | (at << 4)));
            _mm256_storeu_ps(four + 16, zero);
            _mm256_storeu_ps(four + 24, _mm256_permute2f128_ps(block[2], block[2], 0x80 | at));
            _mm256_storeu_ps(four + 32, _mm256_permute2f128_ps(block[3], block[3], 0x08 | (at << 4)));
            _mm256_storeu_ps(four + 40, zero);
        };
        put(std::integral_constant<unsigned, 0>{});
        put(std::integral_constant<unsigned, 1>{});
#endif
    } else {
        const __m128 zero = _mm_setzero_ps();
        for (std::size_t k = 0; k < 4; ++k) {
            _mm_storeu_ps(to + 12 * k, block[k]);
            _mm_storeu_ps(to + 12 * k + 4, zero);
            _mm_storeu_ps(to + 12 * k + 8, zero);
        }
    }
}

/// Writes lane i of `c` as out[i] for the first `valid` lanes.
template <class Arch, class Real>
OBBSAT_LANE_INLINE void store_contacts(const contact_fields<Arch, Real>& c, contact_of_real<Real>* out,
                                       std::size_t valid) {
    store_contacts_to<Arch, Real>(c, [out](std::size_t lane) { return out + lane; }, valid);
}

/// Loads the records of one vector of pairs into fa and fb (one vector per
/// field; Fields reals read, six for a pose, eight for corners): lane i
/// holds pair pair_of(i), pairs[pair_of(i)] of a list or record pair_of(i)
/// of a stream. Records of eight reals (pose_records, corner records and
/// their double stores, the only double records) are read whole and
/// transposed in registers, other rows through a staging copy.
template <class Arch, class Real, std::size_t Fields, class PairOf>
OBBSAT_LANE_INLINE void load_vector_of_pairs(const Real* a, std::size_t a_stride, const Real* b,
                                             std::size_t b_stride, const pair_index* pairs, const PairOf& pair_of,
                                             real_lanes<Arch, Real>* fa, real_lanes<Arch, Real>* fb) {
    using batch = real_lanes<Arch, Real>;
    constexpr std::size_t width = batch::size;
    [[maybe_unused]] const bool whole_records = a_stride == 8 && b_stride == 8;
    auto record_a = [&](std::size_t pair) { return a + 8 * (pairs != nullptr ? pairs[pair].a : pair); };
    auto record_b = [&](std::size_t pair) { return b + 8 * (pairs != nullptr ? pairs[pair].b : pair); };
    if constexpr (std::is_same<Real, double>::value && Fields == 6) {
        const pose64_lanes<Arch> pa = pose64_record_transpose<Arch>::load([&](std::size_t lane) {
            return record_a(pair_of(lane));
        });
        const pose64_lanes<Arch> pb = pose64_record_transpose<Arch>::load([&](std::size_t lane) {
            return record_b(pair_of(lane));
        });
        const batch from_a[6] = {pa.cx, pa.cy, pa.hx, pa.hy, pa.c, pa.s};
        const batch from_b[6] = {pb.cx, pb.cy, pb.hx, pb.hy, pb.c, pb.s};
        for (std::size_t f = 0; f < 6; ++f) {
            fa[f] = from_a[f];
            fb[f] = from_b[f];
        }
    } else if constexpr (std::is_same<Real, double>::value) {
        const quad<batch> qa = record64_transpose<Arch>::load(
            [&](std::size_t lane) { return reinterpret_cast<const rect64*>(record_a(pair_of(lane))); });
        const quad<batch> qb = record64_transpose<Arch>::load(
            [&](std::size_t lane) { return reinterpret_cast<const rect64*>(record_b(pair_of(lane))); });
        for (std::size_t f = 0; f < 8; ++f) {
            fa[f] = qa.c[f];
            fb[f] = qb.c[f];
        }
    } else if (whole_records) {
        const quad_lanes<Arch> qa = record_transpose<Arch>::template load<false>(
            [&](std::size_t lane) { return reinterpret_cast<const rect*>(record_a(pair_of(lane))); });
        const quad_lanes<Arch> qb = record_transpose<Arch>::template load<false>(
            [&](std::size_t lane) { return reinterpret_cast<const rect*>(record_b(pair_of(lane))); });
        for (std::size_t f = 0; f < 8; ++f) {
            fa[f] = qa.c[f];
            fb[f] = qb.c[f];
        }
    } else {
        alignas(64) Real staged_a[Fields][width];
        alignas(64) Real staged_b[Fields][width];
        for (std::size_t lane = 0; lane < width; ++lane) {
            const std::size_t pair = pair_of(lane);
            const Real* ra = a + a_stride * (pairs != nullptr ? pairs[pair].a : pair);
            const Real* rb = b + b_stride * (pairs != nullptr ? pairs[pair].b : pair);
            for (std::size_t f = 0; f < Fields; ++f) {
                staged_a[f][lane] = ra[f];
                staged_b[f][lane] = rb[f];
            }
        }
        for (std::size_t f = 0; f < Fields; ++f) {
            fa[f] = batch::load_aligned(staged_a[f]);
            fb[f] = batch::load_aligned(staged_b[f]);
        }
    }
}

/// Asks for the records of pairs [from, to) of a list (fetch_ahead.hpp). A
/// list sorted by its first index, as a broadphase emits it, reads the
/// first records in order, a few pairs to each. For float records, when the
/// first indices of these pairs lie within four records a pair, the core's
/// own prefetcher streams those records from L3, and only the second ones
/// are asked for: asking for both took 256K sorted pairs over 128K poses (a
/// 4 MiB store, a 12 MiB answer) 10-15% longer with AVX-512, each prefetch
/// a load slot. Double records are asked for both: there the answer is
/// twice as large and pushes the store out of L3, and without them the same
/// pairs took 25% longer. Other lists (shuffled) ask for both.
template <pair_fetch Fetch, class Real>
OBBSAT_LANE_INLINE void fetch_records_of_pairs(const Real* a, std::size_t a_stride, const Real* b,
                                               std::size_t b_stride, const pair_index* pairs, std::size_t from,
                                               std::size_t to) {
    // Unsigned: a last index below the first is a spread as large as any.
    const bool streamed =
        std::is_same<Real, float>::value && std::size_t{pairs[to - 1].a - pairs[from].a} < 4 * (to - from);
    if (streamed) {
        for (std::size_t k = from; k < to; ++k) {
            fetch_record<Fetch>(b + b_stride * pairs[k].b);
        }
    } else {
        for (std::size_t k = from; k < to; ++k) {
            fetch_record<Fetch>(a + a_stride * pairs[k].a);
            fetch_record<Fetch>(b + b_stride * pairs[k].b);
        }
    }
}

/// Walks pairs [0, count) one vector at a time: loads each lane's two
/// records into fa and fb (load_vector_of_pairs) and calls body(fa, fb, i,
/// valid) for the vector of pairs i to i + valid. Whole vectors take the
/// pair indices as they are; the last, partial vector repeats its last pair
/// in the unused lanes, so nothing past the caller's arrays is read. A pair
/// list's records are read at random: those of the pairs ahead, up to pair
/// `fetchable` of the list, are asked into L2 (fetch_ahead.hpp), which costs
/// two instructions a pair against a contact's hundreds and hides the reads
/// of a store larger than the caches; records just read are not fetched
/// again (fetchable 0), nor any with Fetch none (a store the caches hold).
template <class Arch, class Real, std::size_t Fields, pair_fetch Fetch = pair_fetch::into_l2, class Body>
OBBSAT_LANE_INLINE void for_each_vector_of_pairs(const Real* a, std::size_t a_stride, const Real* b,
                                                 std::size_t b_stride, const pair_index* pairs, std::size_t count,
                                                 std::size_t fetchable, const Body& body) {
    using batch = real_lanes<Arch, Real>;
    constexpr std::size_t width = batch::size;
    constexpr std::size_t ahead = pairs_ahead<Fetch>;
    std::size_t i = 0;
    for (; i + width <= count; i += width) {
        if (Fetch != pair_fetch::none && pairs != nullptr && i + width + ahead <= fetchable) {
            fetch_records_of_pairs<Fetch>(a, a_stride, b, b_stride, pairs, i + ahead, i + ahead + width);
        }
        batch fa[8], fb[8];
        load_vector_of_pairs<Arch, Real, Fields>(a, a_stride, b, b_stride, pairs,
                                                 [i](std::size_t lane) { return i + lane; }, fa, fb);
        body(fa, fb, i, width);
    }
    // The last, partial vector, if any (a loop run at most once: written as an
    // if, the double 256K row compiled 35% slower with GCC 12 on AVX-512).
    for (; i < count; i += width) {
        const std::size_t valid = count - i;
        batch fa[8], fb[8];
        load_vector_of_pairs<Arch, Real, Fields>(
            a, a_stride, b, b_stride, pairs, [i, valid](std::size_t lane) { return i + (lane < valid ? lane : valid - 1); },
            fa, fb);
        body(fa, fb, i, valid);
    }
}

/// Walks the pairs at places[0, count) of a list (or the rows at those
/// places of a stream) one vector at a time, as for_each_vector_of_pairs
/// walks a list: body(fa, fb, k, valid) for places k to k + valid, the last,
/// partial vector repeating its last place. Fetches nothing: the places are
/// pairs whose records were just read.
template <class Arch, class Real, std::size_t Fields, class Body>
OBBSAT_LANE_INLINE void for_each_vector_of_places(const Real* a, std::size_t a_stride, const Real* b,
                                                  std::size_t b_stride, const pair_index* pairs,
                                                  const std::uint32_t* places, std::size_t count, const Body& body) {
    using batch = real_lanes<Arch, Real>;
    constexpr std::size_t width = batch::size;
    std::size_t k = 0;
    for (; k + width <= count; k += width) {
        batch fa[8], fb[8];
        load_vector_of_pairs<Arch, Real, Fields>(a, a_stride, b, b_stride, pairs,
                                                 [&](std::size_t lane) { return places[k + lane]; }, fa, fb);
        body(fa, fb, k, width);
    }
    for (; k < count; k += width) {
        const std::size_t valid = count - k;
        batch fa[8], fb[8];
        load_vector_of_pairs<Arch, Real, Fields>(
            a, a_stride, b, b_stride, pairs,
            [&](std::size_t lane) { return places[k + (lane < valid ? lane : valid - 1)]; }, fa, fb);
        body(fa, fb, k, valid);
    }
}

/// out[i] = the contact of box a(i) and box b(i) (see contact_fn, contact64_fn).
template <class Arch, class Real, std::size_t Fields, bool Corners>
void contact_batch(const Real* a, std::size_t a_stride, const Real* b, std::size_t b_stride,
                   const pair_index* pairs, std::size_t count, Real margin, contact_of_real<Real>* out) {
    for_each_vector_of_pairs<Arch, Real, Fields>(
        a, a_stride, b, b_stride, pairs, count, count,
        [&](const real_lanes<Arch, Real>* fa, const real_lanes<Arch, Real>* fb, std::size_t i, std::size_t valid)
            __attribute__((always_inline)) {
                store_contacts<Arch, Real>(contacts_of_fields<Arch, Real, Corners>(fa, fb, margin), out + i, valid);
            });
}

/// Appends the place i + lane of every lane set in `bits` (all below the
/// vector's valid lanes) to near_at[count); returns the new count. The array
/// may be written up to 16 entries past it. The second pass reads each kept
/// pair through its place (pairs[place], or the rows at place of a stream),
/// from a list L1 holds: compressing the pairs themselves beside their places
/// took a quarter of the first pass's bookkeeping. AVX-512 and AVX2 compress
/// the places in registers (contact_compress_lanes.hpp); SSE2 writes every
/// valid lane and advances by its bit, without a branch: a loop over the set
/// bits mispredicted its exit on most vectors.
template <class Arch>
OBBSAT_LANE_INLINE std::size_t append_near_lanes(unsigned bits, std::size_t i, std::size_t valid,
                                                 std::uint32_t* near_at, std::size_t count) {
    if constexpr (compresses_lanes<Arch>()) {
        store_compressed_places<Arch>(bits, static_cast<std::uint32_t>(i), near_at + count);
        return count + static_cast<std::size_t>(__builtin_popcount(bits));
    }
    for (std::size_t lane = 0; lane < valid; ++lane) {
        near_at[count] = static_cast<std::uint32_t>(i + lane);
        count += (bits >> lane) & 1u;
    }
    return count;
}

/// What pose_reference_of chose for the pairs within the margin, kept in
/// order beside them, so that the contacts of those pairs need not choose
/// again: that choice (two square roots, two divisions and method local's
/// axes) is a third of their cost, and AVX-512 and AVX2 compress the kept
/// lanes in registers (contact_compress_lanes.hpp). SSE2 does not, and
/// chooses again (holds false, nothing kept).
template <class Arch, class Real, std::size_t Block>
struct kept_references {
    static constexpr bool holds = compresses_lanes<Arch>();
    using batch = real_lanes<Arch, Real>;
    static constexpr std::size_t width = batch::size;
    static constexpr std::size_t fields = holds ? 5 : 1;
    static constexpr std::size_t rows = holds ? Block + width : 1;
    /// Field f of kept pair k at field[f][k]: r + 4 where flip (else r), the
    /// separation of the reference box's best face, the incident box's
    /// reciprocal length, ux, uy: all that steps 4 to 8 read of the choice
    /// for a pair within the margin (pose_choice_lanes), whose test of the
    /// margin holds for every kept pair (known_within). Every keep
    /// writes a whole vector from `count`, so a vector read from the last
    /// kept pair reads only written reals.
    alignas(64) Real field[fields][rows];

    /// Appends the lanes of `bits` of `p` from kept pair `count`.
    OBBSAT_LANE_INLINE void keep(unsigned bits, const pose_choice_lanes<Arch, Real>& p, std::size_t count) {
        if constexpr (holds) {
            const batch values[5] = {p.r + pick<Arch, Real>(p.flip, batch(Real(4)), batch(Real(0))), p.sep, p.inc_inv,
                                     p.ux, p.uy};
            for (std::size_t f = 0; f < 5; ++f) {
                store_compressed<Arch, Real>(bits, values[f], field[f] + count);
            }
        } else {
            (void)bits, (void)p, (void)count;
        }
    }

    /// The contacts of kept pairs k to k + width from their records' fields.
    OBBSAT_LANE_INLINE contact_out_lanes<Arch, Real> contacts_at(const batch* fa, const batch* fb, std::size_t k,
                                                                 Real margin) const {
        if constexpr (holds) {
            auto load = [&](std::size_t f) { return batch::load_unaligned(field[f] + k); };
            const batch code = load(0);
            const auto flip = code >= batch(Real(4));
            const batch r = code - pick<Arch, Real>(flip, batch(Real(4)), batch(Real(0)));
            const pose_choice_lanes<Arch, Real> p{flip, r, load(1), load(2), load(3), load(4)};
            return contact_pose_lanes_from<Arch, Real>(fa, fb, p, known_within{}, margin);
        } else {
            (void)k;
            return contact_pose_lanes_of<Arch, Real>(fa, fb, margin);
        }
    }
};

/// out[i] = the contact of poses a(i) and b(i) (see contact_fn, contact64_fn), in blocks
/// of pairs: first every pair's normal and depth without points (pose steps
/// P1 to P3 and step 4), then, packed into whole vectors, only the pairs
/// whose best faces leave them within the margin, in full. Steps 5 to 8 cost
/// more than half of a contact, and in a scene's candidate pairs most boxes
/// are apart (two thirds of a typical scene's). Each pair's contact is
/// computed by the same lanes either way, so the bits do not change. Fetch
/// into_l2 asks for the records of the pairs ahead (for_each_vector_of_pairs);
/// none asks for nothing, for a store the caches hold: there the two
/// prefetches a pair and their addresses cost a tenth of a contact (4K pairs
/// over 2K poses: 16.3 against 14.7 us with AVX-512) and bring nothing.
template <class Arch, class Real, std::size_t Fields, pair_fetch Fetch>
void contact_pose_batch(const Real* a, std::size_t a_stride, const Real* b, std::size_t b_stride,
                        const pair_index* pairs, std::size_t count, Real margin, contact_of_real<Real>* out) {
    using batch = real_lanes<Arch, Real>;
    using contact_type = contact_of_real<Real>;
    constexpr std::size_t width = batch::size;
    // A block's contacts (24 KiB in float), what its first pass keeps for
    // the second (10 KiB) and its pair lists (6 KiB) stay in a 48 KiB L1
    // until the second pass writes over the contacts of the pairs within the
    // margin: blocks of 1024, twice that, made 256K pairs 10% slower.
    constexpr std::size_t block = 512;
    // The first pass stores 48 bytes a pair (96 in double) faster than the lines it writes
    // arrive from memory: a batch larger than the caches (256K pairs, 12 MiB
    // of contacts) took 1.9 ms against 1.3 until the lines 512 contacts ahead
    // were asked for, for writing.
    // An answer L2 holds (4K pairs: 192 KiB) is not asked for: there the
    // twelve prefetches of a vector bring nothing.
    constexpr std::size_t written_ahead = 512;
    const std::size_t written_until = count * sizeof(contact_type) > store_bytes_in_l2 ? count : 0;
    // append_near_lanes may write 16 entries past the last.
    std::uint32_t near_at[block + 16];
    kept_references<Arch, Real, block> kept;
    for (std::size_t begin = 0; begin < count; begin += block) {
        const std::size_t n = count - begin < block ? count - begin : block;
        // A stream's block starts at its own rows; a list's at its own pairs.
        const pair_index* block_pairs = pairs != nullptr ? pairs + begin : nullptr;
        const Real* block_a = pairs != nullptr ? a : a + a_stride * begin;
        const Real* block_b = pairs != nullptr ? b : b + b_stride * begin;
        contact_type* block_out = out + begin;
        std::size_t near_count = 0;
        // The lines of the answer `written_ahead` contacts past pair i, asked for writing.
        auto fetch_written = [&](std::size_t i) __attribute__((always_inline)) {
            if (begin + i + width + written_ahead <= written_until) {
                const char* line = reinterpret_cast<const char*>(block_out + i + written_ahead);
                for (std::size_t k = 0; k < width * sizeof(contact_type); k += 64) {
                    __builtin_prefetch(line + k, 1, 3);
                }
            }
        };
        // Writes the contacts without points of pairs i to i + valid and keeps those within the margin.
        auto write_apart = [&](const pose_reference_lanes<Arch, Real>& reference, std::size_t i, std::size_t valid)
            __attribute__((always_inline)) {
                const unsigned valid_lanes = valid == width ? ~0u : (1u << valid) - 1u;
                const unsigned near_lanes = lane_bits(may_have_points<Arch, Real>(reference, margin)) & valid_lanes;
                const pose_choice_lanes<Arch, Real> p = pose_choice_of<Arch, Real>(reference);
                // A vector whose every pair is within the margin (most of a
                // scene's colliding pairs) has each contact written by the
                // second pass: nothing to write here.
                if (near_lanes != valid_lanes) {
                    const contact_out_lanes<Arch, Real> apart =
                        contact_without_points<Arch, Real>(p.flip, p.ux, p.uy, p.sep);
                    if constexpr (std::is_same<Real, float>::value) {
                        if (valid == width) {
                            store_contacts_without_points<Arch>(apart.nx, apart.ny, apart.depth, block_out + i);
                        } else {
                            store_contacts<Arch, Real>(fields_of<Arch, Real>(apart), block_out + i, valid);
                        }
                    } else {
                        store_contacts<Arch, Real>(fields_of<Arch, Real>(apart), block_out + i, valid);
                    }
                }
                kept.keep(near_lanes, p, near_count);
                near_count = append_near_lanes<Arch>(near_lanes, i, valid, near_at, near_count);
            };
        for_each_vector_of_pairs<Arch, Real, Fields, Fetch>(
            block_a, a_stride, block_b, b_stride, block_pairs, n, count - begin,
            [&](const batch* fa, const batch* fb, std::size_t i, std::size_t valid) __attribute__((always_inline)) {
                fetch_written(i);
                write_apart(pose_reference_of<Arch, Real>(fa, fb), i, valid);
            });
        for_each_vector_of_places<Arch, Real, Fields>(
            block_a, a_stride, block_b, b_stride, block_pairs, near_at, near_count,
            [&](const batch* fa, const batch* fb, std::size_t k, std::size_t valid) __attribute__((always_inline)) {
                store_contacts_to<Arch, Real>(fields_of<Arch, Real>(kept.contacts_at(fa, fb, k, margin)),
                                              [&](std::size_t lane) { return block_out + near_at[k + lane]; },
                                              valid);
            });
    }
}

/// The closest points of the real type: closest_points (float) or closest_points64 (double).
template <class Real>
using closest_points_of_real = std::conditional_t<std::is_same<Real, float>::value, closest_points, closest_points64>;

/// out[i] = the distance and closest points of box a(i) and box b(i) (see distance_fn, distance64_fn).
template <class Arch, class Real, std::size_t Fields, bool Corners>
void distance_batch(const Real* a, std::size_t a_stride, const Real* b, std::size_t b_stride,
                    const pair_index* pairs, std::size_t count, closest_points_of_real<Real>* out) {
    using batch = real_lanes<Arch, Real>;
    constexpr std::size_t width = batch::size;
    for_each_vector_of_pairs<Arch, Real, Fields>(
        a, a_stride, b, b_stride, pairs, count, count,
        [&](const batch* fa, const batch* fb, std::size_t i, std::size_t valid) __attribute__((always_inline)) {
            const closest_points_lanes<Arch, Real> c = distance_lanes_of<Arch, Real, Corners>(fa, fb);
            alignas(64) Real staged[5][width];
            const batch* fields[5] = {&c.distance, &c.ax, &c.ay, &c.bx, &c.by};
            for (int f = 0; f < 5; ++f) {
                fields[f]->store_aligned(staged[f]);
            }
            for (std::size_t lane = 0; lane < valid; ++lane) {
                out[i + lane] = closest_points_of_real<Real>{staged[0][lane], staged[1][lane], staged[2][lane],
                                                             staged[3][lane], staged[4][lane]};
            }
        });
}

/// The contact table of this ISA.
template <class Arch>
constexpr contact_kernel_table contact_table_of() {
    return contact_kernel_table{contact_pose_batch<Arch, float, 6, pair_fetch::into_l2>,
                                contact_pose_batch<Arch, float, 6, pair_fetch::none>,
                                contact_batch<Arch, float, 8, true>,
                                distance_batch<Arch, float, 6, false>,
                                distance_batch<Arch, float, 8, true>,
                                contact_pose_batch<Arch, double, 6, pair_fetch::into_l2>,
                                contact_pose_batch<Arch, double, 6, pair_fetch::none>,
                                contact_batch<Arch, double, 8, true>,
                                distance_batch<Arch, double, 6, false>,
                                distance_batch<Arch, double, 8, true>,
                                pose_records_accepted<Arch, float>,
                                pose_records_accepted<Arch, double>};
}

}  // namespace
}  // namespace obbsat::detail
