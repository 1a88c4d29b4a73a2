// Every backend against the scalar references of the methods on double poses,
// verdict for verdict: collide_pairs over pose_records64 forced to each backend
// this CPU runs (the forced one must be the one that ran), on one thread and
// two, on contact families where the exact slow path runs in the lanes, on
// partial last vectors, and on poses whose arithmetic overflows (infinite and
// NaN gaps must compare as in the references).
#include "test_support/pose_cases64.hpp"
#include "test_support/pose_references64.hpp"

#include <obbsat/backend.hpp>
#include <obbsat/collide64.hpp>
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

// Pairs (2i, 2i+1) of several families, both ways round, and some across them;
// odd in number, so that every width leaves a partial last vector.
struct pose_batch {
    std::vector<rect_pose64> poses;
    std::vector<pair_index> pairs;
};

pose_batch batch_of(std::size_t pairs_per_family) {
    obbsat::seeded_random random(91);
    pose_batch b;
    obbsat::test::pose_pair64 (*const makes[])(obbsat::seeded_random&) = {
        obbsat::test::utm_random_pair,   obbsat::test::utm_contact_pair, obbsat::test::far_contact_pair,
        obbsat::test::sliver_pair,       obbsat::test::near_parallel_pair, obbsat::test::scaled_rotation_pair,
        obbsat::test::far_random_pair};
    for (auto make : makes) {
        for (std::size_t i = 0; i < pairs_per_family; ++i) {
            const obbsat::test::pose_pair64 p = make(random);
            b.poses.push_back(p.a);
            b.poses.push_back(p.b);
        }
    }
    // Poses whose products overflow or whose margins are out of range.
    b.poses.push_back(rect_pose64{{-1e308, 0}, {1e308, 1}, {1, 0}});
    b.poses.push_back(rect_pose64{{1e308, 5}, {1e308, 1e308}, {0x1p600, 0x1p600}});
    b.poses.push_back(rect_pose64{{0, 0}, {1, 1}, {0x1p-700, 0x1p-700}});
    b.poses.push_back(rect_pose64{{0x1p-1074, 0}, {0, 0}, {1e-320, 1}});
    const auto size = static_cast<std::uint32_t>(b.poses.size());
    for (std::uint32_t i = 0; i + 1 < size; i += 2) {
        b.pairs.push_back(pair_index{i, i + 1});
        b.pairs.push_back(pair_index{i + 1, i});
    }
    for (std::uint32_t i = size - 4; i < size; ++i) {
        for (std::uint32_t j = size - 4; j < size; ++j) {
            b.pairs.push_back(pair_index{i, j});
        }
        b.pairs.push_back(pair_index{i, 0});
    }
    if (b.pairs.size() % 2 == 0) {
        b.pairs.push_back(pair_index{0, size - 1});
    }
    return b;
}

class double_backends : public ::testing::TestWithParam<backend> {};

TEST_P(double_backends, verdicts_are_the_references_bit_for_bit) {
    const backend b = GetParam();
    if (!obbsat::cpu_supports(b)) {
        GTEST_SKIP() << obbsat::backend_name(b) << " does not run on this CPU";
    }
    const pose_batch batch = batch_of(3000);
    const obbsat::pose_records64 store(batch.poses);
    for (const method m : obbsat::methods_on_doubles(obbsat::store_kind::poses)) {
        std::vector<std::uint8_t> expected(batch.pairs.size());
        std::size_t expected_slow = 0;
        for (std::size_t i = 0; i < batch.pairs.size(); ++i) {
            const rect_pose64& a = batch.poses[batch.pairs[i].a];
            const rect_pose64& pb = batch.poses[batch.pairs[i].b];
            expected[i] = reference64(m, a, pb) ? 1 : 0;
            if (m == method::exact) {
                const obbsat::ref::certified_verdict fast = obbsat::ref::certify(a, pb);
                expected_slow += !fast.separated && !fast.intersecting ? 1 : 0;
            }
        }
        for (const unsigned threads : {1u, 2u}) {
            obbsat::collide_options options;
            options.test = m;
            options.use = b;
            options.threads = threads;
            std::size_t slow = 0;
            options.slow_path_pairs = &slow;
            std::vector<std::uint8_t> verdicts(batch.pairs.size(), 9);
            EXPECT_EQ(obbsat::collide_pairs(store, batch.pairs.data(), batch.pairs.size(), verdicts.data(), options),
                      b);  // the forced backend is the one that ran
            for (std::size_t i = 0; i < verdicts.size(); ++i) {
                ASSERT_EQ(verdicts[i], expected[i]) << obbsat::method_name(m) << " on " << obbsat::backend_name(b)
                                                    << ", " << threads << " threads, pair " << i;
            }
            EXPECT_EQ(slow, expected_slow) << obbsat::method_name(m);
        }
        if (m == method::exact) {
            EXPECT_GT(expected_slow, 1000u);  // the slow path ran inside the lanes
        }
    }
}

std::vector<backend> compiled() { return obbsat::compiled_backends(); }

INSTANTIATE_TEST_SUITE_P(every_backend, double_backends, ::testing::ValuesIn(compiled()),
                         [](const ::testing::TestParamInfo<backend>& param_info) {
                             return std::string(obbsat::backend_name(param_info.param));
                         });

}  // namespace
