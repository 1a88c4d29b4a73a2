// The double pose lanes on every backend against the double scalar references,
// verdict for verdict, where the records reach the lanes in new ways:
// - collide_stream over pose_records64 and over pose_soa64 (consecutive
//   records or arrays, no index), on one thread and more, with streams of 1 to
//   9 pairs (every partial last vector up to AVX-512's width plus one) and the
//   stream errors;
// - collide_pairs, whose lanes transpose each lane's 64-byte record in
//   registers, on pair lists of every length up to three vectors, with indices
//   repeated within a vector and the last record of the store in every lane.
#include "test_support/pose_cases64.hpp"
#include "test_support/pose_references64.hpp"

#include <obbsat/backend.hpp>
#include <obbsat/collide64.hpp>
#include <obbsat/error.hpp>
#include <obbsat/pose_soa64.hpp>
#include <obbsat/ref/pose_exact64.hpp>

#include <gtest/gtest.h>

#include <cstdint>
#include <string>
#include <vector>

namespace {

using obbsat::backend;
using obbsat::method;
using obbsat::pair_index;
using obbsat::rect_pose64;

using obbsat::test::reference64;

/// Pairs a[i], b[i] drawn in turn from the double families (contacts, so that
/// the exact slow path runs in the lanes, slivers, far and scaled poses), then
/// pairs whose products overflow or whose margins are out of range.
struct pose_stream {
    std::vector<rect_pose64> a, b;
};

pose_stream stream_of(std::size_t count, std::uint64_t seed) {
    obbsat::seeded_random random(seed);
    obbsat::test::pose_pair64 (*const makes[])(obbsat::seeded_random&) = {
        obbsat::test::utm_contact_pair, obbsat::test::utm_random_pair,      obbsat::test::far_contact_pair,
        obbsat::test::sliver_pair,      obbsat::test::near_parallel_pair,   obbsat::test::scaled_rotation_pair,
        obbsat::test::far_random_pair};
    const rect_pose64 extremes[] = {rect_pose64{{-1e308, 0}, {1e308, 1}, {1, 0}},
                                    rect_pose64{{1e308, 5}, {1e308, 1e308}, {0x1p600, 0x1p600}},
                                    rect_pose64{{0, 0}, {1, 1}, {0x1p-700, 0x1p-700}},
                                    rect_pose64{{0x1p-1074, 0}, {0, 0}, {1e-320, 1}},
                                    // Rotations beyond the margin's range (|c| > 2^500, < 2^-500) whose
                                    // gaps with finite margins would prove overlap: only the oracle may decide.
                                    rect_pose64{{0, 0}, {0x1p-600, 0x1p-600}, {0x1p501, 0}},
                                    rect_pose64{{0, 0}, {0x1p600, 0x1p600}, {0x1p-501, 0}},
                                    rect_pose64{{0x1p590, 0}, {0x1p600, 0x1p600}, {0x1p-501, 0x1p-502}}};
    constexpr std::size_t extreme_count = sizeof(extremes) / sizeof(extremes[0]);
    pose_stream s;
    std::size_t extreme = 0;
    for (std::size_t i = 0; i < count; ++i) {
        if (i % 11 == 10) {
            // Every ordered pair of extremes in turn, each with itself too.
            s.a.push_back(extremes[extreme % extreme_count]);
            s.b.push_back(extremes[(extreme / extreme_count) % extreme_count]);
            ++extreme;
            continue;
        }
        const obbsat::test::pose_pair64 p = makes[i % 7](random);
        s.a.push_back(p.a);
        s.b.push_back(p.b);
    }
    return s;
}

obbsat::collide_options options_of(method m, backend b, unsigned threads, std::size_t* slow) {
    obbsat::collide_options options;
    options.test = m;
    options.use = b;
    options.threads = threads;
    options.slow_path_pairs = slow;
    return options;
}

class double_streams : public ::testing::TestWithParam<backend> {
protected:
    void SetUp() override {
        if (!obbsat::cpu_supports(GetParam())) {
            GTEST_SKIP() << obbsat::backend_name(GetParam()) << " does not run on this CPU";
        }
    }

    /// Both stream entries over `s` with `m` on `threads`: every verdict the
    /// reference's, nothing written past the stream, the slow-path count the
    /// certified path's, and the forced backend the one that ran.
    void expect_references(const pose_stream& s, method m, unsigned threads) {
        const backend b = GetParam();
        const std::size_t n = s.a.size();
        std::vector<std::uint8_t> expected(n);
        std::size_t expected_slow = 0;
        for (std::size_t i = 0; i < n; ++i) {
            expected[i] = reference64(m, s.a[i], s.b[i]) ? 1 : 0;
            if (m == method::exact) {
                const obbsat::ref::certified_verdict fast = obbsat::ref::certify(s.a[i], s.b[i]);
                expected_slow += !fast.separated && !fast.intersecting ? 1 : 0;
            }
        }
        const obbsat::pose_records64 records_a(s.a), records_b(s.b);
        const obbsat::pose_soa64 soa_a(s.a), soa_b(s.b);
        for (const bool arrays : {false, true}) {
            std::size_t slow = 12345;
            const obbsat::collide_options options = options_of(m, b, threads, &slow);
            std::vector<std::uint8_t> verdicts(n + 1, 9);
            const backend ran = arrays ? obbsat::collide_stream(soa_a, soa_b, verdicts.data(), options)
                                       : obbsat::collide_stream(records_a, records_b, verdicts.data(), options);
            EXPECT_EQ(ran, b);
            const std::string where = std::string(obbsat::method_name(m)) + (arrays ? " over pose_soa64" : " over pose_records64") +
                                      ", " + std::to_string(n) + " pairs, " + std::to_string(threads) + " threads, pair ";
            for (std::size_t i = 0; i < n; ++i) {
                ASSERT_EQ(verdicts[i], expected[i]) << where << i;
            }
            EXPECT_EQ(verdicts[n], 9) << where << n << " (past the stream)";
            if (m == method::exact) {
                EXPECT_EQ(slow, expected_slow) << where;
            }
        }
    }
};

TEST_P(double_streams, verdicts_are_the_references_on_any_thread_count) {
    const pose_stream s = stream_of(9001, 17);  // long enough to split over threads, odd for a tail
    std::size_t contacts = 0;
    for (std::size_t i = 0; i < s.a.size(); ++i) {
        const obbsat::ref::certified_verdict fast = obbsat::ref::certify(s.a[i], s.b[i]);
        contacts += !fast.separated && !fast.intersecting ? 1 : 0;
    }
    EXPECT_GT(contacts, 500u);  // the slow path runs inside the stream lanes
    for (const method m : obbsat::methods_on_doubles(obbsat::store_kind::poses)) {
        for (const unsigned threads : {1u, 2u, 0u}) {
            expect_references(s, m, threads);
        }
    }
}

TEST_P(double_streams, every_partial_last_vector) {
    for (std::size_t n = 0; n <= 9; ++n) {
        const pose_stream s = stream_of(n, 100 + n);
        for (const method m : obbsat::methods_on_doubles(obbsat::store_kind::poses)) {
            expect_references(s, m, 1);
        }
    }
}

TEST_P(double_streams, refuses_streams_of_different_lengths_and_other_methods_writing_nothing) {
    const pose_stream s = stream_of(3, 5);
    const obbsat::pose_records64 a(s.a);
    const obbsat::pose_records64 b(std::vector<rect_pose64>(s.b.begin(), s.b.begin() + 2));
    const obbsat::pose_soa64 soa_a(a), soa_b(b);
    std::vector<std::uint8_t> verdicts(3, 9);
    auto message = [&](const auto& run) {
        try {
            run();
        } catch (const obbsat::invalid_input& e) {
            return std::string(e.what());
        }
        return std::string("no error");
    };
    const obbsat::collide_options exact = options_of(method::exact, GetParam(), 1, nullptr);
    const std::string lengths = "stream batches differ in length: 3 poses in A, 2 in B";
    EXPECT_EQ(message([&] { obbsat::collide_stream(a, b, verdicts.data(), exact); }), lengths);
    EXPECT_EQ(message([&] { obbsat::collide_stream(soa_a, soa_b, verdicts.data(), exact); }), lengths);
    EXPECT_EQ(message([&] { obbsat::collide_stream(a, b, exact); }), lengths);
    const obbsat::collide_options sat4 = options_of(method::sat4, GetParam(), 1, nullptr);
    const std::string refused = message([&] { obbsat::collide_stream(a, a, verdicts.data(), sat4); });
    EXPECT_NE(refused.find("method sat4 does not run on double poses"), std::string::npos) << refused;
    EXPECT_EQ(message([&] { obbsat::collide_stream(soa_a, soa_a, verdicts.data(), sat4); }), refused);
    EXPECT_EQ(verdicts, std::vector<std::uint8_t>(3, 9));
}

/// Pair lists over one store: every length from 1 to three vectors of
/// AVX-512 plus one, each list mixing pairs of the families with pairs that
/// repeat one index in every lane, pairs of a pose with itself and pairs
/// that read the last record of the store.
TEST_P(double_streams, gathered_records_on_lists_of_every_length) {
    const pose_stream s = stream_of(301, 23);
    std::vector<rect_pose64> poses = s.a;
    poses.insert(poses.end(), s.b.begin(), s.b.end());
    const obbsat::pose_records64 store(poses);
    const auto size = static_cast<std::uint32_t>(poses.size());
    const std::uint32_t last = size - 1;
    obbsat::seeded_random random(29);
    for (std::size_t count = 1; count <= 25; ++count) {
        std::vector<pair_index> pairs;
        for (std::size_t i = 0; i < count; ++i) {
            switch ((count + i) % 5) {
                case 0: pairs.push_back({last, static_cast<std::uint32_t>(random.below(size))}); break;
                case 1: pairs.push_back({static_cast<std::uint32_t>(random.below(size)), last}); break;
                case 2: pairs.push_back({last, last}); break;
                case 3: pairs.push_back({7, 7}); break;
                default: {
                    const auto k = static_cast<std::uint32_t>(random.below(s.a.size()));
                    pairs.push_back({k, static_cast<std::uint32_t>(s.a.size()) + k});
                }
            }
        }
        for (const method m : obbsat::methods_on_doubles(obbsat::store_kind::poses)) {
            std::vector<std::uint8_t> verdicts(count + 1, 9);
            EXPECT_EQ(obbsat::collide_pairs(store, pairs.data(), count, verdicts.data(),
                                            options_of(m, GetParam(), 1, nullptr)),
                      GetParam());
            for (std::size_t i = 0; i < count; ++i) {
                ASSERT_EQ(verdicts[i], reference64(m, poses[pairs[i].a], poses[pairs[i].b]) ? 1 : 0)
                    << obbsat::method_name(m) << ", " << count << " pairs, pair " << i;
            }
            EXPECT_EQ(verdicts[count], 9) << count << " pairs: written past the list";
        }
    }
}

/// Stores beyond L2 (2.5 MiB of records) and beyond the L3 share (13 MiB),
/// whose pair lists fetch the records of pairs ahead: verdicts unchanged,
/// on lists long enough to fetch and with a partial last vector, whose
/// fetches must stop at the list's end.
TEST_P(double_streams, gathered_records_fetched_ahead_from_large_stores) {
    for (const std::size_t size : {std::size_t{40000}, std::size_t{210000}}) {
        const pose_stream s = stream_of(size / 2, 31);
        std::vector<rect_pose64> poses = s.a;
        poses.insert(poses.end(), s.b.begin(), s.b.end());
        const obbsat::pose_records64 store(poses);
        obbsat::seeded_random random(37);
        std::vector<pair_index> pairs;
        for (std::size_t i = 0; i < 4001; ++i) {
            const auto k = static_cast<std::uint32_t>(random.below(s.a.size()));
            // Half the pairs across the store at random, half the families' pairs.
            pairs.push_back(i % 2 == 0 ? pair_index{k, static_cast<std::uint32_t>(s.a.size()) + k}
                                       : pair_index{k, static_cast<std::uint32_t>(random.below(poses.size()))});
        }
        pairs.back() = pair_index{static_cast<std::uint32_t>(poses.size() - 1), 0};
        for (const method m : obbsat::methods_on_doubles(obbsat::store_kind::poses)) {
            std::vector<std::uint8_t> verdicts(pairs.size() + 1, 9);
            obbsat::collide_pairs(store, pairs.data(), pairs.size(), verdicts.data(),
                                  options_of(m, GetParam(), 1, nullptr));
            for (std::size_t i = 0; i < pairs.size(); ++i) {
                ASSERT_EQ(verdicts[i], reference64(m, poses[pairs[i].a], poses[pairs[i].b]) ? 1 : 0)
                    << obbsat::method_name(m) << ", store of " << size << ", pair " << i;
            }
            EXPECT_EQ(verdicts[pairs.size()], 9);
        }
    }
}

std::vector<backend> compiled() { return obbsat::compiled_backends(); }

INSTANTIATE_TEST_SUITE_P(every_backend, double_streams, ::testing::ValuesIn(compiled()),
                         [](const ::testing::TestParamInfo<backend>& param_info) {
                             return std::string(obbsat::backend_name(param_info.param));
                         });

}  // namespace
