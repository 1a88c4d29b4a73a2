#include "sort/pair_sort.hpp"

#include "support/bit_width.hpp"
#include "support/huge_pages.hpp"
#include "support/work_shares.hpp"

#include <algorithm>
#include <functional>

namespace obbsat::detail {

namespace {

constexpr unsigned bucket_bits = 8;

/// Sorts pairs[0, n), all of whose a share their high bits, by a then b:
/// a counting sort on the low `low_bits` of a through `spare`, then each
/// run of equal a sorted by b on its way back.
template <class Pair>
void sort_bucket(Pair* pairs, std::size_t n, unsigned low_bits, std::vector<Pair>& spare,
                 std::vector<std::uint32_t>& counts) {
    if (n < 2) {
        return;
    }
    const std::uint32_t mask = (std::uint32_t{1} << low_bits) - 1;
    if (n < 32) {
        std::sort(pairs, pairs + n, [](const Pair& x, const Pair& y) {
            return x.a < y.a || (x.a == y.a && x.b < y.b);
        });
        return;
    }
    const std::size_t values = std::size_t{1} << low_bits;
    counts.assign(values + 1, 0);
    for (std::size_t i = 0; i < n; ++i) {
        ++counts[(pairs[i].a & mask) + 1];
    }
    for (std::size_t v = 0; v < values; ++v) {
        counts[v + 1] += counts[v];
    }
    spare.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
        spare[counts[pairs[i].a & mask]++] = pairs[i];
    }
    // counts[v] is now the end of the run of low bits v, that is of one a.
    // Each run goes back to `pairs` sorted by b: a short one by ranks (each
    // pair to the count of pairs before it: smaller b, or equal b earlier),
    // comparisons without branches, where an insertion sort would mispredict
    // about once per pair; a long one by std::sort.
    constexpr std::size_t short_run = 16;
    std::size_t begin = 0;
    for (std::size_t v = 0; v < values; ++v) {
        const std::size_t end = counts[v];
        const std::size_t m = end - begin;
        const Pair* const from = spare.data() + begin;
        Pair* const to = pairs + begin;
        if (m > short_run) {
            std::sort(spare.begin() + static_cast<std::ptrdiff_t>(begin),
                      spare.begin() + static_cast<std::ptrdiff_t>(end),
                      [](const Pair& x, const Pair& y) { return x.b < y.b; });
            std::copy(from, from + m, to);
        } else {
            for (std::size_t i = 0; i < m; ++i) {
                const std::uint32_t b = from[i].b;
                std::size_t rank = 0;
                for (std::size_t j = 0; j < i; ++j) {
                    rank += static_cast<std::size_t>(from[j].b <= b);
                }
                for (std::size_t j = i + 1; j < m; ++j) {
                    rank += static_cast<std::size_t>(from[j].b < b);
                }
                to[rank] = from[i];
            }
        }
        begin = end;
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
    out.resize(n);
    if (n == 0) {
        return;
    }
    const auto run = [](std::size_t parts, const std::function<void(std::size_t)>& task) {
        if (parts <= 1) {
            task(0);
        } else {
            run_parts(parts, task);
        }
    };
    const unsigned a_bits = bits_for(a_count > 0 ? a_count - 1 : 0);
    const unsigned high_shift = a_bits > bucket_bits ? a_bits - bucket_bits : 0;
    const std::size_t buckets = (a_count > 0 ? (a_count - 1) >> high_shift : 0) + 1;
    // Pass 1: the pairs of all sources, taken one after the other, split
    // into equal shares, one a thread (sources may differ in size: a mixed
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
    const std::size_t shares = std::max<std::size_t>(1, std::min(sources.size(), n / 4096));
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
    std::vector<std::vector<std::size_t>> next(shares, std::vector<std::size_t>(buckets, 0));
    run(shares, [&](std::size_t share) {
        std::vector<std::size_t>& count = next[share];
        for_share(share, [&](const Pair& p) { ++count[p.a >> high_shift]; });
    });
    std::vector<std::size_t> begin(buckets + 1, 0);
    std::size_t sum = 0;
    for (std::size_t k = 0; k < buckets; ++k) {
        begin[k] = sum;
        for (std::size_t share = 0; share < shares; ++share) {
            const std::size_t here = next[share][k];
            next[share][k] = sum;
            sum += here;
        }
    }
    begin[buckets] = sum;
    run(shares, [&](std::size_t share) {
        std::vector<std::size_t>& slot = next[share];
        Pair* const to = out.data();
        for_share(share, [&](const Pair& p) { to[slot[p.a >> high_shift]++] = p; });
    });
    // Pass 2: each bucket on its own, the buckets split between the threads
    // by the pairs they hold: a is the smaller index of a pair, so low
    // buckets hold more (the lower half of the indices about three quarters).
    const std::size_t parts = std::max<std::size_t>(1, std::min(scratch.size(), n / 65536));
    std::vector<std::size_t> first_bucket(parts + 1, buckets);
    for (std::size_t part = 0, k = 0; part < parts; ++part) {
        while (k < buckets && begin[k] < n * part / parts) {
            ++k;
        }
        first_bucket[part] = k;
    }
    run(parts, [&](std::size_t part) {
        for (std::size_t k = first_bucket[part]; k < first_bucket[part + 1]; ++k) {
            sort_bucket(out.data() + begin[k], begin[k + 1] - begin[k], high_shift, scratch[part].spare,
                        scratch[part].counts);
        }
    });
}

template void sort_pairs<pair_index>(const std::vector<pair_source<pair_index>>&, std::size_t,
                                     std::vector<pair_index>&, std::vector<pair_sort_scratch<pair_index>>&);
template void sort_pairs<tagged_pair>(const std::vector<pair_source<tagged_pair>>&, std::size_t,
                                      std::vector<tagged_pair>&, std::vector<pair_sort_scratch<tagged_pair>>&);

}  // namespace obbsat::detail
