// Every backend against the scalar references, verdict for verdict, for every
// method and every entry point: collide_stream, collide_pairs over rect_soa
// and collide_pairs over rect_records.
//
// The suite runs once per backend and is named after it. A backend this CPU
// cannot run is skipped, never counted as passed. The reference verdicts are
// computed here with the functions of scalar_ref/ directly, not through the
// scalar backend, so the scalar backend is checked like the others.
#include "test_support/exact_intersection.hpp"
#include "test_support/float_text.hpp"
#include "test_support/hard_pairs.hpp"
#include "test_support/random_pairs.hpp"
#include "test_support/sanitizers.hpp"
#include "test_support/shared_cases.hpp"

#include <obbsat/backend.hpp>
#include <obbsat/collide.hpp>
#include <obbsat/digest.hpp>
#include <obbsat/method.hpp>
#include <obbsat/oracle/contact.hpp>
#include <obbsat/rect_records.hpp>
#include <obbsat/ref/conservative.hpp>
#include <obbsat/ref/sat4.hpp>
#include <obbsat/ref/sat4_centered.hpp>
#include <obbsat/ref/sat4_double.hpp>
#include <obbsat/scene.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <functional>
#include <limits>
#include <map>
#include <numeric>
#include <ostream>
#include <string>
#include <vector>

namespace obbsat {

// Test names and failure messages show a backend by its name.
void PrintTo(backend b, std::ostream* out) { *out << backend_name(b); }

}  // namespace obbsat

namespace {

using obbsat::backend;
using obbsat::method;
using obbsat::pair_index;
using obbsat::rect;
using obbsat::rect_records;
using obbsat::rect_soa;
using obbsat::test_support::describe;
using obbsat::test_support::labelled_pair;
using obbsat::test_support::stream_batch;
using verdicts = std::vector<std::uint8_t>;
using reference_fn = bool (*)(const rect&, const rect&);

// The digests of the verdicts of golden_batch() below, per method: the
// scene's pairs, then the hard pairs. Computed once with the scalar reference
// of each method (the test reference_reproduces_golden_digests prints the
// value on a mismatch) and written here by hand; every backend and the
// reference must reproduce them on every machine. Change one only together
// with a deliberate change of that method, the scene generator or the hard
// pairs, and say so in the commit.
struct golden_entry {
    method test;
    std::uint64_t digest;
};
constexpr golden_entry golden_digests[] = {
    {method::sat4, 0x1b45ee63ec5aa29e},
    {method::sat4_centered, 0x09b8092686886edf},
    {method::sat4_double, 0x3099c979b782180d},
    {method::conservative, 0x59ab712fa3d1242f},
    {method::exact, 0x22608e361cc69299},
};

std::uint64_t golden_digest_of(method m) {
    for (const golden_entry& e : golden_digests) {
        if (e.test == m) {
            return e.digest;
        }
    }
    return 0;
}

std::string hex_digest(std::uint64_t digest) {
    char text[32];
    std::snprintf(text, sizeof text, "0x%016llx", static_cast<unsigned long long>(digest));
    return text;
}

verdicts reference_stream(reference_fn reference, const rect_soa& a, const rect_soa& b) {
    verdicts out(a.size());
    for (std::size_t i = 0; i < a.size(); ++i) {
        out[i] = reference(a[i], b[i]) ? 1 : 0;
    }
    return out;
}

verdicts reference_indexed(reference_fn reference, const rect_soa& rects,
                           const std::vector<pair_index>& pairs) {
    verdicts out(pairs.size());
    for (std::size_t i = 0; i < pairs.size(); ++i) {
        out[i] = reference(rects[pairs[i].a], rects[pairs[i].b]) ? 1 : 0;
    }
    return out;
}

// Describes pair i of a batch for a failure message.
using pair_describer = std::function<std::string(std::size_t)>;

testing::AssertionResult same_verdicts(const verdicts& expected, const std::uint8_t* got,
                                       const pair_describer& describe_pair) {
    std::size_t mismatches = 0;
    std::string report;
    for (std::size_t i = 0; i < expected.size(); ++i) {
        if (got[i] != expected[i]) {
            if (++mismatches <= 5) {
                report += "\n  pair " + std::to_string(i) + ": reference " +
                          std::to_string(expected[i]) + ", backend " + std::to_string(got[i]) +
                          "\n    " + describe_pair(i);
            }
        }
    }
    if (mismatches == 0) {
        return testing::AssertionSuccess();
    }
    return testing::AssertionFailure()
           << mismatches << " of " << expected.size() << " verdicts differ" << report;
}

pair_describer stream_describer(const rect_soa& a, const rect_soa& b) {
    return [&a, &b](std::size_t i) { return "A " + describe(a[i]) + "\n    B " + describe(b[i]); };
}

pair_describer indexed_describer(const rect_soa& rects, const std::vector<pair_index>& pairs) {
    return [&rects, &pairs](std::size_t i) {
        return "rects " + std::to_string(pairs[i].a) + ", " + std::to_string(pairs[i].b) +
               "\n    A " + describe(rects[pairs[i].a]) + "\n    B " + describe(rects[pairs[i].b]);
    };
}

/// One pool of rectangles in both stores and index pairs into it.
struct indexed_batch {
    rect_soa rects;
    rect_records records;
    std::vector<pair_index> pairs;
};

/// The pairs of a stream batch with every rectangle at a shuffled place in
/// one pool, so that pair i of the result is pair i of the stream and the
/// indexed paths read scattered rectangles. Places are shuffled within
/// windows of 4096 rectangles: the indices are as irregular as a full
/// shuffle makes them for the kernels, but the reads stay in cache, so the
/// test spends its time comparing verdicts rather than waiting for memory.
indexed_batch scattered(const stream_batch& batch, std::uint64_t seed) {
    constexpr std::size_t window = 4096;
    const std::size_t n = batch.a.size();
    std::vector<std::uint32_t> place(2 * n);
    std::iota(place.begin(), place.end(), 0u);
    obbsat::seeded_random random(seed);
    for (std::size_t first = 0; first < place.size(); first += window) {
        const std::size_t size = std::min(window, place.size() - first);
        for (std::size_t i = size; i > 1; --i) {
            std::swap(place[first + i - 1], place[first + random.below(i)]);
        }
    }
    std::vector<rect> pool(2 * n);
    indexed_batch out;
    out.pairs.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
        pool[place[2 * i]] = batch.a[i];
        pool[place[2 * i + 1]] = batch.b[i];
        out.pairs[i] = pair_index{place[2 * i], place[2 * i + 1]};
    }
    out.rects = rect_soa(pool);
    out.records = rect_records(pool);
    return out;
}

stream_batch as_stream(const std::vector<labelled_pair>& pairs) {
    stream_batch out;
    out.a.reserve(pairs.size());
    out.b.reserve(pairs.size());
    for (const labelled_pair& p : pairs) {
        out.a.push_back(p.a);
        out.b.push_back(p.b);
    }
    return out;
}

stream_batch as_stream(const rect_soa& rects, const std::vector<pair_index>& pairs) {
    stream_batch out;
    out.a.reserve(pairs.size());
    out.b.reserve(pairs.size());
    for (const pair_index& p : pairs) {
        out.a.push_back(rects[p.a]);
        out.b.push_back(rects[p.b]);
    }
    return out;
}

rect_records as_records(const rect_soa& rects) {
    std::vector<rect> all(rects.size());
    for (std::size_t i = 0; i < rects.size(); ++i) {
        all[i] = rects[i];
    }
    return rect_records(all);
}

obbsat::scene golden_scene() {
    return obbsat::make_scene(
        obbsat::scene_spec_for(obbsat::scene_density::typical, 20000, 200000, 12345));
}

std::uint64_t digest_of(const verdicts& first, const verdicts& second) {
    verdicts all = first;
    all.insert(all.end(), second.begin(), second.end());
    return obbsat::verdict_digest(all.data(), all.size());
}

class backend_equivalence : public testing::TestWithParam<backend> {
protected:
    void SetUp() override {
        if (!obbsat::cpu_supports(GetParam())) {
            GTEST_SKIP() << "backend " << obbsat::backend_name(GetParam())
                         << " is not compiled in or this CPU cannot run it: not tested here";
        }
    }

    obbsat::collide_options forced(method m, unsigned threads = 1) const {
        obbsat::collide_options options;
        options.test = m;
        options.use = GetParam();
        options.threads = threads;
        return options;
    }

    /// Runs method `m` on the pairs as a stream and as indexed pairs over both
    /// stores (pair i of `indexed` is pair i of `stream`); every path must give
    /// the reference's verdicts and report the forced backend. Returns them.
    /// `describe_pair` (default: its two rectangles) tells what stream pair i is.
    verdicts expect_every_path_matches(method m, const stream_batch& stream,
                                       const indexed_batch& indexed, unsigned threads = 1,
                                       pair_describer describe_pair = nullptr) {
        if (!describe_pair) {
            describe_pair = stream_describer(stream.a, stream.b);
        }
        const reference_fn reference = obbsat::method_reference(m);
        const verdicts expected = reference_stream(reference, stream.a, stream.b);
        const std::size_t n = expected.size();
        verdicts got(n, 0xee);
        EXPECT_EQ(obbsat::collide_stream(stream.a, stream.b, got.data(), forced(m, threads)),
                  GetParam());
        EXPECT_TRUE(same_verdicts(expected, got.data(), describe_pair)) << "collide_stream";

        std::fill(got.begin(), got.end(), std::uint8_t{0xee});
        EXPECT_EQ(obbsat::collide_pairs(indexed.rects, indexed.pairs.data(), n, got.data(),
                                        forced(m, threads)),
                  GetParam());
        EXPECT_TRUE(
            same_verdicts(expected, got.data(), indexed_describer(indexed.rects, indexed.pairs)))
            << "collide_pairs over rect_soa";

        std::fill(got.begin(), got.end(), std::uint8_t{0xee});
        EXPECT_EQ(obbsat::collide_pairs(indexed.records, indexed.pairs.data(), n, got.data(),
                                        forced(m, threads)),
                  GetParam());
        EXPECT_TRUE(
            same_verdicts(expected, got.data(), indexed_describer(indexed.rects, indexed.pairs)))
            << "collide_pairs over rect_records";
        return expected;
    }
};

TEST(methods, every_method_has_a_reference_and_a_golden_digest_here) {
    for (const method m : obbsat::methods_on(obbsat::store_kind::corners)) {
        EXPECT_NE(obbsat::method_reference(m), nullptr) << obbsat::method_name(m);
        const bool listed = std::any_of(std::begin(golden_digests), std::end(golden_digests),
                                        [&](const golden_entry& e) { return e.test == m; });
        EXPECT_TRUE(listed) << obbsat::method_name(m) << " has no golden digest";
    }
}

TEST_P(backend_equivalence, forced_backend_is_the_one_that_ran) {
    const obbsat::scene s =
        obbsat::make_scene(obbsat::scene_spec_for(obbsat::scene_density::typical, 2000, 20000, 7));
    const rect_records records = as_records(s.rects);
    const stream_batch stream = as_stream(s.rects, s.pairs);
    verdicts got(s.pairs.size());
    for (const method m : obbsat::methods_on(obbsat::store_kind::corners)) {
        for (const unsigned threads : {1u, 2u, 0u}) {
            SCOPED_TRACE(std::string(obbsat::method_name(m)) + ", " + std::to_string(threads) +
                         " threads");
            EXPECT_EQ(obbsat::collide_pairs(s.rects, s.pairs.data(), s.pairs.size(), got.data(),
                                            forced(m, threads)),
                      GetParam());
            EXPECT_EQ(obbsat::collide_pairs(records, s.pairs.data(), s.pairs.size(), got.data(),
                                            forced(m, threads)),
                      GetParam());
            EXPECT_EQ(obbsat::collide_stream(stream.a, stream.b, got.data(), forced(m, threads)),
                      GetParam());
        }
    }
    EXPECT_EQ(obbsat::resolve_backend(GetParam()), GetParam());
}

// Ten million random pairs through every path with sat4, the article's
// method, and the first two million of them with every other method: the
// other methods share sat4's loads, stores and lane steps, so what they add
// is their own arithmetic, which two million pairs exercise amply. Under the
// sanitizers, the first two million with every method (sanitizers.hpp).
TEST_P(backend_equivalence, ten_million_random_pairs_match_reference) {
    constexpr std::size_t chunks = obbsat::test_support::volume(10, 2);
    constexpr std::size_t pairs_per_chunk = 1000000;
    constexpr std::size_t chunks_for_other_methods = 2;
    std::map<method, std::pair<std::size_t, std::size_t>> hits;  // method -> (hits, pairs)
    for (std::size_t chunk = 0; chunk < chunks; ++chunk) {
        obbsat::seeded_random random(1000 + chunk);
        const stream_batch stream =
            obbsat::test_support::random_stream_batch(random, pairs_per_chunk);
        const indexed_batch indexed = scattered(stream, 2000 + chunk);
        for (const method m : obbsat::methods_on(obbsat::store_kind::corners)) {
            if (m != method::sat4 && chunk >= chunks_for_other_methods) {
                continue;
            }
            SCOPED_TRACE("chunk " + std::to_string(chunk) + ", method " + obbsat::method_name(m));
            const verdicts expected = expect_every_path_matches(m, stream, indexed);
            hits[m].first +=
                static_cast<std::size_t>(std::count(expected.begin(), expected.end(), 1));
            hits[m].second += expected.size();
            if (HasFailure()) {
                return;
            }
        }
    }
    EXPECT_EQ(hits[method::sat4].second, chunks * pairs_per_chunk);
    // Both verdicts must be frequent, or the comparison proves little.
    for (const auto& [m, count] : hits) {
        const double share = static_cast<double>(count.first) / static_cast<double>(count.second);
        EXPECT_GT(share, 0.10) << obbsat::method_name(m);
        EXPECT_LT(share, 0.90) << obbsat::method_name(m);
        RecordProperty(std::string("collision_share_percent_") + obbsat::method_name(m),
                       std::to_string(share * 100.0));
    }
}

TEST_P(backend_equivalence, hard_pairs_match_reference) {
    const std::vector<labelled_pair> hard = obbsat::test_support::hard_pairs();
    const stream_batch stream = as_stream(hard);
    const indexed_batch indexed = scattered(stream, 77);
    // Name the family of every mismatch, so a failure says which kind of input broke.
    const pair_describer with_family = [&](std::size_t i) {
        return std::string(hard[i].family) + "\n    " + stream_describer(stream.a, stream.b)(i);
    };
    for (const method m : obbsat::methods_on(obbsat::store_kind::corners)) {
        SCOPED_TRACE(obbsat::method_name(m));
        expect_every_path_matches(m, stream, indexed, 1, with_family);
    }
}

TEST_P(backend_equivalence, labelled_shared_cases_match_reference) {
    const auto folder = obbsat::test_support::shared_cases_folder();
    if (!folder) {
        GTEST_SKIP() << obbsat::test_support::shared_cases_missing() << ": nothing to compare";
    }
    for (const std::string& name : obbsat::test_support::case_family_names()) {
        const auto family = obbsat::test_support::read_case_family(*folder, name);
        const rect_soa rects(family.rects);
        const rect_records records(family.rects);
        for (const method m : obbsat::methods_on(obbsat::store_kind::corners)) {
            SCOPED_TRACE("family " + name + ", method " + obbsat::method_name(m));
            const verdicts expected = reference_indexed(obbsat::method_reference(m), rects, family.pairs);
            verdicts got(family.pairs.size());
            ASSERT_EQ(obbsat::collide_pairs(rects, family.pairs.data(), family.pairs.size(),
                                            got.data(), forced(m)),
                      GetParam());
            EXPECT_TRUE(same_verdicts(expected, got.data(), indexed_describer(rects, family.pairs)))
                << "over rect_soa";
            ASSERT_EQ(obbsat::collide_pairs(records, family.pairs.data(), family.pairs.size(),
                                            got.data(), forced(m)),
                      GetParam());
            EXPECT_TRUE(same_verdicts(expected, got.data(), indexed_describer(rects, family.pairs)))
                << "over rect_records";
        }
    }
}

// Every length from an empty batch to three full vectors and one more pair,
// through buffers of exactly that size (so a checker of memory errors sees any
// read past them); the bytes around the verdicts must stay as they were.
TEST_P(backend_equivalence, every_batch_length_up_to_three_vectors_and_one) {
    const std::size_t lanes = obbsat::backend_lanes(GetParam());
    const std::vector<labelled_pair> hard = obbsat::test_support::hard_pairs(200);
    constexpr std::size_t guard = 16;
    constexpr std::uint8_t canary = 0xa5;
    auto expect_guards_intact = [&](const verdicts& buffer, std::size_t count, const char* path) {
        for (std::size_t k = 0; k < guard; ++k) {
            ASSERT_EQ(buffer[k], canary) << path << " wrote before the verdicts";
            ASSERT_EQ(buffer[guard + count + k], canary) << path << " wrote past the verdicts";
        }
    };
    for (const method m : obbsat::methods_on(obbsat::store_kind::corners)) {
        const reference_fn reference = obbsat::method_reference(m);
        for (std::size_t count = 0; count <= 3 * lanes + 1; ++count) {
            for (std::size_t start = 0; start < 8; ++start) {
                SCOPED_TRACE(std::string(obbsat::method_name(m)) + ", count " +
                             std::to_string(count) + ", start " + std::to_string(start));
                // A stride through the hard pairs mixes families and both
                // verdicts. The pool holds the Bs in order, then the As backwards.
                std::vector<rect> a(count), b(count), pool(2 * count);
                std::vector<pair_index> pairs(count);
                for (std::size_t i = 0; i < count; ++i) {
                    const labelled_pair& p = hard[(start * 1237 + i * 7919) % hard.size()];
                    a[i] = p.a;
                    b[i] = p.b;
                    pool[i] = p.b;
                    pool[2 * count - 1 - i] = p.a;
                    pairs[i] = pair_index{static_cast<std::uint32_t>(2 * count - 1 - i),
                                          static_cast<std::uint32_t>(i)};
                }
                const rect_soa sa(a), sb(b), rects(pool);
                const rect_records records(pool);
                const verdicts expected = reference_stream(reference, sa, sb);
                ASSERT_EQ(reference_indexed(reference, rects, pairs), expected);

                verdicts buffer(guard + count + guard, canary);
                ASSERT_EQ(obbsat::collide_stream(sa, sb, buffer.data() + guard, forced(m)),
                          GetParam());
                EXPECT_TRUE(
                    same_verdicts(expected, buffer.data() + guard, stream_describer(sa, sb)))
                    << "collide_stream";
                expect_guards_intact(buffer, count, "collide_stream");

                std::fill(buffer.begin(), buffer.end(), canary);
                ASSERT_EQ(obbsat::collide_pairs(rects, pairs.data(), count, buffer.data() + guard,
                                                forced(m)),
                          GetParam());
                EXPECT_TRUE(
                    same_verdicts(expected, buffer.data() + guard, indexed_describer(rects, pairs)))
                    << "collide_pairs over rect_soa";
                expect_guards_intact(buffer, count, "collide_pairs over rect_soa");

                std::fill(buffer.begin(), buffer.end(), canary);
                ASSERT_EQ(obbsat::collide_pairs(records, pairs.data(), count, buffer.data() + guard,
                                                forced(m)),
                          GetParam());
                EXPECT_TRUE(
                    same_verdicts(expected, buffer.data() + guard, indexed_describer(rects, pairs)))
                    << "collide_pairs over rect_records";
                expect_guards_intact(buffer, count, "collide_pairs over rect_records");
            }
        }
    }
}

TEST_P(backend_equivalence, thread_counts_give_identical_verdicts) {
    obbsat::scene s = obbsat::make_scene(
        obbsat::scene_spec_for(obbsat::scene_density::typical, 20000, 200000, 99));
    // An odd length, so the last part ends in a partial vector.
    s.pairs.resize(s.pairs.size() - 13);
    ASSERT_GE(s.pairs.size(), 100000u);
    const stream_batch stream = as_stream(s.rects, s.pairs);
    const indexed_batch indexed{s.rects, as_records(s.rects), s.pairs};
    for (const method m : obbsat::methods_on(obbsat::store_kind::corners)) {
        for (const unsigned threads : {1u, 2u, 3u, 0u}) {
            SCOPED_TRACE(std::string(obbsat::method_name(m)) + ", " + std::to_string(threads) +
                         " threads");
            expect_every_path_matches(m, stream, indexed, threads);
        }
    }
}

TEST_P(backend_equivalence, golden_digests_of_scene_and_hard_pairs) {
    const obbsat::scene s = golden_scene();
    const rect_records scene_records = as_records(s.rects);
    const stream_batch scene_stream = as_stream(s.rects, s.pairs);
    const stream_batch hard = as_stream(obbsat::test_support::hard_pairs());
    const indexed_batch hard_indexed = scattered(hard, 5);
    const std::size_t n_scene = s.pairs.size(), n_hard = hard.a.size();
    for (const method m : obbsat::methods_on(obbsat::store_kind::corners)) {
        SCOPED_TRACE(obbsat::method_name(m));
        const auto options = forced(m, 0);
        verdicts scene_soa(n_scene), scene_rec(n_scene), scene_str(n_scene);
        verdicts hard_str(n_hard), hard_soa(n_hard), hard_rec(n_hard);
        obbsat::collide_pairs(s.rects, s.pairs.data(), n_scene, scene_soa.data(), options);
        obbsat::collide_pairs(scene_records, s.pairs.data(), n_scene, scene_rec.data(), options);
        obbsat::collide_stream(scene_stream.a, scene_stream.b, scene_str.data(), options);
        obbsat::collide_stream(hard.a, hard.b, hard_str.data(), options);
        obbsat::collide_pairs(hard_indexed.rects, hard_indexed.pairs.data(), n_hard,
                              hard_soa.data(), options);
        obbsat::collide_pairs(hard_indexed.records, hard_indexed.pairs.data(), n_hard,
                              hard_rec.data(), options);
        const std::string golden = hex_digest(golden_digest_of(m));
        EXPECT_EQ(hex_digest(digest_of(scene_soa, hard_str)), golden);
        EXPECT_EQ(hex_digest(digest_of(scene_rec, hard_soa)), golden);
        EXPECT_EQ(hex_digest(digest_of(scene_str, hard_rec)), golden);
    }
}

INSTANTIATE_TEST_SUITE_P(every_backend, backend_equivalence,
                         testing::Values(backend::scalar, backend::sse2, backend::avx2,
                                         backend::avx512),
                         [](const testing::TestParamInfo<backend>& param_info) {
                             return std::string(obbsat::backend_name(param_info.param));
                         });

TEST(golden, reference_reproduces_golden_digests) {
    const obbsat::scene s = golden_scene();
    const stream_batch hard = as_stream(obbsat::test_support::hard_pairs());
    for (const method m : obbsat::methods_on(obbsat::store_kind::corners)) {
        const reference_fn reference = obbsat::method_reference(m);
        ASSERT_NE(reference, nullptr) << obbsat::method_name(m);
        const std::uint64_t digest = digest_of(reference_indexed(reference, s.rects, s.pairs),
                                               reference_stream(reference, hard.a, hard.b));
        EXPECT_EQ(hex_digest(digest), hex_digest(golden_digest_of(m)))
            << obbsat::method_name(m) << ": " << s.pairs.size() << " scene pairs, " << hard.a.size()
            << " hard pairs";
    }
}

// Counts the pairs of `family` for which some corner scalar on some of the
// four axes satisfies `pick`: shows that a family reaches the regime it is for.
template <class Pick>
std::size_t pairs_with_scalar(const std::vector<labelled_pair>& pairs, const char* family,
                              Pick pick) {
    std::size_t found = 0;
    for (const labelled_pair& p : pairs) {
        if (std::string(p.family) != family) {
            continue;
        }
        obbsat::point axes[4];
        obbsat::ref::sat4_axes(p.a, p.b, axes);
        bool any = false;
        for (const obbsat::point& axis : axes) {
            for (const rect* r : {&p.a, &p.b}) {
                for (const obbsat::point corner : {r->ul, r->ur, r->lr, r->ll}) {
                    any = any || pick(obbsat::ref::scalar_on_axis(corner, axis));
                }
            }
        }
        found += any ? 1u : 0u;
    }
    return found;
}

TEST(golden, huge_and_subnormal_families_reach_their_regimes) {
    const std::vector<labelled_pair> hard = obbsat::test_support::hard_pairs();
    const std::size_t nan_pairs =
        pairs_with_scalar(hard, "huge", [](float s) { return std::isnan(s); });
    const std::size_t inf_pairs =
        pairs_with_scalar(hard, "huge", [](float s) { return std::isinf(s); });
    const std::size_t subnormal_pairs = pairs_with_scalar(hard, "subnormal", [](float s) {
        return s != 0.0f && std::fabs(s) < std::numeric_limits<float>::min();
    });
    EXPECT_GT(nan_pairs, 10000u) << "pairs of family huge with a NaN scalar (inf - inf)";
    EXPECT_GT(inf_pairs, 10000u) << "pairs of family huge with an infinite scalar";
    EXPECT_GT(subnormal_pairs, 10000u) << "pairs of family subnormal with a subnormal scalar";
    RecordProperty("huge_with_nan", std::to_string(nan_pairs));
    RecordProperty("huge_with_inf", std::to_string(inf_pairs));
    RecordProperty("subnormal_with_subnormal_scalar", std::to_string(subnormal_pairs));
}

// The integer families have small integer corners, so every float operation
// of sat4 is exact there and its verdict must be the exact geometric one:
// touching, nested and identical pairs collide, pairs one lattice step out of
// contact do not, pairs one step in meet or not as the exact oracle says.
// Every other family must produce both verdicts, or it tests less than its
// name says.
TEST(golden, hard_families_give_the_exact_or_both_verdicts) {
    const std::map<std::string, int> exact = {{"integer_touching", 1},
                                              {"integer_one_step_in", -1},
                                              {"integer_identical", 1},
                                              {"integer_nested", 1},
                                              {"integer_one_step_apart", 0}};
    std::map<std::string, std::pair<std::size_t, std::size_t>> counts;  // family -> (hits, total)
    for (const labelled_pair& p : obbsat::test_support::hard_pairs()) {
        const bool hit = obbsat::ref::sat4(p.a, p.b);
        auto& c = counts[p.family];
        c.first += hit ? 1u : 0u;
        c.second += 1;
        const auto known = exact.find(p.family);
        if (known == exact.end()) {
            continue;
        }
        const bool meet = obbsat::test_support::convex_quads_meet(p.a, p.b);
        if (hit != meet || (known->second >= 0 && meet != (known->second == 1))) {
            ADD_FAILURE() << p.family << ": sat4 " << hit << ", exact " << meet << "\n  A "
                          << describe(p.a) << "\n  B " << describe(p.b);
        }
    }
    for (const auto& [family, c] : counts) {
        RecordProperty(family, std::to_string(c.first) + " of " + std::to_string(c.second));
        if (exact.count(family) == 0 || family == "integer_one_step_in") {
            EXPECT_GT(c.first, 0u) << family << ": no pair collides";
            EXPECT_LT(c.first, c.second) << family << ": every pair collides";
        }
    }
    EXPECT_EQ(counts.size(), exact.size() + 9) << "a family is missing or new";
}

}  // namespace
