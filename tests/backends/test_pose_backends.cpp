// Every backend against the scalar references of the methods on poses,
// verdict for verdict: collide_stream and collide_pairs over pose_records, on
// one thread and split over threads; the conversion of poses to corners byte
// for byte; the golden digests of the pose methods. The reference verdicts are
// computed here with the functions of scalar_ref/ directly.
#include "test_support/float_text.hpp"
#include "test_support/sanitizers.hpp"

#include <obbsat/backend.hpp>
#include <obbsat/collide.hpp>
#include <obbsat/digest.hpp>
#include <obbsat/error.hpp>
#include <obbsat/method.hpp>
#include <obbsat/pose_conversion.hpp>
#include <obbsat/pose_records.hpp>
#include <obbsat/pose_soa.hpp>
#include <obbsat/ref/pose_corners.hpp>
#include <obbsat/suites/pose_suite.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <limits>
#include <cmath>
#include <cstdint>
#include <functional>
#include <cstdio>
#include <cstring>
#include <numeric>
#include <string>
#include <vector>

namespace {

using obbsat::backend;
using obbsat::method;
using obbsat::pair_index;
using obbsat::pose_records;
using obbsat::rect_pose;
using obbsat::suites::pose_pairs;
using obbsat::test_support::hex_float;
using verdicts = std::vector<std::uint8_t>;

// The digests of the verdicts of each pose method's scalar reference on
// golden_pairs() below (every pose family mixed, from integer arithmetic and
// exact float operations only, so the same on every machine). Every backend must
// reproduce them. Change one only with a deliberate change of the method or
// of the generator, and say so in the commit.
struct golden_entry {
    method test;
    std::uint64_t digest;
};
constexpr golden_entry golden_digests[] = {
    {method::local, 0xd4ed3c1740d9ba2d},
    {method::conservative, 0x211ec0c6c4225539},  // margins per side since 2026-11-23
    {method::exact, 0xf967d1c22a942ed4},
};

std::string hex_digest(std::uint64_t digest) {
    char text[32];
    std::snprintf(text, sizeof text, "0x%016llx", static_cast<unsigned long long>(digest));
    return text;
}

std::string describe(const rect_pose& p) {
    return "center (" + hex_float(p.center.x) + ", " + hex_float(p.center.y) + ") half (" +
           hex_float(p.half_extents.x) + ", " + hex_float(p.half_extents.y) + ") rotation (" +
           hex_float(p.rotation.x) + ", " + hex_float(p.rotation.y) + ")";
}

pose_pairs golden_pairs() {
    obbsat::seeded_random random(20261123);
    return obbsat::suites::random_pose_pairs(random, 200000);
}

verdicts reference_verdicts(method m, const pose_pairs& pairs) {
    const obbsat::pose_reference_fn reference = obbsat::pose_method_reference(m);
    verdicts out(pairs.a.size());
    for (std::size_t i = 0; i < out.size(); ++i) {
        out[i] = reference(pairs.a[i], pairs.b[i]) ? 1 : 0;
    }
    return out;
}

testing::AssertionResult same_verdicts(const verdicts& expected, const verdicts& got, const pose_pairs& pairs) {
    std::size_t mismatches = 0;
    std::string report;
    for (std::size_t i = 0; i < expected.size(); ++i) {
        if (got[i] != expected[i] && ++mismatches <= 5) {
            report += "\n  pair " + std::to_string(i) + ": reference " + std::to_string(expected[i]) + ", backend " +
                      std::to_string(got[i]) + "\n    A " + describe(pairs.a[i]) + "\n    B " + describe(pairs.b[i]);
        }
    }
    if (mismatches == 0) {
        return testing::AssertionSuccess();
    }
    return testing::AssertionFailure() << mismatches << " of " << expected.size() << " verdicts differ" << report;
}

/// The pairs as one pool of poses with every pose at a shuffled place, and
/// the index pairs into it (pair i of the result is pair i of `pairs`).
struct indexed_poses {
    pose_records pool;
    std::vector<pair_index> pairs;
};

/// The poses of a store as rows in the caller's memory.
std::vector<rect_pose> rows_of(const pose_records& store) {
    std::vector<rect_pose> rows;
    for (std::size_t i = 0; i < store.size(); ++i) {
        rows.push_back(store[i]);
    }
    return rows;
}

indexed_poses scattered(const pose_pairs& pairs, std::uint64_t seed) {
    const std::size_t n = pairs.a.size();
    std::vector<std::uint32_t> place(2 * n);
    std::iota(place.begin(), place.end(), 0u);
    obbsat::seeded_random random(seed);
    for (std::size_t i = place.size(); i > 1; --i) {
        std::swap(place[i - 1], place[random.below(i)]);
    }
    std::vector<rect_pose> pool(2 * n);
    indexed_poses out;
    out.pairs.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
        pool[place[2 * i]] = pairs.a[i];
        pool[place[2 * i + 1]] = pairs.b[i];
        out.pairs[i] = pair_index{place[2 * i], place[2 * i + 1]};
    }
    out.pool = pose_records(pool);
    return out;
}

class pose_backends : public testing::TestWithParam<backend> {
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

    /// Every entry point over poses gives the reference's verdicts for `m`.
    void expect_every_path_matches(method m, const pose_pairs& pairs, unsigned threads) {
        SCOPED_TRACE(std::string(obbsat::method_name(m)) + ", " + std::to_string(threads) + " threads");
        const verdicts expected = reference_verdicts(m, pairs);
        const pose_records a(pairs.a), b(pairs.b);
        verdicts got(expected.size(), 0xee);
        EXPECT_EQ(obbsat::collide_stream(a, b, got.data(), forced(m, threads)), GetParam());
        EXPECT_TRUE(same_verdicts(expected, got, pairs)) << "collide_stream";

        const obbsat::pose_soa soa_a(pairs.a), soa_b(pairs.b);
        std::fill(got.begin(), got.end(), std::uint8_t{0xee});
        EXPECT_EQ(obbsat::collide_stream(soa_a, soa_b, got.data(), forced(m, threads)), GetParam());
        EXPECT_TRUE(same_verdicts(expected, got, pairs)) << "collide_stream over pose_soa";

        const indexed_poses indexed = scattered(pairs, 99);
        std::fill(got.begin(), got.end(), std::uint8_t{0xee});
        EXPECT_EQ(obbsat::collide_pairs(indexed.pool, indexed.pairs.data(), indexed.pairs.size(), got.data(),
                                        forced(m, threads)),
                  GetParam());
        EXPECT_TRUE(same_verdicts(expected, got, pairs)) << "collide_pairs over pose_records";

        const std::vector<rect_pose> rows = rows_of(indexed.pool);
        std::fill(got.begin(), got.end(), std::uint8_t{0xee});
        EXPECT_EQ(obbsat::collide_pairs(rows.data(), rows.size(), indexed.pairs.data(), indexed.pairs.size(),
                                        got.data(), forced(m, threads)),
                  GetParam());
        EXPECT_TRUE(same_verdicts(expected, got, pairs)) << "collide_pairs over rect_pose rows";

        std::vector<pair_index> hits_expected;
        for (std::size_t i = 0; i < expected.size(); ++i) {
            if (expected[i] != 0) {
                hits_expected.push_back(indexed.pairs[i]);
            }
        }
        const std::vector<pair_index> hits = obbsat::colliding_pairs(indexed.pool, indexed.pairs, forced(m, threads));
        ASSERT_EQ(hits.size(), hits_expected.size());
        for (std::size_t i = 0; i < hits.size(); ++i) {
            ASSERT_TRUE(hits[i].a == hits_expected[i].a && hits[i].b == hits_expected[i].b) << i;
        }
    }
};

TEST(pose_methods, the_pose_methods_are_local_conservative_and_exact_on_poses_only_where_offered) {
    const std::vector<method> on_poses = obbsat::methods_on(obbsat::store_kind::poses);
    for (const method m : on_poses) {
        EXPECT_NE(obbsat::pose_method_reference(m), nullptr) << obbsat::method_name(m);
    }
    EXPECT_TRUE(obbsat::runs_on(method::local, obbsat::store_kind::poses));
    EXPECT_FALSE(obbsat::runs_on(method::local, obbsat::store_kind::corners));
    EXPECT_TRUE(obbsat::runs_on(method::conservative, obbsat::store_kind::poses));
    for (const method m : {method::sat4, method::sat4_centered, method::sat4_double}) {
        EXPECT_FALSE(obbsat::runs_on(m, obbsat::store_kind::poses)) << obbsat::method_name(m);
        EXPECT_EQ(obbsat::pose_method_reference(m), nullptr);
    }
}

TEST(pose_methods, every_pose_method_has_a_golden_digest_here) {
    for (const method m : obbsat::methods_on(obbsat::store_kind::poses)) {
        const bool listed = std::any_of(std::begin(golden_digests), std::end(golden_digests),
                                        [&](const golden_entry& e) { return e.test == m; });
        EXPECT_TRUE(listed) << obbsat::method_name(m) << " has no golden digest";
    }
}

TEST(pose_golden, reference_reproduces_golden_digests) {
    const pose_pairs pairs = golden_pairs();
    for (const golden_entry& e : golden_digests) {
        const verdicts v = reference_verdicts(e.test, pairs);
        EXPECT_EQ(hex_digest(obbsat::verdict_digest(v.data(), v.size())), hex_digest(e.digest))
            << obbsat::method_name(e.test) << ": " << std::count(v.begin(), v.end(), 1) << " of " << v.size()
            << " collide";
    }
}

TEST_P(pose_backends, golden_digests_on_every_path) {
    const pose_pairs pairs = golden_pairs();
    const pose_records a(pairs.a), b(pairs.b);
    const obbsat::pose_soa soa_a(pairs.a), soa_b(pairs.b);
    const indexed_poses indexed = scattered(pairs, 5);
    const std::vector<rect_pose> rows = rows_of(indexed.pool);
    for (const golden_entry& e : golden_digests) {
        for (const unsigned threads : {1u, 0u}) {
            const verdicts streamed = obbsat::collide_stream(a, b, forced(e.test, threads));
            EXPECT_EQ(hex_digest(obbsat::verdict_digest(streamed.data(), streamed.size())), hex_digest(e.digest))
                << obbsat::method_name(e.test) << " stream, " << threads << " threads";
            const verdicts soa = obbsat::collide_stream(soa_a, soa_b, forced(e.test, threads));
            EXPECT_EQ(hex_digest(obbsat::verdict_digest(soa.data(), soa.size())), hex_digest(e.digest))
                << obbsat::method_name(e.test) << " stream over pose_soa, " << threads << " threads";
            const verdicts picked = obbsat::collide_pairs(indexed.pool, indexed.pairs, forced(e.test, threads));
            EXPECT_EQ(hex_digest(obbsat::verdict_digest(picked.data(), picked.size())), hex_digest(e.digest))
                << obbsat::method_name(e.test) << " indexed, " << threads << " threads";
            verdicts from_rows(picked.size(), 0xee);
            obbsat::collide_pairs(rows.data(), rows.size(), indexed.pairs.data(), indexed.pairs.size(),
                                  from_rows.data(), forced(e.test, threads));
            EXPECT_EQ(hex_digest(obbsat::verdict_digest(from_rows.data(), from_rows.size())), hex_digest(e.digest))
                << obbsat::method_name(e.test) << " indexed over rows, " << threads << " threads";
        }
    }
}

TEST_P(pose_backends, every_pose_method_matches_its_reference_on_every_kind_and_thread_count) {
    obbsat::seeded_random random(77);
    const pose_pairs pairs = obbsat::suites::random_pose_pairs(random, 60000);
    for (const method m : obbsat::methods_on(obbsat::store_kind::poses)) {
        for (const unsigned threads : {1u, 2u, 0u}) {
            expect_every_path_matches(m, pairs, threads);
        }
    }
}

TEST_P(pose_backends, every_batch_length_and_lane_position) {
    obbsat::seeded_random random(3);
    for (std::size_t n = 0; n <= 70; ++n) {
        const pose_pairs pairs = obbsat::suites::random_pose_pairs(random, n);
        for (const method m : obbsat::methods_on(obbsat::store_kind::poses)) {
            expect_every_path_matches(m, pairs, 1);
        }
    }
}

TEST_P(pose_backends, ten_million_random_pairs_match_the_reference) {
    // In chunks, so that memory stays small; every kind in every chunk. Under
    // the sanitizers, the first two chunks (sanitizers.hpp).
    constexpr std::size_t chunk = 1000000;
    constexpr std::size_t chunks = obbsat::test_support::volume(10, 2);
    obbsat::seeded_random random(1234);
    for (std::size_t done = 0; done < chunks * chunk; done += chunk) {
        const pose_pairs pairs = obbsat::suites::random_pose_pairs(random, chunk);
        const pose_records a(pairs.a), b(pairs.b);
        const obbsat::pose_soa soa_a(pairs.a), soa_b(pairs.b);
        for (const method m : obbsat::methods_on(obbsat::store_kind::poses)) {
            const verdicts expected = reference_verdicts(m, pairs);
            const verdicts got = obbsat::collide_stream(a, b, forced(m, 0));
            ASSERT_TRUE(same_verdicts(expected, got, pairs)) << obbsat::method_name(m) << ", chunk at " << done;
            const verdicts got_soa = obbsat::collide_stream(soa_a, soa_b, forced(m, 1));
            ASSERT_TRUE(same_verdicts(expected, got_soa, pairs))
                << obbsat::method_name(m) << " over pose_soa, chunk at " << done;
        }
    }
}

TEST_P(pose_backends, corners_of_poses_match_the_reference_byte_for_byte) {
    obbsat::seeded_random random(8);
    for (const std::size_t n : {0u, 1u, 3u, 4u, 5u, 15u, 16u, 17u, 33u, 100u, 4099u}) {
        const pose_pairs pairs = obbsat::suites::random_pose_pairs(random, n);
        const pose_records poses(pairs.a);
        std::vector<obbsat::rect> got(n + 1);
        std::memset(got.data(), 0xee, got.size() * sizeof(obbsat::rect));
        const obbsat::rect canary = got[n];
        EXPECT_EQ(obbsat::convert_to_corners(poses, got.data(), GetParam()), GetParam());
        for (std::size_t i = 0; i < n; ++i) {
            const obbsat::rect expected = obbsat::ref::corners_of(pairs.a[i]);
            ASSERT_EQ(std::memcmp(&expected, &got[i], sizeof expected), 0)
                << "pose " << i << " of " << n << ": " << describe(pairs.a[i]);
        }
        EXPECT_EQ(std::memcmp(&canary, &got[n], sizeof canary), 0) << "wrote past the end, n = " << n;
    }
}

TEST_P(pose_backends, corners_keep_the_sign_of_zero_where_products_underflow) {
    // Found by fuzz_pose_backends: every product underflows to a zero, and a
    // backend that negated a zero as 0 - x turned -0 corners into +0.
    const rect_pose tiny{{-0.0f, -0x1.00807ep-82f}, {0x1.000082p-47f, 0x1.04p-143f}, {0x1p-143f, 0x1.0c008p-125f}};
    const pose_records poses(std::vector<rect_pose>(17, tiny));
    std::vector<obbsat::rect> got(17);
    obbsat::convert_to_corners(poses, got.data(), GetParam());
    const obbsat::rect expected = obbsat::ref::corners_of(tiny);
    EXPECT_TRUE(std::signbit(expected.ul.x));
    for (const obbsat::rect& r : got) {
        EXPECT_EQ(std::memcmp(&expected, &r, sizeof r), 0);
    }
}

TEST_P(pose_backends, rows_in_place_refuse_a_bad_pose_or_index_and_write_nothing) {
    obbsat::seeded_random random(8);
    const pose_pairs pairs = obbsat::suites::random_pose_pairs(random, 3000);
    std::vector<rect_pose> rows = pairs.a;
    rows.insert(rows.end(), pairs.b.begin(), pairs.b.end());
    std::vector<pair_index> index_pairs;
    for (std::uint32_t i = 0; i < 3000; ++i) {
        index_pairs.push_back({i, i + 3000});
    }
    const auto refused = [&](const std::vector<pair_index>& list, const std::string& text) {
        verdicts got(list.size(), 0xee);
        try {
            obbsat::collide_pairs(rows.data(), rows.size(), list.data(), list.size(), got.data(),
                                  forced(method::exact, 2));
            ADD_FAILURE() << "accepted; expected: " << text;
        } catch (const obbsat::invalid_input& e) {
            EXPECT_NE(std::string(e.what()).find(text), std::string::npos) << e.what();
        }
        EXPECT_TRUE(std::all_of(got.begin(), got.end(), [](std::uint8_t v) { return v == 0xee; }));
    };
    rows[4100].half_extents.x = -1.0f;
    rows[5000].center.y = std::numeric_limits<float>::infinity();
    refused(index_pairs, "pose 4100: half extent hx is -1, negative");
    rows[4100].half_extents.x = 1.0f;
    refused(index_pairs, "pose 5000: cy is inf, not a finite number");
    rows[5000].center.y = 1.0f;
    std::vector<pair_index> out_of_range = index_pairs;
    out_of_range[2999].b = 6000;
    refused(out_of_range, "pair 2999: index 6000 is out of range");
    EXPECT_THROW(obbsat::collide_pairs(rows.data(), rows.size(), index_pairs.data(), index_pairs.size(), nullptr,
                                       forced(method::sat4)),
                 obbsat::invalid_input);
}

TEST_P(pose_backends, methods_that_do_not_run_on_poses_are_refused_and_nothing_is_written) {
    obbsat::seeded_random random(4);
    const pose_pairs pairs = obbsat::suites::random_pose_pairs(random, 20);
    const pose_records a(pairs.a), b(pairs.b);
    const std::vector<pair_index> index_pairs = {{0, 1}, {2, 3}};
    std::string offered;
    for (const method m : obbsat::methods_on(obbsat::store_kind::poses)) {
        offered += std::string(offered.empty() ? "" : ", ") + obbsat::method_name(m);
    }
    for (const method m : {method::sat4, method::sat4_centered, method::sat4_double}) {
        verdicts got(20, 0xee);
        try {
            obbsat::collide_stream(a, b, got.data(), forced(m));
            ADD_FAILURE() << obbsat::method_name(m) << " ran on poses";
        } catch (const obbsat::invalid_input& e) {
            EXPECT_EQ(std::string(e.what()), std::string("method ") + obbsat::method_name(m) +
                                                 " does not run on poses (pose_records take " + offered + ")");
        }
        EXPECT_THROW(obbsat::collide_pairs(a, index_pairs.data(), 2, got.data(), forced(m)), obbsat::invalid_input);
        EXPECT_TRUE(std::all_of(got.begin(), got.end(), [](std::uint8_t v) { return v == 0xee; }));
    }
    verdicts got(2, 0xee);
    const std::vector<pair_index> out_of_range = {{0, 1}, {2, 20}};
    EXPECT_THROW(obbsat::collide_pairs(a, out_of_range.data(), 2, got.data(), forced(method::local)),
                 obbsat::invalid_input);
    const pose_records shorter(std::vector<rect_pose>(pairs.a.begin(), pairs.a.begin() + 19));
    EXPECT_THROW(obbsat::collide_stream(a, shorter, got.data(), forced(method::local)), obbsat::invalid_input);
    EXPECT_TRUE(std::all_of(got.begin(), got.end(), [](std::uint8_t v) { return v == 0xee; }));
}

INSTANTIATE_TEST_SUITE_P(every_backend, pose_backends,
                         testing::Values(backend::scalar, backend::sse2, backend::avx2, backend::avx512),
                         [](const testing::TestParamInfo<backend>& param_info) {
                             return std::string(obbsat::backend_name(param_info.param));
                         });

}  // namespace

namespace {

TEST(pose_stores, both_stores_refuse_bad_poses_naming_the_pose_and_the_field) {
    const rect_pose good{{1, 2}, {3, 4}, {0.6f, 0.8f}};
    struct bad_case {
        rect_pose pose;
        const char* message;
    };
    const bad_case cases[] = {
        {{{NAN, 2}, {3, 4}, {1, 0}}, "pose 1: cx is nan, not a finite number"},
        {{{1, INFINITY}, {3, 4}, {1, 0}}, "pose 1: cy is inf, not a finite number"},
        {{{1, 2}, {-1, 4}, {1, 0}}, "pose 1: half extent hx is -1, negative"},
        {{{1, 2}, {3, -0.5f}, {1, 0}}, "pose 1: half extent hy is -0.5, negative"},
        {{{1, 2}, {3, 4}, {0, -0.0f}}, "pose 1: rotation vector (c, s) is (0, 0)"},
        {{{1, 2}, {3, 4}, {1, -INFINITY}}, "pose 1: s is -inf, not a finite number"},
    };
    for (const bad_case& c : cases) {
        pose_records records;
        records.push_back(good);
        obbsat::pose_soa soa;
        soa.push_back(good);
        for (auto push : {std::function<void()>([&] { records.push_back(c.pose); }),
                          std::function<void()>([&] { soa.push_back(c.pose); }),
                          std::function<void()>([&] { pose_records(std::vector<rect_pose>{good, c.pose}); })}) {
            try {
                push();
                ADD_FAILURE() << c.message << ": accepted";
            } catch (const obbsat::invalid_input& e) {
                EXPECT_EQ(std::string(e.what()), c.message);
            }
        }
        EXPECT_EQ(records.size(), 1u);
        EXPECT_EQ(soa.size(), 1u);
        try {
            records.set(0, c.pose);
            ADD_FAILURE() << "set accepted " << c.message;
        } catch (const obbsat::invalid_input& e) {
            EXPECT_NE(std::string(e.what()).find("pose 0: "), std::string::npos) << e.what();
        }
    }
    // Zero half extents are a segment or a point: valid.
    pose_records records;
    records.push_back(rect_pose{{0, 0}, {0, 0}, {1e-30f, 0}});
    EXPECT_EQ(records.size(), 1u);
    EXPECT_THROW((void)records.at(1), obbsat::invalid_input);
}

TEST(pose_stores, records_hold_the_pose_as_given_with_zero_padding) {
    const rect_pose p{{0x1.000002p+20f, -3.5f}, {0.0f, 7.25f}, {-0x1p-30f, 0x1.8p+40f}};
    const pose_records records(std::vector<rect_pose>{p, p});
    const float* v = records.data();
    const float expected[8] = {p.center.x, p.center.y, p.half_extents.x, p.half_extents.y,
                               p.rotation.x, p.rotation.y, 0.0f, 0.0f};
    EXPECT_EQ(std::memcmp(v, expected, sizeof expected), 0);
    EXPECT_EQ(std::memcmp(v + 8, expected, sizeof expected), 0);
    EXPECT_EQ(reinterpret_cast<std::uintptr_t>(v) % 64, 0u);
    const obbsat::pose_soa soa(records);
    EXPECT_EQ(soa[1].rotation.y, p.rotation.y);
    EXPECT_EQ(reinterpret_cast<std::uintptr_t>(soa.data(obbsat::pose_field::s)) % 64, 0u);
}

TEST(pose_stores, conversions_from_angles_and_corners) {
    const obbsat::pose angled{{10, 20}, {3, 1}, 0.5f};
    const rect_pose p = obbsat::rect_pose_of(angled);
    EXPECT_EQ(p.rotation.x, static_cast<float>(std::cos(0.5)));
    EXPECT_EQ(p.rotation.y, static_cast<float>(std::sin(0.5)));
    const pose_records from_angles = pose_records::from_angles(std::vector<obbsat::pose>{angled});
    EXPECT_EQ(std::memcmp(from_angles.data(), pose_records(std::vector<rect_pose>{p}).data(), 32), 0);
    EXPECT_THROW(pose_records::from_angles(std::vector<obbsat::pose>{{{0, 0}, {1, 1}, NAN}}), obbsat::invalid_input);
    // An exact rectangle of corners gives back its pose: integer corners of a (3, 4) frame.
    const obbsat::rect r{{-4 - 3, 3 - 4}, {-4 + 3, 3 + 4}, {4 + 3, -3 + 4}, {4 - 3, -3 - 4}};
    const pose_records from_corners = pose_records::from_corners(obbsat::rect_records(std::vector<obbsat::rect>{r}));
    const rect_pose q = from_corners[0];
    EXPECT_EQ(q.center.x, 0.0f);
    EXPECT_EQ(q.center.y, 0.0f);
    EXPECT_EQ(q.half_extents.x, 5.0f);
    EXPECT_EQ(q.half_extents.y, 5.0f);
    EXPECT_EQ(q.rotation.x, 0.6f);
    EXPECT_EQ(q.rotation.y, 0.8f);
    // Degenerate corners still give a valid pose.
    const obbsat::rect point_rect{{1, 1}, {1, 1}, {1, 1}, {1, 1}};
    const rect_pose d = pose_records::from_corners(obbsat::rect_records(std::vector<obbsat::rect>{point_rect}))[0];
    EXPECT_EQ(d.half_extents.x, 0.0f);
    EXPECT_EQ(d.rotation.x, 1.0f);
}

TEST(pose_stores, corner_records_of_refuses_corners_that_overflow) {
    const pose_records poses(std::vector<rect_pose>{{{0, 0}, {1, 1}, {1, 0}}, {{3e38f, 0}, {3e38f, 1}, {1, 0}}});
    try {
        (void)obbsat::corner_records_of(poses);
        ADD_FAILURE() << "accepted";
    } catch (const obbsat::invalid_input& e) {
        EXPECT_NE(std::string(e.what()).find("pose 1:"), std::string::npos) << e.what();
    }
}

}  // namespace
