#include "sort/pair_sort.hpp"

#include "support/bit_width.hpp"
#include "support/huge_pages.hpp"
#include "support/work_shares.hpp"

#include <algorithm>
#include <functional>

namespace obbsat::detail {

namespace {

constexpr unsigned bucket_bits = 8;

/// Bits of b a bucket's first counting sort looks at: the highest ones.
constexpr unsigned b_digit_bits = 12;

/// Sorts pairs[0, n), all of whose a share their high bits, by a then b, b
/// below 2^b_bits: two stable counting sorts, by the highest b_digit_bits of
/// b through `spare` and back by the low `low_bits` of a, leave each run of
/// equal a sorted but for partners whose b share those high bits; a last
/// read finds them and sorts their run. A run of equal a holds a handful of
/// pairs in a scene, and sorting each one by b mispredicted a branch or two
/// per run (ranks over a variable-length run, or an insertion sort); here
/// nothing branches on the data but the rare disorder.
template <class Pair>
void sort_bucket(Pair* pairs, std::size_t n, unsigned low_bits, unsigned b_bits, std::vector<Pair>& spare,
                 std::vector<std::uint32_t>& counts) {
    if (n < 2) {
        return;
    }
    const auto by_pair = [](const Pair& x, const Pair& y) { return x.a < y.a || (x.a == y.a && x.b < y.b); };
    if (n < 32) {
        std::sort(pairs, pairs + n, by_pair);
        return;
    }
    const std::uint32_t mask = (std::uint32_t{1} << low_bits) - 1;
    const unsigned b_shift = b_bits > b_digit_bits ? b_bits - b_digit_bits : 0;
    const std::size_t a_values = std::size_t{1} << low_bits;
    const std::size_t b_values = std::size_t{1} << (b_bits - b_shift);
    // One read counts both digits: a digit's counts do not depend on the order.
    counts.assign(a_values + b_values, 0);
    std::uint32_t* const by_a = counts.data();
    std::uint32_t* const by_b = counts.data() + a_values;
    for (std::size_t i = 0; i < n; ++i) {
        ++by_a[pairs[i].a & mask];
        ++by_b[pairs[i].b >> b_shift];
    }
    const auto starts = [](std::uint32_t* c, std::size_t values) {
        std::uint32_t sum = 0;
        for (std::size_t v = 0; v < values; ++v) {
            const std::uint32_t here = c[v];
            c[v] = sum;
            sum += here;
        }
    };
    starts(by_a, a_values);
    starts(by_b, b_values);
    spare.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
        spare[by_b[pairs[i].b >> b_shift]++] = pairs[i];
    }
    for (std::size_t i = 0; i < n; ++i) {
        pairs[by_a[spare[i].a & mask]++] = spare[i];
    }
    // Partners of one a whose b share their high bits kept the order they
    // came in. The pairs are in order of a now, so a pair is out of place iff
    // (a, b) as one number is below the one before it: one comparison, a
    // branch taken rarely, where testing "same a" first would mispredict on
    // about every other pair. Such a run is sorted by b, once.
    const auto key_of = [](const Pair& p) { return (std::uint64_t{p.a} << 32) | p.b; };
    for (std::size_t i = 1; i < n; ++i) {
        if (key_of(pairs[i]) < key_of(pairs[i - 1])) {
            const std::uint32_t a = pairs[i].a;
            std::size_t run_begin = i - 1;
            while (run_begin > 0 && pairs[run_begin - 1].a == a) {
                --run_begin;
            }
            std::size_t run_end = i + 1;
            while (run_end < n && pairs[run_end].a == a) {
                ++run_end;
            }
            std::sort(pairs + run_begin, pairs + run_end, by_pair);
            i = run_end - 1;
        }
    }
}

}  // namespace

template <class Pair>
void sort_pairs(const std::vector<pair_source<Pair>>& sources, std::size_t a_count, std::vector<Pair>& out,
                std::vector<pair_sort_scratch<Pair>>& scratch) {
    std::size_t n = 0;
    for (const pair_source<Pair>& source : sources) {
        for (const pair_span<Pair>& span : source) {
            n += span.size;
        }
    }
    if (out.capacity() < n) {
        // Fresh memory for the sorted pairs, which rewrite all of it: no old
        // pair is copied over, and huge pages spare the resize below most of
        // its page faults (the 2M pairs of a cold query of 1M boxes: 7-8 ms of the
        // sort's 28 on one thread, 2.5-3.5 ms with huge pages).
        out.clear();
        out.reserve(n);
        advise_huge_pages(out.data(), n * sizeof(Pair));
    }
    if (n == 0) {
        out.clear();
        return;
    }
    // Threads: one a source. Both passes are cut into units taken as they
    // come (work_shares.hpp), a few a thread, so that a thread slowed by
    // other work on its core takes fewer; what each unit writes is fixed by
    // the units before it, never by which thread took it.
    const std::size_t threads = std::max<std::size_t>(1, sources.size());
    const auto run = [threads](std::size_t units, const std::function<void(std::size_t)>& task) {
        if (units <= 1) {
            task(0);
        } else {
            run_units(units, threads, task);
        }
    };
    const unsigned a_bits = bits_for(a_count > 0 ? a_count - 1 : 0);
    const unsigned high_shift = a_bits > bucket_bits ? a_bits - bucket_bits : 0;
    const std::size_t buckets = (a_count > 0 ? (a_count - 1) >> high_shift : 0) + 1;
    // Pass 1: the pairs of all sources, taken one after the other, split
    // into equal shares, a few a thread (sources may differ in size: a mixed
    // scene's strips do), each share scattered by the high bits of a after
    // the same bucket's pairs of the shares before it.
    std::vector<pair_span<Pair>> spans;
    for (const pair_source<Pair>& source : sources) {
        for (const pair_span<Pair>& span : source) {
            if (span.size != 0) {
                spans.push_back(span);
            }
        }
    }
    const std::size_t shares =
        units_for(n, std::max<std::size_t>(1, std::min(threads, n / 4096)), 4096);
    // Calls f(pair) for pairs [n * share / shares, n * (share + 1) / shares) of the spans in turn.
    const auto for_share = [&](std::size_t share, const auto& f) {
        const std::size_t first = n * share / shares;
        const std::size_t last = n * (share + 1) / shares;
        std::size_t at = 0;  // index of the current span's first pair
        for (const pair_span<Pair>& span : spans) {
            const std::size_t from = std::max(first, at);
            const std::size_t to = std::min(last, at + span.size);
            for (std::size_t i = from; i < to; ++i) {
                f(span.data[i - at]);
            }
            at += span.size;
            if (at >= last) {
                break;
            }
        }
    };
    // Each share's counts are made and cleared by the unit that counts it,
    // on its own thread, rather than here for all of them.
    std::vector<std::vector<std::size_t>> counts(shares);
    std::vector<std::uint32_t> b_seen(shares, 0);  ///< every b of a share, or'ed: the bits b takes
    // Unit 0 sizes the answer (value-initialising n pairs: 2M pairs of a
    // cold query of 1M boxes took 2-6 ms, page faults and zeroing) while the
    // other units count, which read only the sources: on two threads the
    // resize is no longer a step the second thread waits through. Being the
    // first unit, it is taken first, never left for the end.
    run(shares + 1, [&](std::size_t unit) {
        if (unit == 0) {
            out.resize(n);
            return;
        }
        const std::size_t share = unit - 1;
        std::vector<std::size_t>& count = counts[share];
        count.assign(buckets, 0);
        std::uint32_t b_any = 0;
        for_share(share, [&](const Pair& p) {
            ++count[p.a >> high_shift];
            b_any |= p.b;
        });
        b_seen[share] = b_any;
    });
    std::uint32_t b_any = 0;
    for (const std::uint32_t b : b_seen) {
        b_any |= b;
    }
    const unsigned b_bits = bits_for(b_any);
    // slots[share * buckets + k]: where the share's first pair of bucket k
    // goes. A table of their own, not written over the counts: a count the
    // other thread wrote is read from its core, where writing it would wait
    // for each cache line to leave that core.
    std::vector<std::size_t> begin(buckets + 1, 0);
    std::vector<std::size_t> slots(shares * buckets);
    std::size_t sum = 0;
    for (std::size_t k = 0; k < buckets; ++k) {
        begin[k] = sum;
        for (std::size_t share = 0; share < shares; ++share) {
            slots[share * buckets + k] = sum;
            sum += counts[share][k];
        }
    }
    begin[buckets] = sum;
    run(shares, [&](std::size_t share) {
        std::size_t* const slot = slots.data() + share * buckets;
        Pair* const to = out.data();
        for_share(share, [&](const Pair& p) { to[slot[p.a >> high_shift]++] = p; });
    });
    // Pass 2: each bucket on its own, the buckets split into units by the
    // pairs they hold: a is the smaller index of a pair, so low buckets hold
    // more (the lower half of the indices about three quarters). Each unit
    // has working memory of its own.
    const std::size_t parts =
        units_for(n, std::max<std::size_t>(1, std::min(threads, n / 65536)), 16384);
    if (scratch.size() < parts) {
        scratch.resize(parts);
    }
    std::vector<std::size_t> first_bucket(parts + 1, buckets);
    for (std::size_t part = 0, k = 0; part < parts; ++part) {
        while (k < buckets && begin[k] < n * part / parts) {
            ++k;
        }
        first_bucket[part] = k;
    }
    run(parts, [&](std::size_t part) {
        for (std::size_t k = first_bucket[part]; k < first_bucket[part + 1]; ++k) {
            sort_bucket(out.data() + begin[k], begin[k + 1] - begin[k], high_shift, b_bits, scratch[part].spare,
                        scratch[part].counts);
        }
    });
}

template void sort_pairs<pair_index>(const std::vector<pair_source<pair_index>>&, std::size_t,
                                     std::vector<pair_index>&, std::vector<pair_sort_scratch<pair_index>>&);
template void sort_pairs<tagged_pair>(const std::vector<pair_source<tagged_pair>>&, std::size_t,
                                      std::vector<tagged_pair>&, std::vector<pair_sort_scratch<tagged_pair>>&);

}  // namespace obbsat::detail
