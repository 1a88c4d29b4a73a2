// The scene queries' sorts against std::stable_sort: radix_sort on one
// thread and split over two (the same result either way, equal keys in their
// input order), in its own buffers and in memory the caller lends, merge_by_key against std::merge in shares split by key, and
// repair_sort on nearly sorted input and past its move budget; radix_sort_indices,
// whose keys come from a fill over slices that tile them, each filled once, and
// whose values are the keys' indices; bucket_starts
// against prefix counts; sort_pairs against std::sort by (a, b). On two
// threads every step of the sorts is cut into more units than threads, taken
// in any order, with the answer of one thread.
#include "sort/pair_sort.hpp"
#include "sort/radix_sort.hpp"
#include "support/executor_scope.hpp"

#include <obbsat/collide.hpp>
#include <obbsat/executor.hpp>
#include <obbsat/scene.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <iterator>
#include <limits>
#include <numeric>
#include <string>
#include <utility>
#include <vector>

namespace {

using keyed = std::vector<std::pair<std::uint32_t, std::uint32_t>>;

/// Keys below 2^key_bits, many repeated; values the input positions.
void random_input(std::size_t n, unsigned key_bits, std::uint64_t seed, std::vector<std::uint32_t>& keys,
                  std::vector<std::uint32_t>& values) {
    obbsat::seeded_random random(seed);
    keys.resize(n);
    values.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
        keys[i] = static_cast<std::uint32_t>(random.next()) & ((std::uint32_t{1} << key_bits) - 1);
        values[i] = static_cast<std::uint32_t>(i);
    }
}

/// What a stable sort by key >> shift gives.
keyed stably_sorted(const std::vector<std::uint32_t>& keys, const std::vector<std::uint32_t>& values,
                    unsigned shift) {
    keyed out(keys.size());
    for (std::size_t i = 0; i < keys.size(); ++i) {
        out[i] = {keys[i], values[i]};
    }
    std::stable_sort(out.begin(), out.end(), [shift](const auto& x, const auto& y) {
        return (x.first >> shift) < (y.first >> shift);
    });
    return out;
}

keyed zipped(const std::vector<std::uint32_t>& keys, const std::vector<std::uint32_t>& values) {
    keyed out(keys.size());
    for (std::size_t i = 0; i < keys.size(); ++i) {
        out[i] = {keys[i], values[i]};
    }
    return out;
}

TEST(radix_sort, equals_a_stable_sort_on_one_thread_and_two) {
    for (const std::size_t n : {std::size_t{0}, std::size_t{1}, std::size_t{1000}, std::size_t{300000}}) {
        for (const unsigned key_bits : {4u, 20u, 32u}) {
            for (const std::size_t parts : {std::size_t{1}, std::size_t{2}}) {
                std::vector<std::uint32_t> keys, values;
                random_input(n, key_bits == 32 ? 31 : key_bits, n + key_bits, keys, values);
                const keyed want = stably_sorted(keys, values, 0);
                obbsat::detail::radix_buffer packed, spare;
                obbsat::detail::radix_sort(keys.data(), values.data(), n, key_bits, packed, spare, parts);
                EXPECT_EQ(zipped(keys, values), want) << n << " keys of " << key_bits << " bits, " << parts << " parts";
            }
        }
    }
}

TEST(radix_sort, on_two_threads_skips_high_digits_every_key_shares) {
    // 32 key bits asked for, keys of 12 (two digits the same for all) or all
    // one key: the split by the highest digit must take the highest that varies.
    for (const unsigned used_bits : {12u, 0u}) {
        std::vector<std::uint32_t> keys, values;
        random_input(300000, used_bits, 17 + used_bits, keys, values);
        const keyed want = stably_sorted(keys, values, 0);
        obbsat::detail::radix_buffer packed, spare;
        obbsat::detail::radix_sort(keys.data(), values.data(), keys.size(), 32, packed, spare, 2);
        EXPECT_EQ(zipped(keys, values), want) << "keys of " << used_bits << " bits";
    }
}

TEST(radix_sort, on_two_threads_sorts_its_buckets_in_the_callers_buffers) {
    // The buckets of a sort on two threads are sorted in the caller's
    // buffers, one a thread, which the next sorts reuse: however many sorts,
    // they hold at most two buckets' worth (two words a key, at most 16384
    // keys a bucket). The answer is that of a sort without them.
    std::vector<std::uint32_t> keys, values;
    random_input(300000, 24, 23, keys, values);
    const keyed want = stably_sorted(keys, values, 0);
    obbsat::detail::radix_buffer packed, spare;
    obbsat::detail::radix_bucket_buffers buckets;
    for (int round = 0; round < 4; ++round) {
        std::vector<std::uint32_t> k = keys, v = values;
        obbsat::detail::radix_sort(k.data(), v.data(), k.size(), 24, packed, spare, 2, &buckets);
        EXPECT_EQ(zipped(k, v), want) << "round " << round;
        EXPECT_GT(buckets.bytes(), 0u) << "round " << round;
        EXPECT_LE(buckets.buffers(), 2u);
        EXPECT_LE(buckets.bytes(), 2u * 2u * 16384u * sizeof(std::uint64_t)) << "round " << round;
    }
}

TEST(radix_sort, in_lent_memory_equals_a_stable_sort_and_writes_only_its_words) {
    // The scene query lends the records' memory: n words for the packed keys
    // and n for the spare, here between words that must keep their values.
    constexpr std::uint64_t canary = 0x5eed5eed5eed5eedull;
    for (const std::size_t n : {std::size_t{2}, std::size_t{5000}, std::size_t{200000}}) {
        for (const std::size_t parts : {std::size_t{1}, std::size_t{2}}) {
            std::vector<std::uint32_t> keys, values;
            random_input(n, 24, n + parts, keys, values);
            const keyed want = stably_sorted(keys, values, 0);
            std::vector<std::uint64_t> lent(2 * n + 3, canary);
            obbsat::detail::radix_sort(keys.data(), values.data(), n, 24, lent.data() + 1, lent.data() + 2 + n,
                                       parts);
            EXPECT_EQ(zipped(keys, values), want) << n << " keys, " << parts << " parts";
            EXPECT_EQ(lent[0], canary);
            EXPECT_EQ(lent[n + 1], canary);
            EXPECT_EQ(lent[2 * n + 2], canary);
        }
    }
}

TEST(radix_sort_indices, fills_each_key_once_over_slices_that_tile_the_keys_and_sorts_the_indices_stably) {
    // The keys come only from `fill`: arrays holding other values beforehand
    // must not leak into the answer, and every index is filled exactly once,
    // in its own memory or in lent memory, on one thread and on two. The
    // indices array is only written, once every key is made: the fill reads
    // the key it makes from there.
    for (const std::size_t n : {std::size_t{0}, std::size_t{1}, std::size_t{5000}, std::size_t{300000}}) {
        for (const std::size_t parts : {std::size_t{1}, std::size_t{2}}) {
            for (const bool lend : {false, true}) {
                std::vector<std::uint32_t> given_keys, positions;
                random_input(n, 20, 3 * n + parts, given_keys, positions);
                const keyed want = stably_sorted(given_keys, positions, 0);
                std::vector<std::uint32_t> keys(n, 0xffffffffu), indices = given_keys;
                std::vector<std::atomic<unsigned>> filled(n);
                std::atomic<bool> outside{false};
                const obbsat::detail::radix_fill fill = [&](std::size_t begin, std::size_t end) {
                    outside.store(outside.load() || begin > end || end > n);
                    for (std::size_t i = begin; i < end && i < n; ++i) {
                        keys[i] = indices[i];
                        filled[i].fetch_add(1);
                    }
                };
                if (lend) {
                    std::vector<std::uint64_t> lent(2 * n + 1);
                    obbsat::detail::radix_sort_indices(keys.data(), indices.data(), n, 20, lent.data(),
                                                       lent.data() + n, parts, fill);
                } else {
                    obbsat::detail::radix_buffer packed, spare;
                    obbsat::detail::radix_sort_indices(keys.data(), indices.data(), n, 20, packed, spare, parts,
                                                       fill);
                }
                const std::string what = std::to_string(n) + " keys, " + std::to_string(parts) + " parts" +
                                         (lend ? ", lent memory" : "");
                EXPECT_FALSE(outside.load()) << what;
                EXPECT_EQ(std::count_if(filled.begin(), filled.end(), [](const auto& f) { return f.load() != 1; }), 0)
                    << what;
                EXPECT_EQ(zipped(keys, indices), want) << what;
            }
        }
    }
}

TEST(radix_sort_indices, on_two_threads_splits_by_the_highest_digit_that_varies) {
    // 24 key bits asked for: keys of 16 bits (the highest digit, the one
    // counted first, the same for all), keys that vary in the highest digit
    // only, and all one key, whose order is the indices themselves.
    const std::vector<std::pair<std::uint32_t, const char*>> masks = {
        {0x00ffffu, "16 low bits"}, {0xff0000u, "the high digit"}, {0u, "one key"}};
    for (const auto& [mask, what] : masks) {
        std::vector<std::uint32_t> given_keys, positions;
        random_input(200000, 24, 29, given_keys, positions);
        for (std::uint32_t& key : given_keys) {
            key = (key & mask) | 0x00a000u;
        }
        const keyed want = stably_sorted(given_keys, positions, 0);
        std::vector<std::uint32_t> keys(given_keys.size()), indices(given_keys.size(), 0xffffffffu);
        obbsat::detail::radix_buffer packed, spare;
        obbsat::detail::radix_sort_indices(keys.data(), indices.data(), keys.size(), 24, packed, spare, 2,
                                           [&](std::size_t begin, std::size_t end) {
                                               std::copy(given_keys.begin() + static_cast<std::ptrdiff_t>(begin),
                                                         given_keys.begin() + static_cast<std::ptrdiff_t>(end),
                                                         keys.begin() + static_cast<std::ptrdiff_t>(begin));
                                           });
        EXPECT_EQ(zipped(keys, indices), want) << what;
    }
}

/// Two runs for merge_by_key, each sorted by (key, value), and their merge.
struct two_runs {
    std::vector<std::uint32_t> a_keys, a_values, b_keys, b_values;
    keyed want;
};

/// The first a_n of `n` random pairs as one run, the rest as the other.
two_runs runs_of(std::size_t a_n, std::size_t b_n, unsigned key_bits, std::uint64_t seed) {
    std::vector<std::uint32_t> keys, values;
    random_input(a_n + b_n, key_bits, seed, keys, values);
    keyed a(a_n), b(b_n);
    for (std::size_t i = 0; i < a_n + b_n; ++i) {
        (i < a_n ? a[i] : b[i - a_n]) = {keys[i], values[i]};
    }
    std::sort(a.begin(), a.end());
    std::sort(b.begin(), b.end());
    two_runs out;
    std::merge(a.begin(), a.end(), b.begin(), b.end(), std::back_inserter(out.want));
    for (const auto& [k, v] : a) {
        out.a_keys.push_back(k);
        out.a_values.push_back(v);
    }
    for (const auto& [k, v] : b) {
        out.b_keys.push_back(k);
        out.b_values.push_back(v);
    }
    return out;
}

TEST(merge_by_key, equals_a_merge_by_key_then_value_on_one_to_four_threads) {
    // Two runs sorted by (key, value), with keys shared between them and
    // long runs of one key (few key bits), one run empty or both of very
    // different lengths; values unique, so the merge has one answer.
    struct sizes {
        std::size_t a, b;
        unsigned key_bits;
    };
    for (const sizes z : {sizes{0, 0, 8}, sizes{0, 5000, 8}, sizes{70000, 0, 12}, sizes{100000, 30000, 6},
                          sizes{20000, 150000, 16}, sizes{90000, 90000, 2}}) {
        const two_runs r = runs_of(z.a, z.b, z.key_bits, z.a + 3 * z.b + z.key_bits);
        for (const std::size_t parts : {std::size_t{1}, std::size_t{2}, std::size_t{3}, std::size_t{4}}) {
            std::vector<std::uint32_t> out_keys(z.a + z.b, 7), out_values(z.a + z.b, 7);
            obbsat::detail::merge_by_key(r.a_keys.data(), r.a_values.data(), z.a, r.b_keys.data(), r.b_values.data(),
                                         z.b, out_keys.data(), out_values.data(), parts);
            EXPECT_EQ(zipped(out_keys, out_values), r.want) << z.a << " + " << z.b << ", " << parts << " parts";
        }
    }
}

TEST(bucket_starts, equals_the_prefix_counts_of_the_buckets_over_any_split_into_shares) {
    // Sorted keys with empty buckets at the start, inside and at the end
    // (keys only in buckets 3 to 290 of 300, many skipped), split into 1 to
    // 7 shares including empty ones.
    const unsigned shift = 12;
    const std::size_t buckets = 300;
    for (const std::size_t n : {std::size_t{1}, std::size_t{2}, std::size_t{37}, std::size_t{5000}}) {
        std::vector<std::uint32_t> keys, values;
        random_input(n, 20, n + 11, keys, values);
        for (std::uint32_t& k : keys) {
            const std::uint32_t bucket = 3 + ((k >> shift) % 288) / 4 * 4;  // every fourth bucket of 3..290
            k = (bucket << shift) | (k & ((1u << shift) - 1));
        }
        std::sort(keys.begin(), keys.end());
        std::vector<std::uint32_t> want(buckets + 1, 0);
        for (const std::uint32_t k : keys) {
            ++want[(k >> shift) + 1];
        }
        for (std::size_t b = 0; b < buckets; ++b) {
            want[b + 1] += want[b];
        }
        for (std::size_t shares = 1; shares <= 7; ++shares) {
            std::vector<std::uint32_t> starts(buckets + 1, 0xdeadbeef);
            for (std::size_t share = shares; share-- > 0;) {  // the order does not matter
                obbsat::detail::bucket_starts(keys.data(), n, shift, buckets, n * share / shares,
                                              n * (share + 1) / shares, starts.data());
            }
            EXPECT_EQ(starts, want) << n << " keys in " << shares << " shares";
        }
    }
}

/// Pairs over a_count first indices, split into `sources` lists: runs of one
/// a from empty to long (up to 3 · 16 + 40 pairs), b drawn from few values so
/// that equal b within a run are common; tags number the pairs. Three or more
/// sources are uneven, as a scene's are: the first lists hold most pairs, and
/// the lower quarter of a holds runs three times as long.
std::vector<std::vector<obbsat::detail::tagged_pair>> random_pairs(std::size_t a_count, std::size_t sources,
                                                                   std::uint64_t seed) {
    obbsat::seeded_random random(seed);
    std::vector<std::vector<obbsat::detail::tagged_pair>> out(sources);
    const bool uneven = sources >= 3;
    std::uint32_t tag = 0;
    for (std::uint32_t a = 0; a < a_count; ++a) {
        const std::uint64_t draw = random.next();
        const std::size_t length = (draw % 7 == 0) ? 17 + draw % 40 : draw % 17;
        const std::size_t run = uneven && a < a_count / 4 ? 3 * length : length;
        for (std::size_t k = 0; k < run; ++k) {
            const std::uint32_t b = static_cast<std::uint32_t>(random.next() % (run + 3)) * 1000u;
            const std::size_t first = random.next() % sources;
            const std::size_t second = random.next() % sources;
            out[uneven ? std::min(first, second) : first].push_back({a, b, tag++});
        }
    }
    for (auto& source : out) {  // sweep order: any order of a
        for (std::size_t i = source.size(); i > 1; --i) {
            std::swap(source[i - 1], source[random.next() % i]);
        }
    }
    return out;
}

TEST(sort_pairs, equals_std_sort_by_a_then_b_with_and_without_tags) {
    for (const std::size_t a_count : {std::size_t{1}, std::size_t{20}, std::size_t{3000}, std::size_t{300000}}) {
        for (const std::size_t sources : {std::size_t{1}, std::size_t{2}, std::size_t{3}}) {
            const auto input = random_pairs(a_count, sources, a_count + sources);
            // Each source in spans of up to 1000 pairs, as a thread hands them over.
            std::vector<obbsat::detail::pair_source<obbsat::detail::tagged_pair>> lists;
            std::vector<obbsat::detail::tagged_pair> want;
            for (const auto& source : input) {
                lists.emplace_back();
                for (std::size_t begin = 0; begin < source.size(); begin += 1000) {
                    lists.back().push_back({source.data() + begin, std::min<std::size_t>(1000, source.size() - begin)});
                }
                want.insert(want.end(), source.begin(), source.end());
            }
            const auto by_pair = [](const auto& x, const auto& y) { return x.a < y.a || (x.a == y.a && x.b < y.b); };
            std::sort(want.begin(), want.end(), by_pair);
            std::vector<obbsat::detail::tagged_pair> got;
            std::vector<obbsat::detail::pair_sort_scratch<obbsat::detail::tagged_pair>> scratch(sources);
            obbsat::detail::sort_pairs(lists, a_count, got, scratch);
            ASSERT_EQ(got.size(), want.size());
            // Sorted by (a, b), and a permutation of the input (every tag once).
            std::vector<unsigned char> seen(got.size(), 0);
            for (std::size_t i = 0; i < got.size(); ++i) {
                ASSERT_EQ(got[i].a, want[i].a) << a_count << " boxes, pair " << i;
                ASSERT_EQ(got[i].b, want[i].b) << a_count << " boxes, pair " << i;
                ASSERT_LT(got[i].tag, seen.size());
                ASSERT_EQ(seen[got[i].tag]++, 0) << "tag " << got[i].tag << " twice";
            }
            // The same pairs without tags.
            std::vector<std::vector<obbsat::pair_index>> plain(sources);
            std::vector<obbsat::detail::pair_source<obbsat::pair_index>> plain_lists;
            for (std::size_t s = 0; s < sources; ++s) {
                for (const auto& p : input[s]) {
                    plain[s].push_back({p.a, p.b});
                }
                plain_lists.push_back({{plain[s].data(), plain[s].size()}});
            }
            std::vector<obbsat::pair_index> plain_got;
            std::vector<obbsat::detail::pair_sort_scratch<obbsat::pair_index>> plain_scratch(sources);
            obbsat::detail::sort_pairs(plain_lists, a_count, plain_got, plain_scratch);
            ASSERT_EQ(plain_got.size(), want.size());
            for (std::size_t i = 0; i < want.size(); ++i) {
                ASSERT_TRUE(plain_got[i].a == want[i].a && plain_got[i].b == want[i].b)
                    << a_count << " boxes, pair " << i;
            }
        }
    }
}

TEST(sort_pairs, sorts_runs_whose_partners_lie_close_together_by_b) {
    // Each a's partners drawn from a narrow window of b, so that many share
    // their high bits: the bucket sort's last read must put those in order.
    obbsat::seeded_random random(11);
    const std::size_t a_count = 2000;
    std::vector<obbsat::pair_index> input;
    for (std::uint32_t a = 0; a < a_count; ++a) {
        std::vector<std::uint32_t> window(600);
        for (std::size_t k = 0; k < window.size(); ++k) {
            window[k] = a * 13u + static_cast<std::uint32_t>(k);
        }
        const std::size_t run = random.next() % 7 == 0 ? random.next() % 300 : random.next() % 9;
        for (std::size_t k = 0; k < run; ++k) {
            std::swap(window[k], window[k + random.next() % (window.size() - k)]);
            input.push_back({a, window[k]});
        }
    }
    for (std::size_t i = input.size(); i > 1; --i) {
        std::swap(input[i - 1], input[random.next() % i]);
    }
    std::vector<obbsat::pair_index> want = input;
    std::sort(want.begin(), want.end(), [](const auto& x, const auto& y) { return x.a < y.a || (x.a == y.a && x.b < y.b); });
    for (const std::size_t sources : {std::size_t{1}, std::size_t{2}}) {
        std::vector<obbsat::detail::pair_source<obbsat::pair_index>> lists(sources);
        for (std::size_t s = 0; s < sources; ++s) {
            const std::size_t begin = input.size() * s / sources;
            const std::size_t end = input.size() * (s + 1) / sources;
            lists[s].push_back({input.data() + begin, end - begin});
        }
        std::vector<obbsat::pair_index> got;
        std::vector<obbsat::detail::pair_sort_scratch<obbsat::pair_index>> scratch(sources);
        obbsat::detail::sort_pairs(lists, a_count, got, scratch);
        ASSERT_EQ(got.size(), want.size());
        for (std::size_t i = 0; i < want.size(); ++i) {
            ASSERT_TRUE(got[i].a == want[i].a && got[i].b == want[i].b) << sources << " sources, pair " << i;
        }
    }
}

TEST(repair_sort, sorts_nearly_sorted_input_and_gives_up_past_its_budget) {
    obbsat::seeded_random random(3);
    std::vector<std::uint32_t> keys(20000), values(20000);
    for (std::size_t i = 0; i < keys.size(); ++i) {
        keys[i] = static_cast<std::uint32_t>(4 * i + random.below(12));  // each key a few places off
        values[i] = static_cast<std::uint32_t>(i);
    }
    const keyed want = stably_sorted(keys, values, 0);
    std::size_t moved = 0;
    ASSERT_TRUE(obbsat::detail::repair_sort(keys.data(), values.data(), keys.size(), keys.size(), &moved));
    EXPECT_EQ(zipped(keys, values), want);
    EXPECT_GT(moved, 0u);
    // Reversed input needs n^2 / 2 moves: refused within a budget of n, still a permutation.
    std::vector<std::uint32_t> reversed(5000), ids(5000);
    for (std::size_t i = 0; i < reversed.size(); ++i) {
        reversed[i] = static_cast<std::uint32_t>(reversed.size() - i);
        ids[i] = static_cast<std::uint32_t>(i);
    }
    EXPECT_FALSE(obbsat::detail::repair_sort(reversed.data(), ids.data(), ids.size(), ids.size()));
    std::sort(ids.begin(), ids.end());
    std::vector<std::uint32_t> all(ids.size());
    std::iota(all.begin(), all.end(), 0u);
    EXPECT_EQ(ids, all);
}

/// The units an executor was handed: the fewest and the most in one step.
struct units_seen {
    std::size_t fewest = std::numeric_limits<std::size_t>::max();
    std::size_t most = 0;
};

/// Every unit a range of its own, the last first, before enqueue returns.
void* enqueue_last_first(obbsat::executor_task task, std::size_t count, std::size_t, void* task_context,
                         void* user) {
    units_seen& seen = *static_cast<units_seen*>(user);
    seen.fewest = std::min(seen.fewest, count);
    seen.most = std::max(seen.most, count);
    for (std::size_t item = count; item-- > 0;) {
        task(item, item + 1, task_context);
    }
    return nullptr;
}

void finish_nothing(void*, void*) {}

TEST(sorts_on_two_threads, cut_every_step_into_more_units_than_threads_with_the_answer_of_one) {
    // A step split one share a thread would hand the executor 2 units; a
    // thread slowed by other work on its core would then hold the other back.
    constexpr std::size_t threads = 2;
    {
        std::vector<std::uint32_t> keys, values;
        random_input(300000, 20, 5, keys, values);
        const keyed want = stably_sorted(keys, values, 0);
        units_seen seen;
        const obbsat::executor last_first{&enqueue_last_first, &finish_nothing, &seen};
        {
            const obbsat::detail::executor_scope scope(&last_first);
            obbsat::detail::radix_buffer packed, spare;
            obbsat::detail::radix_sort(keys.data(), values.data(), keys.size(), 20, packed, spare, threads);
        }
        EXPECT_EQ(zipped(keys, values), want);
        EXPECT_GT(seen.fewest, threads) << "radix_sort";
        EXPECT_NE(seen.most, 0u) << "radix_sort ran on no executor";
    }
    {
        std::vector<std::uint32_t> given_keys, positions;
        random_input(300000, 24, 9, given_keys, positions);
        const keyed want = stably_sorted(given_keys, positions, 0);
        std::vector<std::uint32_t> keys(given_keys.size()), indices(given_keys.size());
        units_seen seen;
        const obbsat::executor last_first{&enqueue_last_first, &finish_nothing, &seen};
        {
            const obbsat::detail::executor_scope scope(&last_first);
            obbsat::detail::radix_buffer packed, spare;
            obbsat::detail::radix_sort_indices(keys.data(), indices.data(), keys.size(), 24, packed, spare, threads,
                                               [&](std::size_t begin, std::size_t end) {
                                                   for (std::size_t i = begin; i < end; ++i) {
                                                       keys[i] = given_keys[i];
                                                   }
                                               });
        }
        EXPECT_EQ(zipped(keys, indices), want);
        EXPECT_GT(seen.fewest, threads) << "radix_sort_indices";
        EXPECT_NE(seen.most, 0u) << "radix_sort_indices ran on no executor";
    }
    {
        const two_runs r = runs_of(120000, 80000, 12, 6);
        std::vector<std::uint32_t> out_keys(r.want.size()), out_values(r.want.size());
        units_seen seen;
        const obbsat::executor last_first{&enqueue_last_first, &finish_nothing, &seen};
        {
            const obbsat::detail::executor_scope scope(&last_first);
            obbsat::detail::merge_by_key(r.a_keys.data(), r.a_values.data(), r.a_keys.size(), r.b_keys.data(),
                                         r.b_values.data(), r.b_keys.size(), out_keys.data(), out_values.data(),
                                         threads);
        }
        EXPECT_EQ(zipped(out_keys, out_values), r.want);
        EXPECT_GT(seen.fewest, threads) << "merge_by_key";
        EXPECT_NE(seen.most, 0u) << "merge_by_key ran on no executor";
    }
    {
        const auto input = random_pairs(300000, threads, 7);
        std::vector<obbsat::detail::pair_source<obbsat::detail::tagged_pair>> lists;
        std::vector<obbsat::detail::tagged_pair> want;
        for (const auto& source : input) {
            lists.push_back({{source.data(), source.size()}});
            want.insert(want.end(), source.begin(), source.end());
        }
        std::sort(want.begin(), want.end(),
                  [](const auto& x, const auto& y) { return x.a < y.a || (x.a == y.a && x.b < y.b); });
        std::vector<obbsat::detail::tagged_pair> got;
        std::vector<obbsat::detail::pair_sort_scratch<obbsat::detail::tagged_pair>> scratch(threads);
        units_seen seen;
        const obbsat::executor last_first{&enqueue_last_first, &finish_nothing, &seen};
        {
            const obbsat::detail::executor_scope scope(&last_first);
            obbsat::detail::sort_pairs(lists, 300000, got, scratch);
        }
        ASSERT_EQ(got.size(), want.size());
        for (std::size_t i = 0; i < want.size(); ++i) {
            ASSERT_TRUE(got[i].a == want[i].a && got[i].b == want[i].b) << "pair " << i;
        }
        EXPECT_GT(seen.fewest, threads) << "sort_pairs";
        EXPECT_NE(seen.most, 0u) << "sort_pairs ran on no executor";
    }
}

}  // namespace
